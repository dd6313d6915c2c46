// The depth test against the order of the surfaces: the law of records (d surfaces over the same
// pixels in uniformly random order write depth H_d = 1 + 1/2 + ... + 1/d times per pixel on
// average; front to back once, back to front d times), early against late testing, hierarchical Z,
// and the framebuffer events that record it all.
#include <algorithm>
#include <bit>
#include <cstdio>
#include <numeric>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "raster/rasterizer.h"
#include "scenes/texture_io.h"
#include "traces/memory_sink.h"

namespace rastrace {
namespace {

constexpr int kSide = 8;  // an 8x8 frame: the law holds per pixel, 64 pixels keep it fast
constexpr int kSurfaces = 10;

RasterVertex corner(float x, float y, float z) {
  RasterVertex v;
  v.x = x;
  v.y = y;
  v.z = z;
  v.uv = glm::vec2(x / kSide, y / kSide);
  return v;
}

// Surface k covers the whole frame at depth (k + 1) / (d + 1): surface 0 is the nearest.
void draw_surface(Rasterizer& raster, int k, const TriangleState& state = {}) {
  const float z = static_cast<float>(k + 1) / static_cast<float>(kSurfaces + 1);
  const float s = static_cast<float>(kSide);
  raster.draw(corner(0, 0, z), corner(s, 0, z), corner(0, s, z), state);
  raster.draw(corner(s, 0, z), corner(s, s, z), corner(0, s, z), state);
}

RasterStats draw_in_order(const std::vector<int>& order, const RasterOptions& options, EventSink* sink = nullptr,
                          const TriangleState& state = {}) {
  Framebuffer fb(kSide, kSide);
  Rasterizer raster(fb, options, sink);
  for (const int k : order) draw_surface(raster, k, state);
  raster.flush();
  EXPECT_EQ(fb.covered_pixels(), static_cast<std::uint64_t>(kSide * kSide));
  return raster.stats();
}

double depth_writes_per_pixel(const RasterStats& stats) {
  return static_cast<double>(stats.fragments_passed) / (kSide * kSide);
}

TEST(DepthOrder, RandomOrdersWriteDepthHarmonicNumberTimesPerPixel) {
  const double h10 = 2.9289682539682538;  // 1 + 1/2 + ... + 1/10
  std::vector<int> order(kSurfaces);
  std::iota(order.begin(), order.end(), 0);
  std::mt19937_64 rng(2026);
  constexpr int kOrders = 10000;
  double sum = 0.0;
  for (int trial = 0; trial < kOrders; ++trial) {
    std::shuffle(order.begin(), order.end(), rng);
    const RasterStats stats = draw_in_order(order, {});
    ASSERT_EQ(stats.fragments, static_cast<std::uint64_t>(kSurfaces * kSide * kSide));
    // Early test: only the fragments that pass are shaded; the others are rejected before.
    ASSERT_EQ(stats.fragments_shaded, stats.fragments_passed);
    ASSERT_EQ(stats.fragments_rejected_early, stats.fragments - stats.fragments_passed);
    sum += depth_writes_per_pixel(stats);
  }
  const double mean = sum / kOrders;
  std::printf("mean depth writes per pixel over %d random orders of %d surfaces: %.4f (H_10 = %.4f)\n", kOrders,
              kSurfaces, mean, h10);
  EXPECT_NEAR(mean, h10, 0.015 * h10) << "mean depth writes per pixel over " << kOrders << " orders";
}

TEST(DepthOrder, FrontToBackWritesOnceBackToFrontWritesEverySurface) {
  std::vector<int> front_to_back(kSurfaces);
  std::iota(front_to_back.begin(), front_to_back.end(), 0);
  std::vector<int> back_to_front(front_to_back.rbegin(), front_to_back.rend());
  EXPECT_EQ(depth_writes_per_pixel(draw_in_order(front_to_back, {})), 1.0);
  EXPECT_EQ(depth_writes_per_pixel(draw_in_order(back_to_front, {})), static_cast<double>(kSurfaces));
}

TEST(DepthOrder, LateTestShadesEveryFragmentEarlyTestOnlyThoseThatPass) {
  Texture checker;
  checker.levels = build_mip_chain(make_checker(16, 4));
  TriangleState textured;
  textured.texture = &checker;
  std::vector<int> front_to_back(kSurfaces);
  std::iota(front_to_back.begin(), front_to_back.end(), 0);
  RasterOptions late;
  late.depth_test = DepthTest::Late;
  MemorySink early_events, late_events;
  const RasterStats early_stats = draw_in_order(front_to_back, {}, &early_events, textured);
  const RasterStats late_stats = draw_in_order(front_to_back, late, &late_events, textured);
  const std::uint64_t pixels = kSide * kSide;
  EXPECT_EQ(early_stats.fragments_shaded, pixels);
  EXPECT_EQ(early_stats.fragments_rejected_early, (kSurfaces - 1) * pixels);
  EXPECT_EQ(late_stats.fragments_shaded, kSurfaces * pixels);
  EXPECT_EQ(late_stats.fragments_rejected_early, 0u);
  EXPECT_EQ(early_stats.fragments_passed, late_stats.fragments_passed);
  // Rejected fragments read no texel: the late test reads d times the texels of the early one.
  EXPECT_GT(early_stats.texel_reads, 0u);
  EXPECT_EQ(late_stats.texel_reads, kSurfaces * early_stats.texel_reads);
  EXPECT_EQ(late_events.texels.size(), late_stats.texel_reads);

  // The events: per quad a depth read of its covered pixels, then writes of those that passed.
  for (const MemorySink* events : {&early_events, &late_events}) {
    std::uint64_t reads = 0, depth_writes = 0, colour_writes = 0;
    for (const FramebufferAccess& a : events->framebuffer) {
      const auto pixels_in = static_cast<std::uint64_t>(std::popcount(static_cast<unsigned>(a.mask)));
      reads += a.op == FramebufferOp::DepthRead ? pixels_in : 0;
      depth_writes += a.op == FramebufferOp::DepthWrite ? pixels_in : 0;
      colour_writes += a.op == FramebufferOp::ColourWrite ? pixels_in : 0;
      EXPECT_EQ(a.x % 2, 0);
      EXPECT_EQ(a.y % 2, 0);
    }
    EXPECT_EQ(reads, kSurfaces * pixels);
    EXPECT_EQ(depth_writes, pixels);
    EXPECT_EQ(colour_writes, pixels);
  }
}

TEST(DepthOrder, HierarchicalZRejectsHiddenQuadsWithoutReadingDepthAndKeepsTheImage) {
  std::vector<int> front_to_back(kSurfaces);
  std::iota(front_to_back.begin(), front_to_back.end(), 0);
  RasterOptions hiz;
  hiz.hierarchical_z = true;
  MemorySink events;
  const RasterStats stats = draw_in_order(front_to_back, hiz, &events);
  // A surface is two triangles: the quads on the diagonal are visited by both (16 + 4 visits).
  const std::uint64_t quads = draw_in_order({0}, {}).quads;
  EXPECT_EQ(quads, 20u);
  // The nearest surface is drawn; every quad of the nine behind it is rejected by its tile.
  EXPECT_EQ(stats.quads_rejected_hiz, (kSurfaces - 1) * quads);
  EXPECT_EQ(stats.fragments_passed, kSide * kSide);
  std::uint64_t depth_reads = 0;
  for (const FramebufferAccess& a : events.framebuffer) depth_reads += a.op == FramebufferOp::DepthRead;
  EXPECT_EQ(depth_reads, quads);

  // Random orders: the same image and the same depth writes with and without hierarchical Z.
  std::vector<int> order = front_to_back;
  std::mt19937_64 rng(5);
  for (int trial = 0; trial < 50; ++trial) {
    std::shuffle(order.begin(), order.end(), rng);
    Framebuffer a(kSide, kSide), b(kSide, kSide);
    Rasterizer plain(a, {}, nullptr), tiled(b, hiz, nullptr);
    for (const int k : order) {
      draw_surface(plain, k);
      draw_surface(tiled, k);
    }
    ASSERT_TRUE(std::equal(a.depth(), a.depth() + kSide * kSide, b.depth()));
    ASSERT_EQ(plain.stats().fragments_passed, tiled.stats().fragments_passed);
    ASSERT_LE(tiled.stats().fragments_shaded, plain.stats().fragments_shaded);
  }
}

TEST(DepthOrder, NoFramebufferEventsForASinkThatDoesNotWantThem) {
  struct TexelsOnly final : EventSink {
    std::uint64_t framebuffer = 0;
    void framebuffer_accesses(std::span<const FramebufferAccess> a) override { framebuffer += a.size(); }
  } sink;
  draw_in_order({0, 1, 2}, {}, &sink);
  EXPECT_EQ(sink.framebuffer, 0u);
}

}  // namespace
}  // namespace rastrace
