// The lower bound on the cover size of Sander, Nehab, Chlamtac, Hoppe 2008 (appendix):
//   B = (|E'| + |minimum V_odd-join|) / 3.
// Every cover face covers at most three dual edges, and around each mesh vertex of odd degree
// an odd number of ring edges is covered twice; the doubly covered edges form a V_odd-join of
// the primal graph, whose minimum is a minimum-weight perfect matching of the odd-degree
// vertices on shortest-path (edge count) distances (Edmonds and Johnson 1973). The matching is
// solved with LEMON's MaxWeightedPerfectMatching (weights turned into maxima) on the pruned graph
// G_prune of the paper's Lemma 2: u and v are joined only when no shortest path between them
// crosses two other odd vertices (an "illegal" path). Each breadth-first search stops at the
// level where every path has crossed two odd vertices, so the search stays local.
//
// Meshes with boundaries: the ring argument holds only around interior vertices, so every
// vertex on a boundary (or on a degenerate face) is merged into one free sink vertex, and the
// join runs over interior edges only; the sink joins the odd set when that count is odd.
//
// Expect |join| of about 5-10% of the faces on real meshes, C/B = 1.02-1.04.
#pragma once

#include <cstdint>

#include "reorder/adjacency/dual.h"

namespace rastrace {

struct CoverBound {
  std::uint64_t dual_edges = 0;    // |E'|
  std::uint64_t odd_vertices = 0;  // |V_odd| (the sink included when it is odd)
  std::uint64_t pruned_edges = 0;  // edges of G_prune given to the matching
  std::uint64_t join_edges = 0;    // |minimum V_odd-join|
  double bound = 0.0;              // (|E'| + |join|) / 3
  double seconds = 0.0;
};

// Throws std::runtime_error if the pruned graph has no perfect matching (Lemma 2 says it always
// has one). prune = false matches on every pair of odd vertices (quadratic: for tests of the
// pruning on small meshes).
CoverBound adjacency_cover_lower_bound(const Mesh& mesh, const AdjacencyDual& dual, bool prune = true);

}  // namespace rastrace
