#include "reorder/adjacency/dual.h"

namespace rastrace {

AdjacencyDual build_adjacency_dual(const Mesh& mesh, const MeshTopology& topology) {
  AdjacencyDual dual;
  const std::uint32_t F = topology.face_count;
  dual.face_count = F;
  dual.vertex_count = topology.vertex_count;
  dual.neighbour.assign(3 * std::size_t{F}, kNoFace);
  dual.neighbour_slot.assign(3 * std::size_t{F}, 0);
  dual.kind.assign(F, DualFaceKind::Interior);
  dual.boundary_vertex.assign(topology.vertex_count, 0);
  const std::uint32_t* idx = mesh.indices.data();

  auto degenerate = [&](std::uint32_t f) {
    return idx[3 * f] == idx[3 * f + 1] || idx[3 * f + 1] == idx[3 * f + 2] || idx[3 * f] == idx[3 * f + 2];
  };
  for (std::uint32_t f = 0; f < F; ++f)
    if (degenerate(f)) {
      dual.kind[f] = DualFaceKind::Degenerate;
      ++dual.degenerate_face_count;
      for (int i = 0; i < 3; ++i) dual.boundary_vertex[idx[3 * f + i]] = 1;
    }

  for (std::uint32_t f = 0; f < F; ++f) {
    if (dual.kind[f] == DualFaceKind::Degenerate) continue;
    for (unsigned i = 0; i < 3; ++i) {
      const std::uint32_t g = topology.face_neighbors[3 * f + i];
      // A proper face never pairs with a degenerate one: that edge is a boundary of f.
      if (g == kNoFace || dual.kind[g] == DualFaceKind::Degenerate) {
        ++dual.boundary_slot_count;
        dual.kind[f] = DualFaceKind::Boundary;
        dual.boundary_vertex[idx[3 * f + i]] = 1;
        dual.boundary_vertex[idx[3 * f + (i + 1) % 3]] = 1;
        continue;
      }
      const int j = edge_slot(idx + 3 * std::size_t{g}, idx[3 * f + i], idx[3 * f + (i + 1) % 3]);
      dual.neighbour[3 * f + i] = g;
      dual.neighbour_slot[3 * f + i] = static_cast<std::uint8_t>(j);
      if (f < g) ++dual.dual_edge_count;
    }
  }
  for (std::uint32_t f = 0; f < F; ++f) dual.boundary_face_count += dual.kind[f] == DualFaceKind::Boundary;
  return dual;
}

AdjacencyDual build_adjacency_dual(const Mesh& mesh) { return build_adjacency_dual(mesh, build_mesh_topology(mesh)); }

}  // namespace rastrace
