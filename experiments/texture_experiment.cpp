#include "experiments/texture_experiment.h"

#include <filesystem>

#include <unistd.h>

#include "core/error.h"
#include "core/units.h"
#include "pipeline/scene_order.h"
#include "traces/tee_sink.h"
#include "traces/trace_writer.h"

namespace rastrace {

namespace {

void accumulate(VertexStreamStats& total, const VertexStreamStats& part) {
  total.lookups += part.lookups;
  total.misses += part.misses;
  total.triangles += part.triangles;
  total.degenerate += part.degenerate;
  total.vertices += part.vertices;
  total.indices_sent += part.indices_sent;
  total.warps += part.warps;
  total.lane_slots += part.lane_slots;
}

// The orderings' streams through the post-transform cache, object by object (the pipeline
// flushes the cache between draws).
VertexStreamStats vertex_stats(const Scene& scene, const OrderedDraws& ordered, const VertexCacheSpec& cache) {
  VertexStreamStats total;
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    if (ordered.draws.empty()) {
      accumulate(total, simulate_vertex_reuse(scene.objects[o].mesh.indices, PrimitiveType::TriangleList, cache));
    } else {
      const DrawCall& draw = ordered.draws[o];
      accumulate(total, simulate_vertex_reuse(draw.indices, draw.type, cache, draw.restart_index));
    }
  }
  return total;
}

}  // namespace

std::vector<TextureRun> run_texture_experiment(const TextureExperiment& experiment) {
  if (experiment.orders.empty() || experiment.rasters.empty())
    throw InputError("texture experiment: expected at least one ordering and one raster order");
  SceneRenderFlags flags = experiment.render;
  const Scene scene = load_render_scene(flags);
  const TextureLevels levels = texture_levels(scene);
  if (levels.empty())
    throw InputError(flags.scene + ": the scene has no texture, so there is no texture cache to measure");
  // Without a trace folder the traces live only as long as their sweeps: a private temporary one.
  const bool keep_traces = !experiment.trace_dir.empty();
  const std::string trace_dir =
      keep_traces
          ? experiment.trace_dir
          : (std::filesystem::temp_directory_path() / ("rastrace-traces-" + std::to_string(::getpid()))).string();
  struct RemoveTemporary {
    std::string dir;
    ~RemoveTemporary() {
      std::error_code ignored;
      if (!dir.empty()) std::filesystem::remove_all(dir, ignored);
    }
  } cleanup{keep_traces ? std::string() : trace_dir};
  std::filesystem::create_directories(trace_dir);
  if (!experiment.image_dir.empty()) std::filesystem::create_directories(experiment.image_dir);

  std::vector<TextureRun> runs;
  for (const std::string& order : experiment.orders) {
    ReorderParams params;
    params.cache_size = experiment.vertex_cache.entries;
    params.policy = experiment.vertex_cache.policy;
    params.texgroup_base = experiment.texgroup_base;
    params.texgroup_regions = experiment.texgroup_regions;
    const OrderedDraws ordered = order_scene(scene, order, params);
    const VertexStreamStats vertex = vertex_stats(scene, ordered, experiment.vertex_cache);
    for (const std::string& raster : experiment.rasters) {
      flags.raster = raster;
      flags.order = order;
      RenderOptions options = render_options_from(flags);
      options.pipeline.cache_policy = experiment.vertex_cache.policy;
      options.pipeline.cache_entries = experiment.vertex_cache.entries;
      options.object_draws = ordered.draws;

      TextureRun run;
      run.order = order;
      run.raster = raster;
      run.vertex = vertex;
      run.trace_path = (std::filesystem::path(trace_dir) / (order + "-" + raster + ".rtrace")).string();
      TraceMetadata metadata = render_trace_metadata(flags, scene, levels);
      if (order == "texgroup")
        metadata.extra.insert(
            {{"texgroup_base", experiment.texgroup_base}, {"texgroup_regions", experiment.texgroup_regions}});
      TraceWriter writer(run.trace_path, metadata);
      FrameCaches caches = experiment.frame;
      caches.vertex = experiment.vertex_cache;
      LiveBankSink bank(frame_bank_config(caches), levels,
                        FrameSize{static_cast<std::uint32_t>(scene.width), static_cast<std::uint32_t>(scene.height)});
      TeeSink tee({&writer, &bank});
      const RenderResult result = render_scene(scene, options, &tee);  // finishes the writer and the bank
      run.traffic = measure_frame_traffic(caches, bank, result);
      run.fragments = result.raster.fragments;
      run.texel_accesses = result.raster.texel_reads;
      if (!experiment.image_dir.empty()) {
        run.image_path = (std::filesystem::path(experiment.image_dir) / (order + "-" + raster + ".png")).string();
        result.framebuffer.write_colour(run.image_path);
      }
      run.sweep = run_sweep(run.trace_path, experiment.sweep);
      if (!keep_traces) run.trace_path.clear();
      runs.push_back(std::move(run));
    }
  }
  return runs;
}

std::vector<FrameTrafficRow> frame_traffic_rows(const std::vector<TextureRun>& runs) {
  std::vector<FrameTrafficRow> rows;
  for (const TextureRun& run : runs) rows.push_back({run.order, run.raster, run.traffic});
  return rows;
}

Table frame_experiment_table(const TextureExperiment& experiment, const std::vector<TextureRun>& runs) {
  FrameCaches caches = experiment.frame;
  caches.vertex = experiment.vertex_cache;
  std::vector<std::pair<std::string, TableCell>> parameters = {{"scene", experiment.render.scene},
                                                               {"filter", experiment.render.filter},
                                                               {"cull", experiment.render.cull},
                                                               {"depth_test", experiment.render.depth_test},
                                                               {"hiz", experiment.render.hiz ? "on" : "off"}};
  if (!experiment.render.size.empty()) parameters.emplace_back("size", experiment.render.size);
  for (auto& parameter : frame_cache_parameters(caches)) parameters.push_back(std::move(parameter));
  Table table = frame_traffic_table("Frame traffic per ordering: " + experiment.render.scene, std::move(parameters),
                                    frame_traffic_rows(runs));
  table.kind = "frame_traffic";
  return table;
}

Table texture_experiment_table(const TextureExperiment& experiment, const std::vector<TextureRun>& runs) {
  Table table;
  table.title = experiment.title;
  table.kind = "texture_sweep";
  table.parameters = {
      {"scene", experiment.render.scene},
      {"filter", experiment.render.filter},
      {"wrap", experiment.render.wrap},
      {"cull", experiment.render.cull},
      {"vertex_cache", experiment.vertex_cache.batched() ? vertex_reuse_name(experiment.vertex_cache)
                                                         : std::string(to_string(experiment.vertex_cache.policy)) + ":" +
                                                               std::to_string(experiment.vertex_cache.entries)},
      {"texgroup_base", experiment.texgroup_base},
      {"texgroup_regions", experiment.texgroup_regions},
      {"texel_bytes", experiment.sweep.layouts.empty() ? 4u : experiment.sweep.layouts.front().texel_bytes},
  };
  if (!experiment.render.size.empty()) table.parameters.emplace_back("size", experiment.render.size);
  if (!experiment.render.texture_format.empty())
    table.parameters.emplace_back("texture_format", experiment.render.texture_format);
  if (experiment.render.aniso > 1) {
    table.parameters.emplace_back("aniso", static_cast<std::uint64_t>(experiment.render.aniso));
    table.parameters.emplace_back("aniso_rule", experiment.render.aniso_rule);
  }
  table.columns = {{"order", "order", 0},
                   {"raster", "raster", 0},
                   {"size_bytes", "size", 0},
                   {"line_bytes", "line", 0},
                   {"assoc", "assoc", 0},
                   {"policy", "policy", 0},
                   {"layout", "layout", 0},
                   {"accesses", "accesses", 0},
                   {"misses", "misses", 0},
                   {"miss_rate", "miss rate", 4},
                   {"bytes_per_fragment", "bytes/fragment", 2},
                   {"vertex_acmr", "vertex ACMR", 3}};
  for (const TextureRun& run : runs) {
    for (const SweepRow& row : run.sweep.rows) {
      const double per_fragment = run.fragments ? double(row.stats.bytes_fetched) / double(run.fragments) : 0.0;
      table.add_row({run.order, run.raster, row.cache.size_bytes, row.cache.line_bytes, row.cache.assoc,
                     to_string(row.cache.policy), row.layout, row.stats.accesses, row.stats.misses,
                     row.stats.miss_rate(), per_fragment, run.vertex.acmr()});
    }
  }
  return table;
}

}  // namespace rastrace
