// The parallel rasterizer's screen tiles grow with the frame when the threads are few: larger
// tiles run a triangle's quad loop fewer times. The tile size must not change a pixel or an event.
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "pipeline/render_scene.h"
#include "raster/parallel_rasterizer.h"
#include "scenes/builtin_scenes.h"
#include "traces/memory_sink.h"

namespace rastrace {
namespace {

TEST(ScreenTiles, EachThreadKeepsSixteenTilesAndTilesStayBetween64And128Pixels) {
  EXPECT_EQ(ParallelRasterizer::screen_tile(1024, 768, 2), 128);   // 48 tiles of 128
  EXPECT_EQ(ParallelRasterizer::screen_tile(1024, 768, 3), 128);   // 48 = 16 x 3
  EXPECT_EQ(ParallelRasterizer::screen_tile(1024, 768, 4), 64);    // 48 < 64
  EXPECT_EQ(ParallelRasterizer::screen_tile(1920, 1080, 4), 128);  // 15 x 9 = 135 tiles
  EXPECT_EQ(ParallelRasterizer::screen_tile(320, 240, 2), 64);
  EXPECT_EQ(ParallelRasterizer::screen_tile(16, 16, 1), 64);
  EXPECT_EQ(ParallelRasterizer::screen_tile(2048, 1024, 64), 64);   // 128 tiles of 128 < 1024
  EXPECT_EQ(ParallelRasterizer::screen_tile(8192, 8192, 64), 128);  // 4096 tiles of 128
}

// The grid at 1024x768: 128-pixel tiles on two threads, 64 on four; each equals one thread's
// image and events.
TEST(ScreenTiles, TheTileSizeChangesNoPixelAndNoEvent) {
  Scene scene = make_builtin_scene("grid");
  scene.width = 1024;
  scene.height = 768;
  RenderOptions options;
  options.pipeline.raster.threads = 1;
  MemorySink serial;
  const RenderResult one = render_scene(scene, options, &serial);
  ASSERT_GT(serial.texels.size(), 100000u);
  for (const unsigned threads : {2u, 4u}) {
    SCOPED_TRACE(std::to_string(threads) + " threads");
    options.pipeline.raster.threads = threads;
    MemorySink parallel;
    const RenderResult many = render_scene(scene, options, &parallel);
    const std::size_t pixels = static_cast<std::size_t>(scene.width) * static_cast<std::size_t>(scene.height);
    EXPECT_EQ(std::memcmp(many.framebuffer.colour(), one.framebuffer.colour(), pixels * 4), 0);
    EXPECT_EQ(std::memcmp(many.framebuffer.depth(), one.framebuffer.depth(), pixels * sizeof(float)), 0);
    ASSERT_EQ(parallel.texels.size(), serial.texels.size());
    EXPECT_EQ(std::memcmp(parallel.texels.data(), serial.texels.data(), serial.texels.size() * sizeof(TexelAccess)), 0);
    ASSERT_EQ(parallel.framebuffer.size(), serial.framebuffer.size());
    for (std::size_t i = 0; i < serial.framebuffer.size(); ++i) {
      const FramebufferAccess &a = parallel.framebuffer[i], &b = serial.framebuffer[i];
      ASSERT_TRUE(a.x == b.x && a.y == b.y && a.op == b.op && a.mask == b.mask && a.triangle == b.triangle) << i;
    }
  }
}

}  // namespace
}  // namespace rastrace
