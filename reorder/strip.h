// The strip stream: turning a face order into a sequential strip stream, and counting what a strip
// stream costs. The `strip` stripifier (stripifier.cpp), `greedy` and `local` all emit through it.
//
// Representation: one GL triangle strip with primitive restart (Ordering::restart_index =
// kStripRestart). Consecutive faces of the order that are oriented neighbours
// (MeshTopology::face_neighbors) continue the strip: one new index, or two when the strip turns
// the "wrong" way for a sequential strip (a swap, emulated by repeating the pivot vertex, which
// makes one degenerate triangle: "u w u n" draws (w, u, n) after (.., u, w)). Any other pair of
// consecutive faces restarts the strip. Every drawn triangle is one mesh face with its original
// winding (GL's alternating strip winding and the repeated pivot keep consistently oriented
// neighbours consistent), in the order given.
//
// Counts (Hoppe 1999 section 2.1; Yang, Mitra, Huang, Table 1 after Evans et al.):
// - vertices sent (Yang et al.'s "cost", "the number of vertex count for each swap and vertex
//   sent"): indices excluding restart markers, i.e. for each strip 2 + triangles + swaps. Evans
//   et al.'s IRIS GL strips pay a swap command per swap and 3 vertices per new strip, the same as
//   our duplicated pivot index and restart; so the counts agree, except that our strips keep each
//   face's winding, which can cost one swap at a strip's start that theirs need not pay. A good
//   stripifier sends 1.1-1.25 vertices per triangle.
// - Hoppe's b (indices per triangle): every index sent including the restart markers, per drawn
//   triangle; 1.1 <= b <= 1.5 for typical strips, 3 for a triangle list.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "reorder/mesh_topology.h"
#include "reorder/ordering.h"

namespace rastrace {

struct StripStats {
  std::uint64_t strips = 0;         // non-empty strips
  std::uint64_t triangles = 0;      // drawn (non-degenerate) triangles
  std::uint64_t swaps = 0;          // degenerate triangles inside strips (duplicated indices)
  std::uint64_t vertices_sent = 0;  // indices excluding restart markers (Yang et al.'s cost)
  std::uint64_t indices = 0;        // all indices including restart markers

  // Hoppe's b.
  double indices_per_triangle() const { return triangles ? double(indices) / double(triangles) : 0.0; }
  double vertices_per_triangle() const { return triangles ? double(vertices_sent) / double(triangles) : 0.0; }
};

// Counts a strip stream (restart_index separates strips; kNoRestart if there is none). A list
// stream can be passed as type TriangleList: then every triangle is its own 3-vertex "strip".
StripStats strip_stats(std::span<const std::uint32_t> indices, PrimitiveType type,
                       RestartIndex restart_index = kStripRestart);

// The strip stream that draws the faces in exactly the given order (see above). The result is a
// TriangleStrip Ordering with face_order = order.
// restart_before (empty, or one flag per position) forces a new strip at the flagged positions
// even where the faces would continue one (a stripifier's own strip boundaries).
Ordering strip_ordering(const Mesh& mesh, const MeshTopology& topology, std::vector<std::uint32_t> order,
                        std::span<const std::uint8_t> restart_before = {});

// Whether face b can follow face a inside a strip: non-degenerate oriented neighbours.
inline bool strip_continues(const Mesh& mesh, const MeshTopology& topology, std::uint32_t a, std::uint32_t b) {
  const std::uint32_t* n = topology.face_neighbors.data() + 3 * std::size_t(a);
  if (a == b || (n[0] != b && n[1] != b && n[2] != b)) return false;
  const std::uint32_t* va = mesh.indices.data() + 3 * std::size_t(a);
  const std::uint32_t* vb = mesh.indices.data() + 3 * std::size_t(b);
  return va[0] != va[1] && va[1] != va[2] && va[0] != va[2] && vb[0] != vb[1] && vb[1] != vb[2] && vb[0] != vb[2];
}

}  // namespace rastrace
