// Tipsy ("Tipsify"): Sander, Nehab and Barczak, "Fast Triangle Reordering for Vertex Locality and
// Reduced Overdraw", SIGGRAPH 2007, the vertex-locality pass (their Algorithm 1).
//
// The order is built by fanning: all not yet emitted triangles around the current vertex are
// emitted in the mesh's own order, every vertex they touch is pushed on the dead-end stack and
// becomes a candidate. The next fanning vertex is the candidate that still has live triangles and
// will still be in a FIFO cache of k entries after its remaining fan is emitted, preferring the
// one that entered the cache earliest (the time-stamp rule: the largest s - C[v] with
// s - C[v] + 2 * live[v] <= k, else any live candidate); with no live candidate the dead-end
// stack is popped for the most recently touched live vertex, and failing that the next live
// vertex in input order is taken. The cache is modelled with time stamps, never simulated.
//
// Parameters: cache_size (k, the FIFO the order is made for; 12 to 32 typical). The policy is
// ignored: the rule is defined for FIFO. Linear time. ACMR on real meshes about 0.65-0.75 at
// k = 16; the paper's steady state on a regular mesh is (n+2)/(2n+2). Deterministic.
#include <algorithm>
#include <memory>

#include "reorder/ordering.h"
#include "reorder/tipsy.h"
#include "reorder/vertex_faces.h"

namespace rastrace {

Ordering reorder_tipsy(const Mesh& mesh, const ReorderParams& params) { return tipsify(mesh, params, nullptr); }

Ordering tipsify(const Mesh& mesh, const ReorderParams& params, std::vector<std::uint32_t>* path_starts) {
  const MeshTopology topology = build_vertex_faces(mesh);
  const std::uint32_t vertex_count = topology.vertex_count, face_count = topology.face_count;
  const std::uint32_t* idx = mesh.indices.data();

  std::vector<std::uint32_t> live(vertex_count);
  for (std::uint32_t v = 0; v < vertex_count; ++v)
    live[v] = topology.vertex_face_offsets[v + 1] - topology.vertex_face_offsets[v];
  std::vector<std::uint32_t> stamp(vertex_count, 0);
  std::vector<std::uint8_t> emitted(face_count, 0);
  // The dead-end stack; the entries a fan pushes are also that fan's candidate list.
  // Never read above its top, so left uninitialised (it is the largest array here). Pushes are
  // branch-free (written, then counted or not), hence the spare entry.
  const std::unique_ptr<std::uint32_t[]> dead_end =
      std::make_unique_for_overwrite<std::uint32_t[]>(3 * std::size_t(face_count) + 1);
  std::size_t dead_end_size = 0;

  Ordering ordering;
  ordering.face_order.resize(face_count);
  ordering.indices.resize(mesh.indices.size());
  std::uint32_t* order_out = ordering.face_order.data();
  std::uint32_t* index_out = ordering.indices.data();

  // Time stamps are unsigned: time - stamp[v] wraps exactly as the paper's counter differences.
  const std::uint32_t k = std::clamp(params.cache_size, 1u, 1u << 24);
  std::uint32_t time = k + 1;
  std::uint32_t input_cursor = 0;
  std::int64_t fan = vertex_count > 0 ? 0 : -1;
  if (path_starts && fan >= 0) path_starts->push_back(0);
  while (fan >= 0) {
    const std::size_t fan_start = dead_end_size;
    const auto fan_vertex = static_cast<std::uint32_t>(fan);
    // live[fan_vertex] faces are left to emit: once they are, the rest of its list is emitted
    // already and is not scanned.
    std::uint32_t remaining = live[fan_vertex];
    for (const std::uint32_t face : topology.faces_of_vertex(fan_vertex)) {
      if (remaining == 0) break;
      if (emitted[face]) continue;
      --remaining;
      emitted[face] = 1;
      *order_out++ = face;
      const std::uint32_t* corners = idx + 3 * std::size_t(face);
      const std::uint32_t a = corners[0], b = corners[1], c = corners[2];
      index_out[0] = a;
      index_out[1] = b;
      index_out[2] = c;
      index_out += 3;
      // A degenerate face counts each distinct vertex once, as its adjacency lists it. The fan
      // vertex is not pushed: it has no live triangle left once its fan is emitted, so neither
      // the candidate scan nor the dead-end stack could ever pick it.
      const std::uint32_t count_b = b != a, count_c = (c != a) & (c != b);
      dead_end[dead_end_size] = a;
      dead_end_size += a != fan_vertex;
      dead_end[dead_end_size] = b;
      dead_end_size += count_b & (b != fan_vertex);
      dead_end[dead_end_size] = c;
      dead_end_size += count_c & (c != fan_vertex);
      live[a] -= 1;
      live[b] -= count_b;
      live[c] -= count_c;
      if (time - stamp[a] > k) stamp[a] = time++;
      if (count_b && time - stamp[b] > k) stamp[b] = time++;
      if (count_c && time - stamp[c] > k) stamp[c] = time++;
    }

    // Time-stamp rule over this fan's vertices.
    std::int64_t next = -1, best = -1;
    for (std::size_t c = fan_start; c < dead_end_size; ++c) {
      const std::uint32_t v = dead_end[c];
      if (live[v] == 0) continue;
      std::int64_t priority = 0;
      const std::uint32_t age = time - stamp[v];
      if (std::int64_t(age) + 2 * std::int64_t(live[v]) <= std::int64_t(k)) priority = age;
      if (priority > best) {
        best = priority;
        next = v;
      }
    }
    // A dead end: the next fan does not continue this one (the overdraw pass cuts clusters here).
    if (next < 0 && path_starts) path_starts->push_back(static_cast<std::uint32_t>(order_out - ordering.face_order.data()));
    if (next < 0) {
      while (dead_end_size > 0) {
        const std::uint32_t v = dead_end[--dead_end_size];
        if (live[v] > 0) {
          next = v;
          break;
        }
      }
    }
    if (next < 0) {
      while (input_cursor < vertex_count && live[input_cursor] == 0) ++input_cursor;
      if (input_cursor < vertex_count) next = input_cursor;
    }
    fan = next;
  }
  return ordering;
}

}  // namespace rastrace
