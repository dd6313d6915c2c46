// `rastrace reproduce [--paper all|castano,hoppe,yang,yang-texture,sander,forsyth] [--local-iterations N]
//  [--format md|csv|latex|json] [-o FILE]`: every published figure of REFERENCE.md beside ours,
// measured now, with the difference (experiments/reproduce/reproduce.h).
#include <memory>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "experiments/cache_report.h"
#include "experiments/reproduce/reproduce.h"

namespace rastrace {

namespace {

struct ReproduceCommand {
  ReproduceOptions options;
  std::string format = "md";
  std::string output;
};

void run_reproduce(const ReproduceCommand& command) {
  const TableFormat format = parse_table_format(command.format);
  write_output(command.output, render_table(reproduction_table(command.options), format));
}

}  // namespace

void add_reproduce_command(CLI::App& app) {
  CLI::App* sub =
      app.add_subcommand("reproduce", "Published figures of the papers beside rastrace's own, with the difference");
  auto command = std::make_shared<ReproduceCommand>();
  sub->add_option("--paper", command->options.papers,
                  "all, or a comma-separated list of castano, hoppe, yang, yang-texture, sander, forsyth, hakura")
      ->capture_default_str();
  sub->add_option("--local-iterations", command->options.local_iterations,
                  "Perturbation searches of Hoppe's local optimization")->check(whole_number(0, 1000000000))
      ->capture_default_str();
  sub->add_option("--format", command->format, "md, csv, latex or json")->capture_default_str();
  sub->add_option("-o,--output", command->output, "Write the table to FILE instead of standard output");
  sub->footer(
      "Examples:\n"
      "  rastrace reproduce\n"
      "  rastrace reproduce --paper castano,yang --format csv\n"
      "  rastrace reproduce --paper sander --format latex -o sander2008.tex");
  sub->callback([command] { run_reproduce(*command); });
}

}  // namespace rastrace
