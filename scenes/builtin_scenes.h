// Built-in scenes, usable anywhere a scene is asked for as "builtin:<name>":
//   grid    a 32x32 Castano grid (2x2 world units, lying at y = 0) with a 512x512 checker of 16x16
//           squares, seen by a perspective camera at a grazing-ish angle (about 25 degrees above
//           the plane), so the far half is minified and uses the deeper mip levels
//   bunny   data/meshes/bunny00.off with Yang et al.'s four-colour texture on planar UVs projected
//           along x (each colour covers one quadrant of the bunny's side view, 17-40% of the faces)
//   spider  data/assimp/OBJ/spider.obj with its own materials and textures
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "scenes/scene.h"

namespace rastrace {

std::vector<std::string> builtin_scene_names();
// name without the "builtin:" prefix; InputError listing the known names otherwise. The textures
// are stored as `texture_format` when given (scene_io.h, load_scene).
Scene make_builtin_scene(const std::string& name, std::optional<TextureFormat> texture_format = std::nullopt);

}  // namespace rastrace
