// `rastrace render SCENE -o image.png [--trace out.rtrace] [--vcache entries=16,policy=fifo]
//  [--tcache size=16KiB,line=64B,assoc=4,policy=lru,layout=block4] [--raster tiled8] [--filter trilinear]
//  [--vipm METHOD --lod N] [--json]`:
// draws a scene with the software pipeline (in a triangle ordering, or at a VIPM level of detail),
// simulating a post-transform vertex cache and a texture cache live (and writing the trace when
// asked), and prints what the frame cost: triangles drawn, vertices shaded, ACMR, fragments,
// texel accesses, texture misses and bytes per fragment.
#include <iostream>
#include <memory>
#include <optional>

#include "apps/commands.h"
#include "apps/render_flags.h"
#include "cache_sim/live_bank_sink.h"
#include "cache_sim/texture_layout.h"
#include "core/error.h"
#include "core/table.h"
#include "core/units.h"
#include "experiments/vipm_render.h"
#include "pipeline/scene_order.h"
#include "traces/tee_sink.h"
#include "traces/trace_writer.h"

namespace rastrace {

namespace {

struct RenderCommand {
  SceneRenderFlags flags;
  std::string output;
  std::string depth;
  std::string trace;
  std::string vcache = "entries=16,policy=fifo";
  std::string tcache = "size=16KiB,line=64B,assoc=4,policy=lru,layout=block4";
  std::string old_layout;  // --layout, replaced by the texture cache's layout key
  std::string vipm;        // a VIPM method: draw the LoD `lod` instead of an ordering
  std::string lod;         // collapses done, with --vipm
  std::string format = "md";
  bool json = false;
};

void run_render(const RenderCommand& command) {
  const TableFormat format = command.json ? TableFormat::Json : parse_table_format(command.format);
  RenderOptions options = render_options_from(command.flags);
  const VertexCacheSpec vcache = parse_vcache_spec(command.vcache);
  options.pipeline.cache_policy = vcache.policy;
  options.pipeline.cache_entries = vcache.entries;
  if (!command.old_layout.empty())
    throw InputError("--layout '" + command.old_layout + "': write the layout in the texture cache spec, e.g. " +
                     "--tcache size=16KiB,line=64B,assoc=4,policy=lru,layout=" + command.old_layout);
  const TextureCacheSpec tcache = parse_tcache_spec(command.tcache);

  if (command.vipm.empty() && !command.lod.empty())
    throw InputError("--lod '" + command.lod.substr(0, 32) + "': the level of detail needs --vipm METHOD" +
                     " (the texture LOD formula is --lod-formula)");
  std::optional<VipmScene> vipm;
  OrderedDraws ordered;
  if (!command.vipm.empty()) {
    if (command.flags.order != "original")
      throw InputError("--order " + command.flags.order + " with --vipm: a VIPM representation has its own order");
    VipmSceneSpec spec;
    spec.method = command.vipm;
    spec.lod = parse_vipm_lod(command.lod.empty() ? "0" : command.lod);
    vipm.emplace(build_vipm_scene(load_render_scene(command.flags), spec));
    options.object_draws = vipm->draws;
    options.draw_objects = vipm->draw_objects;
  }
  const Scene scene = vipm ? vipm->scene : load_render_scene(command.flags);
  if (!vipm) {
    ReorderParams order_params;
    order_params.cache_size = command.flags.order_cache;
    ordered = order_scene(scene, command.flags.order, order_params);
    options.object_draws = ordered.draws;
  }
  const TextureLevels levels = texture_levels(scene);

  CacheBankConfig bank_config;
  bank_config.vertex = {vcache};
  bank_config.texture = {tcache};
  bank_config.three_c = false;
  LiveBankSink bank(bank_config, levels);
  std::vector<EventSink*> sinks = {&bank};
  std::optional<TraceWriter> writer;
  if (!command.trace.empty()) {
    TraceMetadata metadata = render_trace_metadata(command.flags, scene, levels);
    if (vipm) {
      metadata.ordering = "vipm:" + command.vipm;
      metadata.extra["vipm_lod"] = describe_vipm_lods(vipm->parts);
    }
    writer.emplace(command.trace, std::move(metadata));
    sinks.push_back(&*writer);
  }
  TeeSink tee(sinks);
  const RenderResult result = render_scene(scene, options, &tee);  // calls finish() on every sink
  result.framebuffer.write_colour(command.output);
  if (!command.depth.empty()) result.framebuffer.write_depth(command.depth);

  const PipelineStats& p = result.pipeline;
  const RasterStats& r = result.raster;
  const CacheStats& t = bank.texture_stats().at(0);
  const VertexStreamStats& v = bank.vertex_stats().at(0);
  // The live model and the pipeline count the same misses; a warp or batch model is measured by
  // the bank alone (the pipeline shades through its FIFO or LRU of the same entries).
  if (!vcache.batched() && v.misses != p.vertices_shaded)
    throw std::logic_error("vertex cache model disagrees with the pipeline's shader invocations");

  Table table;
  table.title = "Frame: " + scene.name;
  table.parameters = {{"scene", command.flags.scene},
                      {"size", std::to_string(scene.width) + "x" + std::to_string(scene.height)},
                      {"order", vipm ? "vipm:" + command.vipm : command.flags.order},
                      {"vcache", command.vcache},
                      {"tcache", describe(tcache.cache)},
                      {"layout", layout_name(tcache.layout)},
                      {"raster", command.flags.raster},
                      {"filter", command.flags.filter},
                      {"wrap", command.flags.wrap},
                      {"lod_formula", command.flags.lod},
                      {"cull", command.flags.cull},
                      {"image", command.output}};
  if (vipm) {
    table.parameters.emplace_back("vipm", command.vipm);
    table.parameters.emplace_back("vipm_lod", describe_vipm_lods(vipm->parts));
  }
  if (!command.trace.empty()) table.parameters.emplace_back("trace", command.trace);
  table.columns = {{"triangles", "triangles drawn", 0},
                   {"degenerate", "degenerate", 0},
                   {"culled", "culled", 0},
                   {"vertices_shaded", "vertices shaded", 0},
                   {"acmr", "ACMR", 3},
                   {"fragments", "fragments", 0},
                   {"fragments_shaded", "fragments shaded", 0},
                   {"texel_accesses", "texel accesses", 0},
                   {"texture_misses", "texture misses", 0},
                   {"texture_miss_rate", "miss rate", 4},
                   {"texture_bytes", "bytes fetched", 0},
                   {"bytes_per_fragment", "bytes/fragment", 3}};
  const std::uint64_t shaded = vcache.batched() ? v.misses : p.vertices_shaded;
  const double acmr = p.triangles ? double(shaded) / double(p.triangles) : 0.0;
  std::vector<TableCell> row = {p.triangles,      p.degenerate, p.culled, shaded, acmr, r.fragments,
                                r.fragments_passed, r.texel_reads, t.misses, t.miss_rate(), t.bytes_fetched,
                                r.fragments_passed ? double(t.bytes_fetched) / double(r.fragments_passed) : 0.0};
  if (vcache.batched()) {
    table.parameters.emplace_back("vcache_model", vertex_reuse_parameters(vcache));
    table.columns.push_back({"warps", "warps", 0});
    table.columns.push_back({"lane_use", "lane use", 3});
    row.emplace_back(v.warps);
    row.push_back(v.lane_slots ? TableCell(v.lane_use()) : TableCell());
  }
  table.add_row(std::move(row));
  std::cout << render_table(table, format);
}

}  // namespace

void add_render_command(CLI::App& app) {
  CLI::App* command =
      app.add_subcommand("render", "Draw a scene, simulate its vertex and texture caches, write the image");
  auto options = std::make_shared<RenderCommand>();
  add_scene_render_flags(*command, options->flags);
  command->add_option("-o,--output", options->output, "Colour image (PNG, or any format by extension)")->required();
  command->add_option("--depth", options->depth, "Depth buffer as a float EXR");
  command->add_option("--trace", options->trace, "Write the vertex and texel trace (rastrace container)");
  command->add_option("--vcache", options->vcache, "Post-transform vertex cache (cache spec, README)")
      ->capture_default_str();
  command->add_option("--tcache", options->tcache, "Texture cache and layout (cache spec, README)")
      ->capture_default_str();
  command->add_option("--layout", options->old_layout)->group("");  // the old spelling: an error naming the new
  command
      ->add_option("--lod-formula", options->flags.lod,
                   "Texture LOD scale factor: lengths (GL eq. 8.6) or max_component (8.7)")
      ->capture_default_str();
  command->add_option("--vipm", options->vipm,
                      "Draw a VIPM level of detail: vanilla, skipstrips, skiplists, mixed, mixedstrips or sliding");
  command->add_option("--lod", options->lod, "With --vipm: the level of detail, as collapses done (0: full detail)");
  command->add_option("--format", options->format, "md, csv, latex or json")->capture_default_str();
  command->add_flag("--json", options->json, "Same as --format json");
  command->footer(
      "Examples:\n"
      "  rastrace render builtin:bunny -o bunny.png\n"
      "  rastrace render builtin:grid -o grid.png --raster tiled8 --tcache size=8KiB,line=32B,assoc=2,policy=fifo,"
      "layout=morton --json\n"
      "  rastrace render builtin:bunny -o bunny.png --order tipsy --vcache entries=16,policy=fifo --trace "
      "bunny.rtrace\n"
      "  rastrace render builtin:bunny -o bunny-lod.png --vipm sliding --lod 30000 --trace bunny-lod.rtrace");
  command->callback([options] { run_render(*options); });
}

}  // namespace rastrace
