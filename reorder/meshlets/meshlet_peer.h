// The peers: meshoptimizer's meshlet builders (the Debian 0.18 library), run in the same process
// on the same triangle list, their output copied into a MeshletSet (triangles unpadded).
//   meshopt_buildMeshlets      grows by shared vertices, ties broken by distance to the meshlet's
//                              centre, a k-d tree to jump when nothing is adjacent; cone weight 0
//   meshopt_buildMeshletsScan  in the stream's order
// meshoptimizer 0.18 requires max_vertices <= 255 and max_triangles a multiple of 4:
// meshopt_builds_meshlets() says whether it can run on the limits.
#pragma once

#include <span>

#include "reorder/meshlets/meshlet.h"

namespace rastrace {

bool meshopt_builds_meshlets(const MeshletLimits& limits);
// Throw InputError when meshopt_builds_meshlets(limits) is false or the list is invalid.
MeshletSet meshopt_build_meshlets(std::span<const std::uint32_t> triangles, std::span<const glm::vec3> positions,
                                  const MeshletLimits& limits);
MeshletSet meshopt_build_meshlets_scan(std::span<const std::uint32_t> triangles, std::size_t vertex_count,
                                       const MeshletLimits& limits);

}  // namespace rastrace
