// The rasterizer's fill rule, traversal orders, depth test and interpolation.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>
#include <tuple>
#include <vector>

#include <gtest/gtest.h>

#include "raster/rasterizer.h"
#include "scenes/texture_io.h"
#include "traces/memory_sink.h"

namespace rastrace {
namespace {

RasterVertex at(float x, float y, float z = 0.5f) {
  RasterVertex v;
  v.x = x;
  v.y = y;
  v.z = z;
  return v;
}

std::uint64_t written(const Framebuffer& fb) {
  std::uint64_t n = 0;
  for (int i = 0; i < fb.width() * fb.height(); ++i) n += fb.write_count()[i] != 0;
  return n;
}

TEST(Rasterizer, SquareWithCornersOnPixelCentresOwnsTopAndLeftEdgesOnly) {
  // Corners at pixel centres (2.5, 2.5) .. (6.5, 6.5): the centres on the top and left edges
  // belong to the square, those on the bottom and right edges do not: 4 x 4 pixels.
  Framebuffer fb(10, 10, true);
  Rasterizer raster(fb, {}, nullptr);
  raster.draw(at(2.5f, 2.5f), at(6.5f, 2.5f), at(2.5f, 6.5f), {});
  raster.draw(at(6.5f, 2.5f), at(6.5f, 6.5f), at(2.5f, 6.5f), {});
  EXPECT_EQ(written(fb), 16u);
  for (int y = 0; y < 10; ++y)
    for (int x = 0; x < 10; ++x)
      EXPECT_EQ(fb.write_count()[y * 10 + x], (x >= 2 && x <= 5 && y >= 2 && y <= 5) ? 1 : 0) << x << "," << y;
  EXPECT_EQ(raster.stats().fragments, 16u);
}

TEST(Rasterizer, WindingDoesNotChangeCoverage) {
  Framebuffer a(16, 16, true), b(16, 16, true);
  Rasterizer ra(a, {}, nullptr), rb(b, {}, nullptr);
  ra.draw(at(1.5f, 1.5f), at(13.5f, 4.5f), at(5.5f, 14.5f), {});
  rb.draw(at(1.5f, 1.5f), at(5.5f, 14.5f), at(13.5f, 4.5f), {});
  for (int i = 0; i < 256; ++i) EXPECT_EQ(a.write_count()[i], b.write_count()[i]);
  EXPECT_GT(written(a), 50u);
}

// Exact point-in-convex-polygon test on the 1/256 grid the rasterizer snaps to: +1 strictly
// inside, 0 on the boundary, -1 outside.
int classify(const std::vector<std::pair<std::int64_t, std::int64_t>>& polygon, std::int64_t px, std::int64_t py) {
  bool on_boundary = false;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const auto [ax, ay] = polygon[i];
    const auto [bx, by] = polygon[(i + 1) % polygon.size()];
    const std::int64_t cross = (bx - ax) * (py - ay) - (by - ay) * (px - ax);
    if (cross < 0) return -1;
    if (cross == 0) on_boundary = true;
  }
  return on_boundary ? 0 : 1;
}

TEST(Rasterizer, FanOf200TrianglesHasNoCrackAndNoDoubleWrite) {
  // 200 thin triangles around one vertex on a pixel centre; outer vertices on a circle, snapped
  // to the 1/256 grid, so many edges pass through pixel centres at odd slopes.
  const int size = 128, n = 200;
  Framebuffer fb(size, size, true);
  Rasterizer raster(fb, {}, nullptr);
  const float cx = 64.5f, cy = 64.5f, radius = 60.0f;
  std::vector<std::pair<std::int64_t, std::int64_t>> polygon;  // counter-clockwise in image space
  std::vector<RasterVertex> rim;
  for (int i = 0; i < n; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / n;
    const float x = std::round(static_cast<float>(cx + radius * std::cos(angle)) * 256.0f) / 256.0f;
    const float y = std::round(static_cast<float>(cy + radius * std::sin(angle)) * 256.0f) / 256.0f;
    rim.push_back(at(x, y));
    polygon.emplace_back(std::llround(x * 256.0), std::llround(y * 256.0));
  }
  for (int i = 0; i < n; ++i) raster.draw(at(cx, cy), rim[i], rim[(i + 1) % n], {});

  std::uint64_t cracks = 0, doubles = 0, inside = 0, outside_written = 0, on_edge_centres = 0;
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const int count = fb.write_count()[y * size + x];
      const int where = classify(polygon, x * 256 + 128, y * 256 + 128);
      if (count > 1) ++doubles;
      if (where > 0) {
        ++inside;
        if (count == 0) ++cracks;
      }
      if (where < 0 && count != 0) ++outside_written;
      on_edge_centres += fb.centre_on_edge()[y * size + x];
    }
  }
  EXPECT_EQ(cracks, 0u);
  EXPECT_EQ(doubles, 0u);
  EXPECT_EQ(outside_written, 0u);
  EXPECT_GT(inside, 11000u);  // pi * 60^2 = 11310
  // The centre vertex is on a pixel centre: every one of the 200 triangles touches it.
  EXPECT_GE(on_edge_centres, 1u);
  EXPECT_EQ(fb.write_count()[64 * size + 64], 1);
}

TEST(Rasterizer, DepthTestKeepsTheNearerTriangleWhateverTheOrder) {
  for (int order = 0; order < 2; ++order) {
    Framebuffer fb(8, 8);
    fb.clear(glm::vec4(0.0f));
    Rasterizer raster(fb, {}, nullptr);
    RasterVertex near_v[3] = {at(0, 0, 0.25f), at(8, 0, 0.25f), at(0, 8, 0.25f)};
    RasterVertex far_v[3] = {at(0, 0, 0.75f), at(8, 0, 0.75f), at(0, 8, 0.75f)};
    for (auto& v : near_v) v.colour = glm::vec4(1, 0, 0, 1);
    for (auto& v : far_v) v.colour = glm::vec4(0, 0, 1, 1);
    if (order == 0) {
      raster.draw(near_v[0], near_v[1], near_v[2], {});
      raster.draw(far_v[0], far_v[1], far_v[2], {});
    } else {
      raster.draw(far_v[0], far_v[1], far_v[2], {});
      raster.draw(near_v[0], near_v[1], near_v[2], {});
    }
    EXPECT_EQ(fb.colour()[0], 255);
    EXPECT_EQ(fb.colour()[2], 0);
    EXPECT_FLOAT_EQ(fb.depth()[0], 0.25f);
    // 28 centres each (x + y <= 6); the 8 on the hypotenuse belong to a bottom-right edge.
    EXPECT_EQ(raster.stats().fragments, 56u);
    EXPECT_EQ(raster.stats().fragments_passed, order == 0 ? 28u : 56u);
  }
}

TEST(Rasterizer, PerspectiveCorrectInterpolationMatchesTheProjectedAttribute) {
  // A triangle whose right vertex is 4 times farther away (w = 4): at the pixel whose screen x is
  // a fraction f of the way, the attribute is (f / 4) / ((1 - f) + f / 4), not f.
  Framebuffer fb(64, 4);
  fb.clear(glm::vec4(0.0f));
  Rasterizer raster(fb, {}, nullptr);
  RasterVertex a = at(0.0f, 0.0f), b = at(64.0f, 0.0f), c = at(0.0f, 64.0f);
  a.inv_w = c.inv_w = 1.0f;
  b.inv_w = 0.25f;
  a.colour = c.colour = glm::vec4(0, 0, 0, 1);
  b.colour = glm::vec4(1, 0, 0, 1);
  raster.draw(a, b, c, {});
  for (int x : {8, 16, 31, 47}) {
    // Along row 0, c's weight is 0.5/64; solve with all three weights.
    const float l1 = (x + 0.5f) / 64.0f, l2 = 0.5f / 64.0f, l0 = 1.0f - l1 - l2;
    const float q = l0 * 1.0f + l1 * 0.25f + l2 * 1.0f;
    const float expected = (l1 * 0.25f) / q;
    EXPECT_NEAR(fb.colour()[x * 4] / 255.0f, expected, 0.5f / 255.0f + 1e-6f) << x;
  }
}

TEST(Rasterizer, ScanlineAndTiledOrdersDrawTheSameImageFromTheSameTexelsInADifferentOrder) {
  Texture texture;
  texture.levels = build_mip_chain(make_checker(64, 8));
  RasterOptions scanline, tiled;
  tiled.traversal = Traversal::Tiled8;
  Framebuffer fa(48, 48), fb(48, 48);
  MemorySink sa, sb;
  Rasterizer ra(fa, scanline, &sa), rb(fb, tiled, &sb);
  RasterVertex v[3] = {at(1.0f, 2.0f), at(47.0f, 9.0f), at(12.0f, 46.0f)};
  v[1].uv = glm::vec2(2.0f, 0.0f);
  v[2].uv = glm::vec2(0.0f, 2.0f);
  TriangleState state;
  state.texture = &texture;
  state.texture_id = 3;
  state.triangle = 7;
  ra.draw(v[0], v[1], v[2], state);
  rb.draw(v[0], v[1], v[2], state);
  ra.flush();
  rb.flush();
  EXPECT_TRUE(std::equal(fa.colour(), fa.colour() + 48 * 48 * 4, fb.colour()));
  ASSERT_EQ(sa.texels.size(), sb.texels.size());
  ASSERT_EQ(sa.texels.size(), ra.stats().texel_reads);
  auto key = [](const TexelAccess& t) { return std::tuple(t.pixel_y, t.pixel_x, t.level, t.y, t.x); };
  std::multiset<std::tuple<int, int, int, unsigned, unsigned>> ka, kb;
  for (const auto& t : sa.texels) ka.insert(key(t));
  for (const auto& t : sb.texels) kb.insert(key(t));
  EXPECT_EQ(ka, kb);
  EXPECT_EQ(sa.texels.front().texture, 3u);
  EXPECT_EQ(sa.texels.front().triangle, 7u);
  // Trilinear minification here: 8 reads per fragment, or 4 where lambda <= 0.
  EXPECT_GE(sa.texels.size(), 4 * ra.stats().fragments_passed);
  EXPECT_LE(sa.texels.size(), 8 * ra.stats().fragments_passed);
  // Tiled: the pixels of the first 8x8 tile come before any pixel of another tile.
  const int tile_x = sb.texels.front().pixel_x / 8, tile_y = sb.texels.front().pixel_y / 8;
  bool left_tile = false, order_ok = true;
  for (const auto& t : sb.texels) {
    const bool in_tile = t.pixel_x / 8 == tile_x && t.pixel_y / 8 == tile_y;
    if (!in_tile)
      left_tile = true;
    else if (left_tile)
      order_ok = false;
  }
  EXPECT_TRUE(order_ok);
  // Scanline: pixel rows never go back up by more than the quad's own second row.
  bool monotone = true;
  for (std::size_t i = 1; i < sa.texels.size(); ++i)
    if (sa.texels[i].pixel_y / 2 < sa.texels[i - 1].pixel_y / 2) monotone = false;
  EXPECT_TRUE(monotone);
}

}  // namespace
}  // namespace rastrace
