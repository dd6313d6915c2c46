#include "apps/render_wiring.h"

#include <algorithm>

#include "core/error.h"
#include "core/units.h"
#include "raster/rasterizer.h"
#include "raster/sampler.h"
#include "reorder/ordering.h"
#include "scenes/scene_io.h"

namespace rastrace {

void add_scene_render_flags(CLI::App& command, SceneRenderFlags& flags) {
  command.add_option("scene", flags.scene, "Scene: builtin:grid|bunny|spider, a JSON scene or a mesh file")->required();
  command.add_option("--size", flags.size, "Image size WxH (default: the scene's)");
  command
      .add_option("--filter", flags.filter, "nearest, linear, nearest_mipmap_nearest, linear_mipmap_nearest, trilinear")
      ->capture_default_str();
  command.add_option("--wrap", flags.wrap, "repeat or clamp_to_edge")->capture_default_str();
  command.add_option("--raster", flags.raster, "Traversal inside a triangle: scanline or tiled8")
      ->capture_default_str();
  command.add_option("--cull", flags.cull, "Face culling: none, back or front")->capture_default_str();
  command.add_flag("--lighting", flags.lighting, "Gouraud lighting with one directional light");
  command.add_option("--order", flags.order, "Triangle ordering (rastrace reorder --help lists them)")
      ->capture_default_str();
  command.add_option("--order-cache", flags.order_cache, "Cache size the ordering optimizes for")
      ->capture_default_str();
}

Scene load_render_scene(const SceneRenderFlags& flags) {
  Scene scene = load_scene(flags.scene);
  if (!flags.size.empty()) {
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(flags.size.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || x != 'x' || w < 1 || h < 1 ||
        w > 16384 || h > 16384)
      throw InputError("--size '" + flags.size + "': expected WxH with 1..16384 pixels on each side, e.g. 1024x768");
    scene.width = w;
    scene.height = h;
  }
  return scene;
}

RenderOptions render_options_from(const SceneRenderFlags& flags) {
  RenderOptions options;
  SamplerState& sampler = options.pipeline.raster.sampler;
  sampler = parse_filter(flags.filter);
  sampler.wrap_s = sampler.wrap_t = parse_wrap(flags.wrap);
  if (flags.lod == "lengths")
    sampler.lod = LodFormula::Lengths;
  else if (flags.lod == "max_component")
    sampler.lod = LodFormula::MaxComponent;
  else
    throw InputError("--lod '" + flags.lod + "': expected lengths or max_component");
  options.pipeline.raster.traversal = parse_traversal(flags.raster);
  options.pipeline.cull = parse_cull_mode(flags.cull);
  options.pipeline.lighting.enabled = flags.lighting;
  options.pipeline.lighting.direction = glm::vec3(0.3f, 0.5f, 1.0f);
  return options;
}

OrderedDraws order_scene(const Scene& scene, const std::string& order, const ReorderParams& params) {
  OrderedDraws out;
  if (order == "original") return out;
  const ReorderAlgorithm& algorithm = find_reorder_algorithm(order);
  out.indices.resize(scene.objects.size());
  out.materials.resize(scene.objects.size());
  out.draws.resize(scene.objects.size());
  for (std::size_t o = 0; o < scene.objects.size(); ++o) {
    const Mesh& mesh = scene.objects[o].mesh;
    Ordering ordering = algorithm.run(mesh, params);
    out.draws[o].type = ordering.type;
    out.draws[o].restart_index = ordering.restart_index;
    if (mesh.materials.size() > 1 && !mesh.face_material.empty())
      out.materials[o] = primitive_materials(mesh, ordering);
    out.indices[o] = std::move(ordering.indices);
    out.draws[o].indices = out.indices[o];
    out.draws[o].primitive_materials = out.materials[o];
  }
  return out;
}

VertexCacheSpec parse_vcache_spec(const std::string& text) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) throw InputError("--vcache '" + text + "': expected POLICY:ENTRIES, e.g. fifo:16");
  VertexCacheSpec spec;
  spec.policy = parse_vertex_cache_policy(text.substr(0, colon));
  const std::uint64_t entries = parse_count(text.substr(colon + 1), "--vcache");
  if (entries < 1 || entries > 65536) throw InputError("--vcache '" + text + "': expected 1..65536 entries");
  spec.entries = static_cast<unsigned>(entries);
  return spec;
}

CacheConfig parse_tcache_spec(const std::string& text) {
  const std::vector<std::string> items = split_list(text, "--tcache");
  if (items.size() != 4)
    throw InputError("--tcache '" + text + "': expected SIZE,LINE,ASSOC,POLICY, e.g. 16KiB,64B,4way,lru");
  CacheConfig config;
  config.size_bytes = parse_byte_size(items[0], "--tcache size");
  const std::uint64_t line = parse_byte_size(items[1], "--tcache line size");
  if (line > 0xFFFFFFFFull) throw InputError("--tcache '" + text + "': line size too large");
  config.line_bytes = static_cast<std::uint32_t>(line);
  const std::string& assoc = items[2];
  if (assoc == "full")
    config.assoc = 0;
  else if (assoc == "direct")
    config.assoc = 1;
  else if (assoc.size() > 3 && assoc.ends_with("way"))
    config.assoc = static_cast<std::uint32_t>(parse_count(assoc.substr(0, assoc.size() - 3), "--tcache associativity"));
  else
    throw InputError("--tcache '" + text + "': associativity '" + assoc + "': expected Nway, direct or full");
  config.policy = parse_replacement_policy(items[3]);
  validate(config);
  return config;
}

TextureLevels texture_levels(const Scene& scene) {
  TextureLevels levels;
  for (const Texture& texture : scene.textures) {
    std::vector<LevelSize> sizes;
    for (const Image& image : texture.levels)
      sizes.push_back(LevelSize{static_cast<std::uint32_t>(image.width), static_cast<std::uint32_t>(image.height)});
    levels.push_back(std::move(sizes));
  }
  return levels;
}

void TeeSink::begin_draw(const DrawInfo& draw) {
  for (EventSink* sink : sinks_) sink->begin_draw(draw);
}
void TeeSink::vertex_fetches(std::span<const VertexFetch> fetches) {
  for (EventSink* sink : sinks_) sink->vertex_fetches(fetches);
}
void TeeSink::texel_accesses(std::span<const TexelAccess> accesses) {
  for (EventSink* sink : sinks_) sink->texel_accesses(accesses);
}
void TeeSink::end_draw() {
  for (EventSink* sink : sinks_) sink->end_draw();
}
void TeeSink::finish() {
  for (EventSink* sink : sinks_) sink->finish();
}

}  // namespace rastrace
