// The write-back cache of the depth and colour buffers: read misses fetch, write misses allocate
// without fetching, dirty lines are written back when evicted or flushed.
#include <cstdint>
#include <random>

#include <gtest/gtest.h>

#include "cache_sim/byte_cache.h"
#include "cache_sim/write_back_cache.h"
#include "core/error.h"

namespace rastrace {
namespace {

TEST(WriteBackCache, ReadMissesFetchWriteMissesAllocateDirtyLinesAreWrittenBackOnce) {
  // 2 sets x 2 ways of 64-byte lines, LRU. Lines 0, 2, 4 share set 0.
  WriteBackCache cache(CacheConfig{256, 64, 2, ReplacementPolicy::Lru, 1});
  cache.read(0);   // miss, fetch
  cache.write(0);  // hit, dirty
  cache.write(2);  // miss, allocated dirty, no fetch
  cache.read(2);   // hit
  cache.read(4);   // miss, fetch; evicts line 0 (least recent), dirty: written back
  cache.read(0);   // miss, fetch; evicts line 2, dirty: written back
  cache.write(1);  // set 1: miss, dirty
  WriteBackStats s = cache.stats();
  EXPECT_EQ(s.reads, 4u);
  EXPECT_EQ(s.writes, 3u);
  EXPECT_EQ(s.read_misses, 3u);
  EXPECT_EQ(s.write_misses, 2u);
  EXPECT_EQ(s.lines_fetched, 3u);
  EXPECT_EQ(s.lines_written_back, 2u);
  cache.flush();  // line 1 is the only dirty line left
  cache.flush();  // nothing dirty: nothing more
  s = cache.stats();
  EXPECT_EQ(s.lines_written_back, 3u);
  EXPECT_EQ(s.bytes_read, 3u * 64u);
  EXPECT_EQ(s.bytes_written, 3u * 64u);
}

TEST(WriteBackCache, ReadOnlyStreamsMissExactlyAsTheByteCacheDoes) {
  std::mt19937_64 rng(7);
  std::vector<std::uint64_t> lines(20000);
  for (std::uint64_t& line : lines) line = rng() % 300;
  for (const ReplacementPolicy policy : {ReplacementPolicy::Fifo, ReplacementPolicy::Lru, ReplacementPolicy::Random})
    for (const std::uint32_t assoc : {1u, 4u, 0u}) {
      const CacheConfig config{4096, 64, assoc, policy, 3};
      WriteBackCache write_back(config);
      ByteCache reference(config);
      for (const std::uint64_t line : lines) {
        write_back.read(line);
        reference.access_line(line);
      }
      EXPECT_EQ(write_back.stats().read_misses, reference.misses()) << describe(config);
      EXPECT_EQ(write_back.stats().lines_written_back, 0u);
    }
}

TEST(WriteBackCache, RefusesOptAndBadGeometry) {
  EXPECT_THROW(WriteBackCache(CacheConfig{4096, 64, 4, ReplacementPolicy::Opt, 1}), InputError);
  EXPECT_THROW(WriteBackCache(CacheConfig{4096, 48, 4, ReplacementPolicy::Lru, 1}), InputError);
}

}  // namespace
}  // namespace rastrace
