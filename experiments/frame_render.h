// One frame as `rastrace render` draws it (and the Python module's `render`): a scene in a
// triangle ordering or at a VIPM level of detail, drawn by the software pipeline with a
// post-transform vertex cache, a texture cache and the depth and colour caches simulated live, the
// trace written when asked, and the frame's cost as a one-row table (triangles, vertices shaded,
// ACMR, fragments, texel accesses, texture misses, bytes per fragment, overdraw, and the four
// streams of memory traffic of experiments/frame_traffic.h) that states every setting.
#pragma once

#include <optional>
#include <string>

#include "core/table.h"
#include "experiments/hierarchy_tables.h"
#include "experiments/render_settings.h"
#include "experiments/texture_miss_map.h"
#include "pipeline/render_scene.h"

namespace rastrace {

struct FrameSpec {
  SceneRenderFlags flags;
  std::string vcache = "entries=16,policy=fifo";                          // cache spec, one vertex cache
  std::string tcache = "size=16KiB,line=64B,assoc=4,policy=lru,layout=block4";  // one byte cache and layout
  std::string zcache = "model=attila";  // depth cache (source=depth implied)
  std::string ccache = "model=attila";  // colour cache (source=colour implied)
  std::string trace;  // write the frame's trace (rastrace container) here when not empty
  std::string vipm;   // a VIPM method: draw the LoD `lod` instead of an ordering
  std::string lod;    // collapses done, with vipm
  std::string image;  // where the caller writes the image: stated in the table only
  HierarchyRequest hierarchy;  // render --level ...: a texture cache hierarchy simulated live
  // render --frames N: frames 0..N-1 along the scene's camera path (its static camera without
  // one), through caches that keep their contents between frames (the inter-frame reuse of Cox,
  // Bhandari and Shantz 1998). The table's counts are totals over all frames (its "frames"
  // parameter says how many), the image is the last frame's, the trace holds every frame
  // (each chunk stamped with its frame), and with a hierarchy a "Caches per frame" table follows its totals.
  unsigned frames = 1;
  bool miss_map = false;  // render --miss-map: charge the texture cache's misses to their pixels (frame 1)
};

struct Frame {
  RenderResult result;  // several frames: the last frame's image, the counts of all frames
  Table table;  // one row; title "Frame: <scene>"
  std::vector<Table> hierarchy;  // with spec.hierarchy: "Cache hierarchy" (totals), "Caches per frame" (frames > 1)
  std::optional<TextureMissMap> miss_map;  // with spec.miss_map, under the texture cache (tcache)
};

// Throws InputError for a bad scene, cache spec, ordering or VIPM setting.
Frame render_frame(const FrameSpec& spec);

}  // namespace rastrace
