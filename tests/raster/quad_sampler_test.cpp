// The quad sampler against the scalar one: for every filter, wrap, level of detail and kind of
// coordinate (inside, outside, far outside, not finite), the four pixels' colours are bit for bit
// sample_texture's and their texel reads are the same events in the same order; likewise the
// anisotropic filter against sample_elliptical at maximum anisotropy 2, 4 and 16.
#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "raster/quad_sampler.h"
#include "raster/sampler.h"
#include "scenes/texture_io.h"
#include "traces/memory_sink.h"

namespace rastrace {
namespace {

Texture random_texture(int width, int height, std::mt19937& random) {
  Image base;
  base.width = width;
  base.height = height;
  base.rgba.resize(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  for (auto& byte : base.rgba) byte = static_cast<std::uint8_t>(random());
  Texture texture;
  texture.levels = build_mip_chain(std::move(base));
  return texture;
}

bool same_bits(float a, float b) { return std::memcmp(&a, &b, sizeof a) == 0; }

bool same_events(const MemorySink::Events<TexelAccess>& a, const MemorySink::Events<TexelAccess>& b) {
  if (a.size() != b.size()) return false;
  for (std::size_t i = 0; i < a.size(); ++i)
    if (a[i].texture != b[i].texture || a[i].level != b[i].level || a[i].x != b[i].x || a[i].y != b[i].y ||
        a[i].pixel_x != b[i].pixel_x || a[i].pixel_y != b[i].pixel_y || a[i].triangle != b[i].triangle)
      return false;
  return true;
}

// A coordinate of each kind the rasterizer can hand the sampler.
float random_coordinate(std::mt19937& random) {
  std::uniform_real_distribution<float> unit(-0.25f, 1.25f);
  switch (random() % 16) {
    case 0: return std::numeric_limits<float>::infinity();
    case 1: return -std::numeric_limits<float>::infinity();
    case 2: return std::numeric_limits<float>::quiet_NaN();
    case 3: return unit(random) * 1.0e6f;  // clamped to +-2^16
    case 4: return unit(random) * 300.0f;  // many repeats
    case 5: return std::floor(unit(random) * 64.0f) / 64.0f;  // on texel boundaries
    default: return unit(random);
  }
}

// The coordinates of a quad's four pixels and which of them are sampled (at least one).
struct RandomQuad {
  simd::f32x4 s, t;
  unsigned pixels;
};
RandomQuad random_quad(std::mt19937& random) {
  RandomQuad q{};
  for (int i = 0; i < 4; ++i) {
    q.s[i] = random_coordinate(random);
    q.t[i] = random_coordinate(random);
  }
  q.pixels = 1u + random() % 15u;
  return q;
}

constexpr int kQuadX = 100, kQuadY = 50;

// Samples the `pixels` of the quad at (kQuadX, kQuadY) one by one with scalar(s, t, recorder,
// site) and at once with quad(recorder, site, rgba), then compares their events and colour bits.
// `compared` counts the pixels compared.
template <class Scalar, class Quad>
::testing::AssertionResult quad_equals_scalar(simd::f32x4 s, simd::f32x4 t, unsigned pixels, const Scalar& scalar,
                                              const Quad& quad, int& compared) {
  const TexelSite site{7, 0, 0, 123456};
  MemorySink scalar_sink, quad_sink;
  simd::f32x4 quad_rgba[4] = {};
  glm::vec4 scalar_rgba[4];
  {
    TexelRecorder scalar_recorder(&scalar_sink), quad_recorder(&quad_sink);
    for (int i = 0; i < 4; ++i) {
      if (!(pixels >> i & 1u)) continue;
      TexelSite pixel_site = site;
      pixel_site.pixel_x = static_cast<std::uint16_t>(kQuadX + (i & 1));
      pixel_site.pixel_y = static_cast<std::uint16_t>(kQuadY + (i >> 1));
      scalar_rgba[i] = scalar(s[i], t[i], scalar_recorder, pixel_site);
    }
    quad(quad_recorder, site, quad_rgba);
  }
  if (!same_events(scalar_sink.texels, quad_sink.texels)) return ::testing::AssertionFailure() << "texel events differ";
  for (int i = 0; i < 4; ++i) {
    if (!(pixels >> i & 1u)) continue;
    for (int ch = 0; ch < 4; ++ch)
      if (!same_bits(scalar_rgba[i][ch], quad_rgba[ch][i]))
        return ::testing::AssertionFailure() << "pixel " << i << " s " << s[i] << " t " << t[i] << ": "
                                             << scalar_rgba[i][ch] << " against " << quad_rgba[ch][i];
    ++compared;
  }
  return ::testing::AssertionSuccess();
}

TEST(QuadSampler, EqualsTheScalarSamplerForEveryFilterWrapAndLevel) {
  std::mt19937 random(20261203);
  const Texture textures[] = {random_texture(64, 64, random), random_texture(37, 20, random),
                              random_texture(1, 16, random)};
  const TextureFilter filters[] = {TextureFilter::Nearest, TextureFilter::Linear, TextureFilter::NearestMipmapNearest,
                                   TextureFilter::LinearMipmapNearest, TextureFilter::LinearMipmapLinear};
  const TextureWrap wraps[] = {TextureWrap::Repeat, TextureWrap::ClampToEdge};
  std::uniform_real_distribution<float> lod(-3.0f, 9.0f);
  int compared = 0;
  for (const Texture& texture : textures)
    for (const TextureFilter filter : filters)
      for (const TextureWrap wrap_s : wraps)
        for (const TextureWrap wrap_t : wraps)
          for (const TextureFilter mag : {TextureFilter::Nearest, TextureFilter::Linear})
            for (int trial = 0; trial < 60; ++trial) {
              SamplerState state;
              state.min_filter = filter;
              state.mag_filter = mag;
              state.wrap_s = wrap_s;
              state.wrap_t = wrap_t;
              // Whole and half levels too: the boundaries of level selection.
              const float lambda = trial % 4 == 0 ? static_cast<float>(trial % 20) * 0.5f - 1.0f : lod(random);
              const RandomQuad q = random_quad(random);
              const simd::f32x4 s = q.s, t = q.t;
              const unsigned pixels = q.pixels;
              const auto scalar = [&](float ps, float pt, TexelRecorder& recorder, const TexelSite& site) {
                return sample_texture(texture, state, ps, pt, lambda, recorder, site);
              };
              const auto quad = [&](TexelRecorder& recorder, const TexelSite& site, simd::f32x4 rgba[4]) {
                sample_quad(texture, state, s, t, lambda, pixels, kQuadX, kQuadY, recorder, site, rgba);
              };
              ASSERT_TRUE(quad_equals_scalar(s, t, pixels, scalar, quad, compared))
                  << "filter " << to_string(filter) << " lambda " << lambda;
            }
  // 3 textures x 5 filters x 4 wraps x 2 magnification filters x 60 quads, about 2 pixels each.
  EXPECT_GT(compared, 5000);
}

// Derivatives of each kind: isotropic, stretched along one axis up to 100:1, rotated, zero, not
// finite.
float random_derivative(std::mt19937& random) {
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  switch (random() % 12) {
    case 0:
      return 0.0f;
    case 1:
      return std::numeric_limits<float>::quiet_NaN();
    case 2:
      return unit(random) * 1.5f;  // a whole texture per pixel
    default:
      return unit(random) * 0.02f;
  }
}

TEST(QuadSampler, EqualsTheScalarEllipticalFilterAtAniso2And4And16) {
  std::mt19937 random(20261206);
  const Texture textures[] = {random_texture(64, 64, random), random_texture(37, 20, random)};
  const TextureWrap wraps[] = {TextureWrap::Repeat, TextureWrap::ClampToEdge};
  int compared = 0;
  for (const int aniso : {2, 4, 16})
    for (const Texture& texture : textures)
      for (const TextureWrap wrap : wraps)
        for (const TextureFilter filter : {TextureFilter::Linear, TextureFilter::LinearMipmapLinear})
          for (int trial = 0; trial < 40; ++trial) {
            SamplerState state;
            state.min_filter = filter;
            state.wrap_s = state.wrap_t = wrap;
            state.max_anisotropy = aniso;
            const EllipticalFootprint footprint =
                elliptical_footprint(texture, state, random_derivative(random), random_derivative(random),
                                     random_derivative(random), random_derivative(random));
            const RandomQuad q = random_quad(random);
            const simd::f32x4 s = q.s, t = q.t;
            const unsigned pixels = q.pixels;
            const auto scalar = [&](float ps, float pt, TexelRecorder& recorder, const TexelSite& site) {
              return sample_elliptical(texture, state, footprint, ps, pt, recorder, site);
            };
            const auto quad = [&](TexelRecorder& recorder, const TexelSite& site, simd::f32x4 rgba[4]) {
              sample_quad_elliptical(texture, state, footprint, s, t, pixels, kQuadX, kQuadY, recorder, site, rgba);
            };
            ASSERT_TRUE(quad_equals_scalar(s, t, pixels, scalar, quad, compared)) << "aniso " << aniso;
          }
  // 3 maxima x 2 textures x 2 wraps x 2 filters x 40 quads, about 2 pixels each.
  EXPECT_GT(compared, 700);
}

TEST(QuadSampler, ATrilinearQuadReadsEightTexelsPerPixelInPixelOrder) {
  Texture texture;
  texture.levels = build_mip_chain(make_uv_gradient(64));
  MemorySink sink;
  simd::f32x4 rgba[4];
  {
    TexelRecorder recorder(&sink);
    const simd::f32x4 s{0.30f, 0.31f, 0.30f, 0.31f}, t{0.60f, 0.60f, 0.61f, 0.61f};
    sample_quad(texture, SamplerState{}, s, t, 2.25f, 0b1011u, 10, 20, recorder, TexelSite{5, 0, 0, 99}, rgba);
    EXPECT_EQ(recorder.reads(), 24u);
  }
  ASSERT_EQ(sink.texels.size(), 24u);
  const int pixels[3] = {0, 1, 3};  // pixel 2 is not sampled
  for (int p = 0; p < 3; ++p)
    for (int k = 0; k < 8; ++k) {
      const TexelAccess& event = sink.texels[static_cast<std::size_t>(p * 8 + k)];
      EXPECT_EQ(event.pixel_x, 10 + (pixels[p] & 1));
      EXPECT_EQ(event.pixel_y, 20 + (pixels[p] >> 1));
      EXPECT_EQ(event.level, k < 4 ? 2 : 3);
      EXPECT_EQ(event.triangle, 99u);
    }
  // Level 2 is 16x16: u = 0.3 * 16 - 0.5 = 4.3 -> texels 4, 5; v = 0.6 * 16 - 0.5 = 9.1 -> 9, 10.
  EXPECT_EQ(sink.texels[0].x, 4u);
  EXPECT_EQ(sink.texels[0].y, 9u);
  EXPECT_EQ(sink.texels[3].x, 5u);
  EXPECT_EQ(sink.texels[3].y, 10u);
}

}  // namespace
}  // namespace rastrace
