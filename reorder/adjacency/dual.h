// The dual graph of a mesh for triangle-with-adjacency primitives (Sander, Nehab, Chlamtac,
// Hoppe 2008, "Efficient traversal of mesh edges using adjacency primitives", section 3): one
// dual vertex per face, one dual edge per pair of faces sharing a mesh edge.
//
// Conventions (shared by every reorder/adjacency/* file):
// - Slot i of face f is its edge from vertex i to vertex (i+1)%3, as in reorder/mesh_topology.h.
// - A slot with a neighbour is an interior edge (a dual edge). A slot of a proper face without a
//   neighbour is a boundary edge: a hole's rim, or a face left unpaired at a non-manifold or
//   inconsistently oriented edge (mesh_topology pairs only opposite half-edges). Each boundary
//   slot is processed once, by its own face, which is therefore always in the cover.
// - A face with a repeated vertex is Degenerate: no dual edges, no edges to process; it still gets
//   a primitive of its own so that every face of the mesh is drawn exactly once.
#pragma once

#include <cstdint>
#include <vector>

#include "reorder/mesh_topology.h"
#include "scenes/mesh.h"

namespace rastrace {

enum class DualFaceKind : std::uint8_t { Interior, Boundary, Degenerate };

struct AdjacencyDual {
  std::uint32_t face_count = 0;
  std::uint32_t vertex_count = 0;
  // Three per face: the face across slot i (kNoFace at a boundary slot or on a degenerate face)
  // and the slot of the same edge in that neighbour.
  std::vector<std::uint32_t> neighbour;
  std::vector<std::uint8_t> neighbour_slot;
  std::vector<DualFaceKind> kind;  // per face
  // Per mesh vertex: set when the vertex touches a boundary slot or a degenerate face (the ring
  // argument of the lower bound only holds around the other, interior, vertices).
  std::vector<std::uint8_t> boundary_vertex;

  std::uint64_t dual_edge_count = 0;      // |E'|
  std::uint64_t boundary_slot_count = 0;  // boundary edges (slots) of proper faces
  std::uint32_t boundary_face_count = 0;  // |B'|
  std::uint32_t degenerate_face_count = 0;

  std::uint32_t across(std::uint32_t face, unsigned slot) const { return neighbour[3 * face + slot]; }
  bool interior(std::uint32_t face) const { return kind[face] == DualFaceKind::Interior; }
};

// O(F). Throws InputError (naming the mesh) on an index out of range or a bad index count.
AdjacencyDual build_adjacency_dual(const Mesh& mesh, const MeshTopology& topology);
AdjacencyDual build_adjacency_dual(const Mesh& mesh);

}  // namespace rastrace
