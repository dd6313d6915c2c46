#include <random>

#include <gtest/gtest.h>

#include "cache_sim/byte_cache.h"
#include "cache_sim/cache_spec.h"
#include "cache_sim/cache_hierarchy.h"
#include "cache_sim/sectored_cache.h"
#include "core/error.h"
#include "naive_hierarchy.h"

namespace rastrace {
namespace {

using testing::NaiveHierarchy;
using testing::NaiveLevel;
using testing::NaiveLevelStats;
using testing::NaiveSectoredCache;

struct NamedTrace {
  std::string name;
  std::vector<std::uint64_t> addresses;
};

// Random and adversarial byte-address traces.
std::vector<NamedTrace> traces() {
  std::vector<NamedTrace> out;
  std::mt19937_64 rng(2024);
  {
    NamedTrace t{"uniform", {}};
    for (int i = 0; i < 1200; ++i) t.addresses.push_back(rng() % 16384);
    out.push_back(t);
  }
  {
    NamedTrace t{"hot-and-cold", {}};  // a texture footprint: a hot block and a long tail
    for (int i = 0; i < 1200; ++i) t.addresses.push_back(rng() % 4 ? rng() % 2048 : rng() % 131072);
    out.push_back(t);
  }
  {
    NamedTrace t{"sector-walk", {}};  // every sector of a line in turn, lines just over capacity
    for (int r = 0; r < 12; ++r)
      for (std::uint64_t a = 0; a < 5000; a += 32) t.addresses.push_back(a);
    out.push_back(t);
  }
  {
    NamedTrace t{"same-set", {}};  // lines that all map to one set of a 4 KiB cache
    for (int r = 0; r < 40; ++r)
      for (std::uint64_t k = 0; k < 9; ++k) t.addresses.push_back(k * 4096 + (r % 4) * 32);
    out.push_back(t);
  }
  {
    NamedTrace t{"scan-then-reuse", {}};
    for (std::uint64_t a = 0; a < 12000; a += 8) t.addresses.push_back(a);
    for (int i = 0; i < 800; ++i) t.addresses.push_back(rng() % 3000);
    out.push_back(t);
  }
  return out;
}

CacheConfig config(std::uint64_t size, std::uint32_t line, std::uint32_t assoc, ReplacementPolicy policy) {
  CacheConfig c;
  c.size_bytes = size;
  c.line_bytes = line;
  c.assoc = assoc;
  c.policy = policy;
  return c;
}

void expect_level(const LevelStats& fast, const NaiveLevelStats& naive, const std::string& where) {
  EXPECT_EQ(fast.accesses, naive.accesses) << where;
  EXPECT_EQ(fast.misses, naive.misses) << where;
  EXPECT_EQ(fast.line_misses, naive.line_misses) << where;
  EXPECT_EQ(fast.bytes_requested, naive.bytes_requested) << where;
  EXPECT_EQ(fast.bytes_fetched, naive.bytes_fetched) << where;
  EXPECT_EQ(fast.invalidations, naive.invalidations) << where;
}

TEST(SectoredCache, CountsLineAndSectorMissesByHand) {
  // 128-byte lines of four 32-byte sectors: 0 allocates the line and fetches sector 0, 32 and 96
  // fetch their sectors into the resident line, 0 and 40 hit.
  SectoredCache cache(config(1024, 128, 2, ReplacementPolicy::Lru), 32);
  for (const std::uint64_t a : {0, 32, 0, 96, 40}) cache.access(a);
  EXPECT_EQ(cache.accesses(), 5u);
  EXPECT_EQ(cache.misses(), 3u);
  EXPECT_EQ(cache.line_misses(), 1u);
  EXPECT_EQ(cache.bytes_fetched(), 96u);  // three sectors, not three lines (384 bytes)
}

TEST(SectoredCache, MatchesTheNaiveReferenceOnRandomAndAdversarialTraces) {
  const ReplacementPolicy policies[] = {ReplacementPolicy::Fifo, ReplacementPolicy::Lru, ReplacementPolicy::Random};
  int checked = 0;
  for (const NamedTrace& trace : traces())
    for (const ReplacementPolicy policy : policies)
      for (const std::uint32_t line : {64u, 128u})
        for (const std::uint32_t sector : {0u, 16u, 32u})
          for (const std::uint32_t assoc : {1u, 2u, 4u, 0u})  // 0: fully associative, 32 or 64 ways
            for (const std::uint64_t size : {2048u, 4096u}) {
              const CacheConfig c = config(size, line, assoc, policy);
              SectoredCache fast(c, sector);
              NaiveSectoredCache naive(size, line, assoc, to_string(policy), sector);
              for (const std::uint64_t a : trace.addresses) {
                const bool hit = fast.access(a).hit;
                ASSERT_EQ(hit, naive.access(a).hit) << trace.name << " " << describe(c) << " sector " << sector;
              }
              EXPECT_EQ(fast.misses(), naive.stats.misses);
              EXPECT_EQ(fast.line_misses(), naive.stats.line_misses);
              EXPECT_EQ(fast.bytes_fetched(), naive.stats.bytes_fetched);
              ++checked;
            }
  EXPECT_EQ(checked, 5 * 3 * 2 * 3 * 4 * 2);
}

TEST(SectoredCache, OneSectorPerLineIsThePlainCacheAccessByAccess) {
  const ReplacementPolicy policies[] = {ReplacementPolicy::Fifo, ReplacementPolicy::Lru, ReplacementPolicy::Random};
  for (const NamedTrace& trace : traces())
    for (const ReplacementPolicy policy : policies)
      for (const std::uint32_t assoc : {1u, 4u, 0u}) {
        const CacheConfig c = config(4096, 64, assoc, policy);
        SectoredCache sectored(c, 64);
        ByteCache plain(c);
        for (const std::uint64_t a : trace.addresses)
          ASSERT_EQ(sectored.access(a).hit, plain.access(a)) << trace.name << " " << describe(c);
        EXPECT_EQ(sectored.misses(), plain.misses());
        EXPECT_EQ(sectored.line_misses(), plain.misses());
        EXPECT_EQ(sectored.bytes_fetched(), plain.stats().bytes_fetched);
      }
}

TEST(SectoredCache, LineMissesAreThePlainCacheMissesWhateverTheSectors) {
  // Replacement decisions see lines only, so sectoring changes what a miss fetches, never which
  // line is resident.
  const ReplacementPolicy policies[] = {ReplacementPolicy::Fifo, ReplacementPolicy::Lru, ReplacementPolicy::Random};
  for (const NamedTrace& trace : traces())
    for (const ReplacementPolicy policy : policies)
      for (const std::uint32_t sector : {8u, 32u}) {
        const CacheConfig c = config(4096, 128, 2, policy);
        SectoredCache sectored(c, sector);
        ByteCache plain(c);
        for (const std::uint64_t a : trace.addresses) {
          sectored.access(a);
          plain.access(a);
        }
        EXPECT_EQ(sectored.line_misses(), plain.misses()) << trace.name << " " << describe(c);
        EXPECT_GE(sectored.misses(), plain.misses());
        EXPECT_LE(sectored.bytes_fetched(), plain.stats().bytes_fetched);
      }
}

TEST(SectoredCache, RefusesBadSectorsAndOpt) {
  EXPECT_THROW(SectoredCache(config(4096, 64, 4, ReplacementPolicy::Lru), 128), InputError);
  EXPECT_THROW(SectoredCache(config(4096, 64, 4, ReplacementPolicy::Lru), 24), InputError);
  EXPECT_THROW(SectoredCache(config(65536, 1024, 4, ReplacementPolicy::Lru), 8), InputError);  // 128 sectors
  EXPECT_THROW(SectoredCache(config(4096, 64, 4, ReplacementPolicy::Opt), 0), InputError);
}

// A random hierarchy: 1-3 levels, sectors or not, 1-4 units, inclusive or not.
struct RandomHierarchy {
  HierarchyConfig fast;
  std::vector<NaiveLevel> naive;
};

RandomHierarchy random_hierarchy(std::mt19937_64& rng) {
  const ReplacementPolicy policies[] = {ReplacementPolicy::Fifo, ReplacementPolicy::Lru, ReplacementPolicy::Random};
  RandomHierarchy h;
  const std::size_t levels = 1 + rng() % 3;
  std::uint64_t size = 512u << (rng() % 2);
  for (std::size_t k = 0; k < levels; ++k) {
    const std::uint32_t line = 32u << (rng() % 3);  // 32..128
    constexpr std::uint32_t kAssocs[] = {1, 2, 4, 0};
    const std::uint32_t assoc = kAssocs[rng() % 4];
    const ReplacementPolicy policy = policies[rng() % 3];
    const std::uint32_t sector = rng() % 2 ? 0u : std::max(8u, line >> (1 + rng() % 2));
    h.fast.levels.push_back({config(size, line, assoc, policy), sector});
    h.naive.push_back({size, line, assoc, to_string(policy), sector});
    size *= 2 + rng() % 3;
  }
  h.fast.units = 1 + static_cast<std::uint32_t>(rng() % 4);
  h.fast.inclusion = rng() % 2 ? Inclusion::Inclusive : Inclusion::NonInclusive;
  h.fast.element_bytes = 4;
  return h;
}

TEST(CacheHierarchy, MatchesTheNaiveReferenceOnRandomHierarchiesAndTraces) {
  std::mt19937_64 rng(77);
  int checked = 0, inclusive_with_invalidations = 0, multi_unit = 0;
  for (int round = 0; round < 60; ++round) {
    const RandomHierarchy h = random_hierarchy(rng);
    for (const NamedTrace& trace : traces()) {
      CacheHierarchy fast(h.fast);
      NaiveHierarchy naive(h.naive, h.fast.units, h.fast.inclusion == Inclusion::Inclusive);
      std::mt19937_64 units(round);
      for (const std::uint64_t a : trace.addresses) {
        const std::uint32_t unit = static_cast<std::uint32_t>(units() % h.fast.units);
        fast.access(a, unit);
        naive.access(a, unit);
      }
      const std::vector<LevelStats> got = fast.stats();
      const std::vector<NaiveLevelStats> want = naive.stats();
      ASSERT_EQ(got.size(), want.size());
      for (std::size_t k = 0; k < got.size(); ++k)
        expect_level(got[k], want[k], trace.name + " " + describe(h.fast) + " level " + std::to_string(k + 1));
      inclusive_with_invalidations += got.front().invalidations > 0;
      multi_unit += h.fast.units > 1;
      ++checked;
    }
  }
  EXPECT_EQ(checked, 300);
  EXPECT_GT(inclusive_with_invalidations, 10);  // back-invalidation was exercised
  EXPECT_GT(multi_unit, 100);
}

TEST(CacheHierarchy, AnL1OfOneLineInFrontOfL2EqualsTheL2Alone) {
  const ReplacementPolicy policies[] = {ReplacementPolicy::Fifo, ReplacementPolicy::Lru, ReplacementPolicy::Random};
  for (const NamedTrace& trace : traces())
    for (const ReplacementPolicy policy : policies)
      for (const Inclusion inclusion : {Inclusion::NonInclusive, Inclusion::Inclusive}) {
        const CacheConfig l2 = config(4096, 64, 4, policy);
        HierarchyConfig h;
        h.levels = {{config(64, 64, 0, ReplacementPolicy::Lru), 0}, {l2, 0}};
        h.inclusion = inclusion;
        CacheHierarchy hierarchy(h);
        ByteCache alone(l2);
        for (const std::uint64_t a : trace.addresses) {
          hierarchy.access(a, 0);
          alone.access(a);
        }
        const std::vector<LevelStats> s = hierarchy.stats();
        EXPECT_EQ(s[1].misses, alone.misses()) << trace.name << " " << to_string(policy);
        EXPECT_EQ(s[1].bytes_fetched, alone.stats().bytes_fetched);
        // The L2 sees exactly the accesses that change line: the L1 hits are the repeats.
        EXPECT_EQ(s[0].misses, s[1].accesses);
      }
}

TEST(CacheHierarchy, BytesFlowDownAsGranules) {
  // L1: 128-byte lines unsectored; L2: 32-byte sectors. One L1 miss asks the L2 for 128 bytes,
  // four sector accesses, all missing on a cold L2: 4 sector misses, 1 line miss.
  HierarchyConfig h;
  h.levels = {{config(1024, 128, 2, ReplacementPolicy::Lru), 0}, {config(8192, 128, 4, ReplacementPolicy::Lru), 32}};
  CacheHierarchy hierarchy(h);
  hierarchy.access(200, 0);
  const std::vector<LevelStats> s = hierarchy.stats();
  EXPECT_EQ(s[0].bytes_requested, 4u);
  EXPECT_EQ(s[0].bytes_fetched, 128u);
  EXPECT_EQ(s[1].accesses, 4u);
  EXPECT_EQ(s[1].misses, 4u);
  EXPECT_EQ(s[1].line_misses, 1u);
  EXPECT_EQ(s[1].bytes_requested, 128u);
  EXPECT_EQ(s[1].bytes_fetched, 128u);
  EXPECT_DOUBLE_EQ(s[0].byte_miss_ratio(), 32.0);
}

TEST(CacheHierarchy, ScreenTilesAreDealtOutToUnits) {
  EXPECT_EQ(CacheHierarchy::unit_of_pixel(0, 0, 16, 4), 0u);
  EXPECT_EQ(CacheHierarchy::unit_of_pixel(15, 15, 16, 4), 0u);
  EXPECT_EQ(CacheHierarchy::unit_of_pixel(16, 0, 16, 4), 1u);
  EXPECT_EQ(CacheHierarchy::unit_of_pixel(0, 16, 16, 4), 1u);
  EXPECT_EQ(CacheHierarchy::unit_of_pixel(48, 16, 16, 4), 0u);
  EXPECT_EQ(CacheHierarchy::unit_of_pixel(100, 100, 16, 1), 0u);
}

TEST(CacheHierarchy, NamesTheBadLevel) {
  HierarchyConfig h;
  h.levels = {{config(1024, 64, 2, ReplacementPolicy::Lru), 0}, {config(1000, 64, 2, ReplacementPolicy::Lru), 0}};
  try {
    CacheHierarchy hierarchy(h);
    FAIL() << "expected an InputError";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("L2: "), std::string::npos) << e.what();
  }
  h.levels.clear();
  EXPECT_THROW(CacheHierarchy{h}, InputError);
}

TEST(CacheSpecSectors, SectorIsAKeyWithAlternativesThatReplayTakesAndSweepAndRenderRefuse) {
  const CacheSpec spec = parse_cache_spec("size=16KiB,line=128B,sector=32B/64B,assoc=4", "--cache");
  EXPECT_EQ(spec.combinations(), 2u);
  const std::vector<ByteCacheChoice> caches = byte_caches(spec);
  ASSERT_EQ(caches.size(), 2u);
  EXPECT_EQ(caches[0].sector_bytes, 32u);
  EXPECT_EQ(caches[1].sector_bytes, 64u);
  EXPECT_EQ(caches[0].cache.line_bytes, 128u);
  EXPECT_EQ(byte_caches(parse_cache_spec("size=16KiB", "--cache")).front().sector_bytes, 0u);  // unsectored
  EXPECT_THROW(sweep_spec(spec, SweepSource::Texel), InputError);
  EXPECT_THROW(parse_byte_cache("size=16KiB,line=128B,sector=32B", "--tcache"), InputError);
  EXPECT_THROW(parse_cache_spec("size=16KiB,sector=0B", "--cache"), InputError);
  EXPECT_THROW(parse_cache_spec("source=depth,size=16KiB,sector=32B", "--cache"), InputError);
}

}  // namespace
}  // namespace rastrace
