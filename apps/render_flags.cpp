#include "apps/render_flags.h"

#include "core/error.h"
#include "core/units.h"

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

}  // namespace rastrace
