// Subdivided icosahedron: each subdivision splits every triangle into four at its edge midpoints
// (made once per edge, so vertices stay shared) and pushes the new vertices onto the unit sphere.
#include <cmath>
#include <string>
#include <unordered_map>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "scenes/procedural.h"

namespace rastrace {

Mesh make_icosphere(int subdivisions) {
  if (subdivisions < 0 || subdivisions > 8)
    throw InputError("icosphere: " + std::to_string(subdivisions) + " subdivisions: expected 0 to 8");
  const float t = (1.0f + std::sqrt(5.0f)) / 2.0f;
  Mesh mesh;
  mesh.name = "icosphere" + std::to_string(subdivisions);
  mesh.positions = {{-1, t, 0},  {1, t, 0},  {-1, -t, 0}, {1, -t, 0}, {0, -1, t},  {0, 1, t},
                    {0, -1, -t}, {0, 1, -t}, {t, 0, -1},  {t, 0, 1},  {-t, 0, -1}, {-t, 0, 1}};
  for (auto& p : mesh.positions) p = glm::normalize(p);
  mesh.indices = {0, 11, 5, 0, 5, 1, 0, 1, 7, 0, 7, 10, 0, 10, 11, 1, 5, 9, 5, 11, 4,  11, 10, 2,  10, 7, 6, 7, 1, 8,
                  3, 9,  4, 3, 4, 2, 3, 2, 6, 3, 6, 8,  3, 8,  9,  4, 9, 5, 2, 4,  11, 6,  2,  10, 8,  6, 7, 9, 8, 1};
  std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
  for (int level = 0; level < subdivisions; ++level) {
    midpoints.clear();
    const auto midpoint = [&](std::uint32_t a, std::uint32_t b) {
      const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      const auto [it, inserted] = midpoints.emplace(key, static_cast<std::uint32_t>(mesh.positions.size()));
      if (inserted) mesh.positions.push_back(glm::normalize(mesh.positions[a] + mesh.positions[b]));
      return it->second;
    };
    std::vector<std::uint32_t> next;
    next.reserve(mesh.indices.size() * 4);
    for (std::size_t i = 0; i < mesh.indices.size(); i += 3) {
      const std::uint32_t a = mesh.indices[i], b = mesh.indices[i + 1], c = mesh.indices[i + 2];
      const std::uint32_t ab = midpoint(a, b), bc = midpoint(b, c), ca = midpoint(c, a);
      next.insert(next.end(), {a, ab, ca, b, bc, ab, c, ca, bc, ab, bc, ca});
    }
    mesh.indices = std::move(next);
  }
  mesh.normals = mesh.positions;
  project_uvs_spherical(mesh);
  return mesh;
}

}  // namespace rastrace
