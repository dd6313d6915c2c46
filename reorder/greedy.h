// Hoppe 1999, "Optimization of mesh locality for transparent vertex caching" (SIGGRAPH 99),
// section 5: greedy strip-growing with lookahead simulations of the vertex cache.
//
// A strip grows face by face, turning counter-clockwise (left, around the strip's left vertex)
// whenever that face is unvisited and queueing the clockwise neighbour as a restart location.
// Before adding each face, lookahead simulations over the next s faces decide whether to restart
// the strip instead: simulation i forces a restart after exactly i faces and scores the cache
// hits per visited face; the strip restarts only if restarting now (i = 0) beats every i in
// 1..s-1. s = k + 5 for FIFO, k/2 + 5 for LRU (the paper: LRU's optimal strip length is about
// k - 2 faces against 2k - 4 for FIFO). Early exit: C(i_min) of the previous face is tried right
// after C(0), and the search stops at the first C(i) no worse than C(0) (about 2-3 simulations
// per face). Restarts take the first unvisited face of the queue; when it is empty, the face
// with the most vertices in the cache, then the fewest unvisited neighbours, then the lowest id.
//
// Expected: FIFO 16 ACMR 0.6-0.7 on scanned meshes (fandisk 0.626, where Hoppe's own MeshReorder
// gives 0.628; triceratops 0.689, bunny00 0.670), 1.38-1.54 indices per triangle; speed well
// above 1 M faces/s.
#pragma once

#include <cstdint>
#include <vector>

#include "reorder/mesh_topology.h"
#include "reorder/ordering.h"

namespace rastrace {

struct GreedyStats {
  std::uint64_t simulations = 0;   // lookahead simulations run (paper: about 2.9 per face)
  std::uint64_t restarts = 0;      // strips ended by the lookahead
  std::uint64_t from_scratch = 0;  // restarts with an empty queue
};

// The greedy face order (params.cache_size, params.policy). Deterministic.
std::vector<std::uint32_t> hoppe_greedy_order(const Mesh& mesh, const MeshTopology& topology,
                                              const ReorderParams& params, GreedyStats* stats = nullptr);

}  // namespace rastrace
