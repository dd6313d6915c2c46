#include <string>

#include "core/error.h"
#include "scenes/procedural.h"

namespace rastrace {

Mesh make_grid(int width, int height) {
  if (width < 1 || height < 1)
    throw InputError("grid " + std::to_string(width) + "x" + std::to_string(height) + ": expected at least 1x1 quads");
  Mesh mesh;
  mesh.name = "grid" + std::to_string(width) + "x" + std::to_string(height);
  mesh.grid = GridShape{width, height};
  for (int y = 0; y <= height; ++y) {
    for (int x = 0; x <= width; ++x) {
      const float u = static_cast<float>(x) / static_cast<float>(width);
      const float v = static_cast<float>(y) / static_cast<float>(height);
      mesh.positions.emplace_back(u, v, 0.0f);
      mesh.normals.emplace_back(0.0f, 0.0f, 1.0f);
      mesh.uvs.emplace_back(u, v);
    }
  }
  const auto vertex = [width](int x, int y) { return static_cast<std::uint32_t>((width + 1) * y + x); };
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const std::uint32_t a = vertex(x, y), b = vertex(x, y + 1), c = vertex(x + 1, y), d = vertex(x + 1, y + 1);
      mesh.indices.insert(mesh.indices.end(), {a, b, c, c, b, d});
    }
  }
  return mesh;
}

}  // namespace rastrace
