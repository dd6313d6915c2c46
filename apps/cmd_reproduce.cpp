// `rastrace reproduce [--paper all|castano,hoppe,yang,yang-texture,sander,forsyth,hakura,hakura-compressed]
//  [--local-iterations N] [--format md|csv|latex|json] [-o FILE]`: every published figure of
// REFERENCE.md beside ours, measured now, with the difference (experiments/reproduce/reproduce.h).
// `rastrace reproduce --study compressed [--plot FILE]`: the study of texture traffic by storage
// format and anisotropy instead (experiments/compressed_study.h).
#include <memory>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "core/error.h"
#include "experiments/cache_report.h"
#include "experiments/compressed_study.h"
#include "experiments/reproduce/reproduce.h"

namespace rastrace {

namespace {

struct ReproduceCommand {
  ReproduceOptions options;
  std::string format = "md";
  std::string output;
  std::string study;
  std::string plot;
};

void run_reproduce(const ReproduceCommand& command) {
  const TableFormat format = parse_table_format(command.format);
  if (command.study.empty()) {
    if (!command.plot.empty()) throw InputError("--plot draws a study: add --study compressed");
    write_output(command.output, render_table(reproduction_table(command.options), format));
    return;
  }
  if (command.study != "compressed") throw InputError("--study '" + command.study + "': expected compressed");
  const CompressedStudy study;
  if (!command.plot.empty()) gnuplot_terminal(command.plot, 1, 1);  // a bad name fails before the renders
  const std::vector<CompressedStudyRow> rows = run_compressed_study(study);
  write_output(command.output, render_table(compressed_study_table(study, rows), format));
  if (!command.plot.empty()) write_compressed_study_plot(command.plot, rows, study.scenes.front(), "original");
}

}  // namespace

void add_reproduce_command(CLI::App& app) {
  CLI::App* sub =
      app.add_subcommand("reproduce", "Published figures of the papers beside rastrace's own, with the difference");
  auto command = std::make_shared<ReproduceCommand>();
  sub->add_option("--paper", command->options.papers,
                  "all, or a comma-separated list of castano, hoppe, yang, yang-texture, sander, forsyth, hakura, "
                  "hakura-compressed")
      ->capture_default_str();
  sub->add_option("--local-iterations", command->options.local_iterations,
                  "Perturbation searches of Hoppe's local optimization")->check(whole_number(0, 1000000000))
      ->capture_default_str();
  sub->add_option("--format", command->format, "md, csv, latex or json")->capture_default_str();
  sub->add_option("-o,--output", command->output, "Write the table to FILE instead of standard output");
  sub->add_option("--study", command->study,
                  "compressed: texture bytes per fragment and miss ratio at 1 KiB-256 KiB for RGBA8, BC1 and BC7 at "
                  "anisotropy 1, 4 and 16, per scene and ordering, instead of the published figures");
  sub->add_option("--plot", command->plot, "With --study: bytes per fragment against cache size (.png or .svg)");
  sub->footer(
      "Examples:\n"
      "  rastrace reproduce\n"
      "  rastrace reproduce --paper castano,yang --format csv\n"
      "  rastrace reproduce --paper sander --format latex -o sander2008.tex\n"
      "  rastrace reproduce --study compressed --format csv -o compressed.csv --plot compressed.png");
  sub->callback([command] { run_reproduce(*command); });
}

}  // namespace rastrace
