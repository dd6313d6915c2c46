// The reference renderer: draws a Scene through Mesa's OSMesa (legacy fixed-function GL) with the
// state rastrace's pipeline uses, so both renderers draw the same frame: the same projection and
// model-view matrices (glLoadMatrixf with camera_matrices()), glViewport, depth test GL_LESS,
// face culling, the same light, every texture uploaded level by level from rastrace's own mip
// chain (so both sample the same texels) with the same filters and wraps, GL_MODULATE. A
// block-compressed texture is uploaded as its blocks (glCompressedTexImage2D per level: S3TC,
// RGTC, BPTC or ASTC LDR, all exposed by softpipe and llvmpipe in Mesa 22.3), so Mesa decodes
// the bits that texcodec decoded.
//
// OSMesa picks its Gallium driver (softpipe or llvmpipe) from GALLIUM_DRIVER once per process,
// at the first context creation: a process cannot use both. Each call therefore forks a child
// process that sets the environment, renders, and sends the image back through a pipe; the
// calling process never creates a GL context and can ask for either driver any number of times.
// OSMesa's buffer has row 0 at the bottom; the returned image has row 0 at the top.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include <glm/vec4.hpp>

#include "pipeline/pipeline.h"
#include "raster/sampler.h"
#include "scenes/scene.h"

namespace rastrace {

enum class ReferenceDriver { Softpipe, Llvmpipe };
// "softpipe" or "llvmpipe"; throws InputError otherwise.
ReferenceDriver parse_reference_driver(const std::string& text);
const char* to_string(ReferenceDriver driver);

struct ReferenceOptions {
  ReferenceDriver driver = ReferenceDriver::Softpipe;
  SamplerState sampler;
  CullMode cull = CullMode::None;
  Lighting lighting;
  std::optional<glm::vec4> clear_colour;  // default: the scene's background
  int frames = 1;                         // frames drawn; the timing is per frame (best of)
  int llvmpipe_threads = -1;              // LP_NUM_THREADS for the child; -1 leaves it alone
};

struct ReferenceImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;   // row 0 at the top
  std::string renderer;             // GL_RENDERER, e.g. "softpipe" or "llvmpipe (LLVM 15.0.6, 256 bits)"
  double best_frame_seconds = 0.0;  // the fastest of `frames` frames, glFinish included
  double first_frame_seconds = 0.0;
  // The fastest frame in CPU time of the child process (all its threads): with llvmpipe's
  // LP_NUM_THREADS=0 this is single-threaded work, comparable under a loaded machine.
  double best_frame_cpu_seconds = 0.0;
};

// Throws InputError if the scene is invalid and std::runtime_error if OSMesa fails (the message
// carries the child's error), or if the driver that answered is not the one asked for.
ReferenceImage render_reference(const Scene& scene, const ReferenceOptions& options);

}  // namespace rastrace
