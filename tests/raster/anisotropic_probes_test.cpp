// EXT_texture_filter_anisotropic's probe rule on hand-computed derivatives: the number of probes,
// their level of detail and their texel reads, and the isotropic sampler where there is no
// anisotropy to follow.
#include <cmath>

#include <gtest/gtest.h>

#include "raster/anisotropic_probes.h"
#include "scenes/texture_io.h"

namespace rastrace {
namespace {

Texture gradient_texture() {
  Texture texture;
  texture.levels = build_mip_chain(make_uv_gradient(256));  // 256x256 to 1x1
  return texture;
}

SamplerState probes(int maximum) {
  SamplerState state;
  state.max_anisotropy = maximum;
  state.aniso_rule = AnisotropyRule::Probes;
  return state;
}

std::uint64_t reads(const Texture& texture, const SamplerState& state, const ProbeFootprint& f) {
  TexelRecorder recorder(nullptr);
  sample_probes(texture, state, f, 0.3f, 0.6f, recorder, TexelSite{});
  return recorder.reads();
}

TEST(AnisotropicProbes, AFourToOneFootprintTakesFourTrilinearProbesAtTheMinorAxisLevel) {
  const Texture texture = gradient_texture();
  // Pmax = 16 texels along x, Pmin = 4 along y.
  const ProbeFootprint f = probe_footprint(texture, probes(16), 16.0f / 256, 0.0f, 0.0f, 4.0f / 256);
  EXPECT_EQ(f.probes, 4);
  EXPECT_FLOAT_EQ(f.lambda, 2.0f);  // log2(16 / 4)
  EXPECT_FLOAT_EQ(f.step_s, 16.0f / 256);
  EXPECT_FLOAT_EQ(f.step_t, 0.0f);
  EXPECT_EQ(reads(texture, probes(16), f), 4u * 8u);
}

TEST(AnisotropicProbes, TheMaximumBoundsTheProbesAndRaisesTheLevel) {
  const Texture texture = gradient_texture();
  // 40:1 along y: 16 probes at max 16 (lambda log2(40 / 16)), 2 at max 2 (log2(20)).
  const ProbeFootprint at16 = probe_footprint(texture, probes(16), 1.0f / 256, 0.0f, 0.0f, 40.0f / 256);
  EXPECT_EQ(at16.probes, 16);
  EXPECT_FLOAT_EQ(at16.lambda, std::log2(40.0f / 16.0f));
  EXPECT_FLOAT_EQ(at16.step_t, 40.0f / 256);
  EXPECT_EQ(reads(texture, probes(16), at16), 16u * 8u);
  const ProbeFootprint at2 = probe_footprint(texture, probes(2), 1.0f / 256, 0.0f, 0.0f, 40.0f / 256);
  EXPECT_EQ(at2.probes, 2);
  EXPECT_FLOAT_EQ(at2.lambda, std::log2(20.0f));
  // A ratio just above 3 takes 4 probes (the ceiling).
  EXPECT_EQ(probe_footprint(texture, probes(16), 3.1f / 256, 0.0f, 0.0f, 1.0f / 256).probes, 4);
}

TEST(AnisotropicProbes, AnIsotropicOrDegenerateFootprintIsTheIsotropicSample) {
  const Texture texture = gradient_texture();
  const SamplerState state = probes(16);
  const ProbeFootprint square = probe_footprint(texture, state, 2.0f / 256, 0.0f, 0.0f, 2.0f / 256);
  EXPECT_EQ(square.probes, 1);
  TexelRecorder a(nullptr), b(nullptr);
  const glm::vec4 probed = sample_probes(texture, state, square, 0.3f, 0.6f, a, TexelSite{});
  const glm::vec4 plain = sample_texture(texture, state, 0.3f, 0.6f, square.lambda, b, TexelSite{});
  EXPECT_EQ(probed, plain);
  EXPECT_EQ(a.reads(), b.reads());
  const ProbeFootprint nan = probe_footprint(texture, state, NAN, 0.0f, 0.0f, 1.0f / 256);
  EXPECT_EQ(nan.probes, 1);
  // Constant coordinates (both derivatives 0) take one probe; a line footprint (Pmin = 0) the maximum.
  EXPECT_EQ(probe_footprint(texture, state, 0.0f, 0.0f, 0.0f, 0.0f).probes, 1);
  EXPECT_EQ(probe_footprint(texture, state, 8.0f / 256, 0.0f, 0.0f, 0.0f).probes, 16);
}

}  // namespace
}  // namespace rastrace
