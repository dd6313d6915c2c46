// The O(1) LRU (and the timestamp FIFO) post-transform cache against the naive reference
// (tests/cache_sim/naive_cache.h: a fully associative cache of k one-byte lines is a k-entry
// vertex cache), on random and adversarial streams, for cache sizes from 1 to beyond the number
// of distinct vertices, with clears in between as the pipeline does per draw.
#include <algorithm>
#include <cstdint>
#include <random>
#include <string>
#include <vector>

#include <gtest/gtest.h>

#include "cache_sim/vertex_cache.h"
#include "tests/cache_sim/naive_cache.h"

namespace rastrace {
namespace {

struct Stream {
  std::string name;
  std::vector<std::uint32_t> vertices;
};

std::vector<Stream> streams() {
  std::vector<Stream> out;
  std::mt19937 rng(7);
  for (const std::uint32_t distinct : {1u, 2u, 3u, 17u, 300u}) {
    Stream s{"uniform over " + std::to_string(distinct), {}};
    std::uniform_int_distribution<std::uint32_t> pick(0, distinct - 1);
    for (int i = 0; i < 3000; ++i) s.vertices.push_back(pick(rng));
    out.push_back(s);
  }
  {
    // A random walk: mesh-like locality, hits at every depth of the recency list.
    Stream s{"random walk", {}};
    std::int64_t v = 500;
    std::uniform_int_distribution<int> step(-6, 6);
    for (int i = 0; i < 6000; ++i) {
      v = std::clamp<std::int64_t>(v + step(rng), 0, 999);
      s.vertices.push_back(static_cast<std::uint32_t>(v));
    }
    out.push_back(s);
  }
  for (const std::uint32_t period : {2u, 5u, 16u, 17u, 64u, 65u}) {
    // Cycling through period vertices: LRU's worst case when period = k + 1 (every access
    // misses), all hits after the first round when period <= k.
    Stream s{"cycle of " + std::to_string(period), {}};
    for (int i = 0; i < 2000; ++i) s.vertices.push_back(static_cast<std::uint32_t>(i) % period);
    out.push_back(s);
  }
  {
    Stream s{"sawtooth 0..99..0", {}};
    for (int r = 0; r < 10; ++r) {
      for (std::uint32_t v = 0; v < 100; ++v) s.vertices.push_back(v);
      for (std::uint32_t v = 100; v-- > 0;) s.vertices.push_back(v);
    }
    out.push_back(s);
  }
  {
    // Sparse, large ids (the per-vertex index grows) and a hot vertex hit between them.
    Stream s{"sparse ids with a hot vertex", {}};
    std::uniform_int_distribution<std::uint32_t> pick(0, 40);
    for (int i = 0; i < 3000; ++i) s.vertices.push_back(i % 3 == 0 ? 7u : 100000u + 9973u * pick(rng));
    out.push_back(s);
  }
  return out;
}

// Misses of the cache over the stream, cleared every `clear_every` accesses (0: never).
std::uint64_t cache_misses(VertexCachePolicy policy, unsigned k, const std::vector<std::uint32_t>& stream,
                           std::size_t clear_every) {
  VertexCache cache(policy, k);
  std::uint64_t misses = 0;
  for (std::size_t i = 0; i < stream.size(); ++i) {
    if (clear_every && i % clear_every == 0) cache.clear();
    misses += !cache.access(stream[i]);
  }
  return misses;
}

std::uint64_t reference_misses(const std::string& policy, unsigned k, const std::vector<std::uint32_t>& stream,
                               std::size_t clear_every) {
  std::uint64_t misses = 0;
  const std::size_t segment = clear_every ? clear_every : stream.size();
  for (std::size_t begin = 0; begin < stream.size(); begin += segment) {
    std::vector<std::uint64_t> addresses(
        stream.begin() + static_cast<std::ptrdiff_t>(begin),
        stream.begin() + static_cast<std::ptrdiff_t>(std::min(begin + segment, stream.size())));
    misses += testing::naive_misses(addresses, k, 1, 0, policy);
  }
  return misses;
}

TEST(VertexCacheLru, MissesEqualTheNaiveReferenceForEveryStreamAndSize) {
  for (const Stream& s : streams()) {
    for (const unsigned k : {1u, 2u, 3u, 4u, 5u, 8u, 15u, 16u, 17u, 32u, 64u, 65u, 100u, 1000u, 5000u}) {
      for (const std::size_t clear_every : {std::size_t{0}, std::size_t{97}}) {
        EXPECT_EQ(cache_misses(VertexCachePolicy::Lru, k, s.vertices, clear_every),
                  reference_misses("lru", k, s.vertices, clear_every))
            << s.name << ", LRU " << k << ", clear every " << clear_every;
        EXPECT_EQ(cache_misses(VertexCachePolicy::Fifo, k, s.vertices, clear_every),
                  reference_misses("fifo", k, s.vertices, clear_every))
            << s.name << ", FIFO " << k << ", clear every " << clear_every;
      }
    }
  }
}

TEST(VertexCacheLru, AdversarialCyclesGiveTheTextbookMissCounts) {
  // 2000 accesses cycling through k + 1 vertices: LRU misses every one. Through k: only the
  // first round misses.
  for (const unsigned k : {1u, 2u, 16u, 64u}) {
    std::vector<std::uint32_t> over, fits;
    for (std::uint32_t i = 0; i < 2000; ++i) {
      over.push_back(i % (k + 1));
      fits.push_back(i % k);
    }
    EXPECT_EQ(cache_misses(VertexCachePolicy::Lru, k, over, 0), 2000u) << k;
    EXPECT_EQ(cache_misses(VertexCachePolicy::Lru, k, fits, 0), k) << k;
  }
}

TEST(VertexCacheLru, TheLargestCacheTheCommandLineAcceptsStartsSmall) {
  // 2^20 entries: slots are allocated as vertices arrive, so a short stream stays cheap.
  VertexCache cache(VertexCachePolicy::Lru, 1u << 20);
  std::uint64_t misses = 0;
  for (std::uint32_t r = 0; r < 3; ++r)
    for (std::uint32_t v = 0; v < 5000; ++v) misses += !cache.access(v * 31u);
  EXPECT_EQ(misses, 5000u);
  cache.clear();
  EXPECT_FALSE(cache.access(0));
  EXPECT_TRUE(cache.access(0));
}

}  // namespace
}  // namespace rastrace
