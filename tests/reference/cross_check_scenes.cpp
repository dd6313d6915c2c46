#include "cross_check_scenes.h"

#include <cmath>
#include <numbers>

#include <glm/ext/matrix_transform.hpp>

#include "scenes/bounding_box.h"
#include "scenes/procedural.h"
#include "scenes/scene_io.h"
#include "scenes/texture_io.h"
#include "tests/support/textured_bunny.h"

namespace rastrace::testing {

namespace {

// A 64x64 view in which world (x, y, 0) lands exactly on image pixel ((x + 1) * 32, (1 - y) * 32):
// camera at z = 1, 90 degrees, square image (tan 45 degrees rounds to exactly 1 in float).
Scene pixel_exact_scene(const std::string& name) {
  Scene scene;
  scene.name = name;
  scene.width = scene.height = 64;
  scene.camera.eye = glm::vec3(0.0f, 0.0f, 1.0f);
  scene.camera.target = glm::vec3(0.0f);
  scene.camera.fov_y_degrees = 90.0f;
  scene.camera.near_plane = 0.5f;
  scene.camera.far_plane = 4.0f;
  return scene;
}

glm::vec3 world_of_pixel(double x, double y) {
  return glm::vec3(static_cast<float>(x / 32.0 - 1.0), static_cast<float>(1.0 - y / 32.0), 0.0f);
}

Material flat(const char* name, float r, float g, float b) {
  Material m;
  m.name = name;
  m.diffuse = glm::vec4(r, g, b, 1.0f);
  return m;
}

Texture checker_texture(int size, int checks) {
  Texture texture;
  texture.name = "checker";
  texture.levels = build_mip_chain(make_checker(size, checks));
  return texture;
}

Material textured(int texture) {
  Material m;
  m.name = "checker";
  m.texture = texture;
  return m;
}

}  // namespace

Scene flat_triangles_scene() {
  Scene scene = pixel_exact_scene("flat triangles");
  SceneObject grid;
  grid.mesh = make_grid(4, 4);
  // Grid vertex (i, j) at pixel centre (8.5 + 12 i, 8.5 + 12 j).
  for (glm::vec3& p : grid.mesh.positions) p = world_of_pixel(8.5 + 48.0 * p.x, 8.5 + 48.0 * p.y);
  grid.mesh.uvs.clear();
  grid.mesh.materials = {flat("red", 0.8f, 0.2f, 0.2f), flat("green", 0.2f, 0.8f, 0.2f), flat("blue", 0.2f, 0.2f, 0.8f),
                         flat("grey", 0.6f, 0.6f, 0.6f)};
  for (std::size_t f = 0; f < grid.mesh.face_count(); ++f)
    grid.mesh.face_material.push_back(static_cast<std::uint32_t>(f % 4));
  scene.objects.push_back(grid);

  SceneObject skew;
  skew.mesh.name = "skewed pair";
  skew.mesh.positions = {world_of_pixel(3.5, 58.5), world_of_pixel(30.5, 60.5), world_of_pixel(9.5, 61.5),
                         world_of_pixel(33.5, 57.5)};
  skew.mesh.indices = {0, 1, 2, 0, 3, 1};
  skew.mesh.materials = {flat("orange", 1.0f, 0.6f, 0.2f)};
  skew.mesh.face_material = {0, 0};
  scene.objects.push_back(skew);
  return scene;
}

Scene fan_scene() {
  Scene scene = pixel_exact_scene("fan of 200");
  SceneObject fan;
  fan.mesh.name = "fan";
  const int n = 200;
  fan.mesh.positions.push_back(world_of_pixel(32.5, 32.5));
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / n;
    const double x = std::round((32.5 + 29.0 * std::cos(angle)) * 256.0) / 256.0;
    const double y = std::round((32.5 + 29.0 * std::sin(angle)) * 256.0) / 256.0;
    fan.mesh.positions.push_back(world_of_pixel(x, y));
  }
  for (int i = 0; i < n; ++i)
    fan.mesh.indices.insert(fan.mesh.indices.end(),
                            {0u, static_cast<std::uint32_t>(1 + i), static_cast<std::uint32_t>(1 + (i + 1) % n)});
  fan.mesh.materials = {flat("a", 0.9f, 0.3f, 0.1f), flat("b", 0.1f, 0.4f, 0.9f)};
  for (int i = 0; i < n; ++i) fan.mesh.face_material.push_back(static_cast<std::uint32_t>(i % 2));
  scene.objects.push_back(fan);
  return scene;
}

Scene near_clip_scene() {
  Scene scene;
  scene.name = "near-plane clipping";
  scene.width = 160;
  scene.height = 120;
  scene.textures.push_back(checker_texture(256, 8));
  SceneObject floor;
  floor.mesh = make_plane(4, 4.0f);
  floor.mesh.materials = {textured(0)};
  floor.mesh.face_material.clear();
  floor.transform = glm::scale(glm::mat4(1.0f), glm::vec3(3.0f));  // [-3, 3] in x and z
  scene.objects.push_back(floor);
  // Low above the floor, looking down steeply: the floor's near half lies behind the near plane.
  scene.camera.eye = glm::vec3(0.2f, 0.6f, 1.5f);
  scene.camera.target = glm::vec3(0.0f, 0.0f, 0.5f);
  scene.camera.fov_y_degrees = 70.0f;
  scene.camera.near_plane = 0.4f;
  scene.camera.far_plane = 20.0f;
  return scene;
}

Scene grazing_plane_scene() {
  Scene scene;
  scene.name = "grazing plane";
  scene.width = 256;
  scene.height = 192;
  scene.textures.push_back(checker_texture(256, 8));
  SceneObject plane;
  plane.mesh = make_plane(8, 32.0f);
  plane.mesh.materials = {textured(0)};
  plane.mesh.face_material.clear();
  plane.transform = glm::scale(glm::mat4(1.0f), glm::vec3(40.0f, 1.0f, 40.0f));
  scene.objects.push_back(plane);
  scene.camera.eye = glm::vec3(0.3f, 1.0f, 38.0f);
  scene.camera.target = glm::vec3(0.0f, 0.0f, 24.0f);
  scene.camera.fov_y_degrees = 60.0f;
  scene.camera.near_plane = 0.5f;
  scene.camera.far_plane = 100.0f;
  return scene;
}

Scene bunny_checker_scene(int width, int height) {
  Scene scene = textured_bunny(width, height, 256, 16);
  const BoundingBox box = bounding_box(scene.objects[0].mesh.positions);
  scene.camera = frame_bounds(box.lo, box.hi, static_cast<float>(width) / static_cast<float>(height));
  scene.camera.fov_y_degrees = 45.0f;
  return scene;
}

}  // namespace rastrace::testing
