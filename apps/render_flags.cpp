#include "apps/render_flags.h"

#include "apps/option_checks.h"
#include "cache_sim/cache_spec.h"
#include "core/error.h"
#include "core/units.h"
#include "raster/sampler.h"

namespace rastrace {

void add_anisotropy_flags(CLI::App& command, unsigned& aniso, std::string& rule) {
  command
      .add_option("--aniso", aniso,
                  "Maximum anisotropy 1..16 (GL_TEXTURE_MAX_ANISOTROPY): above 1, llvmpipe's elliptical filter")
      ->check(whole_number(1, kMaxAnisotropy))
      ->capture_default_str();
  command
      .add_option("--aniso-rule", rule,
                  "With --aniso above 1: ellipse (llvmpipe's elliptical average of one level, cross-checked) or "
                  "probes (EXT_texture_filter_anisotropic: up to N trilinear probes along the major axis, as GPUs)")
      ->capture_default_str();
}

void add_scene_render_flags(CLI::App& command, SceneRenderFlags& flags) {
  command.add_option("scene", flags.scene, "Scene: builtin:grid|bunny|spider, a JSON scene or a mesh file")->required();
  command.add_option("--size", flags.size, "Image size WxH (default: the scene's)");
  command
      .add_option("--filter", flags.filter, "nearest, linear, nearest_mipmap_nearest, linear_mipmap_nearest, trilinear")
      ->capture_default_str();
  add_anisotropy_flags(command, flags.aniso, flags.aniso_rule);
  command.add_option("--wrap", flags.wrap, "repeat or clamp_to_edge")->capture_default_str();
  command.add_option("--raster", flags.raster, "Traversal inside a triangle: scanline, tiled8 or hilbert (8x8 tiles along the screen Hilbert curve)")
      ->capture_default_str();
  command.add_option("--cull", flags.cull, "Face culling: none, back or front")->capture_default_str();
  command.add_flag("--lighting", flags.lighting, "Gouraud lighting with one directional light");
  command
      .add_option("--depth-test", flags.depth_test,
                  "early (before shading and texturing, as GPUs do for opaque geometry) or late")
      ->capture_default_str();
  command.add_flag("--hiz", flags.hiz, "Hierarchical Z: reject 2x2 quads against each 8x8 tile's farthest depth");
  command.add_option("--threads", flags.threads,
                     "Raster threads (default: every core); images and traces are the same for any count");
  command.add_option("--texture-format", flags.texture_format,
                     "Store every texture as rgba8, bc1, bc3, bc4, bc5, bc7, astc4x4 or astc8x8: each mip level is "
                     "encoded and decoded at load (default: each texture's format in the scene file, else rgba8)");
  command.add_option("--order", flags.order, "Triangle ordering (rastrace reorder --help lists them)")
      ->capture_default_str();
  command.add_option("--order-cache", flags.order_cache, "Cache size the ordering optimizes for")->check(whole_number(1, 65536))
      ->capture_default_str();
}

VertexCacheSpec parse_vcache_spec(const std::string& text) { return parse_vertex_cache(text, "--vcache"); }

TextureCacheSpec parse_tcache_spec(const std::string& text) {
  const ByteCacheChoice choice = parse_byte_cache(text, "--tcache");
  return {choice.cache, choice.layout};
}

}  // namespace rastrace
