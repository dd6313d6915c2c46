#include "experiments/overdraw_table.h"

#include <chrono>
#include <sstream>

#include "cache_sim/vertex_cache.h"
#include "core/error.h"
#include "core/index_stream.h"
#include "experiments/vcache_table.h"
#include "overdraw/meshopt_peer.h"
#include "overdraw/view_independent.h"

#include <meshoptimizer.h>

namespace rastrace {

namespace {

std::string rules_name(const OverdrawRules& rules) {
  if (rules == OverdrawRules::exact()) return "exact";
  if (rules == OverdrawRules::meshopt_fixed()) return "meshopt-fixed";
  if (rules == OverdrawRules::meshopt_018()) return "meshopt-0.18";
  return "custom";
}

double seconds_since(std::chrono::steady_clock::time_point start) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

}  // namespace

std::vector<std::uint32_t> drawn_triangle_list(const Ordering& ordering) {
  std::vector<std::uint32_t> list;
  list.reserve(ordering.indices.size());
  for_each_triangle(ordering.indices, ordering.type, ordering.restart_index,
                    [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
                      if (a == b || b == c || a == c) return;
                      list.insert(list.end(), {a, b, c});
                    });
  return list;
}

Table overdraw_table(const Mesh& mesh, const std::string& mesh_spec, const OverdrawTableSpec& spec) {
  if (spec.cache == 0) throw InputError("--cache 0: a vertex cache needs at least 1 entry");
  const std::vector<const ReorderAlgorithm*> algorithms = select_algorithms(spec.algorithms, mesh);
  OverdrawOptions axes;
  axes.resolution = spec.resolution;
  axes.rules = spec.rules;
  OverdrawOptions sphere = axes;
  sphere.sphere_views = spec.sphere_views;
  ReorderParams params;
  params.cache_size = spec.cache;
  params.seed = spec.seed;
  params.overdraw_lambda = spec.lambda;
  params.view_direction = spec.view_direction;

  Table table;
  table.title = "View-independent overdraw: " + mesh_spec;
  std::ostringstream view;
  view << spec.view_direction.x << "," << spec.view_direction.y << "," << spec.view_direction.z;
  table.parameters = {{"mesh", mesh_spec},
                      {"mesh_faces", mesh.face_count()},
                      {"mesh_vertices", mesh.vertex_count()},
                      {"cache", "fifo " + std::to_string(spec.cache)},
                      {"lambda", spec.lambda},
                      {"view", view.str()},
                      {"views", "axes x, y, z from both sides, back faces culled"},
                      {"resolution", spec.resolution},
                      {"rules", rules_name(spec.rules)},
                      {"overdraw_meshopt", "meshopt_analyzeOverdraw (meshoptimizer " +
                                               std::to_string(MESHOPTIMIZER_VERSION / 1000) + "." +
                                               std::to_string(MESHOPTIMIZER_VERSION % 1000 / 10) +
                                               ") on the same index buffer"}};
  if (spec.sphere_views) table.parameters.emplace_back("sphere_views", spec.sphere_views);
  table.columns = {{"algo", "algorithm", 0},       {"triangles", "triangles", 0},
                   {"acmr", "ACMR", 3},            {"overdraw", "overdraw", 4},
                   {"shaded", "shaded", 0},        {"covered", "covered", 0},
                   {"overdraw_meshopt", "overdraw (meshopt)", 4}};
  if (spec.sphere_views) table.columns.push_back({"overdraw_sphere", "overdraw (sphere)", 4});
  if (spec.with_time) table.columns.push_back({"seconds", "seconds", 4});

  const auto add_row = [&](const std::string& name, const Ordering& ordering, double seconds) {
    const std::vector<std::uint32_t> list = drawn_triangle_list(ordering);
    const VertexStreamStats stats = simulate_vertex_stream(ordering.indices, ordering.type, VertexCachePolicy::Fifo,
                                                           spec.cache, ordering.restart_index);
    const OverdrawCounts ours = view_independent_overdraw(mesh.positions, list, axes);
    std::vector<TableCell> row = {name,
                                  stats.triangles,
                                  stats.acmr(),
                                  ours.overdraw(),
                                  ours.shaded,
                                  ours.covered,
                                  meshopt_analyze_overdraw(mesh.positions, list).overdraw()};
    if (spec.sphere_views) row.emplace_back(view_independent_overdraw(mesh.positions, list, sphere).overdraw());
    if (spec.with_time) row.emplace_back(seconds);
    table.add_row(std::move(row));
  };

  for (const ReorderAlgorithm* algorithm : algorithms) {
    const auto start = std::chrono::steady_clock::now();
    const Ordering ordering = algorithm->run(mesh, params);
    add_row(algorithm->name, ordering, seconds_since(start));
  }
  if (spec.peers && mesh.face_count() > 0) {
    // Tipsy's list through meshoptimizer's overdraw pass (timed: both passes).
    auto start = std::chrono::steady_clock::now();
    Ordering peer;
    peer.indices = meshopt_optimize_overdraw(mesh.positions, reorder_tipsy(mesh, params).indices, float(spec.lambda));
    add_row("meshopt-overdraw", peer, seconds_since(start));
    start = std::chrono::steady_clock::now();
    std::vector<std::uint32_t> vcache(mesh.indices.size());
    meshopt_optimizeVertexCache(vcache.data(), mesh.indices.data(), mesh.indices.size(), mesh.vertex_count());
    peer.indices = meshopt_optimize_overdraw(mesh.positions, vcache, float(spec.lambda));
    add_row("meshopt-full", peer, seconds_since(start));
  }
  return table;
}

}  // namespace rastrace
