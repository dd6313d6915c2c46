// The whole construction of Sander, Nehab, Chlamtac, Hoppe 2008 in one call: dual graph, cover
// (reorder/adjacency/cover.h), restricted assignment (reorder/adjacency/assign.h) and the
// primitives in cover-face order (reorder/adjacency/encode.h). Order them with
// reorder/adjacency/order.h. The lower bound (reorder/adjacency/bound.h) is separate: it is only
// needed to judge the cover.
#pragma once

#include "reorder/adjacency/assign.h"
#include "reorder/adjacency/cover.h"
#include "reorder/adjacency/dual.h"
#include "reorder/adjacency/encode.h"

namespace rastrace {

struct AdjacencyBuild {
  AdjacencyDual dual;
  CoverResult cover;
  FaceAssignment assignment;
  AdjacencyPrimitives primitives;
};

// Throws InputError on a malformed mesh (index out of range).
AdjacencyBuild build_adjacency_primitives(const Mesh& mesh, const CoverParams& params = {});

}  // namespace rastrace
