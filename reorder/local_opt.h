// Hoppe 1999, "Optimization of mesh locality for transparent vertex caching", section 6: local
// optimization of a face order (seeded by the greedy strip-growing of greedy.h).
//
// Cost (scaled by 1000 to stay in integers): 32 * misses_k + 6 * strips
//   + 0.003 * misses_(k-1) + 0.002 * misses_(k+1)   (the secondary cost keeps slack in the cache).
// Misses are those of the strip stream strip.h would emit for the order (a face continuing a strip
// reads its one new vertex; a strip's first face reads the vertex opposite its exit edge first),
// with a FIFO cache as in the paper.
// Perturbations of the sequence F, each with two positions x, y:
//   Reflect(x, y)  reverses F[x..y];
//   Insert1(x, y)  moves F[x] next to F[y] (just after it if y > x, just before it if y < x);
//   Insert2(x, y)  moves F[x], F[x+1] next to F[y] likewise.
// x visits every face in a seeded random order; y ranges over the faces sharing a vertex with
// F[x] and F[x-1], F[x+1] (for a vertex in more than 32 faces, a fan's centre, only those within
// 8 positions of x and 8 spread over the rest, so that a pass stays near linear on non-manifold
// fans and meshes of few vertices); the best beneficial perturbation is chased (x <- y, y <- z) until it
// is locally best, then applied. Costs are re-evaluated from per-face miss bits and access lists
// stored for the forward and the reverse traversal (3 cache sizes each): the cache state before
// a slice point is rebuilt from the last k stored misses, the re-simulation runs on time-stamped
// FIFOs (O(1) per access), and it stops once k successive misses agree with the stored ones, so
// the change in cost is exact for any k (the true cost is still checked before a change is kept).
// After a change only the window around it is re-simulated. x positions in the middle of a strip
// whose three faces miss fewer than 3 times in total are pruned.
//
// Budget: ReorderParams::iteration_budget x positions (reproducible), capped by
// time_budget_seconds. Without a budget it runs to convergence (a whole pass finds nothing): about
// 3 s of CPU time on fandisk, 30 s on bunny00 (docs/PERFORMANCE.md). Expect a 4-7% lower ACMR than greedy (Hoppe: 3-6%): at FIFO 16 fandisk
// 0.598, triceratops 0.643, bunny00 0.641. LRU: the cost model is FIFO-only, so for LRU the greedy LRU order
// is returned unchanged.
#pragma once

#include <cstdint>
#include <vector>

#include "reorder/mesh_topology.h"
#include "reorder/ordering.h"

namespace rastrace {

struct LocalStats {
  std::uint64_t iterations = 0;   // x positions visited
  std::uint64_t evaluations = 0;  // perturbation costs evaluated
  std::uint64_t applied = 0;      // perturbations applied
  std::uint64_t rejected = 0;     // applied perturbations undone because the true cost did not drop
  std::uint64_t passes = 0;       // passes over all faces started
  std::int64_t initial_cost = 0;  // scaled cost before and after
  std::int64_t final_cost = 0;
  bool converged = false;  // a whole pass found nothing
};

// Improves `order` in place (FIFO, params.cache_size).
void hoppe_local_optimize(const Mesh& mesh, const MeshTopology& topology, const ReorderParams& params,
                          std::vector<std::uint32_t>& order, LocalStats* stats = nullptr);

}  // namespace rastrace
