#include "experiments/render_settings.h"

#include <algorithm>
#include <cstdio>
#include <string>
#include <thread>

#include "core/error.h"
#include "raster/rasterizer.h"
#include "raster/sampler.h"
#include "scenes/scene_io.h"

namespace rastrace {

Scene load_render_scene(const SceneRenderFlags& flags) {
  std::optional<TextureFormat> texture_format;
  if (!flags.texture_format.empty()) texture_format = parse_texture_format(flags.texture_format, "--texture-format");
  Scene scene = load_scene(flags.scene, texture_format);
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
  if (flags.aniso < 1 || flags.aniso > static_cast<unsigned>(kMaxAnisotropy))
    throw InputError("--aniso " + std::to_string(flags.aniso) + ": expected a maximum anisotropy from 1 to " +
                     std::to_string(kMaxAnisotropy) + " (1: isotropic filtering)");
  sampler.max_anisotropy = static_cast<int>(flags.aniso);
  try {
    sampler.aniso_rule = parse_anisotropy_rule(flags.aniso_rule);
  } catch (const InputError&) {
    throw InputError("--aniso-rule '" + flags.aniso_rule + "': expected ellipse or probes");
  }
  if (flags.lod == "lengths")
    sampler.lod = LodFormula::Lengths;
  else if (flags.lod == "max_component")
    sampler.lod = LodFormula::MaxComponent;
  else
    throw InputError("--lod-formula '" + flags.lod + "': expected lengths or max_component");
  options.pipeline.raster.traversal = parse_traversal(flags.raster);
  options.pipeline.raster.depth_test = parse_depth_test(flags.depth_test);
  options.pipeline.raster.hierarchical_z = flags.hiz;
  options.pipeline.raster.threads = flags.threads ? flags.threads : std::max(1u, std::thread::hardware_concurrency());
  options.pipeline.cull = parse_cull_mode(flags.cull);
  options.pipeline.lighting.enabled = flags.lighting;
  options.pipeline.lighting.direction = glm::vec3(0.3f, 0.5f, 1.0f);
  return options;
}

TraceMetadata render_trace_metadata(const SceneRenderFlags& flags, const Scene& scene, const TextureLevels& levels) {
  TraceMetadata metadata;
  metadata.scene = flags.scene;
  metadata.ordering = flags.order;
  metadata.width = static_cast<std::uint32_t>(scene.width);
  metadata.height = static_cast<std::uint32_t>(scene.height);
  metadata.filter = flags.filter;
  metadata.textures = levels;
  metadata.extra = {{"raster", flags.raster},
                    {"wrap", flags.wrap},
                    {"lod", flags.lod},
                    {"cull", flags.cull},
                    {"lighting", flags.lighting ? "on" : "off"},
                    {"depth_test", flags.depth_test},
                    {"hiz", flags.hiz ? "on" : "off"}};
  if (flags.aniso > 1) {
    metadata.extra["aniso"] = std::to_string(flags.aniso);
    metadata.extra["aniso_rule"] = flags.aniso_rule;
  }
  return metadata;
}

}  // namespace rastrace
