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

namespace {

// Buckets up to this size are sorted by insertion (about six entries on a manifold mesh, where
// std::sort's set-up costs more); larger ones, the centres of fans, by std::sort.
constexpr std::uint32_t kInsertionSortMax = 32;

// The slots of one edge's run still waiting for a partner, per direction, in run order.
struct OpenHalfEdges {
  std::vector<std::uint32_t> slots[2];
  std::size_t head[2] = {0, 0};
};

// Pairs the half-edges of one undirected edge (n slots in face order, forward[i]: the slot runs
// from the lower to the upper vertex) as the greedy rule says: each unpaired slot, in order,
// takes the first later unpaired slot of the opposite direction in another face. The same pairs
// come from one sweep: each slot takes the earliest still-open slot of the opposite direction in
// another face, or waits. That is linear where the greedy search is quadratic on an edge shared
// by thousands of faces all running the same way (a non-manifold fan). A face holds at most one
// slot of each direction of an edge, so at most one open slot is passed over.
void pair_opposite_half_edges(const std::uint64_t* keys, const std::uint8_t* forward, std::uint32_t n,
                              OpenHalfEdges& open, std::vector<std::uint32_t>& face_neighbors) {
  for (int d = 0; d < 2; ++d) {
    open.slots[d].clear();
    open.head[d] = 0;
  }
  for (std::uint32_t i = 0; i < n; ++i) {
    const std::uint32_t s = static_cast<std::uint32_t>(keys[i]);
    const int d = forward[i];
    std::vector<std::uint32_t>& waiting = open.slots[1 - d];
    std::size_t& head = open.head[1 - d];
    std::size_t j = head;
    while (j < waiting.size() && waiting[j] / 3 == s / 3) ++j;
    if (j == waiting.size()) {
      open.slots[d].push_back(s);
      continue;
    }
    const std::uint32_t partner = waiting[j];
    face_neighbors[s] = partner / 3;
    face_neighbors[partner] = s / 3;
    // Removes waiting[j]: the slots passed over move up one place, keeping their order.
    for (; j > head; --j) waiting[j] = waiting[j - 1];
    ++head;
  }
}

}  // namespace

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
  std::vector<std::uint64_t> sorted;
  std::vector<std::uint32_t> upper_counts;
  for (std::uint32_t v = 0; v < V; ++v) {
    std::uint64_t* key = keys.data() + bucket_offsets[v];
    std::uint8_t* fwd = forward.data() + bucket_offsets[v];
    const std::uint32_t n = bucket_offsets[v + 1] - bucket_offsets[v];
    if (n > kInsertionSortMax) {
      // A vertex in thousands of faces (a fan, or a mesh on few vertices): insertion sort would be
      // quadratic. The keys are distinct (the slot is in them), so any sort gives the same order;
      // the direction bytes are read again from the indices afterwards, once per entry. The
      // bucket is filled in slot order, so a stable counting sort by upper vertex gives it when
      // the upper vertices span a range of the bucket's order of size; std::sort otherwise.
      std::uint32_t lo = 0xFFFFFFFFu, hi = 0;
      for (std::uint32_t i = 0; i < n; ++i) {
        lo = std::min(lo, static_cast<std::uint32_t>(key[i] >> 32));
        hi = std::max(hi, static_cast<std::uint32_t>(key[i] >> 32));
      }
      if (std::uint64_t(hi - lo) < 4 * std::uint64_t(n)) {
        upper_counts.assign(std::size_t(hi - lo) + 2, 0);
        for (std::uint32_t i = 0; i < n; ++i) ++upper_counts[static_cast<std::uint32_t>(key[i] >> 32) - lo + 1];
        for (std::size_t u = 1; u < upper_counts.size(); ++u) upper_counts[u] += upper_counts[u - 1];
        sorted.resize(n);
        for (std::uint32_t i = 0; i < n; ++i) sorted[upper_counts[static_cast<std::uint32_t>(key[i] >> 32) - lo]++] = key[i];
        std::copy(sorted.begin(), sorted.end(), key);
      } else {
        std::sort(key, key + n);
      }
      for (std::uint32_t i = 0; i < n; ++i) {
        const std::size_t s = static_cast<std::uint32_t>(key[i]);
        fwd[i] = idx[s] < idx[s % 3 == 2 ? s - 2 : s + 1];
      }
      continue;
    }
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
  OpenHalfEdges open;
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
      pair_opposite_half_edges(keys.data() + run, forward.data() + run, run_end - run, open, t.face_neighbors);
      run = run_end;
    }
  }
  t.vertex_edge_offsets[V] = t.edge_count();
  return t;
}

}  // namespace rastrace
