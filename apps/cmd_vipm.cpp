// `rastrace vipm MESH [--methods all|vanilla,skipstrips,skiplists,mixed,mixedstrips,sliding]
//  [--cache entries=16,policy=fifo] [--lod-step N] [--tolerance X] [--min-triangles N]
//  [--format md|csv|latex|json] [--plot FILE] [-o FILE]`: the VIPM representations of the mesh's
// progressive mesh (Forsyth 2001) measured at every lod-step-th LoD: a table per LoD sample, the
// summary per method, and Forsyth's Table 4.1.1 with our figure beside each of his words.
#include <memory>

#include "apps/commands.h"
#include "core/error.h"
#include "cache_sim/cache_spec.h"
#include "experiments/cache_report.h"
#include "experiments/vipm_experiment.h"
#include "scenes/mesh_spec.h"

namespace rastrace {

namespace {

struct VipmOptions {
  std::string mesh;
  std::string cache = "entries=16,policy=fifo";
  std::string format = "md";
  std::string plot;
  std::string output;
  VipmExperimentSpec spec;
};

void run_vipm(VipmOptions options) {
  const TableFormat format = parse_table_format(options.format);
  options.spec.cache = parse_vertex_cache(options.cache, "--cache");
  if (options.spec.cache.batched())
    throw InputError("--cache '" + options.cache + "': the VIPM measures use a FIFO or LRU cache shared by the draw, " +
                     "not warp or batch models: write entries=N,policy=fifo or lru");
  const Mesh mesh = load_mesh_spec(options.mesh);
  const VipmExperiment experiment = run_vipm_experiment(mesh, options.mesh, options.spec);
  const std::vector<Table> tables = {vipm_lod_table(experiment), vipm_summary_table(experiment),
                                     vipm_forsyth_table(experiment)};
  write_output(options.output, format == TableFormat::Json ? vipm_json(experiment) : render_tables(tables, format));
  if (!options.plot.empty()) write_vipm_plot(options.plot, experiment);
}

}  // namespace

void add_vipm_command(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("vipm", "VIPM representations of a mesh's progressive mesh, measured per LoD (Forsyth 2001)");
  auto options = std::make_shared<VipmOptions>();
  command->add_option("mesh", options->mesh, "Mesh file, builtin:<scene> or grid:WxH")->required();
  command
      ->add_option("--methods", options->spec.methods,
                   "all, or a comma-separated list of vanilla, skipstrips, skiplists, mixed, mixedstrips, sliding")
      ->capture_default_str();
  command->add_option("--cache", options->cache, "The post-transform vertex cache: entries=N,policy=fifo|lru")
      ->capture_default_str();
  command->add_option("--lod-step", options->spec.lod_step, "Measure every N-th LoD (collapses between samples)")
      ->capture_default_str();
  command
      ->add_option("--tolerance", options->spec.tolerance,
                   "Sliding window: relax the collapse order within this fraction of the mean collapse error")
      ->capture_default_str();
  command
      ->add_option("--min-triangles", options->spec.min_triangles,
                   "Stop collapsing at this many triangles (0: max(16, 2% of the faces))")
      ->capture_default_str();
  command->add_option("--format", options->format, "md, csv, latex or json")->capture_default_str();
  command->add_option("--plot", options->plot,
                      "Draw vertices per triangle against triangles and memory per method: FILE.png or FILE.svg");
  command->add_option("-o,--output", options->output, "Write the tables to this file (default: stdout)");
  command->footer(
      "Examples:\n"
      "  rastrace vipm data/meshes/bunny00.off --lod-step 200\n"
      "  rastrace vipm data/meshes/fandisk.off --methods vanilla,sliding --cache entries=24,policy=lru --format csv\n"
      "  rastrace vipm grid:16x16 --format json -o grid_vipm.json --plot grid_vipm.png");
  command->callback([options] { run_vipm(*options); });
}

}  // namespace rastrace
