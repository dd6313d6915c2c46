// Shared wiring of `rastrace render` and `rastrace compare`: scene loading with the options both
// take (image size, filter, wrap, LOD formula, traversal, culling, lighting, triangle order), the
// command-line cache specs, and an EventSink that feeds several sinks.
#pragma once

#include <memory>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "cache_sim/cache_config.h"
#include "cache_sim/live_bank_sink.h"
#include "pipeline/render_scene.h"
#include "reorder/ordering.h"
#include "scenes/scene.h"
#include "traces/sink.h"

namespace rastrace {

struct SceneRenderFlags {
  std::string scene;
  std::string size;  // "WxH"; empty: the scene's own
  std::string filter = "trilinear";
  std::string wrap = "repeat";
  std::string lod = "lengths";  // lengths | max_component (compare: auto)
  std::string raster = "scanline";
  std::string cull = "none";
  bool lighting = false;
  std::string order = "original";
  unsigned order_cache = 16;
};

void add_scene_render_flags(CLI::App& command, SceneRenderFlags& flags);

// The scene with the size override applied.
Scene load_render_scene(const SceneRenderFlags& flags);
// Sampler, traversal, culling, lighting from the flags (the LOD formula as given).
RenderOptions render_options_from(const SceneRenderFlags& flags);

// One draw per object in the requested triangle order; `storage` keeps the index streams alive.
struct OrderedDraws {
  std::vector<std::vector<std::uint32_t>> indices;
  std::vector<std::vector<std::uint32_t>> materials;
  std::vector<DrawCall> draws;
};
// Empty when the order is "original" (the file's own triangle lists). Each object is drawn from
// its ordering's own stream (list, strip, ...), every triangle with its face's material.
OrderedDraws order_scene(const Scene& scene, const std::string& order, const ReorderParams& params);

// "fifo:16" / "lru:32".
VertexCacheSpec parse_vcache_spec(const std::string& text);
// "16KiB,64B,4way,lru": size, line size, associativity (Nway, direct, full), policy.
CacheConfig parse_tcache_spec(const std::string& text);

// Every texture's level sizes, as the trace metadata and the live cache bank want them.
TextureLevels texture_levels(const Scene& scene);

// Forwards every event to each sink in turn.
class TeeSink final : public EventSink {
 public:
  explicit TeeSink(std::vector<EventSink*> sinks) : sinks_(std::move(sinks)) {}
  void begin_draw(const DrawInfo& draw) override;
  void vertex_fetches(std::span<const VertexFetch> fetches) override;
  void texel_accesses(std::span<const TexelAccess> accesses) override;
  void end_draw() override;
  void finish() override;

 private:
  std::vector<EventSink*> sinks_;
};

}  // namespace rastrace
