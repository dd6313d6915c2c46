// Renders a whole Scene into a framebuffer: one draw per object (its triangle list in file order,
// per-face materials, unless RenderOptions::object_draws says otherwise), with the scene's camera. The reference
// renderer uses the same matrices (camera_matrices) so that both draw exactly the same frame.
#pragma once

#include <optional>
#include <span>

#include <glm/mat4x4.hpp>
#include <glm/vec4.hpp>

#include "pipeline/pipeline.h"
#include "raster/framebuffer.h"
#include "scenes/scene.h"
#include "traces/sink.h"
#include "traces/trace_metadata.h"

namespace rastrace {

struct CameraMatrices {
  glm::mat4 view{1.0f};
  glm::mat4 projection{1.0f};  // GL clip space: z in [-w, w]
};
// lookAt(eye, target, up) and perspective(fov_y, width / height, near, far), as glFrustum.
CameraMatrices camera_matrices(const Scene& scene);

struct RenderOptions {
  PipelineOptions pipeline;
  bool debug_planes = false;              // write counts and centre-on-edge flags
  std::optional<glm::vec4> clear_colour;  // default: the scene's background
  // Optional: one draw call per scene object (e.g. a reordered index stream); empty draws each
  // object's own triangle list. The spans must outlive the call.
  std::span<const DrawCall> object_draws;
  // Optional, with object_draws: the object each draw is of (any number of draws per object, in
  // this order); empty means draw o is of object o.
  std::span<const std::uint32_t> draw_objects;
};

struct RenderResult {
  Framebuffer framebuffer;
  PipelineStats pipeline;
  RasterStats raster;
};

// Throws InputError for an invalid scene (indices, materials, textures out of range).
RenderResult render_scene(const Scene& scene, const RenderOptions& options, EventSink* sink);

struct RenderStats {
  PipelineStats pipeline;
  RasterStats raster;
};
// The same into a framebuffer the caller keeps from frame to frame, as a GL context keeps its
// render target: it is cleared (to options.clear_colour, else the scene's background) and drawn
// into, and a new frame allocates and faults in no 6 MB of fresh pages. It must be the scene's
// size, with debug planes exactly when options.debug_planes; InputError otherwise.
RenderStats render_scene_into(Framebuffer& framebuffer, const Scene& scene, const RenderOptions& options,
                              EventSink* sink);

// Every texture's level sizes, as render_scene's texel accesses address them: what the trace
// metadata records and a live cache bank lays out in memory.
TextureLevels texture_levels(const Scene& scene);

}  // namespace rastrace
