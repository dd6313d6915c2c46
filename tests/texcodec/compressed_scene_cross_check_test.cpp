// The spider (a built-in scene with its own JPEG textures) stored as BC1, BC7 and ASTC 4x4, drawn
// by rastrace (sampling texcodec's decoded texels) and by OSMesa (softpipe and llvmpipe, given the
// same blocks with glCompressedTexImage2D): the images must meet the cross-check's bar of
// tests/reference (PSNR >= 40 dB against both drivers), which holds only if both decode the
// blocks alike. For ASTC this compares astcenc's decoder with Mesa's own.
#include <cstdio>

#include <gtest/gtest.h>

#include "pipeline/render_scene.h"
#include "reference/image_compare.h"
#include "reference/osmesa_renderer.h"
#include "scenes/scene_io.h"

namespace rastrace {
namespace {

const glm::vec4 kClear(0.1f, 0.1f, 0.1f, 0.0f);  // alpha 0: uncovered

double psnr_against(const Scene& scene, ReferenceDriver driver, LodFormula lod) {
  SamplerState sampler;
  sampler.lod = lod;
  RenderOptions options;
  options.debug_planes = true;
  options.clear_colour = kClear;
  options.pipeline.raster.sampler = sampler;
  const RenderResult ours = render_scene(scene, options, nullptr);
  ReferenceOptions reference_options;
  reference_options.driver = driver;
  reference_options.sampler = sampler;
  reference_options.clear_colour = kClear;
  const ReferenceImage reference = render_reference(scene, reference_options);
  const Framebuffer& fb = ours.framebuffer;
  const ImageDifference d =
      compare_images(fb.width(), fb.height(), fb.colour(), reference.rgba.data(), fb.centre_on_edge());
  std::printf("%-8s %-8s covered %6llu  >2: %.4f  max %3d  PSNR %6.2f dB\n", to_string(scene.textures[0].format),
              to_string(driver), static_cast<unsigned long long>(d.covered), d.fraction(d.diff_gt_2), d.max_difference,
              d.psnr);
  EXPECT_GT(d.covered, 1000u);
  return d.psnr;
}

class CompressedSpider : public ::testing::TestWithParam<TextureFormat> {};

TEST_P(CompressedSpider, MatchesOsmesaDecodingTheSameBlocksAbove40Db) {
  Scene scene = load_scene("builtin:spider", GetParam());
  scene.width = 512;
  scene.height = 384;
  ASSERT_FALSE(scene.textures.empty());
  for (const Texture& texture : scene.textures) {
    ASSERT_EQ(texture.format, GetParam());
    ASSERT_EQ(texture.blocks.size(), texture.levels.size());
  }
  // Each driver's LOD formula, as in tests/reference: llvmpipe uses the derivative vectors'
  // lengths, softpipe their largest component.
  EXPECT_GE(psnr_against(scene, ReferenceDriver::Llvmpipe, LodFormula::Lengths), 40.0);
  EXPECT_GE(psnr_against(scene, ReferenceDriver::Softpipe, LodFormula::MaxComponent), 40.0);
}

INSTANTIATE_TEST_SUITE_P(Bc1Bc7AndAstc, CompressedSpider,
                         ::testing::Values(TextureFormat::Bc1, TextureFormat::Bc7, TextureFormat::Astc4x4),
                         [](const auto& info) { return std::string(to_string(info.param)); });

}  // namespace
}  // namespace rastrace
