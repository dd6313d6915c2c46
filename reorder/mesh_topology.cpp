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

  // Half-edge slots 3f+i bucketed by lower vertex, sorted by (upper vertex, slot). A bucket entry
  // carries its sort key, (upper << 32) | slot, and a parallel byte whether the slot runs from
  // lower to upper vertex, so the sort and the pairing read nothing outside the bucket (the
  // faces are in arbitrary order: scattered reads are what this pass costs). The buckets, about
  // six entries each, are sorted by insertion; std::stable_sort allocates a buffer per call.
  const std::size_t S = 3 * std::size_t(F);
  std::vector<std::uint32_t> bucket_offsets(std::size_t(V) + 1, 0);
  for (std::size_t s = 0; s < S; ++s) {
    const std::uint32_t a = idx[s], b = idx[s % 3 == 2 ? s - 2 : s + 1];
    if (a != b) ++bucket_offsets[std::min(a, b) + 1];
  }
  for (std::uint32_t v = 0; v < V; ++v) bucket_offsets[v + 1] += bucket_offsets[v];
  std::vector<std::uint64_t> keys(bucket_offsets[V]);
  std::vector<std::uint8_t> forward(bucket_offsets[V]);
  {
    std::vector<std::uint32_t> fill(bucket_offsets.begin(), bucket_offsets.end() - 1);
    for (std::size_t f = 0; f < F; ++f)
      for (std::size_t i = 0; i < 3; ++i) {
        const std::size_t s = 3 * f + i;
        const std::uint32_t a = idx[s], b = idx[i == 2 ? s - 2 : s + 1];
        if (a == b) continue;
        const std::uint32_t k = fill[std::min(a, b)]++;
        keys[k] = std::uint64_t(std::max(a, b)) << 32 | s;
        forward[k] = a < b;
      }
  }
  for (std::uint32_t v = 0; v < V; ++v) {
    std::uint64_t* key = keys.data() + bucket_offsets[v];
    std::uint8_t* fwd = forward.data() + bucket_offsets[v];
    const std::uint32_t n = bucket_offsets[v + 1] - bucket_offsets[v];
    for (std::uint32_t i = 1; i < n; ++i) {
      const std::uint64_t k = key[i];
      const std::uint8_t d = fwd[i];
      std::uint32_t j = i;
      for (; j > 0 && key[j - 1] > k; --j) {
        key[j] = key[j - 1];
        fwd[j] = fwd[j - 1];
      }
      key[j] = k;
      fwd[j] = d;
    }
  }

  t.face_edges.assign(S, kNoEdge);
  t.face_neighbors.assign(S, kNoFace);
  t.vertex_edge_offsets.assign(std::size_t(V) + 1, 0);
  // Upper bounds (every slot its own edge), so the loop below never reallocates.
  t.edge_vertices.reserve(2 * keys.size());
  t.edge_face_offsets.reserve(keys.size() + 1);
  t.edge_faces.reserve(keys.size());
  t.edge_face_offsets.push_back(0);
  std::vector<std::uint8_t> paired;  // per entry of the current run
  for (std::uint32_t v = 0; v < V; ++v) {
    t.vertex_edge_offsets[v] = t.edge_count();
    std::uint32_t run = bucket_offsets[v];
    const std::uint32_t end = bucket_offsets[v + 1];
    while (run < end) {
      const std::uint32_t upper = static_cast<std::uint32_t>(keys[run] >> 32);
      std::uint32_t run_end = run;
      while (run_end < end && static_cast<std::uint32_t>(keys[run_end] >> 32) == upper) ++run_end;
      const std::uint32_t e = t.edge_count();
      t.edge_vertices.push_back(v);
      t.edge_vertices.push_back(upper);
      for (std::uint32_t k = run; k < run_end; ++k) {
        const std::uint32_t s = static_cast<std::uint32_t>(keys[k]);
        t.face_edges[s] = e;
        if (t.edge_faces.size() == t.edge_face_offsets.back() || t.edge_faces.back() != s / 3)
          t.edge_faces.push_back(s / 3);
      }
      t.edge_face_offsets.push_back(static_cast<std::uint32_t>(t.edge_faces.size()));
      // Greedy pairing of opposite half-edges in face order: symmetric by construction. A slot
      // is only ever paired within its own run.
      paired.assign(run_end - run, 0);
      for (std::uint32_t a = run; a < run_end; ++a) {
        if (paired[a - run]) continue;
        const std::uint32_t sa = static_cast<std::uint32_t>(keys[a]);
        for (std::uint32_t b = a + 1; b < run_end; ++b) {
          const std::uint32_t sb = static_cast<std::uint32_t>(keys[b]);
          if (paired[b - run] || sb / 3 == sa / 3 || forward[a] == forward[b]) continue;
          t.face_neighbors[sa] = sb / 3;
          t.face_neighbors[sb] = sa / 3;
          paired[a - run] = paired[b - run] = 1;
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
