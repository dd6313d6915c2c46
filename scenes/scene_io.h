// Loading scenes: a JSON scene file (docs/scene-format.md, docs/example_scene.json), a plain mesh
// file framed by a default camera, or a built-in scene ("builtin:grid", "builtin:bunny",
// "builtin:spider"; see builtin_scenes.h). Every material's texture is loaded into
// Scene::textures with its mip chain and Material::texture set to its index (textures shared by
// several materials are loaded once).
#pragma once

#include <optional>
#include <string>

#include <glm/vec3.hpp>

#include "scenes/scene.h"

namespace rastrace {

// spec: "builtin:<name>", a path ending in .json, or any mesh file load_mesh reads.
// InputError for a malformed scene (with its line/column for JSON syntax errors and the JSON
// path, e.g. "objects[2].camera.fov_y", for values of the wrong shape). `texture_format`, when
// given, stores every texture in that format whatever the scene file says (render --texture-format).
Scene load_scene(const std::string& spec, std::optional<TextureFormat> texture_format = std::nullopt);

// The folder with the real data: $RASTRACE_DATA if set, else the compile-time RASTRACE_DATA_DIR.
std::string data_directory();

// A camera looking at the box [lo, hi] from the front (+z), slightly above, with the whole box in
// view for the given aspect ratio (width / height); near and far bracket the box.
Camera frame_bounds(const glm::vec3& lo, const glm::vec3& hi, float aspect);

// Fills Scene::textures from every material's TextureSource and sets Material::texture; a given
// `format` replaces every TextureSource's format first.
void load_scene_textures(Scene& scene, std::optional<TextureFormat> format = std::nullopt);

}  // namespace rastrace
