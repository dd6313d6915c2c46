#include "reorder/mesh_topology.h"

#include <algorithm>
#include <string>

#include "core/error.h"
#include "reorder/vertex_faces.h"

namespace rastrace {

std::uint32_t MeshTopology::find_edge(std::uint32_t a, std::uint32_t b) const {
  if (a == b || a >= vertex_count || b >= vertex_count) return kNoEdge;
  const std::uint32_t lo = std::min(a, b), hi = std::max(a, b);
  std::uint32_t first = vertex_edge_offsets[lo], last = vertex_edge_offsets[lo + 1];
  while (first < last) {
    const std::uint32_t mid = first + (last - first) / 2;
    const std::uint32_t upper = edge_vertices[2 * mid + 1];
    if (upper == hi) return mid;
    if (upper < hi)
      first = mid + 1;
    else
      last = mid;
  }
  return kNoEdge;
}

MeshTopology build_mesh_topology(const Mesh& mesh) {
  // Validates the indices and fills vertex -> faces (a degenerate face lists a repeated vertex once).
  MeshTopology t = build_vertex_faces(mesh);
  const std::uint32_t V = t.vertex_count, F = t.face_count;
  const std::uint32_t* idx = mesh.indices.data();

  // Half-edge slots 3f+i bucketed by lower vertex, sorted by (upper vertex, slot).
  auto slot_lo = [&](std::uint32_t s) {
    const std::uint32_t f = s / 3, i = s % 3;
    return std::min(idx[3 * f + i], idx[3 * f + (i + 1) % 3]);
  };
  auto slot_hi = [&](std::uint32_t s) {
    const std::uint32_t f = s / 3, i = s % 3;
    return std::max(idx[3 * f + i], idx[3 * f + (i + 1) % 3]);
  };
  auto slot_forward = [&](std::uint32_t s) {  // runs from lower to upper vertex
    const std::uint32_t f = s / 3, i = s % 3;
    return idx[3 * f + i] < idx[3 * f + (i + 1) % 3];
  };
  std::vector<std::uint32_t> bucket_offsets(V + 1, 0);
  for (std::uint32_t s = 0; s < 3 * F; ++s)
    if (slot_lo(s) != slot_hi(s)) ++bucket_offsets[slot_lo(s) + 1];
  for (std::uint32_t v = 0; v < V; ++v) bucket_offsets[v + 1] += bucket_offsets[v];
  std::vector<std::uint32_t> slots(bucket_offsets[V]);
  {
    std::vector<std::uint32_t> fill(bucket_offsets.begin(), bucket_offsets.end() - 1);
    for (std::uint32_t s = 0; s < 3 * F; ++s)
      if (slot_lo(s) != slot_hi(s)) slots[fill[slot_lo(s)]++] = s;
  }
  for (std::uint32_t v = 0; v < V; ++v) {
    // Slots were filled in increasing order, so a stable sort by upper vertex keeps slot order.
    std::stable_sort(slots.begin() + bucket_offsets[v], slots.begin() + bucket_offsets[v + 1],
                     [&](std::uint32_t a, std::uint32_t b) { return slot_hi(a) < slot_hi(b); });
  }

  t.face_edges.assign(3 * std::size_t(F), kNoEdge);
  t.face_neighbors.assign(3 * std::size_t(F), kNoFace);
  t.vertex_edge_offsets.assign(V + 1, 0);
  t.edge_face_offsets.push_back(0);
  for (std::uint32_t v = 0; v < V; ++v) {
    t.vertex_edge_offsets[v] = t.edge_count();
    std::uint32_t run = bucket_offsets[v];
    const std::uint32_t end = bucket_offsets[v + 1];
    while (run < end) {
      const std::uint32_t hi = slot_hi(slots[run]);
      std::uint32_t run_end = run;
      while (run_end < end && slot_hi(slots[run_end]) == hi) ++run_end;
      const std::uint32_t e = t.edge_count();
      t.edge_vertices.push_back(v);
      t.edge_vertices.push_back(hi);
      for (std::uint32_t k = run; k < run_end; ++k) {
        const std::uint32_t s = slots[k];
        t.face_edges[s] = e;
        if (t.edge_faces.size() == t.edge_face_offsets.back() || t.edge_faces.back() != s / 3)
          t.edge_faces.push_back(s / 3);
      }
      t.edge_face_offsets.push_back(static_cast<std::uint32_t>(t.edge_faces.size()));
      // Greedy pairing of opposite half-edges in face order: symmetric by construction.
      for (std::uint32_t a = run; a < run_end; ++a) {
        const std::uint32_t sa = slots[a];
        if (t.face_neighbors[sa] != kNoFace) continue;
        for (std::uint32_t b = a + 1; b < run_end; ++b) {
          const std::uint32_t sb = slots[b];
          if (t.face_neighbors[sb] != kNoFace || sb / 3 == sa / 3 || slot_forward(sa) == slot_forward(sb)) continue;
          t.face_neighbors[sa] = sb / 3;
          t.face_neighbors[sb] = sa / 3;
          break;
        }
      }
      run = run_end;
    }
  }
  t.vertex_edge_offsets[V] = t.edge_count();
  return t;
}

}  // namespace rastrace
