// Sweeps: every combination of cache size, line size, associativity, replacement policy and
// texture layout over one trace, run in parallel. Each worker streams the trace file through its
// own LiveBankSink (the bank `rastrace replay` and live rendering use), holding the caches of one
// (layout, line size) group, so memory stays bounded by the caches, not the trace; OPT groups hold
// their line stream (see opt_cache.h for the limit).
// Combinations whose geometry is impossible (fewer lines than ways) are skipped and listed.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cache_sim/cache_config.h"
#include "cache_sim/live_bank_sink.h"
#include "cache_sim/texture_layout.h"

namespace rastrace {

// Which accesses of the trace feed the byte caches.
enum class SweepSource { Texel, VertexBuffer, Address };
const char* to_string(SweepSource source);
// "texel", "vertex", "address"; throws InputError otherwise.
SweepSource parse_sweep_source(const std::string& text);

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
};

struct SweepRow {
  CacheConfig cache;
  std::string layout;  // layout name, "stride32" for vertex buffers, "-" for addresses
  CacheStats stats;
};

struct SweepResult {
  std::vector<SweepRow> rows;        // sorted by layout, policy, line, assoc, size
  std::vector<std::string> skipped;  // impossible combinations, described
};

// threads = 0: one per core. progress: a bar on stderr when it is a terminal.
SweepResult run_sweep(const std::string& trace_path, const SweepSpec& spec, unsigned threads = 0, bool progress = true);

struct VertexSweepRow {
  VertexCacheSpec cache;
  VertexStreamStats stats;
};
// Post-transform vertex caches: every policy x entry count in one pass over the vertex fetches.
std::vector<VertexSweepRow> run_vertex_sweep(const std::string& trace_path,
                                             const std::vector<VertexCachePolicy>& policies,
                                             const std::vector<unsigned>& entries, bool flush_per_draw = true);

}  // namespace rastrace
