#include <vector>

#include <gtest/gtest.h>

#include "cache_sim/vertex_cache.h"
#include "scenes/procedural.h"

namespace rastrace {
namespace {

TEST(VertexCache, GridInScanlineOrderMatchesCastanoScanlineRow) {
  const Mesh grid = make_grid(16, 16);
  for (unsigned k : {12u, 16u, 20u}) {
    const VertexStreamStats stats =
        simulate_vertex_stream(grid.indices, PrimitiveType::TriangleList, VertexCachePolicy::Fifo, k);
    EXPECT_EQ(stats.triangles, 512u);
    EXPECT_EQ(stats.vertices, 289u);
    EXPECT_NEAR(stats.acmr(), 1.062, 0.0005) << "FIFO " << k;
    EXPECT_NEAR(stats.atvr(), 1.882, 0.0005) << "FIFO " << k;
  }
}

TEST(VertexCache, HoppeFifoAnomalyHasTwiceTheMissesAtFiveEntriesAsAtFour) {
  // Hoppe 1999: 6,1,7,2,4,6, then (1,2,3,4,5,6,7) repeated.
  std::vector<std::uint32_t> sequence = {6, 1, 7, 2, 4, 6};
  const std::vector<std::uint32_t> period = {1, 2, 3, 4, 5, 6, 7};
  const int repeats = 22;
  for (int r = 0; r < repeats; ++r) sequence.insert(sequence.end(), period.begin(), period.end());
  const auto periodic_misses = [&](unsigned k) {
    VertexCache cache(VertexCachePolicy::Fifo, k);
    std::uint64_t misses = 0;
    for (std::size_t i = 0; i < sequence.size(); ++i) {
      const bool hit = cache.access(sequence[i]);
      // Count the last 20 periods: in the limit a size-4 cache settles into a two-period cycle.
      if (i >= 6 + 2 * period.size() && !hit) ++misses;
    }
    return misses;
  };
  EXPECT_EQ(periodic_misses(5), 2 * periodic_misses(4));
}

TEST(VertexCache, LruKeepsRecentlyHitVertexThatFifoEvicts) {
  VertexCache fifo(VertexCachePolicy::Fifo, 2), lru(VertexCachePolicy::Lru, 2);
  for (std::uint32_t v : {1u, 2u, 1u, 3u}) {
    fifo.access(v);
    lru.access(v);
  }
  EXPECT_FALSE(fifo.access(1));  // FIFO evicted 1 (oldest insertion) when 3 came
  EXPECT_TRUE(lru.access(1));    // LRU evicted 2 (least recently used)
}

TEST(VertexCache, StripDegeneratesAreLookedUpButNotDrawn) {
  const std::vector<std::uint32_t> strip = {0, 1, 2, 3, 3, 4, 4, 5, 6};
  const VertexStreamStats stats =
      simulate_vertex_stream(strip, PrimitiveType::TriangleStrip, VertexCachePolicy::Fifo, 16);
  EXPECT_EQ(stats.lookups, 9u);
  EXPECT_EQ(stats.misses, 7u);
  EXPECT_EQ(stats.triangles + stats.degenerate, 7u);
  EXPECT_EQ(stats.degenerate, 4u);  // (2,3,3) (3,3,4) (3,4,4) (4,4,5)
  EXPECT_EQ(stats.triangles, 3u);
}

TEST(VertexCache, ZeroEntriesIsAnError) { EXPECT_THROW(VertexCache(VertexCachePolicy::Fifo, 0), std::exception); }

}  // namespace
}  // namespace rastrace
