#include "reorder/meshlets/meshlet_peer.h"

#include <meshoptimizer.h>

#include <string>
#include <vector>

#include "core/error.h"

namespace rastrace {

namespace {

void require_meshopt_limits(const MeshletLimits& limits) {
  validate(limits);
  if (!meshopt_builds_meshlets(limits))
    throw InputError("meshoptimizer 0.18 builds meshlets of at most 255 vertices and a multiple of 4 triangles: " +
                     std::to_string(limits.max_vertices) + "/" + std::to_string(limits.max_triangles) +
                     " is outside its limits");
}

// meshoptimizer's output (triangles padded to 4 bytes per meshlet) as a MeshletSet.
template <typename Build>
MeshletSet run_meshopt(std::span<const std::uint32_t> triangles, const MeshletLimits& limits, Build&& build) {
  const std::size_t bound = meshopt_buildMeshletsBound(triangles.size(), limits.max_vertices, limits.max_triangles);
  std::vector<meshopt_Meshlet> meshlets(bound);
  std::vector<unsigned int> vertices(bound * limits.max_vertices);
  std::vector<unsigned char> corners(bound * limits.max_triangles * 3);
  meshlets.resize(build(meshlets.data(), vertices.data(), corners.data()));
  MeshletSet set;
  for (const meshopt_Meshlet& m : meshlets) {
    set.meshlets.push_back({static_cast<std::uint32_t>(set.vertices.size()),
                            static_cast<std::uint32_t>(set.triangle_count()), m.vertex_count, m.triangle_count});
    set.vertices.insert(set.vertices.end(), vertices.begin() + m.vertex_offset,
                        vertices.begin() + m.vertex_offset + m.vertex_count);
    set.triangles.insert(set.triangles.end(), corners.begin() + m.triangle_offset,
                         corners.begin() + m.triangle_offset + 3 * m.triangle_count);
  }
  return set;
}

}  // namespace

bool meshopt_builds_meshlets(const MeshletLimits& limits) {
  return limits.max_vertices >= 3 && limits.max_vertices <= 255 && limits.max_triangles >= 4 &&
         limits.max_triangles <= 512 && limits.max_triangles % 4 == 0;
}

MeshletSet meshopt_build_meshlets(std::span<const std::uint32_t> triangles, std::span<const glm::vec3> positions,
                                  const MeshletLimits& limits) {
  require_meshopt_limits(limits);
  validate_triangle_list(triangles, positions.size());
  return run_meshopt(triangles, limits, [&](meshopt_Meshlet* meshlets, unsigned int* vertices, unsigned char* corners) {
    return meshopt_buildMeshlets(meshlets, vertices, corners, triangles.data(), triangles.size(), &positions[0].x,
                                 positions.size(), sizeof(glm::vec3), limits.max_vertices, limits.max_triangles, 0.0f);
  });
}

MeshletSet meshopt_build_meshlets_scan(std::span<const std::uint32_t> triangles, std::size_t vertex_count,
                                       const MeshletLimits& limits) {
  require_meshopt_limits(limits);
  validate_triangle_list(triangles, vertex_count);
  return run_meshopt(triangles, limits, [&](meshopt_Meshlet* meshlets, unsigned int* vertices, unsigned char* corners) {
    return meshopt_buildMeshletsScan(meshlets, vertices, corners, triangles.data(), triangles.size(), vertex_count,
                                     limits.max_vertices, limits.max_triangles);
  });
}

}  // namespace rastrace
