// The edge stage for triangle-with-adjacency primitives (Sander, Nehab, Chlamtac, Hoppe 2008):
// what a geometry shader does with the primitives of reorder/adjacency/encode.h, as a
// PrimitiveHook of the pipeline (pipeline/pipeline.h).
//
// Per 6-index primitive (i0 .. i5; cover face (i0, i2, i4); position p is the edge i[2p] ->
// i[2p+2 mod 6], i[2p+1] the vertex across it): the cover face is processed; face (i0, i1, i2)
// is processed when i1 is a real vertex (the assigned face); each edge is
//   skipped            when i[2p+1] == i[2p+2 mod 6] (it is covered by another primitive),
//   a boundary edge    when i[2p+1] == i[2p],
//   an interior edge   otherwise, with the faces (i0, i2, i4) and (i[2p], i[2p+1], i[2p+2]).
// An interior edge is a silhouette when exactly one of its faces is front-facing (counter-
// clockwise in window space, decided by the sign of det[x y w] of the clip positions, which is
// the window-space orientation whenever all w > 0), and a sharp feature edge when the angle
// between the two faces' object-space normals exceeds sharp_degrees. Primitives that are not
// 6 indices long are ignored, so the stage can stay attached to any draw.
//
// Lines are drawn 1 pixel wide into a separate framebuffer without depth test, one pixel per
// column (x-major) or row (y-major) at the pixel centres, the last pixel left out, as GL's
// diamond-exit rule gives for most lines; lines with a vertex behind the eye (w <= 0) are not
// drawn (counted in lines_rejected).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "pipeline/pipeline.h"
#include "raster/framebuffer.h"
#include "scenes/mesh.h"

namespace rastrace {

struct EdgeStageOptions {
  float sharp_degrees = 60.0f;  // dihedral threshold for feature edges
  bool draw_silhouettes = true;
  bool draw_sharp = false;
  bool draw_boundary = true;
  std::array<std::uint8_t, 4> colour{255, 255, 255, 255};
  bool record = false;  // keep every processed face and edge (tests)
};

struct EdgeStageStats {
  std::uint64_t primitives = 0;      // 6-index primitives seen
  std::uint64_t cover_faces = 0;     // non-degenerate central faces
  std::uint64_t assigned_faces = 0;  // real faces (i0, i1, i2)
  std::uint64_t edges = 0;           // edges processed (interior + boundary)
  std::uint64_t boundary_edges = 0;
  std::uint64_t silhouette_edges = 0;
  std::uint64_t sharp_edges = 0;
  std::uint64_t lines_drawn = 0;
  std::uint64_t lines_rejected = 0;  // a vertex behind the eye
  std::uint64_t pixels = 0;          // line pixels written
  std::uint64_t faces() const { return cover_faces + assigned_faces; }
};

enum EdgeFlags : std::uint8_t { kEdgeBoundary = 1, kEdgeSilhouette = 2, kEdgeSharp = 4 };

struct ProcessedEdge {
  std::uint32_t from = 0, to = 0;
  std::uint8_t flags = 0;  // EdgeFlags
};

class EdgeStage final : public PrimitiveHook {
 public:
  // `lines` may be nullptr (classification and counts only). Its size is the viewport.
  EdgeStage(const Mesh& mesh, const EdgeStageOptions& options, Framebuffer* lines);

  void primitive(const AssembledPrimitive& primitive) override;

  const EdgeStageStats& stats() const { return stats_; }
  // With options.record: every processed edge, and every processed face (cover and assigned)
  // as its three vertex ids in the winding the primitive gives.
  const std::vector<ProcessedEdge>& edges() const { return edges_; }
  const std::vector<std::array<std::uint32_t, 3>>& faces() const { return faces_; }

 private:
  void draw_line(const glm::vec4& a, const glm::vec4& b);

  const Mesh& mesh_;
  EdgeStageOptions options_;
  float sharp_cosine_;
  Framebuffer* lines_;
  EdgeStageStats stats_;
  std::vector<ProcessedEdge> edges_;
  std::vector<std::array<std::uint32_t, 3>> faces_;
};

}  // namespace rastrace
