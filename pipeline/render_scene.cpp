#include "pipeline/render_scene.h"

#include <glm/ext/matrix_clip_space.hpp>
#include <glm/ext/matrix_transform.hpp>
#include <glm/trigonometric.hpp>

#include "core/error.h"

namespace rastrace {

CameraMatrices camera_matrices(const Scene& scene) {
  CameraMatrices m;
  const Camera& camera = scene.camera;
  m.view = glm::lookAt(camera.eye, camera.target, camera.up);
  m.projection = glm::perspective(glm::radians(camera.fov_y_degrees),
                                  static_cast<float>(scene.width) / static_cast<float>(scene.height), camera.near_plane,
                                  camera.far_plane);
  return m;
}

RenderResult render_scene(const Scene& scene, const RenderOptions& options, EventSink* sink) {
  RenderResult result{Framebuffer(scene.width, scene.height, options.debug_planes), {}, {}};
  result.framebuffer.clear(options.clear_colour.value_or(scene.background));
  Pipeline pipeline(result.framebuffer, options.pipeline, sink);
  const CameraMatrices camera = camera_matrices(scene);
  pipeline.set_camera(camera.view, camera.projection);
  if (!options.object_draws.empty() && options.object_draws.size() != scene.objects.size())
    throw InputError(scene.name + ": " + std::to_string(options.object_draws.size()) + " draw calls for " +
                     std::to_string(scene.objects.size()) + " objects");
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const SceneObject& object = scene.objects[o];
    DrawCall call;
    if (options.object_draws.empty()) {
      call.indices = object.mesh.indices;
      call.type = PrimitiveType::TriangleList;
      call.primitive_materials = object.mesh.face_material;
    } else {
      call = options.object_draws[o];
    }
    pipeline.draw(object.mesh, object.transform, call, scene.textures);
  }
  pipeline.finish();
  result.pipeline = pipeline.stats();
  result.raster = pipeline.raster_stats();
  return result;
}

TextureLevels texture_levels(const Scene& scene) {
  TextureLevels levels;
  for (const Texture& texture : scene.textures) {
    std::vector<LevelSize> sizes;
    for (const Image& image : texture.levels)
      sizes.push_back(LevelSize{static_cast<std::uint32_t>(image.width), static_cast<std::uint32_t>(image.height)});
    levels.push_back(std::move(sizes));
  }
  return levels;
}

}  // namespace rastrace
