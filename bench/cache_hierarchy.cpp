// Sectored caches and cache hierarchies (cache_sim/sectored_cache.h, cache_hierarchy.h) against
// the plain set-associative cache on the same texel stream: what sectors, texture units and a
// second level cost per access. No peer runs here: neither Dinero IV nor libCacheSim is packaged
// for Debian 12, so the reference is rastrace's own ByteCache (ratio `vs_plain` = this
// benchmark's accesses/s over BM_Plain's), and exactness against a naive simulator is a test
// (tests/cache_sim/naive_hierarchy.h), not a benchmark.
// Input: the synthetic frame-like texel trace of bench/cache_sim.cpp (512x512 pixels, bilinear, a
// 1024^2 texture in block4 layout, tests/support/synthetic_frame.h), as byte addresses with the
// texture unit of each access's screen tile precomputed.
//   build/bench/bench_cache_hierarchy --benchmark_min_time=0.2
#include <time.h>

#include <benchmark/benchmark.h>

#include "cache_sim/byte_cache.h"
#include "cache_sim/cache_hierarchy.h"
#include "cache_sim/sectored_cache.h"
#include "cache_sim/texture_layout.h"
#include "tests/support/synthetic_frame.h"

namespace rastrace {
namespace {

struct Stream {
  std::vector<std::uint64_t> addresses;
  std::vector<std::uint32_t> pixel_x, pixel_y;
};

const Stream& frame_stream() {
  static const Stream stream = [] {
    const testing::SyntheticFrame frame = testing::make_synthetic_frame(512, 512, 1024);
    const TextureLayout layout(parse_layout("block4"), frame.textures);
    Stream s;
    for (const TexelAccess& t : frame.texels) {
      s.addresses.push_back(layout.address(t.texture, t.level, t.x, t.y));
      s.pixel_x.push_back(t.pixel_x);
      s.pixel_y.push_back(t.pixel_y);
    }
    return s;
  }();
  return stream;
}

constexpr CacheConfig kL1{16 * 1024, 128, 4, ReplacementPolicy::Lru, 1};
constexpr CacheConfig kL2{256 * 1024, 128, 16, ReplacementPolicy::Lru, 1};

double& plain_rate() {
  static double rate = 0;
  return rate;
}

void report(benchmark::State& state, double seconds, std::uint64_t misses) {
  const double accesses = double(state.iterations()) * double(frame_stream().addresses.size());
  state.SetItemsProcessed(static_cast<std::int64_t>(accesses));
  state.counters["misses"] = double(misses);
  if (seconds > 0 && plain_rate() > 0) state.counters["vs_plain"] = accesses / seconds / plain_rate();
}

// This thread's CPU time (the machine is shared: wall time would measure the other jobs).
double thread_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + double(t.tv_nsec) * 1e-9;
}

template <typename Body>
double timed(benchmark::State& state, Body body) {
  double seconds = 0;
  for (auto _ : state) {
    const double start = thread_seconds();
    body();
    seconds += thread_seconds() - start;
  }
  return seconds;
}

// The reference: the whole-line cache, one access at a time through the same byte interface.
void BM_Plain_16KiB_128B_4way(benchmark::State& state) {
  const Stream& s = frame_stream();
  ByteCache cache(kL1);
  const double seconds = timed(state, [&] {
    cache.clear();
    for (const std::uint64_t a : s.addresses) benchmark::DoNotOptimize(cache.access(a));
  });
  plain_rate() = double(state.iterations()) * double(s.addresses.size()) / seconds;
  report(state, seconds, cache.stats().misses);
}
BENCHMARK(BM_Plain_16KiB_128B_4way);

// Arg: sector bytes (128 = one sector per line, ByteCache's behaviour through the sectored code).
void BM_Sectored_16KiB_128B_4way(benchmark::State& state) {
  const Stream& s = frame_stream();
  SectoredCache cache(kL1, static_cast<std::uint32_t>(state.range(0)));
  const double seconds = timed(state, [&] {
    cache.clear();
    for (const std::uint64_t a : s.addresses) benchmark::DoNotOptimize(cache.access(a).hit);
  });
  report(state, seconds, cache.misses());
  state.counters["line_misses"] = double(cache.line_misses());
}
BENCHMARK(BM_Sectored_16KiB_128B_4way)->Arg(128)->Arg(32);

// Args: texture units, then 1 for inclusive. L1 as above with 32-byte sectors, a shared 256 KiB
// 16-way L2, 16-pixel tiles.
void BM_Hierarchy_L1xUnits_L2_256KiB(benchmark::State& state) {
  const Stream& s = frame_stream();
  HierarchyConfig config;
  config.levels = {{kL1, 32}, {kL2, 0}};
  config.units = static_cast<std::uint32_t>(state.range(0));
  config.inclusion = state.range(1) ? Inclusion::Inclusive : Inclusion::NonInclusive;
  std::vector<std::uint32_t> units(s.addresses.size());
  for (std::size_t i = 0; i < units.size(); ++i)
    units[i] = CacheHierarchy::unit_of_pixel(s.pixel_x[i], s.pixel_y[i], config.tile, config.units);
  std::vector<LevelStats> stats;
  const double seconds = timed(state, [&] {
    CacheHierarchy hierarchy(config);
    for (std::size_t i = 0; i < units.size(); ++i) benchmark::DoNotOptimize(hierarchy.access(s.addresses[i], units[i]));
    stats = hierarchy.stats();
  });
  report(state, seconds, stats.front().misses);
  state.counters["l2_misses"] = double(stats.back().misses);
}
BENCHMARK(BM_Hierarchy_L1xUnits_L2_256KiB)->Args({1, 0})->Args({4, 0})->Args({4, 1});

}  // namespace
}  // namespace rastrace
