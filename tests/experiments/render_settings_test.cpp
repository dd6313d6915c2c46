// The render settings as the commands spell them, and the trace metadata every command that
// records a render's trace builds from them (render_trace_metadata).
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "experiments/render_settings.h"

namespace rastrace {
namespace {

TEST(RenderTraceMetadata, StatesEverySettingOfTheRender) {
  SceneRenderFlags flags;
  flags.scene = "builtin:grid";
  flags.size = "96x64";
  flags.filter = "nearest";
  flags.wrap = "clamp_to_edge";
  flags.lod = "max_component";
  flags.raster = "tiled8";
  flags.cull = "back";
  flags.lighting = true;
  flags.order = "tipsy";
  flags.depth_test = "late";
  flags.hiz = true;
  const Scene scene = load_render_scene(flags);
  const TextureLevels levels = texture_levels(scene);
  ASSERT_FALSE(levels.empty());
  const TraceMetadata metadata = render_trace_metadata(flags, scene, levels);
  EXPECT_EQ(metadata.scene, "builtin:grid");
  EXPECT_EQ(metadata.ordering, "tipsy");
  EXPECT_EQ(metadata.width, 96u);
  EXPECT_EQ(metadata.height, 64u);
  EXPECT_EQ(metadata.filter, "nearest");
  EXPECT_EQ(metadata.textures, levels);
  const std::map<std::string, std::string> extra = {
      {"cull", "back"},         {"lighting", "on"},       {"lod", "max_component"}, {"raster", "tiled8"},
      {"wrap", "clamp_to_edge"}, {"depth_test", "late"}, {"hiz", "on"}};
  EXPECT_EQ(metadata.extra, extra);
}

}  // namespace
}  // namespace rastrace
