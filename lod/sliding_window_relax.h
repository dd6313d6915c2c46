// Forsyth's relaxation of the QEM collapse order for sliding window ("Comparison of VIPM
// Methods", 2001): follow the builder's order until its next collapse would bin or change a
// triangle already changed in the current level (which forces a new level); then do instead the
// lowest-error collapse that does not force one, provided its error is at most the wanted one's
// plus `tolerance` times the mean collapse error; only when there is none, start the new level.
//
// The builder exposes its sequence, not its candidate queue, so the relaxation re-orders that
// sequence, keeping to the re-orderings that leave every collapse's neighbourhood as it was: a
// collapse may move before an earlier one only if that one did not touch its binned vertex's
// triangles (the binned vertex was not in the earlier collapse's one-ring). Then each collapse
// bins and changes the same triangles with the same vertices, keeps its error, and the last LoD
// is the same mesh; the result is itself a valid sequence (checked by rebuilding the numbering).
#pragma once

#include <cstdint>
#include <vector>

#include "lod/progressive_mesh.h"

namespace rastrace {

struct RelaxedOrder {
  // The re-ordered progressive mesh; vertex_order / triangle_origin refer to the SOURCE mesh of
  // the input (composed through the input's own numbering).
  ProgressiveMesh pm;
  // New vertex -> vertex of the input progressive mesh (to renumber its vertex buffer).
  std::vector<std::uint32_t> input_vertex;
  std::uint32_t levels = 0;        // sliding-window levels of the new order
  std::uint32_t out_of_order = 0;  // collapses done before one that precedes them in the input
};

// tolerance >= 0 (0.1 is Forsyth's sample code; 0 still lets a collapse of equal or lower error go
// first, which a builder's order has when errors tie or drop after neighbouring collapses); throws
// InputError otherwise.
RelaxedOrder relax_for_sliding_window(const ProgressiveMesh& pm, double tolerance = 0.1);

}  // namespace rastrace
