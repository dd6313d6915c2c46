// The built-in scenes: a checkered Castano grid, Yang et al.'s four-colour bunny, assimp's spider.
#include "scenes/builtin_scenes.h"

#include <filesystem>

#include <glm/ext/matrix_transform.hpp>

#include "core/error.h"
#include "scenes/bounding_box.h"
#include "scenes/mesh_io.h"
#include "scenes/procedural.h"
#include "scenes/scene_io.h"

namespace rastrace {

namespace {

std::string data_file(const std::string& relative) {
  const std::filesystem::path path = std::filesystem::path(data_directory()) / relative;
  if (!std::filesystem::exists(path))
    throw InputError(
        path.string() +
        ": no such file: the built-in scenes need the data folder (run scripts/setup.sh, or set RASTRACE_DATA)");
  return path.string();
}

Scene grid_scene() {
  Scene scene;
  scene.name = "builtin:grid";
  SceneObject object;
  object.mesh = make_grid(32, 32);
  Material checker;
  checker.name = "checker";
  checker.texture_source.kind = TextureSource::Kind::Checker;
  checker.texture_source.size = 512;
  checker.texture_source.checks = 16;
  object.mesh.materials.push_back(checker);
  // The grid's front faces look down -z; turn them up (+y) and centre the unit square so the grid
  // spans [-1, 1] in x and z at y = 0: (x, y, z) -> (2x - 1, -2z, 2y - 1), exact in floating point.
  object.transform = glm::mat4(glm::vec4(2.0f, 0.0f, 0.0f, 0.0f), glm::vec4(0.0f, 0.0f, 2.0f, 0.0f),
                               glm::vec4(0.0f, -2.0f, 0.0f, 0.0f), glm::vec4(-1.0f, 0.0f, -1.0f, 1.0f));
  scene.objects.push_back(std::move(object));
  const float elevation = glm::radians(25.0f), distance = 2.4f;
  scene.camera.target = glm::vec3(0.0f, 0.0f, -0.2f);
  scene.camera.eye = scene.camera.target + distance * glm::vec3(0.0f, std::sin(elevation), std::cos(elevation));
  scene.camera.fov_y_degrees = 50.0f;
  scene.camera.near_plane = 0.1f;
  scene.camera.far_plane = 10.0f;
  scene.background = glm::vec4(0.2f, 0.2f, 0.25f, 1.0f);
  return scene;
}

Scene bunny_scene() {
  Scene scene;
  scene.name = "builtin:bunny";
  SceneObject object;
  object.mesh = load_mesh(data_file("meshes/bunny00.off"));
  project_uvs_planar(object.mesh, 0);  // the side view: every quadrant holds 17-40% of the faces
  Material four;
  four.name = "four_colour";
  four.texture_source.kind = TextureSource::Kind::FourColour;
  four.texture_source.size = 256;
  object.mesh.materials.push_back(four);
  scene.objects.push_back(std::move(object));
  return scene;
}

Scene spider_scene() {
  Scene scene;
  scene.name = "builtin:spider";
  scene.objects.push_back(SceneObject{load_mesh(data_file("assimp/OBJ/spider.obj")), glm::mat4(1.0f)});
  return scene;
}

void frame(Scene& scene) {
  const BoundingBox box = bounding_box(scene);
  scene.camera = frame_bounds(box.lo, box.hi, static_cast<float>(scene.width) / static_cast<float>(scene.height));
}

}  // namespace

std::vector<std::string> builtin_scene_names() { return {"grid", "bunny", "spider"}; }

Scene make_builtin_scene(const std::string& name, std::optional<TextureFormat> texture_format) {
  Scene scene;
  if (name == "grid") {
    scene = grid_scene();
  } else if (name == "bunny") {
    scene = bunny_scene();
    frame(scene);
  } else if (name == "spider") {
    scene = spider_scene();
    frame(scene);
  } else {
    throw InputError("builtin:" + name +
                     ": no such built-in scene; expected builtin:grid, builtin:bunny or builtin:spider");
  }
  load_scene_textures(scene, texture_format);
  return scene;
}

}  // namespace rastrace
