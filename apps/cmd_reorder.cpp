// `rastrace reorder MESH --algo NAME [--cache 16] [--policy fifo|lru] [--seed N] [--vertices keep|first-use]
// -o OUT.off|ply|obj`: writes the mesh with its faces in the algorithm's order. Faces keep their winding and
// material. Vertices keep their order, or with --vertices first-use are renumbered in the order the
// reordered faces first use them (meshopt_optimizeVertexFetch's order; reorder/vertex_order.h), every
// attribute moved with its vertex. Only faces are written: an
// ordering's extra degenerate triangles (Castano's prefetch row) and strip encodings do not
// survive in a mesh file. Prints one line: the faces written and their ACMR on the given cache.
#include <iostream>
#include <memory>

#include "apps/commands.h"
#include "apps/option_checks.h"
#include "cache_sim/vertex_cache.h"
#include "cache_sim/vertex_fetch.h"
#include "core/error.h"
#include "reorder/ordering.h"
#include "reorder/vertex_order.h"
#include "scenes/mesh_io.h"
#include "scenes/mesh_spec.h"

namespace rastrace {

namespace {

struct ReorderOptions {
  std::string mesh;
  std::string algorithm;
  unsigned cache = 16;
  std::string policy = "fifo";
  std::uint64_t seed = 1;
  double time_budget = 60.0;
  std::string vertices = "keep";
  std::string output;
};

void run_reorder(const ReorderOptions& options) {
  const ReorderAlgorithm& algorithm = find_reorder_algorithm(options.algorithm);
  ReorderParams params;
  params.cache_size = options.cache;
  params.policy = parse_vertex_cache_policy(options.policy);
  params.seed = options.seed;
  params.time_budget_seconds = options.time_budget;
  VertexCache check(params.policy, params.cache_size);  // rejects a cache of 0 before any work
  if (options.vertices != "keep" && options.vertices != "first-use")
    throw InputError("--vertices '" + options.vertices + "': expected keep or first-use");
  Mesh mesh = load_mesh_spec(options.mesh);
  const Ordering ordering = algorithm.run(mesh, params);

  mesh.indices = indices_in_face_order(mesh, ordering.face_order);
  if (!mesh.face_material.empty()) {
    std::vector<std::uint32_t> materials(ordering.face_order.size());
    for (std::size_t i = 0; i < materials.size(); ++i) materials[i] = mesh.face_material[ordering.face_order[i]];
    mesh.face_material = std::move(materials);
  }
  mesh.grid.reset();  // the faces are no longer in make_grid's order
  if (options.vertices == "first-use") remap_vertices(mesh, first_use_vertex_remap(mesh.indices, mesh.vertex_count()));
  save_mesh(mesh, options.output);

  const VertexStreamStats before =
      simulate_vertex_stream(ordering.indices, ordering.type, params.policy, params.cache_size, ordering.restart_index);
  const VertexStreamStats written =
      simulate_vertex_stream(mesh.indices, PrimitiveType::TriangleList, params.policy, params.cache_size);
  std::cout << options.output << ": " << mesh.face_count() << " faces in " << algorithm.name << " order, ACMR "
            << written.acmr() << " on " << to_string(params.policy) << " " << params.cache_size;
  if (written.misses != before.misses) std::cout << " (" << before.acmr() << " as the algorithm's own index stream)";
  const VertexFetchStats fetch =
      simulate_vertex_fetch(mesh.indices, PrimitiveType::TriangleList, kNoRestart, 32, meshopt_fetch_cache());
  std::cout << "; vertex fetch " << fetch.bytes_fetched << " bytes, overfetch " << fetch.overfetch()
            << " (32-byte vertices, meshopt's model)\n";
}

}  // namespace

void add_reorder_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("reorder", "Write a mesh with its faces reordered for the vertex cache");
  auto options = std::make_shared<ReorderOptions>();
  command->add_option("mesh", options->mesh, "Mesh file, builtin:<scene> or grid:WxH")->required();
  command->add_option("--algo", options->algorithm, "Ordering algorithm (see `rastrace vcache --help`)")->required();
  command->add_option("--cache", options->cache, "Cache size the ordering optimizes for")->check(whole_number(1, 65536))->capture_default_str();
  command->add_option("--policy", options->policy, "fifo or lru")->capture_default_str();
  command->add_option("--seed", options->seed, "Seed of the randomized orderings")->check(whole_number(0, 9223372036854775807))->capture_default_str();
  command->add_option("--time-budget", options->time_budget, "Seconds for iterative orderings (local)")->check(finite_number(0, 1e6))
      ->capture_default_str();
  command
      ->add_option("--vertices", options->vertices,
                   "keep (the file's vertex order) or first-use (vertices in the order the faces first use them)")
      ->capture_default_str();
  command->add_option("-o,--output", options->output, "Output mesh (.off, .ply or .obj)")->required();
  command->footer(
      "Examples:\n"
      "  rastrace reorder data/meshes/bunny00.off --algo tipsy --cache 16 -o bunny_tipsy.ply\n"
      "  rastrace reorder data/meshes/bunny00.off --algo tipsy --vertices first-use -o bunny_tipsy_fetch.ply\n"
      "  rastrace reorder grid:64x64 --algo grid --cache 24 -o grid64.obj");
  command->callback([options] { run_reorder(*options); });
}

}  // namespace rastrace
