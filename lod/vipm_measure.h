// Measurements of VIPM representations at every LoD (or every lod_step-th one), as plain rows:
// one VipmLodRow per (method, LoD), one VipmSummary per method.
//
// Per frame (a frame = the draws of one LoD, caches cold at its start):
// - the post-transform vertex cache (FIFO or LRU, any size; flushed between the draws of a frame,
//   as a new DrawIndexedPrimitive may start cold): vertices transformed, drawn triangles (not
//   degenerate), degenerate triangles submitted; vertices per drawn triangle = ACMR;
// - the index fetches through a byte cache (cache_sim/byte_cache.h) at each index's address;
// - indices and index bytes sent, draw calls, the vertex range handed to each draw;
// - memory (global, per instance), streaming bytes (vipm_representation.h).
// LoD-change cost: the sweep goes from full detail down to the last LoD in lod_step steps (the
// collapse cost of each row is that of reaching it from the row before), then back up (the
// split cost of each row is that of reaching it from the row after).
#pragma once

#include <array>
#include <cstdint>
#include <string>
#include <vector>

#include "cache_sim/cache_config.h"
#include "cache_sim/vertex_cache.h"
#include "lod/vipm_representation.h"

namespace rastrace {

struct VipmMeasureParams {
  VertexCachePolicy policy = VertexCachePolicy::Fifo;
  unsigned cache_entries = 16;
  CacheConfig index_cache{};  // 16 KiB, 64-byte lines, 4-way LRU
  std::uint32_t lod_step = 1;
};

struct VipmLodRow {
  std::string method;
  std::uint32_t lod = 0;
  std::uint32_t level = 0;
  std::uint64_t triangles = 0;   // drawn (non-degenerate)
  std::uint64_t degenerate = 0;  // submitted and rejected
  std::uint64_t vertices_transformed = 0;
  double vertices_per_triangle = 0.0;  // ACMR over drawn triangles
  std::uint64_t indices = 0;
  std::uint64_t index_bytes = 0;
  std::uint64_t index_cache_misses = 0;
  std::uint64_t index_bytes_fetched = 0;  // lines fetched by the index cache
  std::uint32_t draw_calls = 0;
  std::array<std::uint32_t, 2> draw_vertex_range{0, 0};  // per draw (a third draw is folded into the second)
  std::uint64_t global_bytes = 0;
  std::uint64_t instance_bytes = 0;
  std::uint64_t streaming_bytes = 0;
  LodChangeCost collapse_cost;  // reaching this LoD from the previous row (down the sweep)
  LodChangeCost split_cost;     // reaching this LoD from the next row (back up)
};

struct VipmSummary {
  std::string method;
  std::string layout;  // record or table layout
  std::uint32_t index_bits = 16;
  std::uint32_t levels = 1;
  std::uint32_t lods_measured = 0;
  double mean_vertices_per_triangle = 0.0;  // mean of the rows' ACMR
  double mean_degenerate_fraction = 0.0;    // degenerate / submitted triangles, mean over rows
  double mean_index_bytes = 0.0;            // per frame
  double mean_draw_calls = 0.0;
  std::uint64_t global_bytes = 0;
  std::uint64_t vertex_bytes = 0, index_list_bytes = 0, record_bytes = 0, table_bytes = 0;
  std::uint64_t max_instance_bytes = 0;
  double mean_instance_bytes = 0.0;
  double mean_streaming_bytes = 0.0;
  double index_writes_per_collapse = 0.0;
  double index_writes_per_split = 0.0;
  std::uint64_t level_switches = 0;  // down and up
  double bytes_copied_per_level_switch = 0.0;
};

// Throws InputError for lod_step 0 or a cache of 0 entries or an invalid index cache.
std::vector<VipmLodRow> measure_vipm(VipmRepresentation& representation, const VipmMeasureParams& params = {});
VipmSummary summarize_vipm(const VipmRepresentation& representation, const std::vector<VipmLodRow>& rows);

}  // namespace rastrace
