// Sweeps: every combination of cache size, line size, associativity, replacement policy and
// texture layout over one trace, run in parallel. Each worker streams the trace file through its
// own LiveBankSink (the bank `rastrace replay` and live rendering use), holding the caches of one
// (layout, line size) group, so memory stays bounded by the caches, not the trace; OPT groups hold
// their line stream (see opt_cache.h for the limit).
// Combinations whose geometry is impossible (fewer lines than ways) are skipped and listed.
#pragma once

#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cache_sim/cache_config.h"
#include "cache_sim/live_bank_sink.h"
#include "cache_sim/shards.h"
#include "cache_sim/texture_layout.h"
#include "core/huge_page_allocator.h"

namespace rastrace {

// Which accesses of the trace feed the byte caches.
enum class SweepSource { Texel, VertexBuffer, Address };
const char* to_string(SweepSource source);
// "texel", "vertex", "address"; throws InputError otherwise.
SweepSource parse_sweep_source(const std::string& text);

// The K-th of N disjoint parts of a sweep's configuration set (`sweep --shard K/N`): configuration
// i of the full set (in the order of the rows, impossible combinations counted) belongs to part
// i % N + 1, so every part gets sizes from the whole range and about the same work.
struct SweepShard {
  std::uint32_t index = 1;  // 1 .. count
  std::uint32_t count = 1;
  bool owns(std::size_t configuration) const { return configuration % count == index - 1; }
};
// "K/N" with 1 <= K <= N <= 65536; throws InputError naming --shard otherwise.
SweepShard parse_sweep_shard(const std::string& text);

// Where a sampled sweep simulates exactly instead, because a sample would state less error than
// it has (sampled_sweep.h; the figures behind the defaults: docs/RELIABILITY.md, "Sampled
// estimates state their true error").
struct SampleGuards {
  // A sweep of at most this many simulated accesses (the source's records x rows) runs exactly:
  // on 2 cores that costs under a second more than the sample, and a trace that short has too few
  // distinct lines for a 1% sample to hold more than a handful.
  std::uint64_t exact_accesses = 64ull << 20;
  // A row whose cache, scaled to the sample, holds fewer sampled lines than this (C x R < K) is
  // simulated exactly: below a few lines the scaled cache's miss ratio is biased (a 1-line scaled
  // cache stands for every cache up to 1/R lines), and the part samples' spread does not see it.
  std::uint64_t min_sampled_lines = 32;
  // A set-associative row of fewer ways than this is simulated exactly: hash sampling does not
  // keep which lines share a set, so a scaled direct-mapped or 2-way cache sees conflicts the
  // full one does not (a 1 MiB direct-mapped cache over a 1024x1024 bunny frame: 0.0024
  // measured, 0.0076 estimated at 10%), and the part samples share that bias.
  std::uint32_t min_sampled_assoc = 4;
};

struct SweepSpec {
  SweepSource source = SweepSource::Texel;
  std::vector<std::uint64_t> sizes{16 * 1024};
  std::vector<std::uint32_t> lines{64};
  std::vector<std::uint32_t> assocs{4};  // 0 = fully associative
  std::vector<ReplacementPolicy> policies{ReplacementPolicy::Lru};
  std::vector<LayoutSpec> layouts{LayoutSpec{}};  // texel source only
  std::uint32_t stride = 32;                      // vertex source only
  std::uint64_t seed = 1;
  bool three_c = true;
  SweepShard shard;
  // Estimate every row from a spatially hashed sample of the lines instead (sampled_sweep.h),
  // except where its guards simulate exactly.
  std::optional<SampleSpec> sample;
  SampleGuards sample_guards;
};

struct SweepRow {
  CacheConfig cache;
  std::string layout;  // layout name, "stride32" for vertex buffers, "-" for addresses
  CacheStats stats;
  std::size_t configuration = 0;  // index in the full configuration set (see SweepShard)
  std::size_t layout_index = 0;   // into SweepSpec::layouts (texel source)
  // Sampled sweeps only: how the row was estimated ("shards", "mini" and the scaled cache, or
  // "exact" where the guards of sampled_sweep.h simulate it) and the error its miss rate states
  // (0 for exact rows; < 0: not a sampled sweep).
  std::string sampled_as = {};
  double expected_error = -1;
};
// A sweep's rows: 10^6 configurations are about 190 MB, so they live in huge pages
// (core/huge_page_allocator.h): building them faults once per 2 MiB instead of once per 4 KiB,
// and freeing them unmaps a hundred pages, not fifty thousand.
using SweepRows = std::vector<SweepRow, HugePageAllocator<SweepRow>>;

struct SweepResult {
  SweepRows rows;                    // sorted by layout, policy, line, assoc, size (this shard's)
  std::vector<std::string> skipped;  // impossible combinations, described (this shard's)
  std::size_t configurations = 0;    // in the full set, impossible ones included
};

// How a sweep's rows were found: "exact" (no --sample, or every row simulated by the guards of
// SampleGuards), "sampled" (every row estimated) or "sampled+exact-rows" (the rows under
// SampleGuards::min_sampled_lines or min_sampled_assoc simulated, the rest estimated).
const char* sweep_method(std::span<const SweepRow> rows);
// The same from whether some rows were estimated and some simulated (a merge of shards' rows).
const char* sweep_method(bool estimated, bool simulated);

// The layout column of the rows of SweepSpec::layouts[layout_index] (texel source; a layout's
// name), and of every row of the other sources ("stride32" for vertex buffers, "-" for addresses).
std::string sweep_layout_name(const SweepSpec& spec, std::size_t layout_index);

// Receives a sweep's rows as they are done, so that another form of the result (the Python
// module's numpy columns) is written while the sweep runs, each row while it is still in the
// cache, instead of in a second pass over all rows after it (10^6 rows are 180 MB).
class SweepRowSink {
 public:
  virtual ~SweepRowSink() = default;
  // Once, on the calling thread, before any row is done: how many rows the result will hold.
  virtual void begin(std::size_t rows) = 0;
  // rows[i] for i in `indices` are final. Called from the worker threads, concurrently; every
  // index of the result comes exactly once.
  virtual void done(const SweepRows& rows, const std::vector<std::size_t>& indices) = 0;
};

// threads = 0: one per core. progress: a bar on stderr when it is a terminal. Throws InputError
// when no combination of the whole set is valid; a shard with no valid one returns no rows.
// `row_sink` (optional) sees every row as it is done.
SweepResult run_sweep(const std::string& trace_path, const SweepSpec& spec, unsigned threads = 0, bool progress = true,
                      SweepRowSink* row_sink = nullptr);

struct VertexSweepRow {
  VertexCacheSpec cache;
  VertexStreamStats stats;
  std::size_t configuration = 0;  // index in `caches`
};
// Post-transform vertex reuse models (vertex_caches() of a spec) in one pass over the vertex fetches.
std::vector<VertexSweepRow> run_vertex_sweep(const std::string& trace_path, const std::vector<VertexCacheSpec>& caches,
                                             bool flush_per_draw = true, const SweepShard& shard = {});

}  // namespace rastrace
