// `rastrace replay TRACE --cache SPEC...`: replays a trace (rastrace container, CSV export or
// Dinero din) through the given caches in one pass, with the LiveBankSink that live rendering uses.
#include <memory>

#include "apps/commands.h"
#include "experiments/cache_report.h"
#include "experiments/replay_tables.h"

namespace rastrace {

void add_replay_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("replay", "Replay a trace through one or more caches");
  auto trace = std::make_shared<std::string>();
  auto specs = std::make_shared<std::vector<std::string>>();
  auto format = std::make_shared<std::string>("md");
  auto output = std::make_shared<std::string>();
  auto keep_vertex_cache = std::make_shared<bool>(false);
  command->add_option("trace", *trace, "Trace file: rastrace trace (.rtrace), .csv export or Dinero .din")->required();
  command
      ->add_option("--cache", *specs,
                   "Caches to simulate (repeatable; cache spec, README; alternatives a/b expand to every "
                   "combination). Byte cache: size=16KiB,line=64B,assoc=4|full,policy=fifo|lru|random|opt,"
                   "layout=linear|block2..block16|morton[,texel=4B][,align=4KiB][,source=texel|vertex|address]"
                   "[,stride=32B][,seed=1]. Depth or colour cache: source=depth|colour with size=... or model=attila"
                   "[,pixel=4B]. Post-transform vertex cache: entries=16,policy=fifo|lru")
      ->required();
  command->add_option("--format", *format, "Table format: md, csv, latex or json");
  command->add_option("-o,--output", *output, "Write the table to this file (atomically) instead of stdout");
  command->add_flag("--keep-vertex-cache", *keep_vertex_cache,
                    "Keep the post-transform cache across draws (default: empty at each draw)");
  command->footer(
      "Examples:\n"
      "  rastrace replay frame.rtrace --cache size=16KiB,line=64B,assoc=4,policy=lru,layout=block4\n"
      "  rastrace replay frame.rtrace --cache entries=16,policy=fifo --cache size=8KiB,assoc=full,policy=opt\n"
      "  rastrace replay old.din --cache size=32KiB,line=32B,assoc=2 --format json");
  command->callback([=] {
    const TableFormat table_format = parse_table_format(*format);
    const std::vector<Table> tables = replay_tables(*trace, *specs, *keep_vertex_cache);
    write_output(*output, render_tables(tables, table_format));
  });
}

}  // namespace rastrace
