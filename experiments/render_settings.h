// The settings of a scene render as the commands spell them (`rastrace render`, `compare`,
// `texsweep`, the report): scene, image size, filter, wrap, LOD formula, traversal, culling,
// lighting, triangle order; their parsing into the pipeline's options; and the trace metadata a
// render with them records. Binding them to command-line flags is the commands' business.
#pragma once

#include <string>

#include "pipeline/render_scene.h"
#include "scenes/scene.h"
#include "traces/trace_metadata.h"

namespace rastrace {

struct SceneRenderFlags {
  std::string scene;
  std::string size;  // "WxH"; empty: the scene's own
  std::string filter = "trilinear";
  unsigned aniso = 1;  // GL_TEXTURE_MAX_ANISOTROPY: 1 (isotropic) to 16 (raster/anisotropy.h)
  std::string aniso_rule = "ellipse";  // ellipse (llvmpipe's) | probes (EXT_texture_filter_anisotropic's)
  std::string wrap = "repeat";
  std::string lod = "lengths";  // lengths | max_component (compare: auto)
  std::string raster = "scanline";
  std::string cull = "none";
  bool lighting = false;
  std::string order = "original";
  unsigned order_cache = 16;
  std::string depth_test = "early";  // early | late (raster/rasterizer.h)
  bool hiz = false;                  // hierarchical Z on 8x8 tiles
  unsigned threads = 0;              // raster threads; 0: every core (the output does not depend on it)
  std::string texture_format;        // empty: each texture's own (the scene file's, else rgba8)
};

// The scene with the size override applied.
Scene load_render_scene(const SceneRenderFlags& flags);
// Sampler, traversal, depth test, hierarchical Z, culling, lighting from the flags (the LOD
// formula as given).
RenderOptions render_options_from(const SceneRenderFlags& flags);

// What a trace of this render says about itself: scene, ordering, frame size, filter, texture
// levels, and (in `extra`) raster, wrap, lod, cull, lighting, depth test, hierarchical Z and, above
// 1, the maximum anisotropy (absent: 1, as in traces older than it). Every command that records a
// render's trace builds its metadata here, so all traces state the same settings.
TraceMetadata render_trace_metadata(const SceneRenderFlags& flags, const Scene& scene, const TextureLevels& levels);

}  // namespace rastrace
