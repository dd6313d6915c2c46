// A progressive mesh for view-independent progressive meshing (VIPM): the sequence of half-edge
// collapses that takes a mesh from full detail down to a minimum triangle count, with the vertex
// and triangle buffers laid out in "vanilla" VIPM order (Forsyth, "Comparison of VIPM Methods",
// Game Programming Gems 2, 2001), so that every representation of the same sequence (vanilla,
// skip strips, mixed-mode, sliding window) can be built from this one structure.
//
// - Half-edge collapses only (Hoppe, "Progressive Meshes", SIGGRAPH 1996, restricted as in
//   Forsyth's article): the binned vertex moves onto the kept vertex along an existing edge; no
//   new vertex is made, so vertex positions never change with the level of detail.
// - Ordered by the quadric error metric (Garland and Heckbert, "Surface Simplification Using
//   Quadric Error Metrics", SIGGRAPH 1997): area-weighted face-plane quadrics plus, on every
//   boundary edge, a heavily weighted plane through the edge perpendicular to its face, so open
//   borders keep their shape.
// - A collapse is refused if it would make the mesh non-manifold (the link condition), duplicate
//   a triangle, leave a vertex with no triangle, or flip or flatten a changed triangle.
//
// Numbering (the "new" numbering used by every index in ProgressiveMesh):
// - Vertex: the vertices still in use after all collapses come first (in original order), then
//   the binned vertices in reverse collapse order, so collapse n bins vertex
//   vertex_count_at(n) - 1, and the vertices in use at LoD n are exactly 0 .. vertex_count_at(n)-1.
//   Vertices no triangle uses are dropped.
// - Triangle: the triangles left after all collapses come first (in original face order), then
//   the triangles binned by the last collapse, ..., those binned by the first collapse at the
//   end; so the triangles alive at LoD n are exactly 0 .. triangle_count_at(n)-1.
// - LoD n is the mesh after the first n collapses (LoD 0 = full detail).
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "scenes/mesh.h"

namespace rastrace {

struct ProgressiveMeshParams {
  // Stop collapsing at the first LoD with at most this many triangles (or earlier, when no
  // collapse passes the checks). 0 selects the default: max(16, 2% of the faces).
  std::uint32_t min_triangles = 0;
  // Breaks ties between collapses of equal error (flat regions) in a seeded, reproducible order.
  std::uint64_t seed = 1;
  // Weight of the boundary-preserving planes relative to the face planes (both are scaled by
  // area: a face plane by the face's area, a boundary plane by its edge's squared length).
  double boundary_weight = 100.0;
};

struct CollapseRecord {
  std::uint32_t kept = 0;    // vertex that stays (new numbering)
  std::uint32_t binned = 0;  // vertex that moves onto `kept` and is no longer used; always
                             // vertex_count_at(n) - 1 for collapse n
  // Triangles (ids into ProgressiveMesh::triangles) that use the edge kept-binned and vanish:
  // always the last ones alive before the collapse, in increasing id order.
  std::vector<std::uint32_t> binned_triangles;
  // Triangles that use the binned vertex but not the kept one, and survive with `binned`
  // replaced by `kept` (increasing id order), and, for each, the flat index 3 * triangle + corner
  // of the corner that holds `binned` (Forsyth's wIndexOffset); same order as changed_triangles.
  std::vector<std::uint32_t> changed_triangles;
  std::vector<std::uint32_t> changed_corners;
  // The quadric error of the collapse: (Q_kept + Q_binned) evaluated at the kept vertex, in
  // squared length times area (the units of the mesh's positions to the fourth power).
  double error = 0.0;
};

struct ProgressiveMesh {
  std::string name;                            // the source mesh's name
  std::vector<std::uint32_t> vertex_order;     // new vertex -> original vertex
  std::vector<std::uint32_t> triangle_origin;  // new triangle -> original face
  // Full-detail triangles in the new numbering, with the original winding.
  std::vector<std::array<std::uint32_t, 3>> triangles;
  std::vector<CollapseRecord> collapses;  // in collapse order
  // triangle_counts[n] = triangles alive at LoD n (collapses.size() + 1 entries).
  std::vector<std::uint32_t> triangle_counts;

  std::size_t lod_count() const { return collapses.size() + 1; }
  std::uint32_t vertex_count_at(std::size_t n) const { return static_cast<std::uint32_t>(vertex_order.size() - n); }
  std::uint32_t triangle_count_at(std::size_t n) const { return triangle_counts[n]; }
  // The smallest LoD with at most `triangles` triangles (the last LoD if none has so few).
  std::size_t lod_for_triangle_count(std::uint32_t triangles) const;
};

// Builds the collapse sequence. Throws InputError (naming the mesh) for an empty mesh, an index
// out of range, a non-finite position, a face repeating a vertex, a non-manifold edge or vertex,
// inconsistent winding, or min_triangles larger than the mesh's face count. Deterministic for a
// given seed.
ProgressiveMesh build_progressive_mesh(const Mesh& mesh, const ProgressiveMeshParams& params = {});

// The source mesh with its vertex buffer (positions, normals, UVs) in the new numbering and its
// faces (and face materials) in the new triangle order: the full-detail buffers a VIPM
// representation draws from.
Mesh reordered_mesh(const Mesh& mesh, const ProgressiveMesh& pm);

// The reference for every representation: the non-degenerate triangles at LoD n, computed
// independently of the collapse records' triangle lists by mapping every binned vertex of the
// first n collapses to its final kept vertex and dropping the triangles that become degenerate.
// Triangles keep their winding and their full-detail order. n <= collapses.size().
std::vector<std::array<std::uint32_t, 3>> triangles_at_lod(const ProgressiveMesh& pm, std::size_t n);

// Vanilla VIPM's per-instance state: an index buffer (3 indices per triangle, in the triangle
// order above) edited in place by collapses and splits. The drawn triangles at LoD n are the
// first triangle_count() triples; they equal triangles_at_lod(pm, n) as triples, in order.
class ProgressiveMeshCursor {
 public:
  explicit ProgressiveMeshCursor(const ProgressiveMesh& pm);

  std::size_t lod() const { return lod_; }
  std::uint32_t vertex_count() const { return pm_->vertex_count_at(lod_); }
  std::uint32_t triangle_count() const { return pm_->triangle_count_at(lod_); }
  // The drawn index stream: 3 * triangle_count() indices.
  std::span<const std::uint32_t> indices() const { return {indices_.data(), 3 * std::size_t(triangle_count())}; }

  // Collapse n (LoD n -> n + 1); false (and no change) at the last LoD.
  bool collapse();
  // Undo collapse n - 1 (LoD n -> n - 1); false (and no change) at LoD 0.
  bool split();
  // Collapses or splits until the LoD is n (clamped to the last LoD).
  void set_lod(std::size_t n);

 private:
  const ProgressiveMesh* pm_;
  std::vector<std::uint32_t> indices_;
  std::size_t lod_ = 0;
};

}  // namespace rastrace
