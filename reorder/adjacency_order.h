// Orderings of triangle-with-adjacency primitives for the post-transform vertex cache (Sander,
// Nehab, Chlamtac, Hoppe 2008, section 6). Each returns a permutation of the primitives;
// apply it with permute_primitives (reorder/adjacency_encode.h). All are deterministic.
//
// - careful: the extension of Lin and Yu 2006 (K-Cache-Reorder). A simulated FIFO of
//   cache_size entries is kept; every step considers each cached vertex that still has
//   primitives referencing it (among all six indices: six primitives in a regular region), counts
//   the misses its ring would cost, takes the vertex with the fewest misses per primitive (the
//   oldest on ties, before it is evicted) and emits its ring in the order with fewest misses,
//   chosen greedily primitive by primitive. CM/V about 1.5 at cache 24; O(F * cache_size).
// - fast: the extension of Tipsy (Sander, Nehab, Barczak 2007). Fans around a vertex emit only
//   the primitives whose cover face touches it (three in a regular region); the next fanning
//   vertex is the oldest cached candidate that still fits, with the conservative bound raised
//   from 2 to 5 misses per remaining primitive. Linear time, independent of the cache size;
//   CM/V about 1.75-1.85 at cache 24.
// - baseline: kcache (reorder/kcache.cpp, Lin and Yu's method for plain triangles) run on the
//   cover faces alone, each primitive following its cover face: what an off-the-shelf triangle
//   method gives. The gain of careful and fast is measured against it.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "reorder/adjacency_encode.h"
#include "scenes/mesh.h"

namespace rastrace {

enum class AdjacencyOrder { Careful, Fast, Baseline };

const char* to_string(AdjacencyOrder order);
// "careful", "fast" or "baseline"; throws InputError otherwise.
AdjacencyOrder parse_adjacency_order(const std::string& text);

std::vector<std::uint32_t> order_adjacency_careful(const AdjacencyPrimitives& primitives, std::uint32_t vertex_count,
                                                   unsigned cache_size);
std::vector<std::uint32_t> order_adjacency_fast(const AdjacencyPrimitives& primitives, std::uint32_t vertex_count,
                                                unsigned cache_size);
std::vector<std::uint32_t> order_adjacency_baseline(const Mesh& mesh, const AdjacencyPrimitives& primitives,
                                                    unsigned cache_size);
std::vector<std::uint32_t> order_adjacency(AdjacencyOrder order, const Mesh& mesh,
                                           const AdjacencyPrimitives& primitives, unsigned cache_size);

}  // namespace rastrace
