#include "cache_sim/vertex_reuse.h"

#include <algorithm>
#include <array>
#include <stdexcept>

#include "core/error.h"

namespace rastrace {

namespace {

VertexCacheSpec kerbl_spec(KerblGpu gpu) {
  VertexCacheSpec spec;
  spec.kind = VertexReuseKind::KerblBatch;
  spec.gpu = gpu;
  return spec;
}

VertexCacheSpec named(VertexCacheSpec spec, const char* name) {
  spec.preset = name;
  return spec;
}

const std::array<VertexReusePreset, 8>& presets() {
  static const std::array<VertexReusePreset, 8> table = {{
      {"nv-pascal",
       "FIFO 32 entries flushed per warp of 32 vertices or 32 triangles (meshoptimizer's NVIDIA Pascal profile)",
       named(vertex_cache_spec(VertexCachePolicy::Fifo, 32, 32, 32), "nv-pascal")},
      {"nv-maxwell",
       "FIFO 16 entries flushed per warp of 32 vertices or 32 triangles (meshoptimizer's NVIDIA Kepler-Maxwell "
       "profile)",
       named(vertex_cache_spec(VertexCachePolicy::Fifo, 16, 32, 32), "nv-maxwell")},
      {"amd-gcn",
       "FIFO 14 entries flushed per wave of 64 vertices or 128 triangles (meshoptimizer's AMD GCN profile)",
       named(vertex_cache_spec(VertexCachePolicy::Fifo, 14, 64, 128), "amd-gcn")},
      {"intel", "FIFO 128 entries, no warp or primitive-group flush (meshoptimizer's Intel profile)",
       named(vertex_cache_spec(VertexCachePolicy::Fifo, 128, 0, 0), "intel")},
      {"kerbl-nv",
       "batches of 96 indices / 32 vertices cut at triangles, reuse while the last use is within 39-44 indices "
       "(position mod 3, D3D), 32 lanes (Kerbl et al. 2018, NVIDIA)",
       named(kerbl_spec(KerblGpu::NvidiaD3d), "kerbl-nv")},
      {"kerbl-nv-gl",
       "batches of 96 indices / 32 vertices cut at triangles, reuse while the last use is within 42 indices (GL), "
       "32 lanes (Kerbl et al. 2018, NVIDIA)",
       named(kerbl_spec(KerblGpu::NvidiaGl), "kerbl-nv-gl")},
      {"kerbl-amd",
       "static batches of 384 indices, cut at 64 vertices, LRU of 15 vertices, 64 lanes (Kerbl et al. 2018, AMD)",
       named(kerbl_spec(KerblGpu::Amd), "kerbl-amd")},
      {"kerbl-intel",
       "batches of 1791 indices / 128 vertices cut at triangles, every vertex of a batch reused, SIMD8 threads "
       "(Kerbl et al. 2018, Intel lower bound)",
       named(kerbl_spec(KerblGpu::Intel), "kerbl-intel")},
  }};
  return table;
}

std::string policy_words(VertexCachePolicy policy) { return policy == VertexCachePolicy::Fifo ? "FIFO" : "LRU"; }

}  // namespace

std::span<const VertexReusePreset> vertex_reuse_presets() { return presets(); }

const VertexReusePreset* find_vertex_reuse_preset(const std::string& name) {
  for (const VertexReusePreset& preset : presets())
    if (name == preset.name) return &preset;
  return nullptr;
}

VertexCacheSpec vertex_cache_spec(VertexCachePolicy policy, unsigned entries, unsigned warp, unsigned primgroup) {
  VertexCacheSpec spec;
  spec.policy = policy;
  spec.entries = entries;
  spec.warp = warp;
  spec.primgroup = primgroup;
  spec.kind = warp || primgroup ? VertexReuseKind::WarpFifo : VertexReuseKind::Cache;
  return spec;
}

std::string vertex_reuse_name(const VertexCacheSpec& spec) {
  if (!spec.preset.empty()) return spec.preset;
  std::string out = "entries=" + std::to_string(spec.entries) + ",policy=" + to_string(spec.policy);
  if (spec.warp) out += ",warp=" + std::to_string(spec.warp);
  if (spec.primgroup) out += ",primgroup=" + std::to_string(spec.primgroup);
  return out;
}

std::string vertex_reuse_parameters(const VertexCacheSpec& spec) {
  if (const VertexReusePreset* preset = find_vertex_reuse_preset(spec.preset)) return preset->description;
  std::string out = policy_words(spec.policy) + " " + std::to_string(spec.entries) + " entries";
  if (spec.kind == VertexReuseKind::Cache) return out + ", no warp or primitive-group flush";
  out += spec.warp ? ", flushed per warp of " + std::to_string(spec.warp) + " vertices" : ", no warp limit";
  out += spec.primgroup ? " or " + std::to_string(spec.primgroup) + " primitives" : ", no primitive-group limit";
  return out;
}

unsigned vertex_reuse_lanes(const VertexCacheSpec& spec) {
  switch (spec.kind) {
    case VertexReuseKind::Cache:
      return 0;
    case VertexReuseKind::WarpFifo:
      return spec.warp;
    case VertexReuseKind::KerblBatch:
      return kerbl_parameters(spec.gpu).lanes;
  }
  return 0;
}

namespace {
std::variant<VertexCache, WarpFifo, KerblBatch> make_state(const VertexCacheSpec& spec) {
  switch (spec.kind) {
    case VertexReuseKind::Cache:
      return VertexCache(spec.policy, spec.entries);
    case VertexReuseKind::WarpFifo:
      if (spec.policy != VertexCachePolicy::Fifo)
        throw InputError("warp=/primgroup= model meshoptimizer's FIFO: expected policy=fifo");
      return WarpFifo(spec.entries, spec.warp, spec.primgroup);
    case VertexReuseKind::KerblBatch:
      return KerblBatch(spec.gpu);
  }
  throw std::logic_error("VertexReuseModel: unknown kind");
}
}  // namespace

VertexReuseModel::VertexReuseModel(const VertexCacheSpec& spec) : spec_(spec), state_(make_state(spec)) {}

void VertexReuseModel::primitive(const std::uint32_t* vertices, unsigned count) {
  if (auto* fifo = std::get_if<WarpFifo>(&state_))
    fifo->primitive(vertices, count);
  else
    std::get<KerblBatch>(state_).primitive(vertices, count);
}

void VertexReuseModel::flush() {
  if (auto* cache = std::get_if<VertexCache>(&state_)) {
    cache->clear();
    closed_warps_ += open_;
    open_ = false;
  } else if (auto* fifo = std::get_if<WarpFifo>(&state_)) {
    fifo->flush();
  } else {
    std::get<KerblBatch>(state_).flush();
  }
}

std::uint64_t VertexReuseModel::misses() const {
  if (std::holds_alternative<VertexCache>(state_)) return misses_;
  if (const auto* fifo = std::get_if<WarpFifo>(&state_)) return fifo->misses();
  return std::get<KerblBatch>(state_).invocations();
}

std::uint64_t VertexReuseModel::warps() const {
  if (std::holds_alternative<VertexCache>(state_)) return closed_warps_ + open_;
  if (const auto* fifo = std::get_if<WarpFifo>(&state_)) return fifo->warps();
  return std::get<KerblBatch>(state_).warps();
}

namespace {

// A whole triangle list through meshoptimizer's warp FIFO: the flat loop its analyzer runs (no
// primitive walk, no model dispatch, stamps sized once), counting what the general walk counts.
VertexStreamStats simulate_warp_fifo_list(std::span<const std::uint32_t> indices, const VertexCacheSpec& spec) {
  VertexStreamStats stats;
  std::size_t vertex_count = 0;
  for (const std::uint32_t v : indices) vertex_count = std::max(vertex_count, std::size_t{v} + 1);
  std::vector<std::uint8_t> seen(vertex_count, 0);
  WarpFifo fifo(spec.entries, spec.warp, spec.primgroup);
  fifo.reserve(vertex_count);
  for (std::size_t i = 0; i < indices.size(); i += 3) {
    const std::uint32_t* t = indices.data() + i;
    for (unsigned k = 0; k < 3; ++k) {
      stats.vertices += !seen[t[k]];
      seen[t[k]] = 1;
    }
    const bool degenerate = t[0] == t[1] || t[1] == t[2] || t[0] == t[2];
    stats.degenerate += degenerate;
    stats.triangles += !degenerate;
    fifo.primitive(t, 3);
  }
  stats.lookups = stats.indices_sent = indices.size();
  stats.misses = fifo.misses();
  stats.warps = fifo.warps();
  stats.lane_slots = stats.warps * vertex_reuse_lanes(spec);
  return stats;
}

}  // namespace

VertexStreamStats simulate_vertex_reuse(std::span<const std::uint32_t> indices, PrimitiveType type,
                                        const VertexCacheSpec& spec, RestartIndex restart_index) {
  if (spec.kind == VertexReuseKind::Cache) {
    VertexStreamStats stats = simulate_vertex_stream(indices, type, spec.policy, spec.entries, restart_index);
    stats.warps = stats.misses > 0;
    return stats;
  }
  if (spec.kind == VertexReuseKind::WarpFifo && type == PrimitiveType::TriangleList && indices.size() % 3 == 0)
    return simulate_warp_fifo_list(indices, spec);
  VertexReuseModel model(spec);
  VertexStreamStats stats;
  std::vector<bool> seen;
  walk_index_stream(
      indices, type, restart_index,
      [&](std::size_t position, bool) {
        ++stats.lookups;
        const std::uint32_t v = indices[position];
        if (v >= seen.size()) seen.resize(std::max<std::size_t>(std::size_t{v} + 1, seen.size() * 2), false);
        if (!seen[v]) {
          seen[v] = true;
          ++stats.vertices;
        }
      },
      [&](const AssembledTriangle& t) {
        if (t.degenerate())
          ++stats.degenerate;
        else
          ++stats.triangles;
        if (type == PrimitiveType::TriangleStrip) {
          if (!t.degenerate()) model.primitive(t.vertices.data(), 3);
        } else {
          model.primitive(indices.data() + t.first, static_cast<unsigned>(t.count));
        }
      });
  stats.indices_sent = indices.size();
  stats.misses = model.misses();
  stats.warps = model.warps();
  stats.lane_slots = model.lane_slots();
  return stats;
}

}  // namespace rastrace
