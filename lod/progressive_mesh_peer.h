// The peer for the builder's quality: meshoptimizer's meshopt_simplify (edge collapses ordered
// by a quadric error, topology-preserving), run in the same process on the same mesh.
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "scenes/mesh.h"

namespace rastrace {

// meshopt_simplify's triangles (the mesh's own vertex numbering) for a target triangle count,
// with no error limit. It may stop above the target when no further collapse keeps its
// topology checks; the result's size is what it reached.
std::vector<std::array<std::uint32_t, 3>> meshopt_simplified_triangles(const Mesh& mesh,
                                                                       std::uint32_t target_triangles);

}  // namespace rastrace
