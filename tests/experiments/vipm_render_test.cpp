// A scene drawn at a VIPM level of detail (`render --vipm METHOD --lod N`): at full detail every
// representation draws the original frame pixel for pixel; at a coarser LoD every representation
// of the same collapse sequence draws the same triangles, so the same fragments and texels.
#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdlib>
#include <utility>

#include "core/error.h"
#include "experiments/render_settings.h"
#include "experiments/vipm_experiment.h"
#include "experiments/vipm_render.h"
#include "lod/progressive_mesh.h"
#include "pipeline/render_scene.h"
#include "scenes/builtin_scenes.h"

namespace rastrace {
namespace {

using ::testing::HasSubstr;

RenderResult render_vipm(const Scene& scene, const std::string& method, std::uint32_t lod, VipmScene* keep = nullptr) {
  VipmSceneSpec spec;
  spec.method = method;
  spec.lod = lod;
  VipmScene vipm = build_vipm_scene(scene, spec);
  RenderOptions options;
  options.object_draws = vipm.draws;
  options.draw_objects = vipm.draw_objects;
  RenderResult result = render_scene(vipm.scene, options, nullptr);
  if (keep) *keep = std::move(vipm);
  return result;
}

// Pixels that differ from `b`, and the largest difference in one channel.
std::pair<std::size_t, int> image_difference(const Framebuffer& a, const Framebuffer& b) {
  std::size_t pixels = 0;
  int largest = 0;
  for (std::size_t p = 0; p < std::size_t(a.width()) * std::size_t(a.height()); ++p) {
    int worst = 0;
    for (int c = 0; c < 4; ++c)
      worst = std::max(worst, std::abs(int(a.colour()[4 * p + c]) - int(b.colour()[4 * p + c])));
    pixels += worst > 0;
    largest = std::max(largest, worst);
  }
  return {pixels, largest};
}

TEST(VipmRender, EveryMethodAtFullDetailDrawsTheOriginalImage) {
  const Scene scene = make_builtin_scene("grid");
  const RenderResult original = render_scene(scene, RenderOptions{}, nullptr);
  for (const std::string& method : vipm_method_names()) {
    const RenderResult lod0 = render_vipm(scene, method, 0);
    EXPECT_EQ(lod0.pipeline.triangles, 2048u) << method;
    EXPECT_EQ(lod0.raster.fragments, original.raster.fragments) << method;
    EXPECT_EQ(lod0.raster.texel_reads, original.raster.texel_reads) << method;
    const auto [pixels, largest] = image_difference(lod0.framebuffer, original.framebuffer);
    if (method == "skipstrips" || method == "mixedstrips") {
      // A strip hands the rasterizer a triangle's corners in another rotation, which rounds the
      // interpolated texture coordinates differently: a few pixels change by one level.
      EXPECT_LE(largest, 1) << method;
      EXPECT_LE(pixels, 26u) << method;  // 0.01% of 512 x 512
    } else {
      EXPECT_EQ(pixels, 0u) << method;
    }
  }
}

TEST(VipmRender, EveryMethodOfOneSequenceDrawsTheSameTrianglesAtALod) {
  // The grid is flat: no collapse changes the covered pixels, only the triangles over them.
  const Scene scene = make_builtin_scene("grid");
  const ProgressiveMesh pm = build_progressive_mesh(scene.objects[0].mesh);
  const RenderResult vanilla = render_vipm(scene, "vanilla", 300);
  EXPECT_EQ(vanilla.pipeline.triangles, pm.triangle_count_at(300));
  EXPECT_EQ(vanilla.pipeline.triangles, 1469u);
  EXPECT_EQ(vanilla.pipeline.degenerate, 0u);
  EXPECT_EQ(vanilla.raster.texel_reads, 959552u);
  for (const char* method : {"skipstrips", "skiplists", "mixed", "mixedstrips"}) {
    const RenderResult other = render_vipm(scene, method, 300);
    EXPECT_EQ(other.pipeline.triangles, vanilla.pipeline.triangles) << method;
    EXPECT_EQ(other.raster.fragments, vanilla.raster.fragments) << method;
    EXPECT_EQ(other.raster.texel_reads, vanilla.raster.texel_reads) << method;
  }
  // Skip strips keep binned triangles in the list as degenerates; the pipeline does not draw them.
  EXPECT_GT(render_vipm(scene, "skiplists", 300).pipeline.degenerate, 0u);
}

TEST(VipmRender, MixedModeDrawsTwoCallsAndALodPastTheLastIsClamped) {
  const Scene scene = make_builtin_scene("grid");
  VipmScene mixed;
  render_vipm(scene, "mixed", 1u << 30, &mixed);
  ASSERT_EQ(mixed.parts.size(), 1u);
  EXPECT_EQ(mixed.parts[0].draws, 2u);
  EXPECT_EQ(mixed.draws.size(), 2u);
  EXPECT_EQ(mixed.parts[0].lod, mixed.parts[0].last_lod);
  EXPECT_EQ(describe_vipm_lods(mixed.parts), "grid32x32 " + std::to_string(mixed.parts[0].lod) + "/" +
                                                 std::to_string(mixed.parts[0].lod) + " (2 draws)");
}

TEST(VipmRender, BadMethodsAndLodsAreErrorsNamingTheFlag) {
  VipmSceneSpec spec;
  spec.method = "skip";
  try {
    build_vipm_scene(make_builtin_scene("grid"), spec);
    FAIL() << "accepted an unknown method";
  } catch (const InputError& e) {
    EXPECT_THAT(e.what(), HasSubstr("--vipm 'skip': expected one of vanilla, skipstrips"));
  }
  for (const char* text : {"", "-5", "1e3", "4294967296", "+3", "12x"}) EXPECT_THROW(parse_vipm_lod(text), InputError);
  EXPECT_EQ(parse_vipm_lod("4294967295"), 4294967295u);
}

}  // namespace
}  // namespace rastrace
