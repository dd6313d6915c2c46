// Clearing in order with the draws. With several raster threads the other threads clear the
// framebuffer while the calling one sets up the next triangles; wherever a clear falls in the
// frame, the pixels must be the serial clear's.
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>
#include <glm/ext/matrix_transform.hpp>

#include "core/error.h"
#include "pipeline/pipeline.h"
#include "pipeline/render_scene.h"
#include "tests/reference/cross_check_scenes.h"

namespace rastrace {
namespace {

struct Pixels {
  std::vector<std::uint8_t> colour;
  std::vector<float> depth;
};

Pixels pixels_of(const Framebuffer& fb) {
  const std::size_t n = static_cast<std::size_t>(fb.width()) * static_cast<std::size_t>(fb.height());
  return {std::vector<std::uint8_t>(fb.colour(), fb.colour() + n * 4), std::vector<float>(fb.depth(), fb.depth() + n)};
}

// The first pixel where two frames differ, or -1 (a whole-vector comparison would print both).
long first_difference(const Pixels& a, const Pixels& b) {
  for (std::size_t i = 0; i < a.depth.size(); ++i)
    if (a.depth[i] != b.depth[i] || a.colour[4 * i] != b.colour[4 * i] || a.colour[4 * i + 1] != b.colour[4 * i + 1] ||
        a.colour[4 * i + 2] != b.colour[4 * i + 2] || a.colour[4 * i + 3] != b.colour[4 * i + 3])
      return static_cast<long>(i);
  return a.depth.size() == b.depth.size() ? -1 : static_cast<long>(a.depth.size());
}

// Left-over pixels that no clear may let through.
void scribble(Framebuffer& fb) {
  const std::size_t n = static_cast<std::size_t>(fb.width()) * static_cast<std::size_t>(fb.height());
  for (std::size_t i = 0; i < n * 4; ++i) fb.colour()[i] = static_cast<std::uint8_t>(i * 13 + 5);
  for (std::size_t i = 0; i < n; ++i) fb.depth()[i] = 0.5f;
}

// Clear, draw the bunny, clear again to another colour and a depth of 0.75 (the bunny's window
// depths are 0.64-0.83: part of it is behind), draw it moved, finish.
Pixels draw_with_clears(unsigned threads, bool hiz) {
  const Scene scene = testing::bunny_checker_scene(320, 240);
  Framebuffer fb(scene.width, scene.height);
  scribble(fb);
  PipelineOptions options;
  options.raster.threads = threads;
  options.raster.hierarchical_z = hiz;
  Pipeline pipeline(fb, options, nullptr);
  const CameraMatrices camera = camera_matrices(scene);
  pipeline.set_camera(camera.view, camera.projection);
  const SceneObject& object = scene.objects.at(0);
  DrawCall call;
  call.indices = object.mesh.indices;
  call.type = PrimitiveType::TriangleList;
  call.primitive_materials = object.mesh.face_material;
  pipeline.clear(glm::vec4(1.0f, 0.0f, 0.0f, 1.0f));
  pipeline.draw(object.mesh, object.transform, call, scene.textures);
  pipeline.clear(glm::vec4(0.0f, 0.0f, 1.0f, 1.0f), 0.75f);
  pipeline.draw(object.mesh, glm::translate(object.transform, glm::vec3(0.01f, 0.0f, 0.0f)), call, scene.textures);
  pipeline.finish();
  return pixels_of(fb);
}

TEST(Clear, ClearsBetweenDrawsGiveTheSerialPixelsAtTwoAndFourThreads) {
  for (const bool hiz : {false, true}) {
    const Pixels serial = draw_with_clears(1, hiz);
    // The frame shows both the second clear and the bunny in front of its depth.
    std::size_t cleared = 0, drawn = 0;
    for (std::size_t i = 0; i < serial.depth.size(); ++i) (serial.depth[i] == 0.75f ? cleared : drawn) += 1;
    EXPECT_GT(cleared, serial.depth.size() / 2);
    EXPECT_GT(drawn, 1000u);
    for (const unsigned threads : {2u, 4u}) {
      const Pixels parallel = draw_with_clears(threads, hiz);
      EXPECT_EQ(first_difference(parallel, serial), -1) << threads << " threads, hierarchical Z " << hiz;
    }
  }
}

// Also two clears in a row (the second waits for the first), and images with fewer rows than
// there are threads to share them.
TEST(Clear, AClearWithNothingDrawnAfterItIsCompleteAfterFinish) {
  for (const unsigned threads : {1u, 2u, 3u, 4u})
    for (const int height : {67, 2}) {
      Framebuffer fb(101, height);
      scribble(fb);
      PipelineOptions options;
      options.raster.threads = threads;
      Pipeline pipeline(fb, options, nullptr);
      pipeline.clear(glm::vec4(1.0f, 0.0f, 1.0f, 1.0f), 0.75f);
      pipeline.clear(glm::vec4(0.0f, 1.0f, 0.0f, 0.0f), 0.25f);
      pipeline.finish();
      const Pixels p = pixels_of(fb);
      for (std::size_t i = 0; i < p.depth.size(); ++i) {
        ASSERT_EQ(p.depth[i], 0.25f) << threads << " threads, pixel " << i;
        ASSERT_EQ(p.colour[i * 4 + 0], 0) << threads << " threads, pixel " << i;
        ASSERT_EQ(p.colour[i * 4 + 1], 255) << threads << " threads, pixel " << i;
        ASSERT_EQ(p.colour[i * 4 + 2], 0) << threads << " threads, pixel " << i;
        ASSERT_EQ(p.colour[i * 4 + 3], 0) << threads << " threads, pixel " << i;
      }
    }
}

// A draw that throws after a clear leaves the workers idle: the pipeline is destroyed without
// waiting forever, and the next frame on the same threads is the serial one.
TEST(Clear, AnErrorAfterAClearLeavesNothingRunning) {
  const Scene scene = testing::bunny_checker_scene(320, 240);
  RenderOptions options;
  options.pipeline.raster.threads = 2;
  {
    Framebuffer fb(scene.width, scene.height);
    Pipeline pipeline(fb, options.pipeline, nullptr);
    pipeline.clear(glm::vec4(1.0f));
    const std::vector<std::uint32_t> beyond = {0, 1,
                                               static_cast<std::uint32_t>(scene.objects[0].mesh.positions.size())};
    DrawCall call;
    call.indices = beyond;
    call.type = PrimitiveType::TriangleList;
    EXPECT_THROW(pipeline.draw(scene.objects[0].mesh, glm::mat4(1.0f), call, scene.textures), InputError);
  }
  const RenderResult serial = render_scene(scene, RenderOptions{}, nullptr);
  const RenderResult parallel = render_scene(scene, options, nullptr);
  EXPECT_EQ(first_difference(pixels_of(parallel.framebuffer), pixels_of(serial.framebuffer)), -1);
}

// A render target kept from frame to frame (as the benchmarks and an application keep one):
// every frame must equal a frame drawn into a new one.
TEST(Clear, AFrameDrawnIntoAKeptFramebufferEqualsOneDrawnIntoANewOne) {
  const Scene scene = testing::bunny_checker_scene(320, 240);
  RenderOptions options;
  options.pipeline.raster.threads = 2;
  const RenderResult fresh = render_scene(scene, options, nullptr);
  Framebuffer kept(scene.width, scene.height);
  scribble(kept);
  for (int frame = 0; frame < 2; ++frame) {
    render_scene_into(kept, scene, options, nullptr);
    EXPECT_EQ(first_difference(pixels_of(kept), pixels_of(fresh.framebuffer)), -1) << "frame " << frame;
  }
}

}  // namespace
}  // namespace rastrace
