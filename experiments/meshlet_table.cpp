#include "experiments/meshlet_table.h"

#include <chrono>
#include <sstream>

#include "cache_sim/cache_spec.h"
#include "cache_sim/vertex_cache.h"
#include "core/error.h"
#include "core/index_stream.h"
#include "reorder/meshlets/meshlet_peer.h"
#include "reorder/meshlets/meshlet_stats.h"
#include "reorder/ordering.h"

namespace rastrace {

namespace {

std::vector<std::string> split_list(const std::string& list, const std::string& option) {
  std::vector<std::string> names;
  std::stringstream stream(list);
  std::string name;
  while (std::getline(stream, name, ','))
    if (name.empty())
      throw InputError(option + " '" + list + "': empty name");
    else
      names.push_back(name);
  if (names.empty()) throw InputError(option + ": expected at least one name");
  return names;
}

}  // namespace

const std::vector<std::string>& meshlet_builder_names() {
  static const std::vector<std::string> names = {"scan", "greedy", "spatial", "meshopt", "meshopt-scan"};
  return names;
}

std::vector<std::uint32_t> ordered_triangle_list(const Mesh& mesh, const std::string& order, std::uint64_t seed) {
  ReorderParams params;
  params.seed = seed;
  const Ordering ordering = find_reorder_algorithm(order).run(mesh, params);
  std::vector<std::uint32_t> triangles;
  triangles.reserve(mesh.indices.size());
  for_each_triangle(ordering.indices, ordering.type, ordering.restart_index,
                    [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
                      if (a != b && b != c && a != c) triangles.insert(triangles.end(), {a, b, c});
                    });
  return triangles;
}

MeshletSet build_meshlets(const std::string& builder, std::span<const std::uint32_t> triangles, const Mesh& mesh,
                          const MeshletLimits& limits) {
  if (builder == "scan") return build_meshlets_scan(triangles, mesh.vertex_count(), limits);
  if (builder == "greedy") return build_meshlets_greedy(triangles, mesh.positions, limits);
  if (builder == "spatial") return build_meshlets_spatial(triangles, mesh.positions, limits);
  if (builder == "meshopt") return meshopt_build_meshlets(triangles, mesh.positions, limits);
  if (builder == "meshopt-scan") return meshopt_build_meshlets_scan(triangles, mesh.vertex_count(), limits);
  throw InputError("--builder '" + builder + "': expected all or scan, greedy, spatial, meshopt, meshopt-scan");
}

Table meshlet_table(const Mesh& mesh, const std::string& mesh_spec, const MeshletTableSpec& spec) {
  validate(spec.limits);
  const std::vector<std::string> orders = split_list(spec.orders, "--order");
  for (const std::string& order : orders) find_reorder_algorithm(order);  // unknown names fail before any work
  std::vector<std::string> builders;
  if (spec.builders == "all") {
    for (const std::string& name : meshlet_builder_names())
      if (name.rfind("meshopt", 0) != 0 || meshopt_builds_meshlets(spec.limits)) builders.push_back(name);
  } else {
    builders = split_list(spec.builders, "--builder");
  }
  VertexCache check(spec.local_cache.policy, spec.local_cache.entries);  // rejects a cache of 0 entries

  Table table;
  table.title = "Meshlets: " + mesh_spec;
  table.parameters = {{"mesh", mesh_spec},
                      {"mesh_faces", mesh.face_count()},
                      {"mesh_vertices", mesh.vertex_count()},
                      {"max_vertices", spec.limits.max_vertices},
                      {"max_triangles", spec.limits.max_triangles},
                      {"local_cache", format_cache_spec(spec.local_cache)},
                      {"bytes_formula", "(4 * vertices + 3 * triangles) / triangles"},
                      {"seed", static_cast<std::int64_t>(spec.seed)}};
  table.columns = {{"order", "order", 0},
                   {"builder", "builder", 0},
                   {"meshlets", "meshlets", 0},
                   {"triangles", "triangles", 0},
                   {"vertices", "vertices", 0},
                   {"vertices_per_triangle", "vertices/triangle", 3},
                   {"perimeter_edges", "perimeter edges", 0},
                   {"vertex_fill", "vertex fill", 3},
                   {"triangle_fill", "triangle fill", 3},
                   {"bytes_per_triangle", "bytes/triangle", 2},
                   {"acmr", "in-meshlet ACMR", 3}};
  if (spec.with_time) table.columns.push_back({"seconds", "seconds", 4});
  for (const std::string& order : orders) {
    const std::vector<std::uint32_t> triangles = ordered_triangle_list(mesh, order, spec.seed);
    for (const std::string& builder : builders) {
      const auto start = std::chrono::steady_clock::now();
      const MeshletSet set = build_meshlets(builder, triangles, mesh, spec.limits);
      const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      const MeshletStats stats = meshlet_stats(set, spec.limits, spec.local_cache);
      std::vector<TableCell> row = {order,
                                    builder,
                                    stats.meshlets,
                                    stats.triangles,
                                    stats.vertices,
                                    stats.vertices_per_triangle,
                                    stats.perimeter_edges,
                                    stats.vertex_fill,
                                    stats.triangle_fill,
                                    stats.bytes_per_triangle,
                                    stats.acmr};
      if (spec.with_time) row.emplace_back(seconds);
      table.add_row(std::move(row));
      if (spec.on_built) spec.on_built(order, builder, set);
    }
  }
  return table;
}

}  // namespace rastrace
