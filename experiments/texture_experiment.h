// The texture-cache experiment of Yang, Mitra and Huang, generalised: for each triangle ordering
// and each rasterization order (Hakura and Gupta), render the scene once, record its texel trace,
// and sweep texture caches over the trace; beside each row, the ordering's post-transform vertex
// cache ACMR, so the two caches' trade-off reads off one table. Each render also measures the
// whole frame's traffic live (vertex, texture, depth and colour, experiments/frame_traffic.h).
//
// Orderings are applied per scene object, and each object is drawn from its ordering's own index
// stream (a strip, a list with prefetch degenerates, ...; order_scene), exactly as `rastrace
// render --order` draws it, so a live render and the sweep of its trace agree to the miss.
#pragma once

#include <string>
#include <vector>

#include "cache_sim/live_bank_sink.h"
#include "cache_sim/sweep.h"
#include "core/table.h"
#include "experiments/frame_traffic.h"
#include "experiments/render_settings.h"

namespace rastrace {

struct TextureExperiment {
  std::string title;        // the table's title
  SceneRenderFlags render;  // scene, size, filter, wrap, culling (raster, order: per run)
  std::vector<std::string> orders{"strip", "texgroup"};
  std::vector<std::string> rasters{"scanline"};
  std::string texgroup_base = "strip";
  std::string texgroup_regions = "auto";
  VertexCacheSpec vertex_cache;  // the post-transform cache orderings target and ACMR uses
  SweepSpec sweep;
  FrameCaches frame;  // the frame-traffic caches (its vertex cache is vertex_cache)
  std::string trace_dir;  // where the traces are kept; empty: a private temporary
                          // folder, removed before returning (trace_path empty)
  std::string image_dir;  // empty: no images; else <order>-<raster>.png
};

struct TextureRun {
  std::string order;
  std::string raster;
  std::string trace_path;
  std::string image_path;
  VertexStreamStats vertex;  // the ordering's own index stream through the vertex cache
  std::uint64_t fragments = 0;
  std::uint64_t texel_accesses = 0;
  SweepResult sweep;
  FrameTraffic traffic;  // the whole frame through experiment.frame's caches
};

// Throws InputError for an unknown ordering, raster, or a scene that fails to load.
std::vector<TextureRun> run_texture_experiment(const TextureExperiment& experiment);

// One row per run and cache configuration: order, raster, size_bytes, line_bytes, assoc, policy,
// layout, accesses, misses, miss_rate, bytes_per_fragment, vertex_acmr.
Table texture_experiment_table(const TextureExperiment& experiment, const std::vector<TextureRun>& runs);

// The frame's four streams per run (frame_traffic_table), with the scene and every cache stated.
Table frame_experiment_table(const TextureExperiment& experiment, const std::vector<TextureRun>& runs);
std::vector<FrameTrafficRow> frame_traffic_rows(const std::vector<TextureRun>& runs);

}  // namespace rastrace
