// The parallel rasterizer keeps its threads and buffers across frames (a process-wide cache of
// workspaces): a frame interrupted by a failing sink, with a batch half binned and tiles half
// drawn, must leave nothing behind that changes the next frame drawn with the same workspace.
#include <algorithm>
#include <cstdint>
#include <cstring>
#include <stdexcept>

#include <gtest/gtest.h>

#include "pipeline/render_scene.h"
#include "tests/reference/cross_check_scenes.h"
#include "traces/memory_sink.h"

namespace rastrace {
namespace {

// Fails at its third batch of texel events.
class FailingSink final : public EventSink {
 public:
  void texel_accesses(std::span<const TexelAccess>) override {
    if (++batches_ == 3) throw std::runtime_error("sink failed");
  }
  bool wants_framebuffer_events() const override { return true; }

 private:
  int batches_ = 0;
};

bool same_texels(const MemorySink& a, const MemorySink& b) {
  return a.texels.size() == b.texels.size() &&
         std::equal(a.texels.begin(), a.texels.end(), b.texels.begin(), [](const TexelAccess& x, const TexelAccess& y) {
           return x.texture == y.texture && x.level == y.level && x.x == y.x && x.y == y.y &&
                  x.pixel_x == y.pixel_x && x.pixel_y == y.pixel_y && x.triangle == y.triangle;
         });
}

bool same_framebuffer_events(const MemorySink& a, const MemorySink& b) {
  return a.framebuffer.size() == b.framebuffer.size() &&
         std::equal(a.framebuffer.begin(), a.framebuffer.end(), b.framebuffer.begin(),
                    [](const FramebufferAccess& x, const FramebufferAccess& y) {
                      return x.x == y.x && x.y == y.y && x.op == y.op && x.mask == y.mask && x.triangle == y.triangle;
                    });
}

TEST(RasterWorkspaceReuse, AFrameAfterAnInterruptedOneEqualsTheSerialFrameToTheEvent) {
  const Scene small = testing::bunny_checker_scene(160, 120);
  const Scene scene = testing::bunny_checker_scene(320, 240);
  RenderOptions serial;
  MemorySink want;
  const RenderResult expected = render_scene(scene, serial, &want);

  RenderOptions parallel;
  parallel.pipeline.raster.threads = 2;
  FailingSink failing;
  EXPECT_THROW(render_scene(scene, parallel, &failing), std::runtime_error);
  // Another size in between: the workspace's tiles are resized both ways.
  MemorySink other;
  render_scene(small, parallel, &other);
  EXPECT_GT(other.texels.size(), 0u);

  MemorySink got;
  const RenderResult result = render_scene(scene, parallel, &got);
  EXPECT_EQ(got.texels.size(), want.texels.size());
  EXPECT_TRUE(same_texels(got, want));
  EXPECT_TRUE(same_framebuffer_events(got, want));
  const std::size_t pixels = static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height);
  EXPECT_EQ(std::memcmp(result.framebuffer.colour(), expected.framebuffer.colour(), 4 * pixels), 0);
  EXPECT_EQ(result.raster.fragments_passed, expected.raster.fragments_passed);
}

}  // namespace
}  // namespace rastrace
