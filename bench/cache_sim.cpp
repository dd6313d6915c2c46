// Cache simulator throughput (docs/PERFORMANCE.md, cache simulator section):
//   - FIFO vertex-cache replay: rastrace's simulate_vertex_stream against meshoptimizer's
//     meshopt_analyzeVertexCache on the same index buffer in the same binary (goal: ratio >= 1)
//   - set-associative LRU byte cache, 16 KiB / 64 B / 4-way (goal: 150 M accesses/s)
//   - one-pass fully associative LRU stack profile, every size at once (goal: 30 M accesses/s)
//   - LRU post-transform cache at k = 16, 64, 1024, 100000: the O(1) recency list of
//     cache_sim/vertex_cache.h against the O(k) version it replaced (a vector of resident vertices,
//     most recent first, searched and rotated on every access), kept here only as the "before";
//     over bunny00 in meshoptimizer's order (hits near the front of the recency list) and a random
//     walk over 2^17 vertices (hits at every depth; a miss scans all resident entries)
//   - vertex caches of every size 3..64 over bunny00 in meshoptimizer's order: one pass of
//     VertexCacheSizes (FIFO lanes, LRU stack) against meshopt_analyzeVertexCache once per size and
//     simulate_vertex_stream once per size (goal: one pass >= 8x the per-size meshoptimizer runs)
//   - SHARDS at 1% and miniature FIFO simulations at 1% over the same line stream
// Byte-cache inputs are the line numbers of a synthetic frame-like texel trace (512x512 pixels,
// bilinear, a 1024^2 texture in block4 layout; tests/support/synthetic_frame.h).
#include <meshoptimizer.h>

#include <algorithm>
#include <random>

#include <benchmark/benchmark.h>

#include "cache_sim/byte_cache.h"
#include "cache_sim/lru_profile.h"
#include "cache_sim/opt_cache.h"
#include "cache_sim/shards.h"
#include "cache_sim/texture_layout.h"
#include "cache_sim/vertex_cache.h"
#include "cache_sim/vertex_cache_sizes.h"
#include "scenes/mesh_io.h"
#include "tests/support/synthetic_frame.h"

namespace rastrace {
namespace {

const std::vector<std::uint32_t>& bunny_indices() {
  // bunny00.off (CGAL), reordered by meshoptimizer for a realistic, cache-friendly stream.
  static const std::vector<std::uint32_t> indices = [] {
    const Mesh mesh = load_mesh(RASTRACE_DATA_DIR "/meshes/bunny00.off");
    std::vector<std::uint32_t> out(mesh.indices.size());
    meshopt_optimizeVertexCache(out.data(), mesh.indices.data(), out.size(), mesh.positions.size());
    return out;
  }();
  return indices;
}

std::size_t vertex_count(const std::vector<std::uint32_t>& indices) {
  std::uint32_t max = 0;
  for (const std::uint32_t i : indices) max = std::max(max, i);
  return std::size_t{max} + 1;
}

void BM_FifoVertexReplay_Rastrace(benchmark::State& state) {
  const auto& indices = bunny_indices();
  const unsigned k = static_cast<unsigned>(state.range(0));
  for (auto _ : state) {
    const VertexStreamStats s =
        simulate_vertex_stream(indices, PrimitiveType::TriangleList, VertexCachePolicy::Fifo, k);
    benchmark::DoNotOptimize(s.misses);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * indices.size()));
}
BENCHMARK(BM_FifoVertexReplay_Rastrace)->Arg(16)->Arg(32);

void BM_FifoVertexReplay_Meshopt(benchmark::State& state) {
  const auto& indices = bunny_indices();
  const std::size_t vertices = vertex_count(indices);
  const unsigned k = static_cast<unsigned>(state.range(0));
  for (auto _ : state) {
    const meshopt_VertexCacheStatistics s =
        meshopt_analyzeVertexCache(indices.data(), indices.size(), vertices, k, 0, 0);
    benchmark::DoNotOptimize(s.vertices_transformed);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * indices.size()));
}
BENCHMARK(BM_FifoVertexReplay_Meshopt)->Arg(16)->Arg(32);

// Every size 3..64 (meshoptimizer asserts at least 3): items are index-stream positions, each
// looked up in all 62 caches.
std::vector<unsigned> sizes_3_to_64() {
  std::vector<unsigned> sizes;
  for (unsigned k = 3; k <= 64; ++k) sizes.push_back(k);
  return sizes;
}

void BM_VertexSizes3to64_OnePass(benchmark::State& state) {
  const auto& indices = bunny_indices();
  const auto policy = static_cast<VertexCachePolicy>(state.range(0));
  const std::vector<unsigned> sizes = sizes_3_to_64();
  std::uint64_t misses16 = 0;
  for (auto _ : state) {
    const auto stats = simulate_vertex_stream_sizes(indices, PrimitiveType::TriangleList, policy, sizes);
    misses16 = stats[13].misses;
    benchmark::DoNotOptimize(misses16);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * indices.size()));
  state.counters["misses_k16"] = static_cast<double>(misses16);
  state.SetLabel(to_string(policy));
}
BENCHMARK(BM_VertexSizes3to64_OnePass)
    ->Arg(static_cast<int>(VertexCachePolicy::Fifo))
    ->Arg(static_cast<int>(VertexCachePolicy::Lru));

void BM_VertexSizes3to64_MeshoptPerSize(benchmark::State& state) {
  const auto& indices = bunny_indices();
  const std::size_t vertices = vertex_count(indices);
  std::uint64_t misses16 = 0;
  for (auto _ : state)
    for (unsigned k = 3; k <= 64; ++k) {
      const auto s = meshopt_analyzeVertexCache(indices.data(), indices.size(), vertices, k, 0, 0);
      if (k == 16) misses16 = s.vertices_transformed;
      benchmark::DoNotOptimize(s.vertices_transformed);
    }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * indices.size()));
  state.counters["misses_k16"] = static_cast<double>(misses16);
}
BENCHMARK(BM_VertexSizes3to64_MeshoptPerSize);

void BM_VertexSizes3to64_RastracePerSize(benchmark::State& state) {
  const auto& indices = bunny_indices();
  const auto policy = static_cast<VertexCachePolicy>(state.range(0));
  for (auto _ : state)
    for (unsigned k = 3; k <= 64; ++k)
      benchmark::DoNotOptimize(simulate_vertex_stream(indices, PrimitiveType::TriangleList, policy, k).misses);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * indices.size()));
  state.SetLabel(to_string(policy));
}
BENCHMARK(BM_VertexSizes3to64_RastracePerSize)
    ->Arg(static_cast<int>(VertexCachePolicy::Fifo))
    ->Arg(static_cast<int>(VertexCachePolicy::Lru));

const std::vector<std::uint64_t>& frame_lines(std::uint32_t line_bytes) {
  static std::vector<std::uint64_t> lines;
  static std::uint32_t cached = 0;
  if (cached != line_bytes) {
    const testing::SyntheticFrame frame = testing::make_synthetic_frame(512, 512, 1024);
    const TextureLayout layout(parse_layout("block4"), frame.textures);
    lines.clear();
    for (const TexelAccess& t : frame.texels)
      lines.push_back(layout.address(t.texture, t.level, t.x, t.y) / line_bytes);
    cached = line_bytes;
  }
  return lines;
}

void BM_SetAssocLru_16KiB_64B_4way(benchmark::State& state) {
  const auto& lines = frame_lines(64);
  ByteCache cache({16 * 1024, 64, 4, ReplacementPolicy::Lru, 1});
  for (auto _ : state) {
    cache.clear();
    benchmark::DoNotOptimize(cache.access_lines(lines));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * lines.size()));
  state.counters["miss_rate"] = cache.stats().miss_rate();
}
BENCHMARK(BM_SetAssocLru_16KiB_64B_4way);

void BM_ByteCachePolicies(benchmark::State& state) {
  const auto& lines = frame_lines(64);
  const auto policy = static_cast<ReplacementPolicy>(state.range(0));
  const std::uint32_t assoc = static_cast<std::uint32_t>(state.range(1));
  ByteCache cache({16 * 1024, 64, assoc, policy, 1});
  for (auto _ : state) {
    cache.clear();
    benchmark::DoNotOptimize(cache.access_lines(lines));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * lines.size()));
  state.SetLabel(describe(cache.config()));
}
BENCHMARK(BM_ByteCachePolicies)
    ->Args({static_cast<int>(ReplacementPolicy::Fifo), 4})
    ->Args({static_cast<int>(ReplacementPolicy::Random), 4})
    ->Args({static_cast<int>(ReplacementPolicy::Lru), 1})
    ->Args({static_cast<int>(ReplacementPolicy::Lru), 16})
    ->Args({static_cast<int>(ReplacementPolicy::Lru), 0})
    ->Args({static_cast<int>(ReplacementPolicy::Fifo), 0});

void BM_OptFullyAssociative_16KiB(benchmark::State& state) {
  const auto& lines = frame_lines(64);
  for (auto _ : state)
    benchmark::DoNotOptimize(simulate_opt({16 * 1024, 64, 0, ReplacementPolicy::Opt, 1}, lines).misses);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * lines.size()));
}
BENCHMARK(BM_OptFullyAssociative_16KiB)->Unit(benchmark::kMillisecond);

void BM_LruStackProfile_AllSizes(benchmark::State& state) {
  const auto& lines = frame_lines(64);
  for (auto _ : state) {
    LruStackProfile profile;
    profile.access_lines(lines);
    benchmark::DoNotOptimize(profile.misses(256));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * lines.size()));
}
BENCHMARK(BM_LruStackProfile_AllSizes);

void BM_SetAssocLruProfile_64Sets_Ways1to16(benchmark::State& state) {
  const auto& lines = frame_lines(64);
  for (auto _ : state) {
    SetAssocLruProfile profile(64, 16);
    profile.access_lines(lines);
    benchmark::DoNotOptimize(profile.misses(4));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * lines.size()));
}
BENCHMARK(BM_SetAssocLruProfile_64Sets_Ways1to16);

void BM_Shards_FixedRate1Percent(benchmark::State& state) {
  const auto& lines = frame_lines(64);
  for (auto _ : state) {
    ShardsProfile shards({0.01, 0});
    shards.access_lines(lines);
    benchmark::DoNotOptimize(shards.miss_ratio(256));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * lines.size()));
}
BENCHMARK(BM_Shards_FixedRate1Percent);

void BM_MiniSim_Fifo1Percent_8Sizes(benchmark::State& state) {
  const auto& lines = frame_lines(64);
  std::vector<CacheConfig> caches;
  for (std::uint64_t size = 8 * 1024; size <= 1024 * 1024; size *= 2)
    caches.push_back({size, 64, 0, ReplacementPolicy::Fifo, 1});
  for (auto _ : state) {
    MiniSimulations minis(caches, 0.01);
    minis.access_lines(lines);
    benchmark::DoNotOptimize(minis.miss_ratio(0));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * lines.size()));
}
BENCHMARK(BM_MiniSim_Fifo1Percent_8Sizes);

// The O(k)-per-access LRU as it was before the recency list: reference for the benchmark only.
class LinearScanLruBefore {
 public:
  explicit LinearScanLruBefore(unsigned entries) : entries_(entries) { recency_.reserve(entries); }
  bool access(std::uint32_t vertex) {
    const auto found = std::find(recency_.begin(), recency_.end(), vertex);
    if (found != recency_.end()) {
      std::rotate(recency_.begin(), found, found + 1);
      return true;
    }
    if (recency_.size() < entries_)
      recency_.push_back(vertex);
    else
      recency_.back() = vertex;
    std::rotate(recency_.begin(), recency_.end() - 1, recency_.end());
    return false;
  }

 private:
  unsigned entries_;
  std::vector<std::uint32_t> recency_;
};

const std::vector<std::uint32_t>& random_walk_stream() {
  static const std::vector<std::uint32_t> stream = [] {
    std::mt19937 rng(1);
    std::uniform_int_distribution<int> step(-64, 64);
    std::vector<std::uint32_t> out;
    std::int64_t v = 1 << 16;
    for (int i = 0; i < 200000; ++i) {
      v = std::clamp<std::int64_t>(v + step(rng), 0, (1 << 17) - 1);
      out.push_back(static_cast<std::uint32_t>(v));
    }
    return out;
  }();
  return stream;
}

template <typename Cache>
void run(benchmark::State& state, const std::vector<std::uint32_t>& stream, Cache make) {
  std::uint64_t misses = 0;
  for (auto _ : state) {
    auto cache = make();
    misses = 0;
    for (const std::uint32_t v : stream) misses += !cache.access(v);
    benchmark::DoNotOptimize(misses);
  }
  state.counters["misses"] = static_cast<double>(misses);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * stream.size()));
}

void BM_Lru_Bunny_RecencyList(benchmark::State& state) {
  const unsigned k = static_cast<unsigned>(state.range(0));
  run(state, bunny_indices(), [k] { return VertexCache(VertexCachePolicy::Lru, k); });
}
void BM_Lru_Bunny_LinearScanBefore(benchmark::State& state) {
  const unsigned k = static_cast<unsigned>(state.range(0));
  run(state, bunny_indices(), [k] { return LinearScanLruBefore(k); });
}
void BM_Lru_RandomWalk_RecencyList(benchmark::State& state) {
  const unsigned k = static_cast<unsigned>(state.range(0));
  run(state, random_walk_stream(), [k] { return VertexCache(VertexCachePolicy::Lru, k); });
}
void BM_Lru_RandomWalk_LinearScanBefore(benchmark::State& state) {
  const unsigned k = static_cast<unsigned>(state.range(0));
  run(state, random_walk_stream(), [k] { return LinearScanLruBefore(k); });
}

BENCHMARK(BM_Lru_Bunny_RecencyList)->Arg(16)->Arg(64)->Arg(1024)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Lru_Bunny_LinearScanBefore)->Arg(16)->Arg(64)->Arg(1024)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Lru_RandomWalk_RecencyList)->Arg(16)->Arg(64)->Arg(1024)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Lru_RandomWalk_LinearScanBefore)->Arg(16)->Arg(64)->Arg(1024)->Arg(100000)->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rastrace
