// Projected texture coordinates for meshes that come without them.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "scenes/bounding_box.h"
#include "scenes/procedural.h"

namespace rastrace {

void project_uvs_spherical(Mesh& mesh) {
  const glm::vec3 centre = bounding_box(mesh.positions).centre();
  mesh.uvs.resize(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3 d = mesh.positions[v] - centre;
    const float length = glm::length(d);
    if (length == 0.0f) {
      mesh.uvs[v] = glm::vec2(0.5f);
      continue;
    }
    const float u = std::atan2(d.x, d.z) / (2.0f * std::numbers::pi_v<float>)+0.5f;
    const float t = std::acos(std::clamp(d.y / length, -1.0f, 1.0f)) / std::numbers::pi_v<float>;
    mesh.uvs[v] = glm::vec2(u, t);
  }
}

void project_uvs_planar(Mesh& mesh, int axis) {
  if (axis < 0 || axis > 2)
    throw InputError("planar UV projection: axis " + std::to_string(axis) + ": expected 0 (x), 1 (y) or 2 (z)");
  static constexpr int kU[3] = {2, 0, 0};
  static constexpr int kV[3] = {1, 2, 1};
  const int ua = kU[axis], va = kV[axis];
  const BoundingBox box = bounding_box(mesh.positions);
  const glm::vec3 lo = box.lo, hi = box.hi;
  const float u_extent = hi[ua] - lo[ua], v_extent = hi[va] - lo[va];
  mesh.uvs.resize(mesh.positions.size());
  for (std::size_t v = 0; v < mesh.positions.size(); ++v) {
    const glm::vec3& p = mesh.positions[v];
    const float u = u_extent > 0.0f ? (p[ua] - lo[ua]) / u_extent : 0.0f;
    const float t = v_extent > 0.0f ? (hi[va] - p[va]) / v_extent : 0.0f;
    mesh.uvs[v] = glm::vec2(u, t);
  }
}

}  // namespace rastrace
