// Texture sampling as the GL specification defines it: LOD, level selection, filters, wraps.
#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "core/error.h"
#include "raster/sampler.h"
#include "scenes/texture_io.h"
#include "traces/memory_sink.h"

namespace rastrace {
namespace {

Texture gradient_texture(int size) {
  Texture t;
  t.levels = build_mip_chain(make_uv_gradient(size));
  return t;
}

TEST(Sampler, LodIsLog2OfTheLongerScaledDerivativeVector) {
  SamplerState state;
  // 4 texels per pixel along x on a 256 texture: lambda = 2.
  EXPECT_FLOAT_EQ(compute_lod(state, 256, 256, 4.0f / 256, 0.0f, 0.0f, 1.0f / 256), 2.0f);
  // Diagonal derivative (3, 4) texels: length 5.
  EXPECT_NEAR(compute_lod(state, 256, 256, 3.0f / 256, 4.0f / 256, 0.0f, 0.0f), std::log2(5.0f), 1e-6);
  // The max-component bound (equation 8.7) gives log2(4) for the same derivatives.
  state.lod = LodFormula::MaxComponent;
  EXPECT_NEAR(compute_lod(state, 256, 256, 3.0f / 256, 4.0f / 256, 0.0f, 0.0f), 2.0f, 1e-6);
  // Non-square textures scale s by the width and t by the height.
  state.lod = LodFormula::Lengths;
  EXPECT_FLOAT_EQ(compute_lod(state, 512, 64, 0.0f, 0.0f, 0.0f, 8.0f / 64), 3.0f);
}

TEST(Sampler, TrilinearReadsEightTexelsFromTwoAdjacentLevels) {
  const Texture texture = gradient_texture(64);
  SamplerState state;  // LINEAR_MIPMAP_LINEAR
  MemorySink sink;
  {
    TexelRecorder recorder(&sink);
    sample_texture(texture, state, 0.3f, 0.6f, 2.25f, recorder, TexelSite{5, 10, 11, 99});
    EXPECT_EQ(recorder.reads(), 8u);
  }
  ASSERT_EQ(sink.texels.size(), 8u);
  for (int i = 0; i < 4; ++i) EXPECT_EQ(sink.texels[i].level, 2);
  for (int i = 4; i < 8; ++i) EXPECT_EQ(sink.texels[i].level, 3);
  // Level 2 is 16x16: u = 0.3 * 16 - 0.5 = 4.3 -> texels 4, 5; v = 0.6 * 16 - 0.5 = 9.1 -> 9, 10.
  EXPECT_EQ(sink.texels[0].x, 4u);
  EXPECT_EQ(sink.texels[0].y, 9u);
  EXPECT_EQ(sink.texels[3].x, 5u);
  EXPECT_EQ(sink.texels[3].y, 10u);
  EXPECT_EQ(sink.texels[0].texture, 5u);
  EXPECT_EQ(sink.texels[0].pixel_x, 10);
  EXPECT_EQ(sink.texels[0].triangle, 99u);
}

TEST(Sampler, LevelSelectionFollowsTheSpecification) {
  const Texture texture = gradient_texture(64);  // 7 levels
  auto levels_read = [&](const SamplerState& state, float lambda) {
    MemorySink sink;
    {
      TexelRecorder recorder(&sink);
      sample_texture(texture, state, 0.5f, 0.5f, lambda, recorder, {});
    }
    std::vector<int> levels;
    for (const auto& t : sink.texels) levels.push_back(t.level);
    return levels;
  };
  SamplerState nmn = parse_filter("nearest_mipmap_nearest");
  EXPECT_EQ(levels_read(nmn, 0.4f), std::vector<int>{0});
  EXPECT_EQ(levels_read(nmn, 1.4f), std::vector<int>{1});  // ceil(1.9) - 1
  EXPECT_EQ(levels_read(nmn, 1.6f), std::vector<int>{2});
  EXPECT_EQ(levels_read(nmn, 30.0f), std::vector<int>{6});  // clamped to the 1x1 level
  SamplerState lmn = parse_filter("linear_mipmap_nearest");
  EXPECT_EQ(levels_read(lmn, 2.7f), std::vector<int>(4, 3));
  SamplerState trilinear = parse_filter("trilinear");
  EXPECT_EQ(levels_read(trilinear, -1.0f), std::vector<int>(4, 0));  // magnification: LINEAR on level 0
  EXPECT_EQ(levels_read(trilinear, 6.5f), std::vector<int>(4, 6));   // beyond the last level
  SamplerState nearest = parse_filter("nearest");
  EXPECT_EQ(levels_read(nearest, 3.0f), std::vector<int>{0});
}

TEST(Sampler, RepeatWrapsAndClampToEdgeClamps) {
  Texture texture;
  texture.levels = {make_uv_gradient(10)};
  auto texel = [&](TextureWrap wrap, TextureFilter filter, float s) {
    SamplerState state;
    state.min_filter = state.mag_filter = filter;
    state.wrap_s = state.wrap_t = wrap;
    MemorySink sink;
    {
      TexelRecorder recorder(&sink);
      sample_texture(texture, state, s, 0.55f, 0.0f, recorder, {});
    }
    return sink.texels;
  };
  EXPECT_EQ(texel(TextureWrap::Repeat, TextureFilter::Nearest, -0.05f)[0].x, 9u);
  EXPECT_EQ(texel(TextureWrap::Repeat, TextureFilter::Nearest, 1.25f)[0].x, 2u);
  EXPECT_EQ(texel(TextureWrap::ClampToEdge, TextureFilter::Nearest, -0.05f)[0].x, 0u);
  EXPECT_EQ(texel(TextureWrap::ClampToEdge, TextureFilter::Nearest, 7.0f)[0].x, 9u);
  const auto repeat = texel(TextureWrap::Repeat, TextureFilter::Linear, 0.01f);  // u = -0.4
  EXPECT_EQ(repeat[0].x, 9u);
  EXPECT_EQ(repeat[1].x, 0u);
  const auto clamp = texel(TextureWrap::ClampToEdge, TextureFilter::Linear, 0.01f);
  EXPECT_EQ(clamp[0].x, 0u);
  EXPECT_EQ(clamp[1].x, 0u);
}

TEST(Sampler, BilinearWeightsBlendTheFourTexels) {
  Texture texture;
  texture.levels = {make_uv_gradient(16)};  // R = x * 17, G = y * 17
  SamplerState state = parse_filter("linear");
  TexelRecorder recorder;
  // u = 0.25 * 16 - 0.5 = 3.5: halfway between texels 3 and 4 -> R = 3.5 * 17 / 255.
  const glm::vec4 c = sample_texture(texture, state, 0.25f, 0.5f, 0.0f, recorder, {});
  EXPECT_NEAR(c.r, 3.5f * 17.0f / 255.0f, 1e-5f);
  EXPECT_NEAR(c.g, 7.5f * 17.0f / 255.0f, 1e-5f);
  EXPECT_EQ(recorder.reads(), 4u);
}

TEST(Sampler, UnknownNamesAreInputErrors) {
  EXPECT_THROW(parse_filter("anisotropic"), InputError);
  EXPECT_THROW(parse_wrap("mirror"), InputError);
}

}  // namespace
}  // namespace rastrace
