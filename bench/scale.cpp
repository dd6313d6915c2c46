// Miss-ratio curves at scale (docs/PERFORMANCE.md, "Miss-ratio curves at scale"): a long texel
// trace made of rendered frames, read, decoded, mapped to 64-byte lines (block4 layout) and fed to
//   - reading and decoding alone (every column, or the texel addresses alone),
//   - nothing (read + decode + layout only: what every replay pays),
//   - the exact one-pass LRU profile of every fully associative size (LruStackProfile),
//   - the one-pass set-associative profile, 64 sets, every associativity 1..16,
//   - SHARDS at a fixed rate of 1% (fully associative LRU, every size) and miniature simulations
//     of FIFO and random caches (16 KiB to 1 MiB) at the same rate.
// CPU time: the machine is shared, so rates are per core of CPU actually used. The exceptions,
// named *_ReadAhead, read with the reader's read-ahead thread (two cores): they report wall time
// and the CPU time of the whole process.
//
// The long trace is not stored anywhere: it is written once per run (or kept, see below) from the
// rendered traces named in RASTRACE_BENCH_TRACES (comma-separated, e.g. the frames of
// `rastrace render builtin:bunny --trace` in several orderings), their texel accesses concatenated
// in turn, each frame's textures kept apart (texture ids offset), until RASTRACE_BENCH_RECORDS
// texel accesses (default 10^8). RASTRACE_BENCH_LONG_TRACE=PATH writes it there and reuses it if
// it exists, so that `rastrace sweep` can be measured on the same file.
#include <unistd.h>

#include <cmath>
#include <ctime>
#include <cstdlib>
#include <memory>
#include <filesystem>
#include <sstream>

#include <benchmark/benchmark.h>

#include "cache_sim/byte_cache.h"
#include "cache_sim/lru_profile.h"
#include "cache_sim/shards.h"
#include "cache_sim/texture_layout.h"
#include "traces/trace_reader.h"
#include "traces/trace_writer.h"

namespace rastrace {
namespace {

std::uint64_t wanted_records() {
  const char* env = std::getenv("RASTRACE_BENCH_RECORDS");
  return env ? std::stoull(env) : 100'000'000ull;
}

std::vector<std::string> source_traces() {
  std::vector<std::string> out;
  const char* env = std::getenv("RASTRACE_BENCH_TRACES");
  if (!env) return out;
  std::stringstream list(env);
  for (std::string path; std::getline(list, path, ',');)
    if (!path.empty()) out.push_back(path);
  return out;
}

double thread_cpu_seconds() {
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return double(t.tv_sec) + 1e-9 * double(t.tv_nsec);
}

std::string g_temporary;  // the long trace written for this run only, removed at exit

// The long trace's path ("" when RASTRACE_BENCH_TRACES is not set).
const std::string& long_trace() {
  static const std::string path = []() -> std::string {
    const std::vector<std::string> sources = source_traces();
    if (sources.empty()) return "";
    const char* keep = std::getenv("RASTRACE_BENCH_LONG_TRACE");
    const std::string p = keep ? std::string(keep)
                               : (std::filesystem::temp_directory_path() /
                                  ("rastrace_bench_long_" + std::to_string(::getpid()) + ".rtrace"))
                                     .string();
    if (keep && std::filesystem::exists(p)) return p;
    if (!keep) g_temporary = p;
    TraceMetadata metadata;
    metadata.scene = "concatenated frames";
    std::vector<std::uint32_t> texture_offset;
    for (const std::string& s : sources) {
      const TraceReader reader(s);
      texture_offset.push_back(static_cast<std::uint32_t>(metadata.textures.size()));
      for (const auto& t : reader.metadata().textures) metadata.textures.push_back(t);
    }
    TraceWriter writer(p, metadata);
    std::uint64_t written = 0;
    std::vector<TexelAccess> shifted;
    while (written < wanted_records()) {
      for (std::size_t s = 0; s < sources.size() && written < wanted_records(); ++s) {
        TexelTraceReader reader(sources[s]);
        std::span<const TexelAccess> batch;
        while (written < wanted_records() && reader.next(batch)) {
          const std::size_t n = std::min<std::uint64_t>(batch.size(), wanted_records() - written);
          shifted.assign(batch.begin(), batch.begin() + static_cast<std::ptrdiff_t>(n));
          for (TexelAccess& t : shifted) t.texture += texture_offset[s];
          writer.texel_accesses(shifted);
          written += n;
        }
      }
    }
    writer.finish();
    return p;
  }();
  return path;
}

// Reads the long trace (texture, level, x and y of each texel: the pixel and triangle columns are
// checked by their chunk's checksum but not decoded, as in `sweep --sample`), maps every texel to
// its 64-byte line, and hands each batch to `use`.
template <typename Use>
void replay_lines(benchmark::State& state, Use&& use, bool read_ahead = false) {
  const std::string& path = long_trace();
  if (path.empty()) {
    state.SkipWithError("set RASTRACE_BENCH_TRACES to rendered trace files");
    return;
  }
  std::uint64_t records = 0;
  const double caller_start = thread_cpu_seconds();
  for (auto _ : state) {
    TexelTraceReader reader(path);
    reader.set_read_ahead(read_ahead);  // off: one core, CPU time is the whole cost
    reader.set_addresses_only(true);    // the layout needs texture, level, x and y
    const TextureLayout layout(parse_layout("block4"), reader.metadata().textures);
    std::vector<std::uint64_t> lines;
    std::span<const TexelAccess> batch;
    while (reader.next(batch)) {
      lines.resize(batch.size());
      for (std::size_t i = 0; i < batch.size(); ++i)
        lines[i] = layout.address(batch[i].texture, batch[i].level, batch[i].x, batch[i].y) >> 6;
      use(lines);
      records += batch.size();
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(records));
  state.counters["records"] = static_cast<double>(records / state.iterations());
  // With read-ahead, the process's CPU time minus this is the read-ahead thread's: on an idle
  // 2-core machine the wall time approaches the larger of the two.
  state.counters["caller_cpu_s"] = (thread_cpu_seconds() - caller_start) / double(state.iterations());
}

// Reading and decoding alone, one thread: every column (arg 1, what `trace convert` and a full
// replay decode) or the texel addresses alone (arg 0, what a cache simulation decodes). The
// issue's one-core decoding goal (200 M records/s) is about this figure.
void BM_Long_ReadDecode(benchmark::State& state) {
  const std::string& path = long_trace();
  if (path.empty()) {
    state.SkipWithError("set RASTRACE_BENCH_TRACES to rendered trace files");
    return;
  }
  std::uint64_t records = 0;
  for (auto _ : state) {
    TexelTraceReader reader(path);
    reader.set_read_ahead(false);
    reader.set_addresses_only(state.range(0) == 0);
    std::span<const TexelAccess> batch;
    while (reader.next(batch)) {
      benchmark::DoNotOptimize(batch.data());
      records += batch.size();
    }
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(records));
  state.SetLabel(state.range(0) ? "every column" : "addresses only");
}
BENCHMARK(BM_Long_ReadDecode)->ArgName("details")->Arg(1)->Arg(0)->Unit(benchmark::kSecond)->Iterations(1);

void BM_Long_ReadDecodeLayout(benchmark::State& state) {
  replay_lines(state, [](const std::vector<std::uint64_t>& lines) { benchmark::DoNotOptimize(lines.data()); });
}
BENCHMARK(BM_Long_ReadDecodeLayout)->Unit(benchmark::kSecond)->Iterations(1);

void BM_Long_LruProfileAllSizes(benchmark::State& state) {
  LruStackProfile* profile = nullptr;
  std::unique_ptr<LruStackProfile> holder;
  replay_lines(state, [&](const std::vector<std::uint64_t>& lines) {
    if (!profile) profile = (holder = std::make_unique<LruStackProfile>()).get();
    profile->access_lines(lines);
  });
  if (profile) {
    state.counters["distinct_lines"] = static_cast<double>(profile->distinct_lines());
    state.counters["miss_rate_16KiB"] = double(profile->misses(256)) / double(profile->accesses());
  }
}
BENCHMARK(BM_Long_LruProfileAllSizes)->Unit(benchmark::kSecond)->Iterations(1);

void BM_Long_SetAssocProfile_64Sets_Ways1to16(benchmark::State& state) {
  SetAssocLruProfile profile(64, 16);
  replay_lines(state, [&](const std::vector<std::uint64_t>& lines) { profile.access_lines(lines); });
  state.counters["miss_rate_4way"] = double(profile.misses(4)) / double(std::max<std::uint64_t>(1, profile.accesses()));
}
BENCHMARK(BM_Long_SetAssocProfile_64Sets_Ways1to16)->Unit(benchmark::kSecond)->Iterations(1);

// The lines are sampled once per batch for both estimators, as `sweep --sample` does.
void shards_1_percent(benchmark::State& state, bool read_ahead) {
  ShardsProfile shards({0.01, 0});
  std::vector<CacheConfig> caches;
  for (const ReplacementPolicy policy : {ReplacementPolicy::Fifo, ReplacementPolicy::Random})
    for (std::uint64_t size = 16 * 1024; size <= 1024 * 1024; size *= 2) caches.push_back({size, 64, 0, policy, 1});
  MiniSimulations minis(caches, 0.01);
  SampledBatch sampled(0.01);
  replay_lines(
      state,
      [&](const std::vector<std::uint64_t>& lines) {
        sampled.sample(lines);
        shards.access_sampled(sampled);
        minis.access_sampled(sampled);
      },
      read_ahead);
  state.counters["lru_16KiB_estimate"] = shards.miss_ratio(256);
  state.counters["fifo_16KiB_estimate"] = minis.miss_ratio(0);
  state.counters["sampled_accesses"] = shards.sampled_accesses();
}

void BM_Long_Shards1Percent(benchmark::State& state) { shards_1_percent(state, false); }
BENCHMARK(BM_Long_Shards1Percent)->Unit(benchmark::kSecond)->Iterations(1);

void BM_Long_Shards1Percent_ReadAhead(benchmark::State& state) { shards_1_percent(state, true); }
BENCHMARK(BM_Long_Shards1Percent_ReadAhead)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

void BM_Long_ReadDecodeLayout_ReadAhead(benchmark::State& state) {
  replay_lines(
      state, [](const std::vector<std::uint64_t>& lines) { benchmark::DoNotOptimize(lines.data()); }, true);
}
BENCHMARK(BM_Long_ReadDecodeLayout_ReadAhead)
    ->Unit(benchmark::kSecond)
    ->Iterations(1)
    ->UseRealTime()
    ->MeasureProcessCPUTime();

// Accuracy, not speed: SHARDS at 1% and 0.1% and the 1% miniature FIFO and random simulations
// against the exact curves (LruStackProfile; one ByteCache per size) over the same lines,
// fully associative caches of 1 KiB .. 4 MiB (13 sizes): the mean absolute error of the miss ratio.
void BM_Long_SampledAccuracy(benchmark::State& state) {
  std::vector<std::uint64_t> sizes;
  for (std::uint64_t size = 1024; size <= 4 * 1024 * 1024; size *= 2) sizes.push_back(size);
  LruStackProfile exact;
  ShardsProfile shards({0.01, 0}), shards_tenth({0.001, 0}), shards_fixed({1.0, 8192});
  std::vector<CacheConfig> caches;
  for (const ReplacementPolicy policy : {ReplacementPolicy::Fifo, ReplacementPolicy::Random})
    for (const std::uint64_t size : sizes) caches.push_back({size, 64, 0, policy, 1});
  MiniSimulations minis(caches, 0.01);
  std::vector<std::unique_ptr<ByteCache>> exact_caches;
  for (const CacheConfig& c : caches) exact_caches.push_back(std::make_unique<ByteCache>(c));
  replay_lines(state, [&](const std::vector<std::uint64_t>& lines) {
    exact.access_lines(lines);
    shards.access_lines(lines);
    shards_tenth.access_lines(lines);
    shards_fixed.access_lines(lines);
    minis.access_lines(lines);
    for (auto& c : exact_caches) c->access_lines(lines);
  });
  if (exact.accesses() == 0) return;
  double lru = 0, lru_tenth = 0, lru_fixed = 0, fifo = 0, random = 0, expected = 0;
  for (const std::uint64_t size : sizes) {
    const double truth = double(exact.misses(size / 64)) / double(exact.accesses());
    lru += std::abs(shards.miss_ratio(size / 64) - truth);
    lru_tenth += std::abs(shards_tenth.miss_ratio(size / 64) - truth);
    lru_fixed += std::abs(shards_fixed.miss_ratio(size / 64) - truth);
    expected += shards.expected_error(size / 64);
  }
  for (std::size_t i = 0; i < caches.size(); ++i) {
    const double error = std::abs(minis.miss_ratio(i) - exact_caches[i]->stats().miss_rate());
    (i < sizes.size() ? fifo : random) += error;
  }
  const double n = double(sizes.size());
  state.counters["mae_lru_shards_1pct"] = lru / n;
  state.counters["mae_lru_shards_0.1pct"] = lru_tenth / n;
  state.counters["mae_lru_shards_fixed_8Ki"] = lru_fixed / n;
  state.counters["expected_error_lru_1pct"] = expected / n;
  state.counters["mae_fifo_mini_1pct"] = fifo / n;
  state.counters["mae_random_mini_1pct"] = random / n;
}
BENCHMARK(BM_Long_SampledAccuracy)->Unit(benchmark::kSecond)->Iterations(1);

}  // namespace
}  // namespace rastrace

int main(int argc, char** argv) {
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  benchmark::Shutdown();
  if (!rastrace::g_temporary.empty()) std::filesystem::remove(rastrace::g_temporary);
  return 0;
}
