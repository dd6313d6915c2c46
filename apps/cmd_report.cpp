// `rastrace report [SCENE] [-o DIR]`: the main job, a compact version of every experiment on one
// scene, written to DIR/report.md (experiments/report.h).
#include <memory>

#include "apps/commands.h"
#include "apps/sweep_flags.h"
#include "experiments/report.h"

namespace rastrace {

namespace {

struct ReportCommand {
  ReportSpec spec;
  SweepFlags sweep{
      .tcache = "size=1KiB..64KiB,line=64B,assoc=full,policy=fifo/lru/opt,layout=linear/block4/block8/morton",
      .retired = {}};
};

}  // namespace

void add_report_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand(
      "report", "The main job: vertex and texture cache experiments on one scene, written to DIR/report.md");
  auto c = std::make_shared<ReportCommand>();
  ReportSpec& spec = c->spec;
  command->add_option("scene", spec.scene, "Scene: builtin:bunny|spider|grid, a JSON scene or a mesh file")
      ->capture_default_str();
  command->add_option("-o,--output", spec.output_dir, "Folder for report.md, plots/, images/ and traces/")
      ->capture_default_str();
  command->add_option("--order", spec.orders, "Orderings whose texture and frame traffic is measured")->capture_default_str();
  command->add_option("--vcache-order", spec.vcache_orders, "Orderings in the vertex cache table")
      ->capture_default_str();
  command->add_option("--model-order", spec.model_orders, "Orderings compared under every vertex reuse preset")
      ->capture_default_str();
  add_sweep_flags(*command, c->sweep);
  command->footer(
      "Examples:\n"
      "  rastrace report                       # builtin:bunny into out/\n"
      "  rastrace report builtin:spider -o out/spider --tcache "
      "size=1KiB..64KiB,assoc=full,policy=lru/opt,layout=block4");
  command->callback([c] {
    ReportSpec report = c->spec;
    report.sweep = sweep_spec_from(c->sweep);
    write_report(report);
  });
}

}  // namespace rastrace
