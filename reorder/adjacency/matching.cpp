#include "reorder/adjacency/matching.h"

#include <algorithm>

// LEMON's ArrayMap constructs default values GCC 12 reads as maybe-uninitialized once sanitizers
// change the inlining (see also reorder/CMakeLists.txt).
#pragma GCC diagnostic ignored "-Wmaybe-uninitialized"
#include <lemon/matching.h>
#include <lemon/smart_graph.h>

namespace rastrace {

long long min_weight_perfect_matching(std::uint32_t node_count, const std::vector<MatchingEdge>& edges) {
  if (node_count == 0) return 0;
  if (node_count % 2 == 1) return -1;
  lemon::SmartGraph graph;
  graph.reserveNode(static_cast<int>(node_count));
  graph.reserveEdge(static_cast<int>(edges.size()));
  std::vector<lemon::SmartGraph::Node> nodes;
  nodes.reserve(node_count);
  for (std::uint32_t i = 0; i < node_count; ++i) nodes.push_back(graph.addNode());
  long long heaviest = 0;
  for (const MatchingEdge& e : edges) heaviest = std::max<long long>(heaviest, e.weight);
  // LEMON maximizes: every perfect matching has node_count / 2 edges, so weight (heaviest + 1) - w
  // turns the minimum into the maximum.
  lemon::SmartGraph::EdgeMap<long long> weight(graph);
  for (const MatchingEdge& e : edges) weight[graph.addEdge(nodes[e.a], nodes[e.b])] = heaviest + 1 - e.weight;
  lemon::MaxWeightedPerfectMatching<lemon::SmartGraph, lemon::SmartGraph::EdgeMap<long long>> matching(graph, weight);
  if (!matching.run()) return -1;
  return static_cast<long long>(node_count / 2) * (heaviest + 1) - matching.matchingWeight();
}

}  // namespace rastrace
