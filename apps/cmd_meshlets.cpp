// `rastrace meshlets MESH [--order ALGO[,ALGO...]] [--builder all|scan,greedy,spatial,meshopt,meshopt-scan]
//  [--max-vertices 64] [--max-triangles 124] [--cache entries=8,policy=fifo] [--format md|csv|latex|json]
//  [--no-time] [-o FILE]`: meshlets built from each ordering's index stream by rastrace's builders and
// meshoptimizer's (experiments/meshlet_table.h); -o writes one builder's meshlets (experiments/meshlet_file.h).
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "cache_sim/cache_spec.h"
#include "core/error.h"
#include "experiments/meshlet_file.h"
#include "experiments/meshlet_table.h"
#include "scenes/mesh_spec.h"

namespace rastrace {

namespace {

struct MeshletsOptions {
  std::string mesh;
  std::string order = "original";
  std::string builder = "all";
  std::uint32_t max_vertices = 64;
  std::uint32_t max_triangles = 124;
  std::string cache = "entries=8,policy=fifo";
  std::uint64_t seed = 1;
  std::string format = "md";
  bool no_time = false;
  std::string output;
};

void run_meshlets(const MeshletsOptions& options) {
  const TableFormat format = parse_table_format(options.format);
  MeshletTableSpec spec;
  spec.orders = options.order;
  spec.builders = options.builder;
  spec.limits = {options.max_vertices, options.max_triangles};
  spec.local_cache = parse_vertex_cache(options.cache, "--cache");
  spec.seed = options.seed;
  spec.with_time = !options.no_time;
  validate(spec.limits);
  const bool one = options.order.find(',') == std::string::npos && options.builder != "all" &&
                   options.builder.find(',') == std::string::npos;
  if (!options.output.empty() && !one)
    throw InputError("-o '" + options.output + "': writes the meshlets of one ordering and one builder: give " +
                     "--order ALGO and --builder NAME (e.g. --builder greedy)");
  if (!options.output.empty())
    spec.on_built = [&](const std::string& order, const std::string& builder, const MeshletSet& set) {
      write_meshlets(options.output, set, {options.mesh, order, builder, spec.limits});
    };
  const Mesh mesh = load_mesh_spec(options.mesh);
  std::cout << render_table(meshlet_table(mesh, options.mesh, spec), format);
}

}  // namespace

void add_meshlets_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("meshlets", "Meshlets (mesh-shader clusters) from each ordering and builder");
  auto options = std::make_shared<MeshletsOptions>();
  command->add_option("mesh", options->mesh, "Mesh file, builtin:<scene> or grid:WxH")->required();
  command->add_option("--order", options->order, "The ordering(s) whose index stream the builders read: a,b,c")
      ->capture_default_str();
  command
      ->add_option("--builder", options->builder,
                   "all, or a list of scan (in stream order), greedy (grows by shared vertices), spatial "
                   "(bisection of centroids), meshopt, meshopt-scan (meshoptimizer's, in the same process)")
      ->capture_default_str();
  command->add_option("--max-vertices", options->max_vertices, "Vertices per meshlet (3-256)")->check(whole_number(0, 4294967295))->capture_default_str();
  command->add_option("--max-triangles", options->max_triangles, "Triangles per meshlet (1-512)")->check(whole_number(0, 4294967295))
      ->capture_default_str();
  command
      ->add_option("--cache", options->cache,
                   "The vertex cache of the in-meshlet ACMR, emptied at each meshlet (cache spec, README)")
      ->capture_default_str();
  command->add_option("--seed", options->seed, "Seed of the randomized orderings")->check(whole_number(0, 9223372036854775807))->capture_default_str();
  command->add_option("--format", options->format, "md, csv, latex or json")->capture_default_str();
  command->add_flag("--no-time", options->no_time, "Leave out the run-time column so outputs compare byte for byte");
  command->add_option("-o,--output", options->output,
                      "Write the meshlets of one --order and --builder: FILE.json, or the binary layout otherwise");
  command->footer(
      "Examples:\n"
      "  rastrace meshlets data/meshes/bunny00.off --order original,tipsy\n"
      "  rastrace meshlets data/meshes/fandisk.off --max-vertices 64 --max-triangles 64 --format json --no-time\n"
      "  rastrace meshlets data/meshes/fandisk.off --order tipsy --builder greedy -o fandisk.meshlets.json");
  command->callback([options] { run_meshlets(*options); });
}

}  // namespace rastrace
