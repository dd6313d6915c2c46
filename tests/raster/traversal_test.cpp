// The traversal skips the quads of a row that no edge lets a pixel into. The skip must be exact
// in what matters: every quad with a covered pixel is still visited, in the same order, with the
// same edge functions, as in the visit of every quad of the box.
#include <cstdint>
#include <random>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "raster/traversal.h"
#include "raster/triangle_setup.h"

namespace rastrace {
namespace {

RasterVertex at(float x, float y) {
  RasterVertex v;
  v.x = x;
  v.y = y;
  v.z = 0.5f;
  return v;
}

using Visit = std::tuple<int, int, std::int64_t, std::int64_t, std::int64_t, std::int64_t>;

// The quads visited with a covered pixel (as the quad stage's coverage test decides), each with
// its edge functions at the top-left pixel; `visited` counts every quad visited.
template <bool kVisitAll>
std::vector<Visit> covered_quads(const TriangleSetup& s, Traversal traversal, const PixelRect& clip,
                                 std::uint64_t& visited) {
  std::vector<Visit> covered;
  for_each_quad<kVisitAll>(
      s, traversal, clip,
      [&](int qx, int qy, const simd::i64x4* e) {
        ++visited;
        if (simd::non_negative_mask((e[0] + s.bias[0]) | (e[1] + s.bias[1]) | (e[2] + s.bias[2])))
          covered.emplace_back(qx, qy, e[0][0], e[1][0], e[2][0], e[0][3]);
      },
      traversal_hilbert_bits(clip.x1 + 1, clip.y1 + 1));
  return covered;
}

TEST(Traversal, SkippingEmptyQuadsVisitsEveryCoveredQuadInTheSameOrder) {
  constexpr int kWidth = 256, kHeight = 192;
  std::mt19937 random(20261206);
  std::uniform_real_distribution<float> coordinate(-40.0f, 300.0f);
  std::uint64_t all_visits = 0, skipping_visits = 0, covered = 0;
  for (int n = 0; n < 400; ++n) {
    const RasterVertex a = at(coordinate(random), coordinate(random));
    const RasterVertex b = at(coordinate(random), coordinate(random));
    const RasterVertex c = at(coordinate(random), coordinate(random));
    for (const Traversal traversal : {Traversal::Scanline, Traversal::Tiled8, Traversal::Hilbert8}) {
      TriangleSetup s;
      if (!setup_triangle(a, b, c, kWidth, kHeight, traversal_alignment(traversal), s)) continue;
      // The whole image, and a tile of it as a parallel worker clips to.
      for (const PixelRect clip : {PixelRect{0, 0, kWidth - 1, kHeight - 1}, PixelRect{64, 32, 127, 95}}) {
        const std::vector<Visit> expected = covered_quads<true>(s, traversal, clip, all_visits);
        const std::vector<Visit> skipping = covered_quads<false>(s, traversal, clip, skipping_visits);
        ASSERT_EQ(skipping, expected) << "triangle " << n << ", traversal " << to_string(traversal);
        covered += expected.size();
      }
    }
  }
  EXPECT_GT(covered, 10000u);
  // Random triangles leave most of their boxes empty: the skip must leave most of that out.
  EXPECT_LT(skipping_visits * 2, all_visits) << skipping_visits << " of " << all_visits;
}

TEST(Traversal, AThinDiagonalTriangleVisitsOnlyQuadsNearItsEdges) {
  TriangleSetup s;
  ASSERT_TRUE(setup_triangle(at(0.0f, 0.0f), at(256.0f, 190.0f), at(250.0f, 192.0f), 256, 192, 2, s));
  std::uint64_t all = 0, skipping = 0;
  const PixelRect image{0, 0, 255, 191};
  const std::size_t covered = covered_quads<true>(s, Traversal::Scanline, image, all).size();
  EXPECT_EQ(covered_quads<false>(s, Traversal::Scanline, image, skipping).size(), covered);
  EXPECT_EQ(all, 128u * 96u);  // every quad of the box
  // At most a few quads per row beside the covered ones.
  EXPECT_LE(skipping, covered + 96u * 3u) << covered << " covered";
}

}  // namespace
}  // namespace rastrace
