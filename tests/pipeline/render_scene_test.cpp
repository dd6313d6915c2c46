// render_scene_into draws into a framebuffer the caller keeps across frames: each frame must be
// the frame render_scene draws into a fresh one, whatever the previous frame left.
#include <cstring>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "pipeline/render_scene.h"
#include "scenes/builtin_scenes.h"

namespace rastrace {
namespace {

bool same_image(const Framebuffer& a, const Framebuffer& b) {
  const std::size_t pixels = static_cast<std::size_t>(a.width()) * static_cast<std::size_t>(a.height());
  return a.width() == b.width() && a.height() == b.height() &&
         std::memcmp(a.colour(), b.colour(), pixels * 4) == 0 &&
         std::memcmp(a.depth(), b.depth(), pixels * sizeof(float)) == 0;
}

TEST(RenderSceneInto, AKeptFramebufferHoldsEachFrameAsAFreshOneWould) {
  Scene spider = make_builtin_scene("spider");
  Scene grid = make_builtin_scene("grid");
  grid.width = spider.width;
  grid.height = spider.height;
  const RenderOptions options;
  const RenderResult fresh_spider = render_scene(spider, options, nullptr);
  const RenderResult fresh_grid = render_scene(grid, options, nullptr);
  ASSERT_FALSE(same_image(fresh_spider.framebuffer, fresh_grid.framebuffer));
  Framebuffer kept(spider.width, spider.height);
  for (int frame = 0; frame < 2; ++frame) {
    const RenderStats stats = render_scene_into(kept, spider, options, nullptr);
    EXPECT_TRUE(same_image(kept, fresh_spider.framebuffer)) << "frame " << frame;
    EXPECT_EQ(stats.raster.fragments_passed, fresh_spider.raster.fragments_passed);
    EXPECT_EQ(stats.pipeline.triangles, fresh_spider.pipeline.triangles);
    render_scene_into(kept, grid, options, nullptr);
    EXPECT_TRUE(same_image(kept, fresh_grid.framebuffer)) << "frame " << frame;
  }
}

TEST(RenderSceneInto, AFramebufferOfAnotherSizeOrPlanesIsAnInputError) {
  const Scene spider = make_builtin_scene("spider");
  Framebuffer small(spider.width / 2, spider.height);
  EXPECT_THROW(render_scene_into(small, spider, RenderOptions{}, nullptr), InputError);
  Framebuffer plain(spider.width, spider.height);
  RenderOptions debug;
  debug.debug_planes = true;
  try {
    render_scene_into(plain, spider, debug, nullptr);
    FAIL() << "expected an InputError";
  } catch (const InputError& error) {
    EXPECT_NE(std::string(error.what()).find("without debug planes"), std::string::npos) << error.what();
  }
}

}  // namespace
}  // namespace rastrace
