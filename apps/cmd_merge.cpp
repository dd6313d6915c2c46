// `rastrace merge PARTS... [-o OUT] [--format md|csv|latex|json]`: the parts a sharded sweep
// (`sweep --shard K/N -o PART.json`) wrote, combined into the table the unsharded sweep prints,
// byte for byte; parts of different traces, configuration sets or versions are refused.
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "experiments/cache_report.h"
#include "experiments/sweep_parts.h"

namespace rastrace {

void add_merge_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("merge", "Combine the parts of a sharded sweep into the whole sweep's table");
  struct Options {
    std::vector<std::string> parts;
    std::string output, format = "md";
  };
  auto o = std::make_shared<Options>();
  command->add_option("parts", o->parts, "Part files written by `sweep --shard K/N -o PART.json`, any order")
      ->required();
  command->add_option("-o,--output", o->output, "Write the table to this file (atomically) instead of stdout");
  command->add_option("--format", o->format, "Table format: md, csv, latex or json")->capture_default_str();
  command->footer(
      "Examples:\n"
      "  for k in 1 2 3 4; do rastrace sweep frame.rtrace --cache size=1KiB..1MiB --shard $k/4 -o part-$k.json; done\n"
      "  rastrace merge part-*.json --format csv -o sweep.csv");
  command->callback([o] {
    const TableFormat format = parse_table_format(o->format);
    std::vector<SweepPart> parts;
    for (const std::string& path : o->parts) parts.push_back(read_sweep_part(path));
    const MergedSweep merged = merge_sweep_parts(parts, o->parts);
    for (const std::string& skipped : merged.skipped) std::cerr << "rastrace merge: skipped " << skipped << "\n";
    write_output(o->output, render_table(merged.table, format));
  });
}

}  // namespace rastrace
