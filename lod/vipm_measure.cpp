#include "lod/vipm_measure.h"

#include <algorithm>

#include "cache_sim/byte_cache.h"
#include "core/error.h"

namespace rastrace {

namespace {

void measure_frame(const VipmRepresentation& r, const VipmMeasureParams& params, ByteCache& index_cache,
                   VipmLodRow& row) {
  index_cache.clear();
  const std::uint32_t ib = r.index_bytes();
  for (const VipmDraw& draw : r.draws()) {
    const VertexStreamStats s =
        simulate_vertex_stream(draw.indices, draw.type, params.policy, params.cache_entries, draw.restart_index);
    row.triangles += s.triangles;
    row.degenerate += s.degenerate;
    row.vertices_transformed += s.misses;
    row.indices += draw.indices.size();
    for (std::size_t i = 0; i < draw.indices.size(); ++i) index_cache.access(draw.index_address + i * ib);
    row.draw_vertex_range[std::min<std::uint32_t>(row.draw_calls, 1)] =
        std::max(row.draw_vertex_range[std::min<std::uint32_t>(row.draw_calls, 1)], draw.vertex_count);
    ++row.draw_calls;
  }
  row.index_bytes = row.indices * ib;
  row.index_cache_misses = index_cache.misses();
  row.index_bytes_fetched = index_cache.misses() * index_cache.config().line_bytes;
  row.vertices_per_triangle = row.triangles ? double(row.vertices_transformed) / double(row.triangles) : 0.0;
}

}  // namespace

std::vector<VipmLodRow> measure_vipm(VipmRepresentation& r, const VipmMeasureParams& params) {
  if (params.lod_step == 0) throw InputError("lod_step 0: expected at least 1");
  if (params.cache_entries == 0) throw InputError("vertex cache of 0 entries: expected at least 1");
  ByteCache index_cache(params.index_cache);
  const std::uint32_t last = r.lod_count() - 1;
  std::vector<std::uint32_t> lods;
  for (std::uint32_t n = 0; n < last; n += params.lod_step) lods.push_back(n);
  lods.push_back(last);

  r.set_lod(0);
  std::vector<VipmLodRow> rows;
  rows.reserve(lods.size());
  for (std::uint32_t n : lods) {
    VipmLodRow row;
    row.method = r.method();
    row.lod = n;
    row.collapse_cost = r.set_lod(n);
    row.level = r.level();
    measure_frame(r, params, index_cache, row);
    const VipmMemory m = r.memory();
    row.global_bytes = m.global_bytes();
    row.instance_bytes = m.instance_bytes;
    row.streaming_bytes = r.streaming_bytes();
    rows.push_back(row);
  }
  for (std::size_t i = rows.size() - 1; i-- > 0;) rows[i].split_cost = r.set_lod(rows[i].lod);
  return rows;
}

VipmSummary summarize_vipm(const VipmRepresentation& r, const std::vector<VipmLodRow>& rows) {
  VipmSummary s;
  s.method = r.method();
  s.layout = r.layout();
  s.index_bits = 8 * r.index_bytes();
  s.levels = r.levels();
  s.lods_measured = static_cast<std::uint32_t>(rows.size());
  const VipmMemory m = r.memory();
  s.global_bytes = m.global_bytes();
  s.vertex_bytes = m.vertex_bytes;
  s.index_list_bytes = m.index_list_bytes;
  s.record_bytes = m.record_bytes;
  s.table_bytes = m.table_bytes;
  LodChangeCost down, up;
  for (const VipmLodRow& row : rows) {
    s.mean_vertices_per_triangle += row.vertices_per_triangle;
    const std::uint64_t submitted = row.triangles + row.degenerate;
    s.mean_degenerate_fraction += submitted ? double(row.degenerate) / double(submitted) : 0.0;
    s.mean_index_bytes += double(row.index_bytes);
    s.mean_draw_calls += row.draw_calls;
    s.max_instance_bytes = std::max(s.max_instance_bytes, row.instance_bytes);
    s.mean_instance_bytes += double(row.instance_bytes);
    s.mean_streaming_bytes += double(row.streaming_bytes);
    down += row.collapse_cost;
    up += row.split_cost;
  }
  if (!rows.empty()) {
    const double n = double(rows.size());
    s.mean_vertices_per_triangle /= n;
    s.mean_degenerate_fraction /= n;
    s.mean_index_bytes /= n;
    s.mean_draw_calls /= n;
    s.mean_instance_bytes /= n;
    s.mean_streaming_bytes /= n;
  }
  s.index_writes_per_collapse = down.collapses ? double(down.index_writes) / double(down.collapses) : 0.0;
  s.index_writes_per_split = up.splits ? double(up.index_writes) / double(up.splits) : 0.0;
  s.level_switches = down.level_switches + up.level_switches;
  s.bytes_copied_per_level_switch =
      s.level_switches ? double(down.bytes_copied + up.bytes_copied) / double(s.level_switches) : 0.0;
  return s;
}

}  // namespace rastrace
