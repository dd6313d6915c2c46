#include "scenes/mesh_spec.h"

#include <charconv>

#include "core/error.h"
#include "scenes/mesh_io.h"
#include "scenes/procedural.h"
#include "scenes/scene_io.h"

namespace rastrace {

namespace {

int parse_grid_side(const std::string& spec, std::string_view text) {
  int value = 0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || value < 1 || value > 4096)
    throw InputError("mesh '" + spec + "': expected grid:WxH with W and H whole numbers from 1 to 4096");
  return value;
}

Mesh merge_objects(const Scene& scene) {
  if (scene.objects.empty()) throw InputError("mesh '" + scene.name + "': the scene has no objects");
  if (scene.objects.size() == 1) return scene.objects.front().mesh;
  Mesh merged;
  merged.name = scene.name;
  for (const SceneObject& object : scene.objects) {
    const Mesh& m = object.mesh;
    const auto base = static_cast<std::uint32_t>(merged.positions.size());
    const auto material_base = static_cast<std::uint32_t>(merged.materials.size());
    merged.positions.insert(merged.positions.end(), m.positions.begin(), m.positions.end());
    for (const std::uint32_t i : m.indices) merged.indices.push_back(base + i);
    for (std::size_t f = 0; f < m.face_count(); ++f) merged.face_material.push_back(material_base + m.material_of(f));
    if (m.materials.empty())
      merged.materials.emplace_back();
    else
      merged.materials.insert(merged.materials.end(), m.materials.begin(), m.materials.end());
  }
  return merged;
}

}  // namespace

Mesh load_mesh_spec(const std::string& spec) {
  if (spec.rfind("grid:", 0) == 0) {
    const std::string_view shape = std::string_view(spec).substr(5);
    const std::size_t x = shape.find('x');
    if (x == std::string_view::npos) throw InputError("mesh '" + spec + "': expected grid:WxH, for example grid:16x16");
    return make_grid(parse_grid_side(spec, shape.substr(0, x)), parse_grid_side(spec, shape.substr(x + 1)));
  }
  if (spec.rfind("builtin:", 0) == 0) return merge_objects(load_scene(spec));
  return load_mesh(spec);
}

}  // namespace rastrace
