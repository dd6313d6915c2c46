// Orderings of triangle-with-adjacency primitives for the post-transform vertex cache (Sander,
// Nehab, Chlamtac, Hoppe 2008, section 6). Each returns a permutation of the primitives;
// apply it with permute_primitives (reorder/adjacency/encode.h). All are deterministic.
//
// - careful: the extension of Lin and Yu 2006 (K-Cache-Reorder). A simulated FIFO of
//   cache_size entries is kept; every step considers each cached vertex that still has
//   primitives referencing it (among all six indices: six primitives in a regular region) and
//   costs its ring by emitting it on a copy of the FIFO, primitive by primitive in the order
//   with fewest misses: cost = misses - 2 * sum over the resident vertices the ring completes of
//   age / cache_size (a vertex about to be evicted is worth completing). Ties go to the larger
//   ring, then the oldest vertex. The ring emitted is chosen by a look-ahead: each of the 3
//   cheapest rings is emitted tentatively, then each of the 2 cheapest after it, then the
//   cheapest third; the first ring of the cheapest sequence wins (a ring of cost <= 0 is taken
//   at once). CM/V at cache 24: fandisk 1.456, triceratops 1.442, bunny00 1.459 (the paper:
//   1.50-1.54); O(F * cache_size * ring) with about 10 FIFO scans per ring emitted: about a
//   second on bunny00 (75k faces).
// - fast: the extension of Tipsy (Sander, Nehab, Barczak 2007). Fans around a vertex emit only
//   the primitives whose cover face touches it (three in a regular region); the next fanning
//   vertex is the oldest cached candidate that still fits, with the conservative bound raised
//   from 2 to 5 misses per remaining primitive. Linear time, independent of the cache size;
//   CM/V 1.64-1.72 at cache 24 (the paper: 1.76-1.82).
// - baseline: kcache (reorder/kcache.cpp, Lin and Yu's method for plain triangles) run on the
//   cover faces alone, as a triangle mesh, each primitive following its cover face: the
//   off-the-shelf method applied to the primitives. CM/V 2.46-2.92 at cache 24. `gain` is measured
//   against it.
// - baseline-mesh: kcache run on all the mesh's faces, as an engine that reorders its triangle
//   buffer would, and the mesh then drawn in that order with each face drawn by the primitive
//   that holds it (as cover or assigned face): each primitive is placed at the first of its
//   two faces. The paper's "naive application of previous reordering methods" read literally.
//   CM/V 2.79-3.13 at cache 24; the paper's baseline (careful CM/V x gain in its Table 1) is
//   2.5-3.0. `gain_mesh` is measured against it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "reorder/adjacency/encode.h"
#include "scenes/mesh.h"

namespace rastrace {

enum class AdjacencyOrder { Careful, Fast, Baseline, BaselineMesh };

const char* to_string(AdjacencyOrder order);
// "careful", "fast", "baseline" or "baseline-mesh"; throws InputError otherwise.
AdjacencyOrder parse_adjacency_order(const std::string& text);

std::vector<std::uint32_t> order_adjacency_careful(const AdjacencyPrimitives& primitives, std::uint32_t vertex_count,
                                                   unsigned cache_size);
std::vector<std::uint32_t> order_adjacency_fast(const AdjacencyPrimitives& primitives, std::uint32_t vertex_count,
                                                unsigned cache_size);
std::vector<std::uint32_t> order_adjacency_baseline(const Mesh& mesh, const AdjacencyPrimitives& primitives,
                                                    unsigned cache_size);
std::vector<std::uint32_t> order_adjacency_baseline_mesh(const Mesh& mesh, const AdjacencyPrimitives& primitives,
                                                         unsigned cache_size);
std::vector<std::uint32_t> order_adjacency(AdjacencyOrder order, const Mesh& mesh,
                                           const AdjacencyPrimitives& primitives, unsigned cache_size);

}  // namespace rastrace
