// The elliptical footprint on hand-computed derivatives: which level it reads, which texels and
// how many, and that the maximum anisotropy (above 1) does not bound it, as in llvmpipe 22.3.
#include <cmath>
#include <limits>

#include <gtest/gtest.h>

#include "raster/anisotropy.h"
#include "scenes/texture_io.h"
#include "traces/memory_sink.h"

namespace rastrace {
namespace {

Texture gradient_texture() {
  Texture texture;
  texture.levels = build_mip_chain(make_uv_gradient(256));  // 9 levels, 256x256 to 1x1
  return texture;
}

SamplerState anisotropic(int maximum) {
  SamplerState state;
  state.max_anisotropy = maximum;
  return state;
}

// The texels sample_elliptical reads at (s, t).
std::uint64_t reads_at(const Texture& texture, const SamplerState& state, const EllipticalFootprint& footprint, float s,
                       float t) {
  TexelRecorder recorder(nullptr);
  sample_elliptical(texture, state, footprint, s, t, recorder, TexelSite{});
  return recorder.reads();
}

TEST(Anisotropy, LevelIsTheFloorOfLog2OfTheMinorAxis) {
  const SamplerState state = anisotropic(16);
  // Pmin = 4 texels (t along y), Pmax = 16 (s along x): a 4:1 footprint.
  EXPECT_EQ(anisotropic_level(state, 256, 256, 8, 16.0f / 256, 0.0f, 0.0f, 4.0f / 256), 2u);
  // Just under a power of two stays below it; Pmin < 1 is level 0.
  EXPECT_EQ(anisotropic_level(state, 256, 256, 8, 16.0f / 256, 0.0f, 0.0f, 3.99f / 256), 1u);
  EXPECT_EQ(anisotropic_level(state, 256, 256, 8, 16.0f / 256, 0.0f, 0.0f, 0.25f / 256), 0u);
  // The minor vector's length counts, not its components: (3, 4) is 5 texels long.
  EXPECT_EQ(anisotropic_level(state, 256, 256, 8, 3.0f / 256, 4.0f / 256, 64.0f / 256, 0.0f), 2u);
  // At most the last level; a filter without mipmaps reads level 0.
  EXPECT_EQ(anisotropic_level(state, 256, 256, 8, 4096.0f / 256, 0.0f, 0.0f, 2048.0f / 256), 8u);
  SamplerState linear = state;
  linear.min_filter = TextureFilter::Linear;
  EXPECT_EQ(anisotropic_level(linear, 256, 256, 8, 16.0f / 256, 0.0f, 0.0f, 4.0f / 256), 0u);
}

TEST(Anisotropy, AFourToOneFootprintReads19TexelsAtTheMinorAxisLevel) {
  const Texture texture = gradient_texture();
  const SamplerState state = anisotropic(4);
  const EllipticalFootprint f = elliptical_footprint(texture, state, 16.0f / 256, 0.0f, 0.0f, 4.0f / 256);
  ASSERT_TRUE(f.valid);
  EXPECT_EQ(f.level, 2u);  // the minor axis: 4 texels of level 0, 1 of level 2
  // In level 2 (64x64) the axes are 4 and 1 texels, each grown by one: q = 2 U^2 + 17 V^2 <= 34.
  // Centred on a texel: 9 texels on the row V = 0 (U^2 <= 17), 5 on V = +-1 (U^2 <= 8.5).
  const float s = (20.0f + 0.5f) / 64.0f, t = (30.0f + 0.5f) / 64.0f;
  MemorySink sink;
  {
    TexelRecorder recorder(&sink);
    sample_elliptical(texture, state, f, s, t, recorder, TexelSite{});
  }
  ASSERT_EQ(sink.texels.size(), 19u);
  for (const TexelAccess& e : sink.texels) {
    EXPECT_EQ(e.level, 2u);
    const int du = static_cast<int>(e.x) - 20, dv = static_cast<int>(e.y) - 30;
    EXPECT_LE(2 * du * du + 17 * dv * dv, 34) << du << ", " << dv;
  }
}

TEST(Anisotropy, AFortyToOneFootprintAtMaximum16Reads195TexelsWhateverTheMaximum) {
  const Texture texture = gradient_texture();
  // Pmax = 40, Pmin = 1: level 0, q = 2 U^2 + 1601 V^2 <= 3202: 81 texels on V = 0 (U^2 <= 1601),
  // 57 on V = +-1 (U^2 <= 800.5). The maximum does not bound the ellipse (llvmpipe 22.3).
  const float s = 100.5f / 256.0f, t = 60.5f / 256.0f;
  for (const int maximum : {2, 4, 16}) {
    const SamplerState state = anisotropic(maximum);
    const EllipticalFootprint f = elliptical_footprint(texture, state, 40.0f / 256, 0.0f, 0.0f, 1.0f / 256);
    EXPECT_EQ(f.level, 0u);
    EXPECT_EQ(reads_at(texture, state, f, s, t), 195u) << "maximum " << maximum;
  }
}

TEST(Anisotropy, AnIsotropicFootprintOfOneTexelReadsTheNineNearestTexels) {
  // du/dx = dv/dy = 1, each grown by one: a circle of radius sqrt(2) around a texel centre, the
  // centre, its four neighbours and the four diagonals on its edge (U^2 + V^2 <= 2).
  const Texture texture = gradient_texture();
  const SamplerState state = anisotropic(2);
  const EllipticalFootprint f = elliptical_footprint(texture, state, 1.0f / 256, 0.0f, 0.0f, 1.0f / 256);
  EXPECT_EQ(f.level, 0u);
  EXPECT_EQ(reads_at(texture, state, f, 10.5f / 256, 10.5f / 256), 9u);
}

TEST(Anisotropy, TheWeightedMeanOfAConstantTextureIsThatConstant) {
  Image image;
  image.width = image.height = 16;
  image.rgba.assign(16 * 16 * 4, 200);
  Texture texture;
  texture.levels = build_mip_chain(std::move(image));
  const SamplerState state = anisotropic(16);
  const EllipticalFootprint f = elliptical_footprint(texture, state, 0.3f, 0.05f, -0.02f, 0.04f);
  TexelRecorder recorder(nullptr);
  const glm::vec4 c = sample_elliptical(texture, state, f, 0.37f, 0.81f, recorder, TexelSite{});
  for (int ch = 0; ch < 4; ++ch) EXPECT_NEAR(c[ch], 200.0f / 255.0f, 1e-6f);
}

TEST(Anisotropy, NonFiniteDerivativesFallBackToTheBilinearFilter) {
  const Texture texture = gradient_texture();
  const SamplerState state = anisotropic(16);
  const EllipticalFootprint f =
      elliptical_footprint(texture, state, std::numeric_limits<float>::infinity(), 0.0f, 0.0f, 1.0f / 256);
  EXPECT_FALSE(f.valid);
  EXPECT_EQ(reads_at(texture, state, f, 0.5f, 0.5f), 4u);
}

}  // namespace
}  // namespace rastrace
