// Triangle rasterization: fixed-point edge functions with 8 sub-pixel bits, a top-left fill rule,
// 2x2 quads visited in scanline or 8x8-tiled order, perspective-correct interpolation, an
// early depth test (GL_LESS), mipmapped texturing modulated by the vertex colour.
//
// Coordinates are image coordinates: x to the right, y down, row 0 at the top, pixel (x, y)
// centred at (x + 1/2, y + 1/2). Vertices snap to 1/256 pixel (24.8 fixed point); the edge
// functions are then exact 64-bit integers, so coverage never depends on rounding.
//
// Fill rule (D3D's and GL implementations' top-left rule): a pixel centre exactly on an edge
// belongs to the triangle only if that edge is a *top* edge (horizontal, the triangle below it)
// or a *left* edge (the triangle to its right). A centre on an edge shared by two triangles is
// therefore drawn exactly once, and a centre on a shared vertex exactly once.
//
// The depth test runs early by default (before shading and texturing: a rejected fragment reads no
// texel, as GPUs do for opaque geometry) or late (every covered fragment is shaded, then tested);
// the image is the same. An optional hierarchical Z keeps the farthest depth of each 8x8-pixel tile
// and rejects a 2x2 quad none of whose covered fragments is nearer, without reading depth.
// Framebuffer events (traces/events.h), per quad: the depth-test read of its covered pixels, the
// depth and colour writes of those that passed, recorded only for a sink that wants them.
// The level of detail is computed once per 2x2 quad from the quad's differences (right minus
// left along the top row, bottom minus top along the left column), helper pixels included.
#pragma once

#include <cstdint>
#include <memory>
#include <string>

#include "raster/framebuffer.h"
#include "raster/framebuffer_recorder.h"
#include "raster/sampler.h"
#include "raster/texel_recorder.h"
#include "raster/traversal.h"
#include "raster/triangle_setup.h"
#include "traces/sink.h"

namespace rastrace {

// What a triangle is drawn with.
struct TriangleState {
  const Texture* texture = nullptr;  // nullptr: the vertex colour alone
  std::uint32_t texture_id = 0;      // in TexelAccess events
  std::uint32_t triangle = 0;        // the drawn triangle's number in the frame, in events
};

enum class DepthTest : std::uint8_t {
  Early,  // before shading and texturing (the default)
  Late,   // after: every covered fragment is shaded and textured
};
// "early" or "late"; throws InputError otherwise.
DepthTest parse_depth_test(const std::string& text);
const char* to_string(DepthTest test);

struct RasterOptions {
  Traversal traversal = Traversal::Scanline;
  SamplerState sampler;
  DepthTest depth_test = DepthTest::Early;
  bool hierarchical_z = false;  // reject quads against each 8x8 tile's farthest depth
  // 1: draw each triangle as it arrives. More: bin triangles to screen tiles drawn by this many
  // threads (raster/parallel_rasterizer.h); images, statistics and events are the same.
  unsigned threads = 1;
};

struct RasterStats {
  std::uint64_t triangles = 0;                 // triangles set up with a non-zero area
  std::uint64_t quads = 0;                     // 2x2 quads with at least one covered pixel
  std::uint64_t fragments = 0;                 // covered pixels
  std::uint64_t fragments_passed = 0;          // covered pixels that passed the depth test (written)
  std::uint64_t fragments_shaded = 0;          // shaded and textured: those passed (early test), all (late)
  std::uint64_t fragments_rejected_early = 0;  // by the early test or hierarchical Z, before shading
  std::uint64_t quads_rejected_hiz = 0;        // by hierarchical Z, without a depth read
  std::uint64_t fragments_textured = 0;        // shaded fragments that sampled a texture
  std::uint64_t texel_reads = 0;
  // Every count summed (frames drawn one after another).
  RasterStats& operator+=(const RasterStats& r) {
    triangles += r.triangles;
    quads += r.quads;
    fragments += r.fragments;
    fragments_passed += r.fragments_passed;
    fragments_shaded += r.fragments_shaded;
    fragments_rejected_early += r.fragments_rejected_early;
    quads_rejected_hiz += r.quads_rejected_hiz;
    fragments_textured += r.fragments_textured;
    texel_reads += r.texel_reads;
    return *this;
  }
};

class HierarchicalZ;
class ParallelRasterizer;

class Rasterizer {
 public:
  // `sink` may be nullptr (no events); the framebuffer must outlive the rasterizer.
  Rasterizer(Framebuffer& framebuffer, const RasterOptions& options, EventSink* sink);
  ~Rasterizer();
  Rasterizer(const Rasterizer&) = delete;
  Rasterizer& operator=(const Rasterizer&) = delete;

  // Where the caller sends its own events (draws, vertex fetches, finish) so that they stay in
  // order with the rasterizer's: the sink itself with one thread; with more, a sink that holds
  // them until the triangles drawn before them have been rasterized. nullptr without a sink.
  EventSink* event_sink();

  // Any winding; zero-area triangles draw nothing. Vertices must lie within +-2^22 pixels
  // (the pipeline's guard band keeps them far inside).
  void draw(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c, const TriangleState& state);
  // Clears the framebuffer to `colour` and `depth` after the triangles drawn so far. With one
  // thread at once; with more, the other threads clear it while the calling one sets up and
  // bins the next triangles (finish() completes it).
  void clear(const glm::vec4& colour, float depth = 1.0f);
  // Hands buffered texel events to the sink (call at the end of a draw).
  void flush();
  // Draws everything still pending (threads > 1; event_sink()'s finish() does it too). The
  // framebuffer and stats() are complete after it.
  void finish();

  RasterStats stats() const;
  const RasterOptions& options() const { return options_; }

 private:
  template <bool kTextured, bool kDebug>
  void traverse(const TriangleSetup& setup, const TriangleState& state);

  Framebuffer& framebuffer_;
  RasterOptions options_;
  TexelRecorder recorder_;
  FramebufferRecorder framebuffer_recorder_;
  RasterStats stats_;
  unsigned hilbert_bits_;                         // traversal_hilbert_bits of the framebuffer
  std::unique_ptr<HierarchicalZ> hiz_;            // hierarchical Z only
  std::unique_ptr<ParallelRasterizer> parallel_;  // threads > 1 only
};

}  // namespace rastrace
