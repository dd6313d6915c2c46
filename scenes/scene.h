// A scene: meshes with transforms, a camera, a viewport. Loaded from JSON (docs/example_scene.json)
// or built in (see builtin_scenes.h).
#pragma once

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scenes/camera_path.h"
#include "scenes/mesh.h"
#include "scenes/texture.h"

namespace rastrace {

struct SceneObject {
  Mesh mesh;
  glm::mat4 transform{1.0f};  // model to world
};

struct Scene {
  std::string name;
  std::vector<SceneObject> objects;
  std::vector<Texture> textures;  // every material's texture, with its mip chain
  Camera camera;           // the static camera (frame 0 when there is no path)
  CameraPath camera_path;  // optional: the camera of frame f is camera_at(camera, camera_path, f)
  int width = 512;
  int height = 512;
  glm::vec4 background{0.0f, 0.0f, 0.0f, 1.0f};
};

}  // namespace rastrace
