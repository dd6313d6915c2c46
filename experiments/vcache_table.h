// The post-transform vertex cache under each ordering, as `rastrace vcache` and the report print
// it: one row per algorithm, policy and cache size with ACMR, ATVR, misses, indices per triangle,
// strips, Hoppe's bandwidth, the vertex-buffer bytes fetched and overfetch, and run time.
//
// Bandwidth is Hoppe 1999's equation 1, bytes per triangle = 32 r + 2 b: vertex_bytes (32 by default) per vertex
// shaded (r = ACMR) and 2 per index sent (b = indices per triangle). b counts every index in the
// stream, the restart index included, so a strip restart is charged: a new strip costs its restart
// index and the two indices that prime it, 6 bytes, the per-strip term of Hoppe's section 6 cost
// (32 bytes per miss + 6 per strip); a swap's repeated index costs 2. A triangle list sends 3
// indices per triangle (6 bytes).
// With reuse models (`--model all`, `--cache model=...`, cache_sim/vertex_reuse.h) one row per
// algorithm and model instead, with the model's warps and SIMD lane use, every model's parameters
// stated; each algorithm orders once, for `target` (16 when 0), so a row compares one order
// across models.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cache_sim/vertex_fetch.h"
#include "cache_sim/vertex_reuse.h"
#include "core/table.h"
#include "reorder/ordering.h"

namespace rastrace {

struct VcacheTableSpec {
  std::string algorithms = "all";  // "all" (those that apply to the mesh) or "a,b,c"
  std::vector<unsigned> caches = {8, 12, 16, 20, 24, 32};
  std::vector<VertexCachePolicy> policies = {VertexCachePolicy::Fifo};
  unsigned target = 0;  // 0: each algorithm orders for the simulated size
  std::uint64_t seed = 1;
  double time_budget = 60.0;
  std::uint64_t iteration_budget = 0;  // local optimization; 0: until no improvement
  bool with_time = true;               // run times differ between runs: leave them out for byte-identical tables
  // Count transforms as NVIDIA Mesh Tools charged them (cache_sim/eviction_charged.h), which is
  // how Castano's grid tables were counted; FIFO only. False: true misses.
  bool eviction_charged = false;
  // Vertex-buffer fetch (cache_sim/vertex_fetch.h): bytes per vertex (also the bandwidth's) and
  // the byte cache the ordering's index stream reads the vertex buffer through.
  std::uint32_t vertex_bytes = 32;
  CacheConfig fetch_cache = meshopt_fetch_cache();
  // Non-empty: also write the per-face miss image (experiments/miss_image.h) of the one ordering
  // and cache the table has (InputError unless one algorithm, one policy and one size).
  std::string miss_image;
  // Reuse models to simulate instead of caches x policies (empty: caches x policies).
  std::vector<VertexCacheSpec> models;
};

// The algorithms of an --algo list: "all" (those that apply to the mesh) or "a,b,c"; throws
// InputError for an unknown or empty name.
std::vector<const ReorderAlgorithm*> select_algorithms(const std::string& list, const Mesh& mesh);

// Throws InputError for an unknown algorithm, a cache of 0 entries, or eviction-charged LRU.
Table vcache_table(const Mesh& mesh, const std::string& mesh_spec, const VcacheTableSpec& spec);

// From a table with models: shader invocations per triangle (ACMR) with one row per algorithm and
// one column per model, and each order's rank under each model (1 = fewest invocations).
Table vcache_model_pivot(const Table& model_table);

// Bars of ACMR per algorithm, one colour per model (gnuplot; PNG or SVG by extension).
void write_vcache_model_plot(const std::string& path, const Table& model_table);

}  // namespace rastrace
