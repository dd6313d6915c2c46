// The quad filter's kernels for each instruction set give the same footprints and the same
// colour bits: the renderer takes the widest the processor has, so an image must not depend on
// which. (The kernel against the scalar sampler: quad_sampler_test.cpp.)
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "raster/quad_filter.h"
#include "raster/quad_loop.h"
#include "raster/sampler.h"

namespace rastrace {
namespace {

TEST(QuadFilter, TheSse2AndAvx2KernelsGiveTheSameTexelsAndColourBits) {
  if (!simd_level_supported(SimdLevel::Avx2)) GTEST_SKIP() << "this processor has no AVX2";
  const QuadFilterKernel sse2 = quad_filter_kernel(SimdLevel::Sse2), avx2 = quad_filter_kernel(SimdLevel::Avx2);
  ASSERT_NE(sse2, avx2);
  std::mt19937 random(6122026);
  // Level sizes: powers of two and not, down to 1 (the masked and the modulo wraps).
  const int sizes[] = {1, 2, 3, 5, 16, 37, 64, 100, 256};
  // Random texels, shared by every size (the largest level is 256x256).
  std::vector<std::uint8_t> texels[2];
  std::uniform_real_distribution<float> near(-2.5f, 2.5f), far(-65536.0f, 65536.0f);
  std::uniform_int_distribution<int> size(0, 8), byte(0, 255), coin(0, 1);
  for (std::vector<std::uint8_t>& level : texels) {
    level.resize(256 * 256 * 4);
    for (std::uint8_t& b : level) b = static_cast<std::uint8_t>(byte(random));
  }
  int compared = 0;
  for (int n = 0; n < 20000; ++n) {
    QuadFilterInput in;
    for (int level = 0; level < 2; ++level) {
      const int width = sizes[size(random)], height = sizes[size(random)];
      in.levels[level] = {texels[level].data(), width, height};
    }
    in.repeat_s = coin(random) == 1;
    in.repeat_t = coin(random) == 1;
    in.blend = coin(random) == 1;
    in.two_pixels = in.blend && coin(random) == 1;
    in.fraction = std::uniform_real_distribution<float>(0.0f, 1.0f)(random);
    for (int i = 0; i < 4; ++i) {
      in.s[i] = n % 10 == 0 ? far(random) : near(random);
      in.t[i] = n % 10 == 1 ? far(random) : near(random);
    }
    QuadFilterOutput a, b;
    sse2(in, a);
    avx2(in, b);
    const int lanes = in.blend && !in.two_pixels ? 8 : 4, pixels_per_level = in.two_pixels ? 2 : 4;
    for (int l = 0; l < lanes; ++l) {
      ASSERT_EQ(a.x0[l], b.x0[l]) << "quad " << n << " lane " << l;
      ASSERT_EQ(a.x1[l], b.x1[l]) << "quad " << n << " lane " << l;
      ASSERT_EQ(a.y0[l], b.y0[l]) << "quad " << n << " lane " << l;
      ASSERT_EQ(a.y1[l], b.y1[l]) << "quad " << n << " lane " << l;
      ASSERT_GE(a.x0[l], 0);
      ASSERT_LT(a.x1[l], in.levels[l / pixels_per_level].width);
      ASSERT_LT(a.y1[l], in.levels[l / pixels_per_level].height);
    }
    for (int c = 0; c < 4; ++c)
      for (int i = 0; i < 4; ++i) {
        ASSERT_EQ(std::bit_cast<std::uint32_t>(a.rgba[c][i]), std::bit_cast<std::uint32_t>(b.rgba[c][i]))
            << "quad " << n << " channel " << c << " pixel " << i;
        ++compared;
      }
  }
  EXPECT_EQ(compared, 20000 * 16);
}

// REPEAT on a level whose size is not a power of two wraps without an integer division: one step
// when every lane is within a repetition either side, else a quotient in double, corrected. Every
// kernel must give wrap_coordinate's texel for every size, out to the coordinate limit, on both
// paths and at the edges between them.
TEST(QuadFilter, RepeatWrapsEqualTheScalarWrapForEverySizeOutToTheCoordinateLimit) {
  std::mt19937 random(41);
  std::uniform_real_distribution<float> any(-kCoordinateLimit, kCoordinateLimit), near(-3.0f, 3.0f);
  std::vector<std::uint8_t> texels(16384 * 4);
  std::vector<int> sizes;
  for (int size = 1; size <= 300; ++size) sizes.push_back(size);
  for (const int size : {1000, 4095, 4097, 12345, 16383, 16384}) sizes.push_back(size);
  const float edges[] = {kCoordinateLimit, -kCoordinateLimit, 0.0f, -0.0f, 1.0f, -1.0f, 0.5f, -0.5f};
  std::int64_t compared = 0;
  for (const SimdLevel level : {SimdLevel::Sse2, SimdLevel::Avx2}) {
    if (!simd_level_supported(level)) continue;
    const QuadFilterKernel kernel = quad_filter_kernel(level);
    for (std::size_t index = 0; index < sizes.size(); ++index)
      for (int trial = 0; trial < 40; ++trial) {
        const int size = sizes[index];
        QuadFilterInput in;
        in.levels[0] = {texels.data(), size, 1};
        // The second level of another size, as a blend's two levels are.
        in.levels[1] = {texels.data(), sizes[(index + 7) % sizes.size()], 1};
        // Edge trials: the texel columns at the ends of the one-step path (-size, 2 size - 1) in
        // every lane, or with the last lane one beyond an end (-size - 1, 2 size), which must send
        // the quad to the division; each with one level and with two.
        const bool edge_trial = trial % 4 == 3;
        const int pattern = (trial / 8) % 3;
        in.blend = edge_trial ? (trial / 4) % 2 == 1 : trial % 2 == 1;
        int column[4] = {};
        for (int i = 0; i < 4; ++i) {
          const int pick = trial * 4 + i;
          if (pick < 8) {
            in.s[i] = edges[pick];
          } else if (trial % 4 == 2) {  // every lane near: the one-step path
            in.s[i] = near(random);
          } else if (edge_trial) {
            column[i] = i % 2 == 0 ? -size : 2 * size - 1;
            if (i == 3 && pattern == 1) column[i] = -size - 1;
            if (i == 3 && pattern == 2) column[i] = 2 * size;
            // A quarter texel into the column: floor(s size - 1/2) is the column.
            in.s[i] = (static_cast<float>(column[i]) + 0.75f) / static_cast<float>(size);
          } else {
            in.s[i] = pick % 3 == 0 ? any(random) : near(random);
          }
          in.t[i] = 0.5f;
        }
        QuadFilterOutput out;
        kernel(in, out);
        for (int l = 0; l < (in.blend ? 8 : 4); ++l) {
          const int lane_size = in.levels[l / 4].width;
          const float u = in.s[l % 4] * static_cast<float>(lane_size) - 0.5f;
          const int i = static_cast<int>(std::floor(u));
          if (edge_trial && l < 4) {
            ASSERT_EQ(i, column[l]) << "size " << size;  // the edge is hit
          }
          ASSERT_EQ(out.x0[l], wrap_coordinate(i, lane_size, TextureWrap::Repeat))
              << to_string(level) << " size " << lane_size << " s " << in.s[l % 4];
          ASSERT_EQ(out.x1[l], wrap_coordinate(i + 1, lane_size, TextureWrap::Repeat))
              << to_string(level) << " size " << lane_size << " s " << in.s[l % 4];
          ++compared;
        }
      }
  }
  EXPECT_GT(compared, 300 * 40 * 4);
}

TEST(QuadFilter, RastraceSimdChoosesTheBaselineKernel) {
  // renderer_simd_level() reads RASTRACE_SIMD once; the test run under RASTRACE_SIMD=sse2
  // (tests/CMakeLists.txt) checks that the variable takes effect.
  const char* forced = std::getenv("RASTRACE_SIMD");
  if (forced && std::string(forced) == "sse2") {
    EXPECT_EQ(renderer_simd_level(), SimdLevel::Sse2);
    EXPECT_EQ(renderer_quad_filter(), quad_filter_kernel(SimdLevel::Sse2));
    EXPECT_FALSE(wide_quad_loop());  // the quad loop's baseline copy too (raster/quad_loop.h)
    use_wide_quad_loop(true);        // which a test cannot turn back on past the variable
    EXPECT_FALSE(wide_quad_loop());
  } else {
    EXPECT_EQ(renderer_simd_level(), simd_level_supported(SimdLevel::Avx2) ? SimdLevel::Avx2 : SimdLevel::Sse2);
  }
}

}  // namespace
}  // namespace rastrace
