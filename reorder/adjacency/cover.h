// The cover of Sander, Nehab, Chlamtac, Hoppe 2008 (section 4): a set C of faces such that every
// mesh edge belongs to a face of C, i.e. a vertex cover of the dual graph. Boundary (and
// degenerate) faces are forced into C; the rest of the cover is the complement of an independent
// set of the interior faces, grown by a stochastic local search in the manner of Grosso,
// Locatelli and Pullan 2007 ("Simple ingredients leading to very efficient heuristics for the
// maximum clique problem") with every edge test negated, as the paper does:
//   - each iteration perturbs the current set by forcing in a random outside face and dropping
//     its neighbours, which become tabu (they may not re-enter for a few iterations);
//   - a local search then re-grows it: free faces are added, and (1,2)-swaps (one face out, two
//     non-adjacent faces that only it blocked in) are applied around the change, as in Andrade,
//     Resende and Werneck 2008;
//   - the iteration is kept if the set did not shrink, otherwise undone.
// The search starts from a min-degree greedy set and stops after max_iterations or
// time_budget_seconds, whichever comes first (only the iteration budget is deterministic).
// A final pass adds every face that is free, so the cover is minimal: no cover face can be
// dropped without uncovering an edge.
//
// On real meshes the cover holds 52-57% of the faces and lies within 2-4% of the lower bound of
// reorder/adjacency/bound.h; about 20 iterations per face reach that.
#pragma once

#include <cstdint>
#include <vector>

#include "reorder/adjacency/dual.h"

namespace rastrace {

struct CoverParams {
  std::uint64_t seed = 1;
  // Iterations of perturbation plus local search; < 0 means 20 per face.
  std::int64_t max_iterations = -1;
  double time_budget_seconds = 0.0;  // 0: no time limit
};

struct CoverResult {
  std::vector<std::uint8_t> in_cover;  // per face
  std::uint32_t size = 0;              // |C|
  std::uint32_t forced = 0;            // boundary and degenerate faces (always in C)
  std::uint32_t greedy_size = 0;       // |C| of the greedy start, for comparison
  std::uint64_t iterations = 0;
  double seconds = 0.0;
};

CoverResult find_adjacency_cover(const AdjacencyDual& dual, const CoverParams& params = {});

// Every dual edge has an end in the cover and every boundary or degenerate face is in it.
bool is_edge_cover(const AdjacencyDual& dual, const std::vector<std::uint8_t>& in_cover);
// An edge cover from which no interior face can be removed (every interior cover face has a
// neighbour outside the cover).
bool is_minimal_cover(const AdjacencyDual& dual, const std::vector<std::uint8_t>& in_cover);

}  // namespace rastrace
