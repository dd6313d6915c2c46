#include "lod/progressive_mesh_peer.h"

#include <meshoptimizer.h>

namespace rastrace {

std::vector<std::array<std::uint32_t, 3>> meshopt_simplified_triangles(const Mesh& mesh,
                                                                       std::uint32_t target_triangles) {
  if (mesh.indices.empty() || mesh.positions.empty()) return {};
  std::vector<unsigned int> out(mesh.indices.size());
  // target_error is relative to the mesh's extent: 1 places no limit on the error.
  const std::size_t count =
      meshopt_simplify(out.data(), mesh.indices.data(), mesh.indices.size(), &mesh.positions[0].x,
                       mesh.positions.size(), sizeof(glm::vec3), 3 * std::size_t(target_triangles), 1.0f, 0, nullptr);
  std::vector<std::array<std::uint32_t, 3>> triangles(count / 3);
  for (std::size_t t = 0; t < triangles.size(); ++t) triangles[t] = {out[3 * t], out[3 * t + 1], out[3 * t + 2]};
  return triangles;
}

}  // namespace rastrace
