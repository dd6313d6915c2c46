// The face assignment of Sander, Nehab, Chlamtac, Hoppe 2008 (section 5): every face outside the
// cover is assigned to one adjacent cover face, each cover face takes at most one, and every
// connected component of cover faces that touches no boundary gets at least one assigned face
// (the "restricted" condition that lets each primitive run the same geometry-shader steps).
//
// Construction (the proof of the paper's Lemma 1):
//   1. M: a maximum bipartite matching uncovered -> cover faces by Hopcroft and Karp (1973); it
//      is perfect on the uncovered side (Hall: each uncovered face has three cover neighbours,
//      each cover face at most three neighbours).
//   2. N: a matching of the non-boundary components (collapsed to one node each) into the
//      uncovered faces, again by Hopcroft-Karp; it saturates the components when the cover is
//      minimal.
//   3. M u N is a union of paths and cycles; each alternating path that starts at a cover face
//      used by N but not by M is flipped, giving a perfect matching M' that also reaches every
//      component of N.
// O(F^1.5); a few tens of milliseconds for 75k faces.
#pragma once

#include <cstdint>
#include <vector>

#include "reorder/adjacency/dual.h"

namespace rastrace {

struct FaceAssignment {
  // Per face: for a cover face, its assigned (uncovered) face or kNoFace; for an uncovered face,
  // the cover face it is assigned to.
  std::vector<std::uint32_t> partner;
  std::uint32_t components = 0;           // connected components of the cover faces
  std::uint32_t free_components = 0;      // those with no boundary or degenerate face (the set A)
  std::uint32_t repaired_components = 0;  // of A, left without an assigned face by M alone
  double seconds = 0.0;
};

// Throws std::logic_error when in_cover is not a minimal edge cover (no such matching exists).
FaceAssignment assign_uncovered_faces(const AdjacencyDual& dual, const std::vector<std::uint8_t>& in_cover);

// Every uncovered face is assigned to an adjacent cover face, the assignment is symmetric and
// one-to-one, and every component of cover faces has a boundary/degenerate face or an assigned face.
bool is_perfect_restricted_assignment(const AdjacencyDual& dual, const std::vector<std::uint8_t>& in_cover,
                                      const FaceAssignment& assignment);

// Per cover face, the id of its connected component within the cover (kNoFace for the others).
std::vector<std::uint32_t> cover_components(const AdjacencyDual& dual, const std::vector<std::uint8_t>& in_cover,
                                            std::uint32_t* component_count);

}  // namespace rastrace
