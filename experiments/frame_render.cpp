#include "experiments/frame_render.h"

#include <optional>
#include <stdexcept>

#include "cache_sim/cache_spec.h"
#include "cache_sim/live_bank_sink.h"
#include "cache_sim/texture_layout.h"
#include "cache_sim/vertex_reuse.h"
#include "core/error.h"
#include "experiments/frame_traffic.h"
#include "experiments/per_frame_caches.h"
#include "experiments/vipm_render.h"
#include "pipeline/scene_order.h"
#include "traces/tee_sink.h"
#include "traces/trace_writer.h"

namespace rastrace {

namespace {

// Forwards every event but finish(): render_scene finishes its sink after each frame, and the
// sinks of several frames (the live caches, the trace writer) are finished once, after the last.
class FramesSink final : public EventSink {
 public:
  explicit FramesSink(EventSink& inner) : inner_(inner) {}
  void begin_frame(std::uint32_t frame) override { inner_.begin_frame(frame); }
  void begin_draw(const DrawInfo& draw) override { inner_.begin_draw(draw); }
  void vertex_fetches(std::span<const VertexFetch> fetches) override { inner_.vertex_fetches(fetches); }
  void texel_accesses(std::span<const TexelAccess> accesses) override { inner_.texel_accesses(accesses); }
  void framebuffer_accesses(std::span<const FramebufferAccess> accesses) override {
    inner_.framebuffer_accesses(accesses);
  }
  bool wants_framebuffer_events() const override { return inner_.wants_framebuffer_events(); }
  void end_draw() override { inner_.end_draw(); }
  void address_accesses(std::span<const AddressAccess> accesses) override { inner_.address_accesses(accesses); }
  void finish() override {}

 private:
  EventSink& inner_;
};

std::string describe_camera(const Scene& scene) {
  if (scene.camera_path.empty()) return "static (the scene's)";
  const std::vector<CameraKeyframe>& keys = scene.camera_path.keyframes;
  return "path of " + std::to_string(keys.size()) + " keyframes, frames " + std::to_string(keys.front().frame) + ".." +
         std::to_string(keys.back().frame);
}

}  // namespace

Frame render_frame(const FrameSpec& spec) {
  if (spec.frames == 0) throw InputError("--frames 0: expected at least one frame");
  if (spec.frames > 1 && spec.miss_map)
    throw InputError("--miss-map with --frames " + std::to_string(spec.frames) +
                     ": a miss map is of one frame (replay --miss-map charges a whole trace's misses)");
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
  Scene scene = vipm ? vipm->scene : load_render_scene(flags);
  const Camera static_camera = scene.camera;
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
  if (spec.hierarchy.decoded_l1 && spec.hierarchy.levels.empty())
    throw InputError("--decoded-l1: expected a hierarchy to apply it to (--level L1 --level L2)");
  if (!spec.hierarchy.levels.empty()) hierarchies.push_back(parse_hierarchy(spec.hierarchy));
  HierarchySink hierarchy_sink(hierarchies, levels);
  FrameCountsSink frame_counts(hierarchy_sink);
  if (!hierarchies.empty()) sinks.push_back(&hierarchy_sink);
  if (!hierarchies.empty() && spec.frames > 1) sinks.push_back(&frame_counts);
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
    if (spec.frames > 1) {
      metadata.extra["frames"] = std::to_string(spec.frames);
      metadata.extra["camera"] = describe_camera(scene);
    }
    writer.emplace(spec.trace, std::move(metadata));
    sinks.push_back(&*writer);
  }
  TeeSink tee(sinks);
  // Frames 0..N-1 along the scene's camera path; the caches keep their contents between frames.
  // One frame is drawn exactly as before (no begin_frame: a single-frame trace, the same events).
  std::optional<RenderResult> last;
  FramesSink frames_sink(tee);
  std::uint64_t covered_pixels = 0;
  for (std::uint32_t f = 0; f < spec.frames; ++f) {
    scene.camera = camera_at(static_camera, scene.camera_path, f);
    if (spec.frames > 1) tee.begin_frame(f);
    RenderResult result = render_scene(scene, options, &frames_sink);
    covered_pixels += result.framebuffer.covered_pixels();
    if (last) {
      result.pipeline += last->pipeline;
      result.raster += last->raster;
    }
    last = std::move(result);  // the last frame's image, every frame's counts
  }
  tee.finish();
  Frame frame{std::move(*last), {}, {}, {}};

  const PipelineStats& p = frame.result.pipeline;
  const RasterStats& r = frame.result.raster;
  const CacheStats& t = bank.texture_stats().at(0);
  FrameTraffic traffic = measure_frame_traffic(caches, bank, frame.result);
  traffic.pixels *= spec.frames;  // per pixel of every frame drawn
  traffic.covered_pixels = covered_pixels;
  const VertexStreamStats& v = bank.vertex_stats().at(0);
  // The live model and the pipeline count the same misses; a warp or batch model is measured by
  // the bank alone (the pipeline shades through its FIFO or LRU of the same entries).
  if (!vcache.batched() && v.misses != p.vertices_shaded)
    throw std::logic_error("vertex cache model disagrees with the pipeline's shader invocations");

  Table& table = frame.table;
  table.title = "Frame: " + scene.name;
  table.kind = "frame";
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
  if (flags.aniso > 1) {
    table.parameters.emplace_back("aniso", static_cast<std::uint64_t>(flags.aniso));
    table.parameters.emplace_back("aniso_rule", flags.aniso_rule);
  }
  for (auto& parameter : frame_cache_parameters(caches))
    if (parameter.first != "vcache" && parameter.first != "tcache") table.parameters.push_back(std::move(parameter));
  if (vipm) {
    table.parameters.emplace_back("vipm", spec.vipm);
    table.parameters.emplace_back("vipm_lod", describe_vipm_lods(vipm->parts));
  }
  if (!spec.trace.empty()) table.parameters.emplace_back("trace", spec.trace);
  if (spec.frames > 1) {
    table.parameters.emplace_back("frames", static_cast<std::uint64_t>(spec.frames));
    table.parameters.emplace_back("camera", describe_camera(scene));
    table.parameters.emplace_back("counts",
                                  "totals over all frames; caches keep their contents between frames; "
                                  "per pixel: of width x height x frames");
  }
  table.columns = {{"triangles", "triangles drawn", 0},
                   {"degenerate", "degenerate", 0},
                   {"culled", "culled", 0},
                   {"vertices_shaded", "vertices shaded", 0},
                   {"acmr", "ACMR", 3},
                   {"fragments", "fragments", 0},
                   {"fragments_shaded", "fragments shaded", 0},
                   {"depth_writes", "depth writes", 0},
                   {"texel_accesses", "texel accesses", 0},
                   {"texels_per_textured_fragment", "texels/textured fragment", 3},
                   {"texture_misses", "texture misses", 0},
                   {"texture_miss_rate", "miss rate", 4},
                   {"bytes_per_fragment", "texture bytes/fragment", 3}};
  for (TableColumn& column : frame_traffic_columns()) table.columns.push_back(std::move(column));
  std::vector<TableCell> row;
  const std::uint64_t shaded = vcache.batched() ? v.misses : p.vertices_shaded;
  for (const std::uint64_t count : {p.triangles, p.degenerate, p.culled, shaded}) row.emplace_back(count);
  row.emplace_back(p.triangles ? double(shaded) / double(p.triangles) : 0.0);
  for (const std::uint64_t count : {r.fragments, r.fragments_shaded, r.fragments_passed, r.texel_reads})
    row.emplace_back(count);
  // 8 for trilinear, 1 to 8 with magnification and NEAREST; with --aniso, the texels inside the
  // ellipses (raster/anisotropy.h), each a probe, or 8 per trilinear probe (anisotropic_probes.h).
  row.emplace_back(r.fragments_textured ? double(r.texel_reads) / double(r.fragments_textured) : 0.0);
  row.emplace_back(t.misses);
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
  if (!hierarchies.empty()) {
    TableParameters parameters = {{"scene", flags.scene}, {"raster", flags.raster}, {"order", flags.order}};
    if (spec.frames > 1) parameters.emplace_back("frames", static_cast<std::uint64_t>(spec.frames));  // totals
    frame.hierarchy.push_back(hierarchy_table(std::move(parameters), hierarchies.front(), hierarchy_sink.hierarchy(0)));
    frame.hierarchy.back().kind = "hierarchy_level";
  }
  if (miss_map) {
    if (miss_map->map().stats.accesses == 0)
      throw InputError("--miss-map: the frame read no texels (the scene has no textured draw)");
    frame.miss_map = miss_map->map();
  }
  if (!hierarchies.empty() && spec.frames > 1) {
    frame.hierarchy.push_back(per_frame_table({{"scene", flags.scene}, {"raster", flags.raster}, {"order", flags.order},
                                               {"camera", describe_camera(scene)},
                                               {"hierarchy", describe(hierarchies.front().hierarchy)}},
                                              {"hierarchy"}, frame_counts));
    frame.hierarchy.back().kind = "hierarchy_frame";
  }
  return frame;
}

}  // namespace rastrace
