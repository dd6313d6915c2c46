// Vanilla VIPM's numbering (Forsyth, "Comparison of VIPM Methods", Game Programming Gems 2, 2001)
// for ANY valid sequence of half-edge collapses, not only the QEM builder's: the same
// ProgressiveMesh the builder makes (see progressive_mesh.h for the numbering), so that every
// representation can be built and checked on hand-made sequences, and on sliding window's
// re-ordered sequence.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "lod/progressive_mesh.h"
#include "scenes/mesh.h"

namespace rastrace {

// One half-edge collapse in the numbering of the mesh it is applied to: `binned` moves onto
// `kept`. `error` is carried through unchanged (the builder's quadric error, or anything).
struct HalfEdgeCollapse {
  std::uint32_t binned = 0;
  std::uint32_t kept = 0;
  double error = 0.0;
};

// Applies the collapses in order to the mesh's triangles and returns the progressive mesh in
// vanilla numbering (vertex_order / triangle_origin refer to `mesh`). A collapse is valid when
// binned != kept, both are in range and still in use, and they share an edge of the current mesh
// (at least one triangle is binned). Throws InputError naming the collapse otherwise, or for a
// face of `mesh` that repeats a vertex or an index out of range.
ProgressiveMesh progressive_mesh_from_collapses(const Mesh& mesh, std::span<const HalfEdgeCollapse> collapses);

// The collapses of a progressive mesh in its own (new) numbering.
std::vector<HalfEdgeCollapse> collapses_of(const ProgressiveMesh& pm);

// The triangles of a progressive mesh at a LoD, with their current vertices, moved forward one
// collapse at a time (the triangles alive at LoD n are 0 .. triangle_count_at(n) - 1).
class TriangleReplay {
 public:
  explicit TriangleReplay(const ProgressiveMesh& pm) : pm_(&pm), triangles_(pm.triangles) {}
  std::uint32_t lod() const { return lod_; }
  // Collapses up to LoD n (n >= lod(), n <= collapses).
  void advance_to(std::uint32_t n);
  // Triangle t's current vertices (meaningful while t is alive).
  const std::array<std::uint32_t, 3>& triangle(std::uint32_t t) const { return triangles_[t]; }
  std::uint32_t alive() const { return pm_->triangle_count_at(lod_); }

 private:
  const ProgressiveMesh* pm_;
  std::vector<std::array<std::uint32_t, 3>> triangles_;
  std::uint32_t lod_ = 0;
};

// The full-detail triangles of a progressive mesh as a Mesh in its own numbering (positions
// taken from `vertices`, a mesh already in that numbering, e.g. reordered_mesh's result).
Mesh triangles_as_mesh(const ProgressiveMesh& pm, const Mesh& vertices);

}  // namespace rastrace
