// The render settings as the commands spell them, and the trace metadata every command that
// records a render's trace builds from them (render_trace_metadata).
#include <map>
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
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

TEST(RenderSettings, AnisoAbove1IsInTheSamplerAndTheMetadataAndOutOfRangeIsAnInputError) {
  SceneRenderFlags flags;
  flags.scene = "builtin:grid";
  EXPECT_EQ(render_options_from(flags).pipeline.raster.sampler.max_anisotropy, 1);
  const Scene scene = load_render_scene(flags);
  EXPECT_EQ(render_trace_metadata(flags, scene, texture_levels(scene)).extra.count("aniso"), 0u);
  flags.aniso = 16;
  EXPECT_EQ(render_options_from(flags).pipeline.raster.sampler.max_anisotropy, 16);
  EXPECT_EQ(render_trace_metadata(flags, scene, texture_levels(scene)).extra.at("aniso"), "16");
  EXPECT_EQ(render_trace_metadata(flags, scene, texture_levels(scene)).extra.at("aniso_rule"), "ellipse");
  flags.aniso_rule = "probes";
  EXPECT_EQ(render_options_from(flags).pipeline.raster.sampler.aniso_rule, AnisotropyRule::Probes);
  flags.aniso_rule = "trilinear";
  try {
    render_options_from(flags);
    ADD_FAILURE() << "accepted --aniso-rule trilinear";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), "--aniso-rule 'trilinear': expected ellipse or probes");
  }
  flags.aniso_rule = "ellipse";
  for (const unsigned bad : {0u, 17u}) {
    flags.aniso = bad;
    try {
      render_options_from(flags);
      ADD_FAILURE() << "accepted --aniso " << bad;
    } catch (const InputError& e) {
      EXPECT_EQ(std::string(e.what()), "--aniso " + std::to_string(bad) +
                                           ": expected a maximum anisotropy from 1 to 16 (1: isotropic filtering)");
    }
  }
}

}  // namespace
}  // namespace rastrace
