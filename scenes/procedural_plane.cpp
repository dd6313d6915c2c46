// A textured square plane at y = 0, facing +y.
#include <cmath>
#include <string>

#include "core/error.h"
#include "scenes/procedural.h"

namespace rastrace {

Mesh make_plane(int segments, float repeat) {
  if (segments < 1 || segments > 4096)
    throw InputError("plane: " + std::to_string(segments) + " segments: expected 1 to 4096");
  if (!(repeat > 0.0f) || !std::isfinite(repeat)) throw InputError("plane: texture repeat must be a positive number");
  Mesh mesh;
  mesh.name = "plane" + std::to_string(segments);
  const int n = segments + 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < n; ++i) {
      const float s = static_cast<float>(i) / static_cast<float>(segments);
      const float t = static_cast<float>(j) / static_cast<float>(segments);
      mesh.positions.emplace_back(-1.0f + 2.0f * s, 0.0f, -1.0f + 2.0f * t);
      mesh.normals.emplace_back(0.0f, 1.0f, 0.0f);
      mesh.uvs.emplace_back(repeat * s, repeat * t);
    }
  for (int j = 0; j < segments; ++j)
    for (int i = 0; i < segments; ++i) {
      const auto a = static_cast<std::uint32_t>(j * n + i), b = a + 1, c = a + static_cast<std::uint32_t>(n), d = c + 1;
      mesh.indices.insert(mesh.indices.end(), {a, c, b, b, c, d});  // counter-clockwise seen from +y
    }
  Material material;
  material.name = "plane";
  material.texture_source.kind = TextureSource::Kind::Checker;
  material.texture_source.size = 256;
  material.texture_source.checks = 8;
  mesh.materials.push_back(material);
  return mesh;
}

}  // namespace rastrace
