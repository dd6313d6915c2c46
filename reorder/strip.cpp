// The strip stream of a face order: consecutive oriented neighbours continue a strip (one new
// index, or two for a swap), any other pair restarts it. Counted as in Yang, Mitra, Huang (vertices
// sent) and Hoppe 1999 (indices per triangle b). See strip.h.
#include "reorder/strip.h"

namespace rastrace {

StripStats strip_stats(std::span<const std::uint32_t> indices, PrimitiveType type, RestartIndex restart_index) {
  StripStats stats;
  stats.indices = indices.size();
  // Lists: every index is sent as a vertex, a trailing partial primitive included.
  for (const std::uint32_t index : indices) stats.vertices_sent += !is_restart(type, restart_index, index);
  walk_index_stream(
      indices, type, restart_index, [&](std::size_t, bool primitive_start) { stats.strips += primitive_start; },
      [&](const AssembledTriangle& t) {
        if (t.degenerate())
          ++stats.swaps;
        else
          ++stats.triangles;
      });
  return stats;
}

namespace {

// The neighbour of face f across its undirected edge (a, b), or kNoFace.
std::uint32_t neighbor_across(const Mesh& mesh, const MeshTopology& topology, std::uint32_t f, std::uint32_t a,
                              std::uint32_t b) {
  const int slot = edge_slot(mesh.indices.data() + 3 * std::size_t(f), a, b);
  return slot < 0 ? kNoFace : topology.neighbor(f, static_cast<unsigned>(slot));
}

// The emitter's state between faces: whether a strip is open and its last two vertices.
struct StripCursor {
  bool open = false;
  std::uint32_t u = 0, w = 0;  // the strip's last two vertices, older first
  std::uint64_t sent = 0;      // indices excluding restart markers
  std::uint64_t strips = 0;
};

// Emits face f, knowing the face that follows it (kNoFace at the end). An open strip was left
// by the previous face through the edge (u, w), which f shares.
template <typename Out>
void strip_step(const Mesh& mesh, const MeshTopology& topology, StripCursor& c, std::uint32_t f, std::uint32_t next,
                Out&& out) {
  const std::uint32_t* v = mesh.indices.data() + 3 * std::size_t(f);
  const bool more = next != kNoFace && strip_continues(mesh, topology, f, next);
  if (!c.open) {
    if (c.strips) out(kStripRestart);
    ++c.strips;
    c.sent += 3;
    int exit = -1;
    if (more)
      for (int s = 0; s < 3 && exit < 0; ++s)
        if (topology.neighbor(f, s) == next) exit = s;
    if (exit < 0) {
      out(v[0]);
      out(v[1]);
      out(v[2]);
      return;
    }
    // Rotate so the last two vertices are the edge shared with the next face.
    out(v[(exit + 2) % 3]);
    out(v[exit]);
    out(v[(exit + 1) % 3]);
    c.u = v[exit];
    c.w = v[(exit + 1) % 3];
    c.open = true;
    return;
  }
  const std::uint32_t u = c.u, w = c.w;
  const std::uint32_t nv = v[0] != u && v[0] != w ? v[0] : v[1] != u && v[1] != w ? v[1] : v[2];
  if (more && neighbor_across(mesh, topology, f, w, nv) == next) {
    out(nv);
    ++c.sent;
    c.u = w;
    c.w = nv;
  } else if (more && neighbor_across(mesh, topology, f, u, nv) == next) {
    out(u);  // swap: the repeated pivot makes one degenerate triangle
    out(nv);
    c.sent += 2;
    c.w = nv;
  } else {
    out(nv);
    ++c.sent;
    c.open = false;
  }
}

}  // namespace

Ordering strip_ordering(const Mesh& mesh, const MeshTopology& topology, std::vector<std::uint32_t> order,
                        std::span<const std::uint8_t> restart_before) {
  Ordering ordering;
  ordering.type = PrimitiveType::TriangleStrip;
  ordering.restart_index = kStripRestart;
  std::vector<std::uint32_t>& out = ordering.indices;
  out.reserve(order.size() * 3 / 2 + 16);
  StripCursor cursor;
  for (std::size_t i = 0; i < order.size(); ++i) {
    const bool last = i + 1 == order.size() || (!restart_before.empty() && restart_before[i + 1]);
    strip_step(mesh, topology, cursor, order[i], last ? kNoFace : order[i + 1],
               [&](std::uint32_t index) { out.push_back(index); });
  }
  ordering.face_order = std::move(order);
  return ordering;
}

}  // namespace rastrace
