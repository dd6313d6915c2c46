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
  const RenderStats stats = render_scene_into(result.framebuffer, scene, options, sink);
  result.pipeline = stats.pipeline;
  result.raster = stats.raster;
  return result;
}

RenderStats render_scene_into(Framebuffer& framebuffer, const Scene& scene, const RenderOptions& options,
                              EventSink* sink) {
  if (framebuffer.width() != scene.width || framebuffer.height() != scene.height ||
      framebuffer.has_debug_planes() != options.debug_planes)
    throw InputError(scene.name + ": a " + std::to_string(framebuffer.width()) + "x" +
                     std::to_string(framebuffer.height()) + " framebuffer" +
                     (framebuffer.has_debug_planes() ? " with" : " without") + " debug planes for a " +
                     std::to_string(scene.width) + "x" + std::to_string(scene.height) + " scene" +
                     (options.debug_planes ? " with" : " without") + " them");
  Pipeline pipeline(framebuffer, options.pipeline, sink);
  pipeline.clear(options.clear_colour.value_or(scene.background));
  const CameraMatrices camera = camera_matrices(scene);
  pipeline.set_camera(camera.view, camera.projection);
  const std::span<const DrawCall> calls = options.object_draws;
  const std::span<const std::uint32_t> objects = options.draw_objects;
  if (!objects.empty() && objects.size() != calls.size())
    throw InputError(scene.name + ": " + std::to_string(objects.size()) + " draw objects for " +
                     std::to_string(calls.size()) + " draw calls");
  if (objects.empty() && !calls.empty() && calls.size() != scene.objects.size())
    throw InputError(scene.name + ": " + std::to_string(calls.size()) + " draw calls for " +
                     std::to_string(scene.objects.size()) + " objects");
  const std::size_t draws = calls.empty() ? scene.objects.size() : calls.size();
  for (std::size_t d = 0; d < draws; ++d) {
    const std::size_t o = objects.empty() ? d : objects[d];
    if (o >= scene.objects.size())
      throw InputError(scene.name + ": draw " + std::to_string(d) + " is of object " + std::to_string(o) + ", of " +
                       std::to_string(scene.objects.size()));
    const SceneObject& object = scene.objects[o];
    DrawCall call;
    if (calls.empty()) {
      call.indices = object.mesh.indices;
      call.type = PrimitiveType::TriangleList;
      call.primitive_materials = object.mesh.face_material;
    } else {
      call = calls[d];
    }
    pipeline.draw(object.mesh, object.transform, call, scene.textures);
  }
  pipeline.finish();
  return {pipeline.stats(), pipeline.raster_stats()};
}

TextureLevels texture_levels(const Scene& scene) {
  TextureLevels levels;
  for (const Texture& texture : scene.textures) {
    std::vector<LevelSize> sizes;
    for (const Image& image : texture.levels)
      sizes.push_back(
          LevelSize{static_cast<std::uint32_t>(image.width), static_cast<std::uint32_t>(image.height), texture.format});
    levels.push_back(std::move(sizes));
  }
  return levels;
}

}  // namespace rastrace
