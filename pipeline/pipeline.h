// The geometry pipeline of one frame: index stream -> vertex fetch -> post-transform vertex
// cache (cache_sim's VertexCache decides which vertices are shaded) -> vertex shading ->
// primitive assembly -> clipping -> perspective divide -> viewport -> culling -> rasterizer.
//
// Primitive types (core/index_stream.h): a triangle list; a strip with an optional restart index,
// degenerate triangles and GL's alternating winding (odd triangles drawn as (v1, v0, v2)); a list
// with adjacency (6 indices, GL_TRIANGLES_ADJACENCY: 0, 2, 4 is the triangle, 1, 3, 5 the
// adjacent vertices). Shader invocations are counted as hardware does: one per cache miss,
// the cache cleared at the start of each draw, restart indices not looked up. Degenerate
// triangles (a repeated index) are fetched and counted, never rasterized.
//
// Events: begin_draw, then one VertexFetch per index (primitive_start on the first index of each
// list triangle, each strip and each adjacency primitive), the rasterizer's TexelAccess events,
// end_draw. A PrimitiveHook sees every assembled primitive (the adjacency edge stage uses it).
#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include <glm/mat4x4.hpp>

#include "cache_sim/vertex_cache.h"
#include "pipeline/clipper.h"
#include "pipeline/vertex_shader.h"
#include "raster/rasterizer.h"
#include "scenes/mesh.h"
#include "traces/event_window.h"
#include "traces/events.h"
#include "traces/sink.h"

namespace rastrace {

enum class CullMode : std::uint8_t { None, Back, Front };
// "none", "back" or "front"; throws InputError otherwise.
CullMode parse_cull_mode(const std::string& text);

struct PipelineOptions {
  VertexCachePolicy cache_policy = VertexCachePolicy::Fifo;
  unsigned cache_entries = 16;
  CullMode cull = CullMode::None;  // front faces wind counter-clockwise in GL window space
  Lighting lighting;
  float guard_band = 4096.0f;  // pixels beyond each viewport side; 0 clips the sides exactly
  RasterOptions raster;
};

// One draw call: an index stream into a mesh's vertices.
struct DrawCall {
  std::span<const std::uint32_t> indices;
  PrimitiveType type = PrimitiveType::TriangleList;
  RestartIndex restart_index = kNoRestart;
  std::uint32_t material = 0;  // index into Mesh::materials (none: white, untextured)
  // Optional: one material per primitive (lists and adjacency lists), e.g. Mesh::face_material.
  std::span<const std::uint32_t> primitive_materials;
};

struct PipelineStats {
  std::uint64_t draws = 0;
  std::uint64_t lookups = 0;          // indices fetched (restart indices excluded)
  std::uint64_t vertices_shaded = 0;  // vertex shader invocations (cache misses)
  std::uint64_t primitives = 0;       // assembled primitives, degenerates included
  std::uint64_t triangles = 0;        // non-degenerate triangles submitted ("drawn" for ACMR)
  std::uint64_t degenerate = 0;
  std::uint64_t culled = 0;      // triangles removed by face culling
  std::uint64_t outside = 0;     // triangles entirely outside one clip plane
  std::uint64_t clipped = 0;     // triangles that needed clipping
  std::uint64_t rasterized = 0;  // triangles handed to the rasterizer (after clipping)
  double acmr() const { return triangles ? double(vertices_shaded) / double(triangles) : 0.0; }
  // Every count summed (frames drawn one after another).
  PipelineStats& operator+=(const PipelineStats& p) {
    draws += p.draws;
    lookups += p.lookups;
    vertices_shaded += p.vertices_shaded;
    primitives += p.primitives;
    triangles += p.triangles;
    degenerate += p.degenerate;
    culled += p.culled;
    outside += p.outside;
    clipped += p.clipped;
    rasterized += p.rasterized;
    return *this;
  }
};

// Every primitive as assembled, before clipping: for the adjacency edge stage and other probes.
struct AssembledPrimitive {
  std::uint32_t draw = 0;
  std::uint32_t primitive = 0;  // within the draw
  std::uint32_t triangle = 0;   // frame-wide number of the triangle (as in TexelAccess events)
  bool degenerate = false;
  std::array<std::uint32_t, 3> triangle_indices{};  // in GL winding
  std::span<const std::uint32_t> indices;           // the primitive's indices (3 or 6)
  std::span<const ShadedVertex> shaded;             // indexed by vertex id; valid for these indices
};

class PrimitiveHook {
 public:
  virtual ~PrimitiveHook() = default;
  virtual void primitive(const AssembledPrimitive& primitive) = 0;
};

class Pipeline {
 public:
  // `sink` and the textures may be nullptr / empty. The framebuffer's size is the viewport.
  Pipeline(Framebuffer& framebuffer, const PipelineOptions& options, EventSink* sink);

  void set_camera(const glm::mat4& view, const glm::mat4& projection);
  void set_primitive_hook(PrimitiveHook* hook) { hook_ = hook; }

  // Draws `call` with the mesh's vertices placed by `model`. Throws InputError for an index
  // >= the vertex count, a material or texture index out of range.
  void draw(const Mesh& mesh, const glm::mat4& model, const DrawCall& call, std::span<const Texture> textures);
  // Clears the framebuffer in order with the draws (Rasterizer::clear). With several raster
  // threads the clear too is complete only after finish().
  void clear(const glm::vec4& colour, float depth = 1.0f) { rasterizer_.clear(colour, depth); }
  // Flushes events, draws what the rasterizer still holds (RasterOptions::threads > 1) and calls
  // the sink's finish(). With several raster threads the framebuffer is complete only after it.
  void finish();

  const PipelineStats& stats() const { return stats_; }
  RasterStats raster_stats() const { return rasterizer_.stats(); }

 private:
  void flush_fetches();
  void triangle(const Mesh& mesh, std::uint32_t a, std::uint32_t b, std::uint32_t c, const Material& material,
                const TriangleState& state);

  Framebuffer& framebuffer_;
  PipelineOptions options_;
  EventSink* sink_;
  PrimitiveHook* hook_ = nullptr;
  Rasterizer rasterizer_;
  Clipper clipper_;
  VertexCache cache_;
  glm::mat4 view_{1.0f}, projection_{1.0f};
  VertexShader shader_;
  std::vector<ShadedVertex> shaded_;       // by vertex id; valid while the vertex is in the cache
  ClipPolygon clipped_;                    // triangle(): what the clipper leaves
  std::array<RasterVertex, 9> projected_;  // triangle(): its vertices in image coordinates
  static constexpr std::size_t kFetchBatch = 1024;
  // Set once sink_ is final (the rasterizer's ordered sink with several threads).
  std::optional<EventWindow<VertexFetch, kFetchBatch>> fetches_;
  std::uint32_t draw_number_ = 0;
  std::uint32_t triangle_number_ = 0;
  PipelineStats stats_;
};

}  // namespace rastrace
