// NVIDIA Mesh Tools' eviction-charged accounting against the strict FIFO miss count.
#include <algorithm>
#include <deque>
#include <random>
#include <vector>

#include <gtest/gtest.h>

#include "cache_sim/eviction_charged.h"
#include "cache_sim/vertex_cache.h"
#include "core/error.h"

namespace rastrace {
namespace {

std::uint64_t fifo_misses(const std::vector<std::uint32_t>& indices, unsigned entries) {
  return simulate_vertex_stream(indices, PrimitiveType::TriangleList, VertexCachePolicy::Fifo, entries).misses;
}

// The accounting rule written out on a deque, to check the timestamp implementation against.
std::uint64_t naive_charged(const std::vector<std::uint32_t>& indices, unsigned entries) {
  std::deque<std::uint32_t> fifo;  // oldest at the front
  const auto cached = [&](std::uint32_t v) { return std::find(fifo.begin(), fifo.end(), v) != fifo.end(); };
  std::uint64_t charged = 0;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    std::uint64_t absent = 0;
    for (std::size_t i = t; i < t + 3; ++i) absent += !cached(indices[i]);
    if (fifo.size() + absent > entries) charged += fifo.size() + absent - entries;
    for (std::size_t i = t; i < t + 3; ++i) {
      if (cached(indices[i])) continue;
      fifo.push_back(indices[i]);
      if (fifo.size() > entries) fifo.pop_front();
    }
  }
  return charged + fifo.size();
}

TEST(EvictionCharged, MatchesTheRuleWrittenOutOnRandomStreams) {
  std::mt19937 random(7);
  for (const unsigned entries : {3u, 4u, 8u, 16u, 32u}) {
    std::vector<std::uint32_t> indices;
    for (int i = 0; i < 12000; ++i) indices.push_back(random() % (i % 5 == 0 ? 20 : 200));  // some repeats
    EXPECT_EQ(eviction_charged_transforms(indices, PrimitiveType::TriangleList, entries),
              naive_charged(indices, entries))
        << entries << " entries";
  }
}

TEST(EvictionCharged, EqualsFifoMissesOnAGridInScanlineOrder) {
  // No triangle repeats a vertex or evicts one of its own: the counts agree (Castano's 544).
  std::vector<std::uint32_t> indices;
  for (std::uint32_t y = 0; y < 16; ++y)
    for (std::uint32_t x = 0; x < 16; ++x) {
      const std::uint32_t v = 17 * y + x;
      indices.insert(indices.end(), {v, v + 17, v + 1, v + 1, v + 17, v + 18});
    }
  for (const unsigned entries : {12u, 16u, 20u}) {
    EXPECT_EQ(fifo_misses(indices, entries), 544u);
    EXPECT_EQ(eviction_charged_transforms(indices, PrimitiveType::TriangleList, entries), 544u);
  }
}

TEST(EvictionCharged, VertexEvictedByItsOwnTriangleIsNotChargedAgain) {
  // Cache (oldest first) 0 1 2 3; triangle (9, 0, 8): inserting 9 evicts 0, which is then
  // inserted again. A strict FIFO counts 3 misses; the accounting charges only 2 evictions.
  const std::vector<std::uint32_t> stream = {0, 1, 2, 1, 2, 3, 9, 0, 8};
  EXPECT_EQ(fifo_misses(stream, 4), 7u);
  EXPECT_EQ(eviction_charged_transforms(stream, PrimitiveType::TriangleList, 4), 6u);
}

TEST(EvictionCharged, RepeatedMissingVertexIsChargedTwiceOnlyWhenTheCacheIsFull) {
  // Not full: (0, 0, 1) on an empty 4-entry cache costs two transforms either way.
  EXPECT_EQ(eviction_charged_transforms(std::vector<std::uint32_t>{0, 0, 1}, PrimitiveType::TriangleList, 4), 2u);
  // Full (0..3 cached), then (9, 9, 8): two vertices are inserted but three evictions are charged.
  const std::vector<std::uint32_t> full = {0, 1, 2, 1, 2, 3, 9, 9, 8};
  EXPECT_EQ(fifo_misses(full, 4), 6u);
  EXPECT_EQ(eviction_charged_transforms(full, PrimitiveType::TriangleList, 4), 7u);
}

TEST(EvictionCharged, StripsAreAssembledIntoTriangles) {
  // Strip 0 1 2 3 | restart | 4 5 6: triangles (0 1 2) (2 1 3) (4 5 6): 7 vertices, no repeats.
  const std::vector<std::uint32_t> strip = {0, 1, 2, 3, kStripRestart, 4, 5, 6};
  EXPECT_EQ(eviction_charged_transforms(strip, PrimitiveType::TriangleStrip, 16, kStripRestart), 7u);
}

TEST(EvictionCharged, StripSwapsAndJoinsAreNotCharged) {
  // A strip with swaps (repeated indices) and a join, on a cache too small to hide them: charged
  // exactly as the list of the triangles it draws.
  const std::vector<std::uint32_t> strip = {0, 1, 2, 3, 3, 2, 4, 5, 5, 9, 9, 8, 10, 11, 12, 13};
  std::vector<std::uint32_t> drawn;
  for_each_triangle(strip, PrimitiveType::TriangleStrip, kNoRestart,
                    [&](std::uint32_t a, std::uint32_t b, std::uint32_t c) {
                      if (a != b && b != c && a != c) drawn.insert(drawn.end(), {a, b, c});
                    });
  ASSERT_EQ(drawn.size(), 3u * 8u);  // 14 assembled, 6 of them degenerate
  for (const unsigned entries : {3u, 4u, 6u})
    EXPECT_EQ(eviction_charged_transforms(strip, PrimitiveType::TriangleStrip, entries, kNoRestart),
              eviction_charged_transforms(drawn, PrimitiveType::TriangleList, entries))
        << entries << " entries";
}

TEST(EvictionCharged, ZeroEntriesIsAnError) {
  EXPECT_THROW(eviction_charged_transforms(std::vector<std::uint32_t>{0, 1, 2}, PrimitiveType::TriangleList, 0),
               InputError);
}

}  // namespace
}  // namespace rastrace
