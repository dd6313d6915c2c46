#include <random>

#include <gtest/gtest.h>

#include "cache_sim/byte_cache.h"
#include "cache_sim/live_bank_sink.h"
#include "cache_sim/lru_profile.h"
#include "cache_sim/opt_cache.h"
#include "cache_sim/vertex_cache.h"
#include "core/error.h"
#include "naive_cache.h"

namespace rastrace {
namespace {

using testing::naive_compulsory;
using testing::naive_misses;

struct NamedTrace {
  std::string name;
  std::vector<std::uint64_t> addresses;
};

// Random and adversarial address traces (byte addresses).
std::vector<NamedTrace> traces() {
  std::vector<NamedTrace> out;
  std::mt19937_64 rng(12345);
  {
    NamedTrace t{"uniform", {}};
    for (int i = 0; i < 1500; ++i) t.addresses.push_back(rng() % 8192);
    out.push_back(t);
  }
  {
    NamedTrace t{"skewed", {}};  // hot set plus a cold tail, as texture footprints look
    for (int i = 0; i < 1500; ++i) t.addresses.push_back(rng() % 4 ? rng() % 1024 : rng() % 65536);
    out.push_back(t);
  }
  {
    NamedTrace t{"loop-one-too-many", {}};  // LRU's and FIFO's worst case: a loop just over capacity
    for (int r = 0; r < 40; ++r)
      for (std::uint64_t a = 0; a < 17 * 64; a += 64) t.addresses.push_back(a);
    out.push_back(t);
  }
  {
    NamedTrace t{"same-set-stride", {}};  // every access in one set of a 4 KiB direct-mapped cache
    for (int r = 0; r < 30; ++r)
      for (std::uint64_t k = 0; k < 9; ++k) t.addresses.push_back(k * 4096 + (r % 3) * 8);
    out.push_back(t);
  }
  {
    NamedTrace t{"hoppe-anomaly-lines", {}};  // Belady's FIFO anomaly pattern on lines
    for (std::uint64_t v : {6, 1, 7, 2, 4, 6}) t.addresses.push_back(v * 64);
    for (int r = 0; r < 30; ++r)
      for (std::uint64_t v = 1; v <= 7; ++v) t.addresses.push_back(v * 64);
    out.push_back(t);
  }
  {
    NamedTrace t{"scan-then-reuse", {}};
    for (std::uint64_t a = 0; a < 8000; a += 16) t.addresses.push_back(a);
    for (int i = 0; i < 1000; ++i) t.addresses.push_back(rng() % 2048);
    out.push_back(t);
  }
  return out;
}

struct Geometry {
  std::uint64_t size, line, assoc;
};

std::vector<Geometry> geometries() {
  std::vector<Geometry> g;
  for (std::uint64_t size : {256u, 1024u, 4096u})
    for (std::uint64_t line : {16u, 64u})
      for (std::uint64_t assoc : {1u, 2u, 4u, 8u, 0u}) {
        if (assoc && size / line < assoc) continue;
        g.push_back({size, line, assoc});
      }
  g.push_back({4096, 16, 32});       // hashed engine with several sets
  g.push_back({3 * 1024, 64, 3});    // 16 sets of 3 ways
  g.push_back({5 * 64 * 4, 64, 4});  // 5 sets: not a power of two
  return g;
}

std::vector<std::uint64_t> lines_of(const std::vector<std::uint64_t>& addresses, std::uint64_t line) {
  std::vector<std::uint64_t> lines;
  for (const std::uint64_t a : addresses) lines.push_back(a / line);
  return lines;
}

TEST(ByteCacheDifferential, EveryPolicyAndGeometryMatchesTheNaiveReference) {
  int checked = 0;
  for (const NamedTrace& trace : traces())
    for (const Geometry& g : geometries())
      for (const char* policy : {"fifo", "lru", "random", "opt"}) {
        const CacheConfig config{g.size, static_cast<std::uint32_t>(g.line), static_cast<std::uint32_t>(g.assoc),
                                 parse_replacement_policy(policy), 99};
        std::uint64_t fast;
        if (config.policy == ReplacementPolicy::Opt) {
          fast = simulate_opt(config, lines_of(trace.addresses, g.line)).misses;
        } else {
          ByteCache cache(config);
          for (const std::uint64_t a : trace.addresses) cache.access(a);
          fast = cache.misses();
        }
        ASSERT_EQ(fast, naive_misses(trace.addresses, g.size, g.line, g.assoc, policy, 99))
            << trace.name << " " << describe(config);
        ++checked;
      }
  EXPECT_EQ(checked, static_cast<int>(traces().size() * geometries().size() * 4));
}

TEST(VertexCacheDifferential, FifoAndLruVertexCachesMatchTheNaiveReference) {
  // A vertex cache of k entries is a fully associative cache of k one-byte lines keyed by id.
  std::mt19937_64 rng(77);
  std::vector<std::vector<std::uint64_t>> streams;
  for (int s = 0; s < 4; ++s) {
    std::vector<std::uint64_t> ids;
    const std::uint64_t range = s == 0 ? 8 : s == 1 ? 40 : 300;
    for (int i = 0; i < 2000; ++i) ids.push_back(s == 3 ? (i / 3 + rng() % 24) % 500 : rng() % range);
    streams.push_back(ids);
  }
  for (const auto& ids : streams)
    for (unsigned k : {1u, 3u, 4u, 5u, 16u, 32u, 64u})
      for (auto policy : {VertexCachePolicy::Fifo, VertexCachePolicy::Lru}) {
        VertexCache cache(policy, k);
        std::uint64_t misses = 0;
        for (const std::uint64_t id : ids) misses += !cache.access(static_cast<std::uint32_t>(id));
        ASSERT_EQ(misses, naive_misses(ids, k, 1, 0, to_string(policy))) << k << " " << to_string(policy);
        // The flat FIFO list path of simulate_vertex_stream agrees too.
        if (policy == VertexCachePolicy::Fifo) {
          std::vector<std::uint32_t> indices(ids.begin(), ids.end());
          EXPECT_EQ(simulate_vertex_stream(indices, PrimitiveType::TriangleList, policy, k).misses, misses);
        }
      }
}

TEST(ByteCacheDifferential, ThreeCSplitMatchesDineroDefinitions) {
  for (const NamedTrace& trace : traces())
    for (const Geometry& g : geometries()) {
      CacheBankConfig bank;
      for (auto policy : {ReplacementPolicy::Lru, ReplacementPolicy::Fifo})
        bank.address.push_back(
            {g.size, static_cast<std::uint32_t>(g.line), static_cast<std::uint32_t>(g.assoc), policy, 1});
      LiveBankSink sink(bank, {});
      std::vector<AddressAccess> accesses;
      for (const std::uint64_t a : trace.addresses) accesses.push_back({a, 0});
      sink.address_accesses(accesses);
      sink.finish();
      const std::uint64_t compulsory = naive_compulsory(trace.addresses, g.line);
      const std::uint64_t fa_lru = naive_misses(trace.addresses, g.size, g.line, 0, "lru");
      for (std::size_t i = 0; i < 2; ++i) {
        const CacheStats& s = sink.address_stats()[i];
        ASSERT_TRUE(s.has_three_c);
        EXPECT_EQ(s.compulsory, compulsory) << trace.name;
        EXPECT_EQ(s.capacity, static_cast<std::int64_t>(fa_lru - compulsory)) << trace.name;
        EXPECT_EQ(static_cast<std::int64_t>(s.compulsory) + s.capacity + s.conflict,
                  static_cast<std::int64_t>(s.misses));
        EXPECT_EQ(s.bytes_fetched, s.misses * g.line);
        EXPECT_EQ(s.hits + s.misses, trace.addresses.size());
      }
    }
}

TEST(ByteCacheDifferential, VertexBufferCachesSeeDrawBaseAndStride) {
  // Draw d's vertex v lives at (d << 40) + v * stride.
  std::mt19937_64 rng(5);
  std::vector<VertexFetch> fetches;
  for (int i = 0; i < 900; ++i) fetches.push_back({static_cast<std::uint32_t>(rng() % 200), i % 3 == 0});
  CacheBankConfig bank;
  bank.three_c = false;
  for (auto policy : {ReplacementPolicy::Lru, ReplacementPolicy::Fifo, ReplacementPolicy::Opt})
    bank.vertex_buffer.push_back({CacheConfig{1024, 64, 2, policy, 1}, 24});
  LiveBankSink sink(bank, {});
  std::vector<std::uint64_t> addresses;
  for (std::uint32_t draw : {0u, 3u}) {
    sink.begin_draw({draw, PrimitiveType::TriangleList, kNoRestart});
    sink.vertex_fetches(fetches);
    sink.end_draw();
    for (const VertexFetch& f : fetches) addresses.push_back((std::uint64_t{draw} << 40) + f.vertex * 24ull);
  }
  sink.finish();
  EXPECT_EQ(sink.vertex_buffer_stats()[0].misses, naive_misses(addresses, 1024, 64, 2, "lru"));
  EXPECT_EQ(sink.vertex_buffer_stats()[1].misses, naive_misses(addresses, 1024, 64, 2, "fifo"));
  EXPECT_EQ(sink.vertex_buffer_stats()[2].misses, naive_misses(addresses, 1024, 64, 2, "opt"));
  EXPECT_FALSE(sink.vertex_buffer_stats()[0].has_three_c);
}

TEST(ByteCacheProperties, OptNeverMissesMoreThanLruOrFifoAndLruIsMonotoneInSize) {
  for (const NamedTrace& trace : traces()) {
    for (const Geometry& g : geometries()) {
      const auto run = [&](ReplacementPolicy p) {
        const CacheConfig config{g.size, static_cast<std::uint32_t>(g.line), static_cast<std::uint32_t>(g.assoc), p, 3};
        if (p == ReplacementPolicy::Opt) return simulate_opt(config, lines_of(trace.addresses, g.line)).misses;
        ByteCache cache(config);
        for (const std::uint64_t a : trace.addresses) cache.access(a);
        return cache.misses();
      };
      const std::uint64_t opt = run(ReplacementPolicy::Opt);
      EXPECT_LE(opt, run(ReplacementPolicy::Lru)) << trace.name;
      EXPECT_LE(opt, run(ReplacementPolicy::Fifo)) << trace.name;
      EXPECT_LE(opt, run(ReplacementPolicy::Random)) << trace.name;
    }
    // Fully associative LRU: more lines, never more misses (the stack property).
    std::uint64_t previous = ~std::uint64_t{0};
    for (std::uint64_t size = 64; size <= 16384; size *= 2) {
      ByteCache cache({size, 64, 0, ReplacementPolicy::Lru, 1});
      for (const std::uint64_t a : trace.addresses) cache.access(a);
      EXPECT_LE(cache.misses(), previous) << trace.name << " " << size;
      previous = cache.misses();
    }
  }
}

TEST(ByteCacheProperties, OneSetOfFullAssociativityEqualsTheFullyAssociativeModel) {
  for (const NamedTrace& trace : traces())
    for (auto policy : {ReplacementPolicy::Fifo, ReplacementPolicy::Lru, ReplacementPolicy::Random}) {
      ByteCache full({2048, 64, 0, policy, 5}), one_set({2048, 64, 32, policy, 5});
      for (const std::uint64_t a : trace.addresses) {
        ASSERT_EQ(full.access(a), one_set.access(a)) << trace.name;
      }
      EXPECT_EQ(full.stats(), one_set.stats());
    }
}

TEST(ByteCache, InvalidGeometriesAreInputErrors) {
  EXPECT_THROW(ByteCache({0, 64, 4, ReplacementPolicy::Lru, 1}), InputError);
  EXPECT_THROW(ByteCache({1024, 48, 4, ReplacementPolicy::Lru, 1}), InputError);
  EXPECT_THROW(ByteCache({1000, 64, 4, ReplacementPolicy::Lru, 1}), InputError);
  EXPECT_THROW(ByteCache({1024, 64, 3, ReplacementPolicy::Lru, 1}), InputError);
  EXPECT_THROW(ByteCache({1024, 64, 4, ReplacementPolicy::Opt, 1}), InputError);
  EXPECT_THROW(parse_replacement_policy("plru"), InputError);
}

TEST(ByteCache, DirectMappedConflictCountsAreExact) {
  // 4 KiB direct mapped, 64 B lines: addresses 0 and 4096 share set 0 and evict each other.
  ByteCache cache({4096, 64, 1, ReplacementPolicy::Lru, 1});
  for (int i = 0; i < 10; ++i) {
    cache.access(0);
    cache.access(4096);
  }
  EXPECT_EQ(cache.misses(), 20u);
  ByteCache two_way({4096, 64, 2, ReplacementPolicy::Lru, 1});
  for (int i = 0; i < 10; ++i) {
    two_way.access(0);
    two_way.access(4096);
  }
  EXPECT_EQ(two_way.misses(), 2u);
}

TEST(LruProfile, StackDistancesGiveEveryFullyAssociativeSizeExactly) {
  for (const NamedTrace& trace : traces()) {
    LruStackProfile profile;
    const auto lines = lines_of(trace.addresses, 16);
    profile.access_lines(lines);
    EXPECT_EQ(profile.compulsory(), naive_compulsory(trace.addresses, 16));
    for (std::uint64_t capacity = 1; capacity <= 600; capacity += capacity < 20 ? 1 : 37) {
      ByteCache cache({capacity * 16, 16, 0, ReplacementPolicy::Lru, 1});
      cache.access_lines(lines);
      ASSERT_EQ(profile.misses(capacity), cache.misses()) << trace.name << " " << capacity << " lines";
    }
  }
}

TEST(LruProfile, RenumberingTheTimeAxisKeepsDistancesExact) {
  // 300k accesses over 5000 lines: the 64 Ki-entry time axis is renumbered several times.
  std::mt19937_64 rng(7);
  std::vector<std::uint64_t> lines;
  for (int i = 0; i < 300000; ++i) lines.push_back(rng() % 3 ? rng() % 500 : rng() % 5000);
  LruStackProfile profile;
  profile.access_lines(lines);
  for (std::uint64_t capacity : {1u, 8u, 100u, 499u, 500u, 2000u, 4999u, 5000u}) {
    ByteCache cache({capacity * 64, 64, 0, ReplacementPolicy::Lru, 1});
    cache.access_lines(lines);
    EXPECT_EQ(profile.misses(capacity), cache.misses()) << capacity;
  }
  EXPECT_EQ(profile.misses(5000), 5000u);
}

TEST(LruProfile, SetAssociativeProfileGivesEveryAssociativityExactly) {
  for (const NamedTrace& trace : traces())
    for (std::uint64_t sets : {1u, 4u, 16u}) {
      SetAssocLruProfile profile(sets, 16);
      const auto lines = lines_of(trace.addresses, 32);
      profile.access_lines(lines);
      for (std::uint32_t ways = 1; ways <= 16; ++ways) {
        ByteCache cache({sets * ways * 32, 32, ways, ReplacementPolicy::Lru, 1});
        cache.access_lines(lines);
        ASSERT_EQ(profile.misses(ways), cache.misses()) << trace.name << " " << sets << "x" << ways;
      }
    }
}

}  // namespace
}  // namespace rastrace
