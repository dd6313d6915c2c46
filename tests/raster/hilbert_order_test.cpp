// The Hilbert tile order (raster/hilbert_order.h) and the rasterizer's hilbert traversal.
#include <algorithm>
#include <set>
#include <tuple>

#include <gtest/gtest.h>

#include "raster/hilbert_order.h"
#include "raster/rasterizer.h"
#include "scenes/texture_io.h"
#include "traces/memory_sink.h"

namespace rastrace {
namespace {

TEST(HilbertOrder, EveryCellOnceAndConsecutiveCellsShareAnEdge) {
  for (unsigned bits = 0; bits <= 5; ++bits) {
    const std::uint32_t side = 1u << bits;
    std::vector<std::pair<std::uint64_t, std::pair<int, int>>> cells;
    for (std::uint32_t y = 0; y < side; ++y)
      for (std::uint32_t x = 0; x < side; ++x) cells.push_back({hilbert_index(x, y, bits), {int(x), int(y)}});
    std::sort(cells.begin(), cells.end());
    for (std::size_t d = 0; d < cells.size(); ++d) ASSERT_EQ(cells[d].first, d) << "bits " << bits;
    for (std::size_t d = 1; d < cells.size(); ++d) {
      const int dx = std::abs(cells[d].second.first - cells[d - 1].second.first);
      const int dy = std::abs(cells[d].second.second - cells[d - 1].second.second);
      ASSERT_EQ(dx + dy, 1) << "bits " << bits << " step " << d;
    }
    EXPECT_EQ(cells.front().second, std::make_pair(0, 0));
    EXPECT_EQ(cells.back().second, std::make_pair(int(side) - 1, 0));
  }
  EXPECT_EQ(hilbert_bits(1, 1), 0u);
  EXPECT_EQ(hilbert_bits(64, 33), 6u);
  EXPECT_EQ(hilbert_bits(65, 2), 7u);
}

TEST(HilbertOrder, TilesOfABoxFollowTheScreenCurve) {
  std::vector<std::uint64_t> tiles;
  hilbert_tiles(1, 0, 2, 1, 2, tiles);  // a 2x2 box inside a 4x4 curve
  // The order-2 curve visits (0,0) (1,0) (1,1) (0,1) (0,2) (0,3) (1,3) (1,2) (2,2) (2,3) (3,3) (3,2)
  // (3,1) (2,1) (2,0) (3,0), so the box's tiles come as (1,0) (1,1) (2,1) (2,0).
  ASSERT_EQ(tiles.size(), 4u);
  EXPECT_EQ(tiles[0], (std::uint64_t{0} << 32) | 1);
  EXPECT_EQ(tiles[1], (std::uint64_t{1} << 32) | 1);
  EXPECT_EQ(tiles[2], (std::uint64_t{1} << 32) | 2);
  EXPECT_EQ(tiles[3], (std::uint64_t{0} << 32) | 2);
}

RasterVertex vertex(float x, float y, float u, float v) {
  RasterVertex r;
  r.x = x;
  r.y = y;
  r.z = 0.5f;
  r.uv = glm::vec2(u, v);
  return r;
}

TEST(HilbertOrder, HilbertTraversalDrawsTheTiledImageFromTheSameTexelsTileByTileAlongTheCurve) {
  Texture texture;
  texture.levels = build_mip_chain(make_checker(64, 8));
  RasterOptions tiled, hilbert;
  tiled.traversal = Traversal::Tiled8;
  hilbert.traversal = parse_traversal("hilbert");
  EXPECT_STREQ(to_string(hilbert.traversal), "hilbert");
  Framebuffer fa(64, 64), fb(64, 64);
  MemorySink sa, sb;
  Rasterizer ra(fa, tiled, &sa), rb(fb, hilbert, &sb);
  const RasterVertex v[3] = {vertex(1.0f, 2.0f, 0, 0), vertex(63.0f, 9.0f, 2, 0), vertex(12.0f, 62.0f, 0, 2)};
  TriangleState state;
  state.texture = &texture;
  ra.draw(v[0], v[1], v[2], state);
  rb.draw(v[0], v[1], v[2], state);
  ra.flush();
  rb.flush();
  EXPECT_TRUE(std::equal(fa.colour(), fa.colour() + 64 * 64 * 4, fb.colour()));
  ASSERT_EQ(sa.texels.size(), sb.texels.size());
  auto key = [](const TexelAccess& t) { return std::tuple(t.pixel_y, t.pixel_x, t.level, t.y, t.x); };
  std::multiset<std::tuple<int, int, int, unsigned, unsigned>> ka, kb;
  for (const auto& t : sa.texels) ka.insert(key(t));
  for (const auto& t : sb.texels) kb.insert(key(t));
  EXPECT_EQ(ka, kb);
  // Tiles come in non-decreasing curve order, and the orders differ from row-major.
  std::uint64_t last = 0;
  bool monotone = true;
  for (const auto& t : sb.texels) {
    const std::uint64_t d = hilbert_index(t.pixel_x / 8, t.pixel_y / 8, 3);
    monotone = monotone && d >= last;
    last = d;
  }
  EXPECT_TRUE(monotone);
  bool differs = false;
  for (std::size_t i = 0; i < sa.texels.size() && !differs; ++i) differs = key(sa.texels[i]) != key(sb.texels[i]);
  EXPECT_TRUE(differs);
}

}  // namespace
}  // namespace rastrace
