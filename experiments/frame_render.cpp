#include "experiments/frame_render.h"

#include <optional>
#include <stdexcept>

#include "cache_sim/cache_spec.h"
#include "cache_sim/live_bank_sink.h"
#include "cache_sim/texture_layout.h"
#include "cache_sim/vertex_reuse.h"
#include "core/error.h"
#include "experiments/frame_traffic.h"
#include "experiments/vipm_render.h"
#include "pipeline/scene_order.h"
#include "traces/tee_sink.h"
#include "traces/trace_writer.h"

namespace rastrace {

namespace {

// Frames 2..N drawn into the hierarchy that drew frame 1; one row per frame and level with that
// frame's share of the counts.
Table repeated_frames_table(const FrameSpec& spec, const Scene& scene, const RenderOptions& options,
                            HierarchySink& sink) {
  std::vector<std::vector<LevelStats>> after = {sink.hierarchy(0).stats()};
  for (unsigned f = 1; f < spec.frames; ++f) {
    render_scene(scene, options, &sink);
    after.push_back(sink.hierarchy(0).stats());
  }
  Table t;
  t.title = "Cache hierarchy per frame";
  t.parameters = {{"scene", spec.flags.scene},
                  {"frames", spec.frames},
                  {"camera", "static (the scene's)"},
                  {"hierarchy", describe(sink.hierarchy(0).config())}};
  t.columns = {{"frame", "frame", 0},       {"level", "level", 0},
               {"accesses", "accesses", 0}, {"misses", "misses", 0},
               {"line_misses", "line misses", 0}, {"bytes_fetched", "bytes from next level", 0}};
  for (std::size_t f = 0; f < after.size(); ++f)
    for (std::size_t k = 0; k < after[f].size(); ++k) {
      const LevelStats& now = after[f][k];
      const LevelStats before = f ? after[f - 1][k] : LevelStats{};
      t.add_row({f + 1, "L" + std::to_string(k + 1), now.accesses - before.accesses, now.misses - before.misses,
                 now.line_misses - before.line_misses, now.bytes_fetched - before.bytes_fetched});
    }
  return t;
}

}  // namespace

Frame render_frame(const FrameSpec& spec) {
  if (spec.frames == 0) throw InputError("--frames 0: expected at least one frame");
  if (spec.frames > 1 && spec.hierarchy.levels.empty())
    throw InputError("--frames " + std::to_string(spec.frames) +
                     ": repeated frames are simulated through a cache hierarchy: add --level SPEC (one or more)");
  const SceneRenderFlags& flags = spec.flags;
  RenderOptions options = render_options_from(flags);
  const VertexCacheSpec vcache = parse_vertex_cache(spec.vcache, "--vcache");
  options.pipeline.cache_policy = vcache.policy;
  options.pipeline.cache_entries = vcache.entries;
  const ByteCacheChoice tcache = parse_byte_cache(spec.tcache, "--tcache");
  FrameCaches caches;
  caches.vertex = vcache;
  caches.texture = {tcache.cache, tcache.layout};
  caches.depth = parse_framebuffer_cache(spec.zcache, "--zcache", FramebufferBuffer::Depth);
  caches.colour = parse_framebuffer_cache(spec.ccache, "--ccache", FramebufferBuffer::Colour);

  if (spec.vipm.empty() && !spec.lod.empty())
    throw InputError("--lod '" + spec.lod.substr(0, 32) + "': the level of detail needs --vipm METHOD" +
                     " (the texture LOD formula is --lod-formula)");
  std::optional<VipmScene> vipm;
  OrderedDraws ordered;
  if (!spec.vipm.empty()) {
    if (flags.order != "original")
      throw InputError("--order " + flags.order + " with --vipm: a VIPM representation has its own order");
    VipmSceneSpec vipm_spec;
    vipm_spec.method = spec.vipm;
    vipm_spec.lod = parse_vipm_lod(spec.lod.empty() ? "0" : spec.lod);
    vipm.emplace(build_vipm_scene(load_render_scene(flags), vipm_spec));
    options.object_draws = vipm->draws;
    options.draw_objects = vipm->draw_objects;
  }
  const Scene scene = vipm ? vipm->scene : load_render_scene(flags);
  if (!vipm) {
    ReorderParams order_params;
    order_params.cache_size = flags.order_cache;
    ordered = order_scene(scene, flags.order, order_params);
    options.object_draws = ordered.draws;
  }
  const TextureLevels levels = texture_levels(scene);

  LiveBankSink bank(frame_bank_config(caches), levels,
                    FrameSize{static_cast<std::uint32_t>(scene.width), static_cast<std::uint32_t>(scene.height)});
  std::vector<EventSink*> sinks = {&bank};
  std::vector<HierarchySpec> hierarchies;
  if (!spec.hierarchy.levels.empty()) hierarchies.push_back(parse_hierarchy(spec.hierarchy));
  HierarchySink hierarchy_sink(hierarchies, levels);
  if (!hierarchies.empty()) sinks.push_back(&hierarchy_sink);
  std::optional<TextureMissMapSink> miss_map;
  if (spec.miss_map) {
    if (tcache.cache.policy == ReplacementPolicy::Opt)
      throw InputError("--miss-map with --tcache policy=opt: a live miss map needs fifo, lru or random (replay the "
                       "trace for OPT's map)");
    miss_map.emplace(tcache.cache, tcache.layout, levels, static_cast<std::uint32_t>(scene.width),
                     static_cast<std::uint32_t>(scene.height));
    sinks.push_back(&*miss_map);
  }
  std::optional<TraceWriter> writer;
  if (!spec.trace.empty()) {
    TraceMetadata metadata = render_trace_metadata(flags, scene, levels);
    if (vipm) {
      metadata.ordering = "vipm:" + spec.vipm;
      metadata.extra["vipm_lod"] = describe_vipm_lods(vipm->parts);
    }
    writer.emplace(spec.trace, std::move(metadata));
    sinks.push_back(&*writer);
  }
  TeeSink tee(sinks);
  Frame frame{render_scene(scene, options, &tee), {}, {}, {}};  // render_scene calls finish() on every sink

  const PipelineStats& p = frame.result.pipeline;
  const RasterStats& r = frame.result.raster;
  const CacheStats& t = bank.texture_stats().at(0);
  const FrameTraffic traffic = measure_frame_traffic(caches, bank, frame.result);
  const VertexStreamStats& v = bank.vertex_stats().at(0);
  // The live model and the pipeline count the same misses; a warp or batch model is measured by
  // the bank alone (the pipeline shades through its FIFO or LRU of the same entries).
  if (!vcache.batched() && v.misses != p.vertices_shaded)
    throw std::logic_error("vertex cache model disagrees with the pipeline's shader invocations");

  Table& table = frame.table;
  table.title = "Frame: " + scene.name;
  table.parameters = {{"scene", flags.scene},
                      {"size", std::to_string(scene.width) + "x" + std::to_string(scene.height)},
                      {"order", vipm ? "vipm:" + spec.vipm : flags.order},
                      {"vcache", spec.vcache},
                      {"tcache", describe(tcache.cache)},
                      {"layout", layout_name(tcache.layout)},
                      {"raster", flags.raster},
                      {"filter", flags.filter},
                      {"wrap", flags.wrap},
                      {"lod_formula", flags.lod},
                      {"cull", flags.cull},
                      {"depth_test", flags.depth_test},
                      {"hiz", flags.hiz ? "on" : "off"},
                      {"image", spec.image}};
  for (auto& parameter : frame_cache_parameters(caches))
    if (parameter.first != "vcache" && parameter.first != "tcache") table.parameters.push_back(std::move(parameter));
  if (vipm) {
    table.parameters.emplace_back("vipm", spec.vipm);
    table.parameters.emplace_back("vipm_lod", describe_vipm_lods(vipm->parts));
  }
  if (!spec.trace.empty()) table.parameters.emplace_back("trace", spec.trace);
  table.columns = {{"triangles", "triangles drawn", 0},
                   {"degenerate", "degenerate", 0},
                   {"culled", "culled", 0},
                   {"vertices_shaded", "vertices shaded", 0},
                   {"acmr", "ACMR", 3},
                   {"fragments", "fragments", 0},
                   {"fragments_shaded", "fragments shaded", 0},
                   {"depth_writes", "depth writes", 0},
                   {"texel_accesses", "texel accesses", 0},
                   {"texture_misses", "texture misses", 0},
                   {"texture_miss_rate", "miss rate", 4},
                   {"bytes_per_fragment", "texture bytes/fragment", 3}};
  for (TableColumn& column : frame_traffic_columns()) table.columns.push_back(std::move(column));
  std::vector<TableCell> row;
  const std::uint64_t shaded = vcache.batched() ? v.misses : p.vertices_shaded;
  for (const std::uint64_t count : {p.triangles, p.degenerate, p.culled, shaded}) row.emplace_back(count);
  row.emplace_back(p.triangles ? double(shaded) / double(p.triangles) : 0.0);
  for (const std::uint64_t count : {r.fragments, r.fragments_shaded, r.fragments_passed, r.texel_reads, t.misses})
    row.emplace_back(count);
  row.emplace_back(t.miss_rate());
  row.emplace_back(r.fragments_shaded ? double(t.bytes_fetched) / double(r.fragments_shaded) : 0.0);
  for (TableCell& cell : frame_traffic_cells(traffic)) row.push_back(std::move(cell));
  if (vcache.batched()) {
    table.parameters.emplace_back("vcache_model", vertex_reuse_parameters(vcache));
    table.columns.push_back({"warps", "warps", 0});
    table.columns.push_back({"lane_use", "lane use", 3});
    row.emplace_back(v.warps);
    row.push_back(v.lane_slots ? TableCell(v.lane_use()) : TableCell());
  }
  table.add_row(std::move(row));
  if (!hierarchies.empty())
    frame.hierarchy.push_back(hierarchy_table({{"scene", flags.scene}, {"raster", flags.raster}, {"order", flags.order}},
                                              hierarchies.front(), hierarchy_sink.hierarchy(0)));
  if (miss_map) {
    if (miss_map->map().stats.accesses == 0)
      throw InputError("--miss-map: the frame read no texels (the scene has no textured draw)");
    frame.miss_map = miss_map->map();
  }
  if (spec.frames > 1) frame.hierarchy.push_back(repeated_frames_table(spec, scene, options, hierarchy_sink));
  return frame;
}

}  // namespace rastrace
