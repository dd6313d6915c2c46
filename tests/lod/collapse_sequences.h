// Hand-made half-edge collapse sequences for the representation tests: shortest edge first with
// the link condition (so the mesh stays manifold), error = squared edge length. Any valid
// sequence must do; these do not depend on the QEM builder.
#pragma once

#include <algorithm>
#include <cstdint>
#include <functional>
#include <queue>
#include <set>
#include <tuple>
#include <vector>

#include <glm/geometric.hpp>

#include "lod/vanilla_numbering.h"
#include "scenes/mesh.h"

namespace rastrace::testing {

inline std::vector<HalfEdgeCollapse> shortest_edge_collapses(const Mesh& mesh, std::size_t max_collapses,
                                                             std::uint64_t seed = 1) {
  const std::size_t V = mesh.vertex_count();
  std::vector<std::array<std::uint32_t, 3>> tri(mesh.face_count());
  std::vector<std::uint8_t> alive(tri.size(), 1), binned(V, 0);
  std::vector<std::vector<std::uint32_t>> star(V);
  for (std::size_t f = 0; f < tri.size(); ++f)
    for (int c = 0; c < 3; ++c) {
      tri[f][c] = mesh.indices[3 * f + c];
      star[tri[f][c]].push_back(static_cast<std::uint32_t>(f));
    }
  auto neighbours = [&](std::uint32_t v) {
    std::set<std::uint32_t> out;
    for (std::uint32_t f : star[v])
      if (alive[f])
        for (std::uint32_t u : tri[f])
          if (u != v) out.insert(u);
    return out;
  };
  using Entry = std::tuple<double, std::uint64_t, std::uint32_t, std::uint32_t>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  auto push = [&](std::uint32_t b, std::uint32_t k) {
    const glm::vec3 d = mesh.positions[b] - mesh.positions[k];
    const std::uint64_t tie = (std::uint64_t(b) * 2654435761u + k * 40503u + seed) % 1000003u;
    queue.push({double(glm::dot(d, d)), tie, b, k});
  };
  for (const auto& t : tri)
    for (int c = 0; c < 3; ++c) push(t[c], t[(c + 1) % 3]), push(t[(c + 1) % 3], t[c]);
  std::vector<HalfEdgeCollapse> out;
  while (out.size() < max_collapses && !queue.empty()) {
    const auto [error, tie, b, k] = queue.top();
    queue.pop();
    if (binned[b] || binned[k]) continue;
    std::size_t shared = 0;
    std::set<std::uint32_t> opposite;
    for (std::uint32_t f : star[b])
      if (alive[f] && std::find(tri[f].begin(), tri[f].end(), k) != tri[f].end()) {
        ++shared;
        for (std::uint32_t u : tri[f])
          if (u != b && u != k) opposite.insert(u);
      }
    if (shared == 0) continue;
    const std::set<std::uint32_t> nb = neighbours(b), nk = neighbours(k);
    std::size_t common = 0;
    for (std::uint32_t u : nb) common += nk.count(u);
    if (common != opposite.size() || nb.size() <= 2 || nk.size() <= 2) continue;  // link condition
    out.push_back({b, k, error});
    for (std::uint32_t f : star[b]) {
      if (!alive[f]) continue;
      if (std::find(tri[f].begin(), tri[f].end(), k) != tri[f].end()) {
        alive[f] = 0;
        continue;
      }
      for (std::uint32_t& u : tri[f])
        if (u == b) u = k;
      star[k].push_back(f);
    }
    binned[b] = 1;
    for (std::uint32_t u : neighbours(k)) push(u, k), push(k, u);
  }
  return out;
}

// The progressive mesh of such a sequence, and its vertex buffer in the new numbering.
struct TestPm {
  ProgressiveMesh pm;
  Mesh vertices;
};

inline TestPm test_progressive_mesh(const Mesh& mesh, std::size_t max_collapses, std::uint64_t seed = 1) {
  TestPm out;
  out.pm = progressive_mesh_from_collapses(mesh, shortest_edge_collapses(mesh, max_collapses, seed));
  out.vertices.name = mesh.name;
  for (std::uint32_t v : out.pm.vertex_order) out.vertices.positions.push_back(mesh.positions[v]);
  return out;
}

}  // namespace rastrace::testing
