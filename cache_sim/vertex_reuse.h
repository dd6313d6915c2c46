// Post-transform vertex reuse models, one spec for all of them:
//   cache        a FIFO or LRU of `entries` vertices shared by the whole draw (1999-2009 hardware)
//   warp FIFO    the FIFO flushed at warp and primitive-group boundaries, meshoptimizer's analyzer
//                model (cache_sim/warp_fifo.h)
//   batch        Kerbl et al. 2018's batch models of NVIDIA, AMD and Intel GPUs (cache_sim/kerbl_batch.h)
// and the named presets of the cache-spec grammar (`model=nv-pascal`, cache_sim/cache_spec.h).
//
// Every model reports shader invocations (misses), warps (or waves, SIMD threads) and lane slots
// (invocations rounded up to the warp width per warp), beside ACMR and ATVR. A plain cache has no
// warps: the draw counts as one warp, as meshoptimizer counts a stream without a warp limit.
// Warp and batch models see primitives: a list as sent (degenerate triangles included, as
// meshoptimizer analyzes them), a strip as the list of its drawn triangles (degenerates dropped,
// as cache_sim/eviction_charged.h does), an adjacency list as its 6-index primitives.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <variant>
#include <vector>

#include "cache_sim/kerbl_batch.h"
#include "cache_sim/vertex_cache.h"
#include "cache_sim/warp_fifo.h"

namespace rastrace {

enum class VertexReuseKind : std::uint8_t { Cache, WarpFifo, KerblBatch };

struct VertexCacheSpec {
  VertexCachePolicy policy = VertexCachePolicy::Fifo;
  unsigned entries = 16;
  unsigned warp = 0;       // warp FIFO: vertices per warp (0 = no limit)
  unsigned primgroup = 0;  // warp FIFO: primitives per warp (0 = no limit)
  VertexReuseKind kind = VertexReuseKind::Cache;  // Cache and WarpFifo are told apart by warp/primgroup
  KerblGpu gpu = KerblGpu::NvidiaD3d;             // KerblBatch only
  std::string preset{};                           // the preset name, or "" when spelled out

  bool batched() const { return kind != VertexReuseKind::Cache; }
};

struct VertexReusePreset {
  const char* name;
  const char* description;  // the full parameters and their source
  VertexCacheSpec spec;
};

// nv-pascal, nv-maxwell, amd-gcn, intel (meshoptimizer's profiles), kerbl-nv, kerbl-nv-gl,
// kerbl-amd, kerbl-intel (Kerbl et al. 2018), in that order.
std::span<const VertexReusePreset> vertex_reuse_presets();
// nullptr when `name` is not a preset.
const VertexReusePreset* find_vertex_reuse_preset(const std::string& name);

// A cache of `entries` with warp and primgroup limits (both 0: a plain FIFO or LRU cache).
VertexCacheSpec vertex_cache_spec(VertexCachePolicy policy, unsigned entries, unsigned warp = 0, unsigned primgroup = 0);

// The model's name in tables: the preset, or the spec ("entries=16,policy=fifo,warp=32").
std::string vertex_reuse_name(const VertexCacheSpec& spec);
// Every parameter in words: "FIFO 32 entries, warps of 32 vertices, 32 primitives per warp".
std::string vertex_reuse_parameters(const VertexCacheSpec& spec);
// Lanes a warp of this model has (0 for a plain cache, which has no warps).
unsigned vertex_reuse_lanes(const VertexCacheSpec& spec);

// One model's running state, fed index by index (plain caches) or primitive by primitive.
class VertexReuseModel {
 public:
  explicit VertexReuseModel(const VertexCacheSpec& spec);

  bool per_index() const { return spec_.kind == VertexReuseKind::Cache; }
  // Plain caches: one fetched index. Returns true on a miss.
  bool index(std::uint32_t vertex) {
    const bool miss = !std::get<VertexCache>(state_).access(vertex);
    misses_ += miss;
    open_ |= miss;
    return miss;
  }
  // Warp and batch models: one primitive's fetched indices.
  void primitive(const std::uint32_t* vertices, unsigned count);
  // A draw boundary: the open warp or batch ends and the model is emptied.
  void flush();

  std::uint64_t misses() const;
  std::uint64_t warps() const;
  std::uint64_t lane_slots() const { return warps() * vertex_reuse_lanes(spec_); }
  const VertexCacheSpec& spec() const { return spec_; }

 private:
  VertexCacheSpec spec_;
  std::variant<VertexCache, WarpFifo, KerblBatch> state_;
  std::uint64_t misses_ = 0;        // plain caches
  std::uint64_t closed_warps_ = 0;  // plain caches: draws with a miss
  bool open_ = false;
};

// The whole stream under one model: VertexStreamStats with misses, warps and lanes set.
VertexStreamStats simulate_vertex_reuse(std::span<const std::uint32_t> indices, PrimitiveType type,
                                        const VertexCacheSpec& spec, RestartIndex restart_index = kNoRestart);

}  // namespace rastrace
