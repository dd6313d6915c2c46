// K-Cache-Reorder: Lin and Yu, "An Improved Vertex Caching Scheme for 3D Mesh Rendering", IEEE
// TVCG 12(4), 2006.
#pragma once

#include "reorder/ordering.h"

namespace rastrace {

// The `kcache` algorithm, as the independent public implementations of Lin and Yu's method
// agree on it. A FIFO of K entries is simulated, with each vertex's unemitted triangles.
//  - Each step scores every resident vertex v that has unemitted triangles by emitting v's whole
//    remaining fan (its triangles in mesh order, corners in winding order) on a copy of the
//    FIFO: C1 = vertices pushed, C2 = v's unemitted triangles, C3 = pushes until v would leave
//    the copy, over K (1 if it has left). The focus is the lowest 1.0 C1 - 0.5 C2 + 1.3 C3 (the
//    most recently entered on ties); with no candidate (the start, a dead end), the vertex with
//    the fewest unemitted triangles (lowest id on ties).
//  - The focus's fan is emitted: each triangle's missing corners are pushed, and a push that
//    completes other unemitted triangles (all three corners resident) draws them too, right
//    after the fan triangle, so the stream misses exactly what the simulated FIFO does.
// Parameters: cache_size (K, the FIFO ordered for; above 1024 ordered as 1024). The policy is
// ignored (the cost is defined on a FIFO). O(faces x K x valence): bunny00 (75,408 faces) in
// about 70 ms of CPU at K = 16, 1.8 times Forsyth's time. Deterministic.
// FIFO ACMR ordered for and run on K = 12 / 16 / 20: 16x16 grid 0.602 / 0.590 / 0.564, CGAL's
// fandisk 0.621 / 0.601 / 0.575, triceratops 0.645 / 0.611 / 0.604, bunny00 0.641 / 0.612 /
// 0.594; about 0.56-0.65 on real meshes from K = 32 down to 12.
Ordering reorder_kcache(const Mesh& mesh, const ReorderParams& params);

}  // namespace rastrace
