#include "reorder/adjacency/bound.h"

#include <algorithm>
#include <chrono>
#include <stdexcept>

#include "reorder/adjacency/matching.h"

namespace rastrace {

CoverBound adjacency_cover_lower_bound(const Mesh& mesh, const AdjacencyDual& dual, bool prune) {
  const auto start = std::chrono::steady_clock::now();
  CoverBound result;
  result.dual_edges = dual.dual_edge_count;
  const std::uint32_t V = dual.vertex_count;
  const std::uint32_t* idx = mesh.indices.data();

  // Nodes: interior vertices, then the sink standing for every boundary vertex.
  constexpr std::uint32_t kNone = 0xFFFFFFFFu;
  std::vector<std::uint32_t> node_of(V, kNone);
  std::uint32_t N = 0;
  bool has_boundary = false;
  for (std::uint32_t v = 0; v < V; ++v) {
    if (dual.boundary_vertex[v])
      has_boundary = true;
    else
      node_of[v] = N++;
  }
  const std::uint32_t sink = has_boundary ? N++ : kNone;
  for (std::uint32_t v = 0; v < V; ++v)
    if (dual.boundary_vertex[v]) node_of[v] = sink;

  // The primal edges of the dual edges (interior edges only), as CSR on the nodes.
  std::vector<std::uint32_t> degree(N, 0), ring(V, 0);
  auto for_each_dual_edge = [&](auto&& visit) {
    for (std::uint32_t f = 0; f < dual.face_count; ++f)
      for (unsigned i = 0; i < 3; ++i) {
        const std::uint32_t g = dual.across(f, i);
        if (g == kNoFace || g < f) continue;
        visit(idx[3 * f + i], idx[3 * f + (i + 1) % 3]);
      }
  };
  for_each_dual_edge([&](std::uint32_t a, std::uint32_t b) {
    ++ring[a];
    ++ring[b];
    if (node_of[a] == node_of[b]) return;
    ++degree[node_of[a]];
    ++degree[node_of[b]];
  });
  std::vector<std::uint32_t> offsets(N + 1, 0);
  for (std::uint32_t n = 0; n < N; ++n) offsets[n + 1] = offsets[n] + degree[n];
  std::vector<std::uint32_t> adjacent(offsets[N]);
  {
    std::vector<std::uint32_t> fill(offsets.begin(), offsets.end() - 1);
    for_each_dual_edge([&](std::uint32_t a, std::uint32_t b) {
      const std::uint32_t na = node_of[a], nb = node_of[b];
      if (na == nb) return;
      adjacent[fill[na]++] = nb;
      adjacent[fill[nb]++] = na;
    });
  }

  // The odd set T: interior vertices whose ring has odd length (+ the sink to make |T| even).
  std::vector<std::uint32_t> odd_index(N, kNone), odd_nodes;
  for (std::uint32_t v = 0; v < V; ++v)
    if (!dual.boundary_vertex[v] && ring[v] % 2 == 1) {
      odd_index[node_of[v]] = static_cast<std::uint32_t>(odd_nodes.size());
      odd_nodes.push_back(node_of[v]);
    }
  if (odd_nodes.size() % 2 == 1) {
    if (sink == kNone) throw std::logic_error("odd number of odd-degree vertices in a closed mesh");
    odd_index[sink] = static_cast<std::uint32_t>(odd_nodes.size());
    odd_nodes.push_back(sink);
  }
  result.odd_vertices = odd_nodes.size();

  // G_prune by a breadth-first search from each odd node. count[x] is the largest number of odd
  // nodes (the start excluded, x included) on a shortest path to x: a target y is legal when
  // count[y] <= 2, and nothing beyond a node with count >= 2 can be legal.
  std::vector<MatchingEdge> pairs;
  std::vector<std::uint32_t> stamp(N, kNone), dist(N, 0);
  std::vector<std::uint8_t> count(N, 0);
  std::vector<std::uint32_t> frontier, next;
  for (std::uint32_t t = 0; t < odd_nodes.size(); ++t) {
    const std::uint32_t source = odd_nodes[t];
    frontier.assign(1, source);
    stamp[source] = t;
    dist[source] = 0;
    count[source] = 0;
    for (;;) {
      next.clear();
      for (const std::uint32_t x : frontier)
        for (std::uint32_t k = offsets[x]; k < offsets[x + 1]; ++k) {
          const std::uint32_t y = adjacent[k];
          const std::uint8_t through = static_cast<std::uint8_t>(std::min(3, count[x] + (odd_index[y] != kNone)));
          if (stamp[y] != t) {
            stamp[y] = t;
            dist[y] = dist[x] + 1;
            count[y] = through;
            next.push_back(y);
          } else if (dist[y] == dist[x] + 1) {
            count[y] = std::max(count[y], through);
          }
        }
      bool live = false;
      for (const std::uint32_t y : next) {
        if (odd_index[y] != kNone && (count[y] <= 2 || !prune) && odd_index[y] > t)
          pairs.push_back({t, odd_index[y], dist[y]});
        live = live || count[y] <= 1 || !prune;
      }
      if (!live || next.empty()) break;
      frontier.swap(next);
    }
  }
  result.pruned_edges = pairs.size();

  const long long join = min_weight_perfect_matching(static_cast<std::uint32_t>(odd_nodes.size()), pairs);
  if (join < 0) throw std::runtime_error("lower bound: the pruned odd-vertex graph has no perfect matching");
  result.join_edges = static_cast<std::uint64_t>(join);
  result.bound = (double(result.dual_edges) + double(result.join_edges)) / 3.0;
  result.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return result;
}

}  // namespace rastrace
