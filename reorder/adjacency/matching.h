// Minimum-weight perfect matching on a general graph, through LEMON's
// MaxWeightedPerfectMatching (Edmonds' blossom algorithm with fractional initialisation). Used by
// the cover lower bound (reorder/adjacency/bound.h).
//
// LEMON 1.3 calls std::allocator::construct, which C++20 removed, so this file is compiled as
// C++17 (see reorder/adjacency/CMakeLists.txt) and its interface uses nothing newer.
#pragma once

#include <cstdint>
#include <vector>

namespace rastrace {

struct MatchingEdge {
  std::uint32_t a = 0, b = 0;  // node ids < node_count
  std::uint32_t weight = 0;
};

// The smallest total weight of a perfect matching, or -1 if the graph has none.
long long min_weight_perfect_matching(std::uint32_t node_count, const std::vector<MatchingEdge>& edges);

}  // namespace rastrace
