// A scene: meshes with transforms, a camera, a viewport. Loaded from JSON (docs/example_scene.json)
// or built in (see builtin_scenes.h).
#pragma once

#include <string>
#include <vector>

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include "scenes/mesh.h"
#include "scenes/texture.h"

namespace rastrace {

struct Camera {
  glm::vec3 eye{0.0f, 0.0f, 3.0f};
  glm::vec3 target{0.0f, 0.0f, 0.0f};
  glm::vec3 up{0.0f, 1.0f, 0.0f};
  float fov_y_degrees = 45.0f;
  float near_plane = 0.1f;
  float far_plane = 100.0f;
};

struct SceneObject {
  Mesh mesh;
  glm::mat4 transform{1.0f};  // model to world
};

struct Scene {
  std::string name;
  std::vector<SceneObject> objects;
  std::vector<Texture> textures;  // every material's texture, with its mip chain
  Camera camera;
  int width = 512;
  int height = 512;
  glm::vec4 background{0.0f, 0.0f, 0.0f, 1.0f};
};

}  // namespace rastrace
