// Mesh connectivity shared by every reordering algorithm: vertex -> faces, undirected edges with
// their faces, and the oriented face-face adjacency across edges that strips and Hoppe's
// strip-growing (Hoppe 1999, "Optimization of mesh locality for transparent vertex caching")
// walk on. Flat CSR arrays, built in O(F) plus small per-vertex sorts; no per-face allocation.
//
// Conventions:
// - Face f has vertices indices[3f], [3f+1], [3f+2]; its edge i runs from vertex i to vertex
//   (i+1)%3 (so edge 0 is (v0, v1), edge 1 (v1, v2), edge 2 (v2, v0)).
// - An edge whose two ends are the same vertex (a degenerate face) is not an edge: face_edges
//   holds kNoEdge there and the face has no neighbour across it.
// - face_neighbors pairs faces that share an edge with *opposite* directions (consistently
//   oriented, as a strip needs). The pairing is symmetric: if g is f's neighbour across f's edge
//   i, then f is g's neighbour across the same undirected edge. At a non-manifold edge (more than
//   two faces) faces are paired greedily in face-id order, the rest have no neighbour there;
//   edge_faces still lists them all.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "scenes/mesh.h"

namespace rastrace {

inline constexpr std::uint32_t kNoFace = 0xFFFFFFFFu;
inline constexpr std::uint32_t kNoEdge = 0xFFFFFFFFu;

struct MeshTopology {
  std::uint32_t vertex_count = 0;
  std::uint32_t face_count = 0;

  // vertex -> faces using it (each face once, increasing face id). CSR: vertex_count + 1 offsets.
  std::vector<std::uint32_t> vertex_face_offsets;
  std::vector<std::uint32_t> vertex_faces;

  // Undirected edges: edge e joins edge_vertices[2e] < edge_vertices[2e+1]. Edges are numbered
  // by lower vertex, then upper vertex; vertex_edge_offsets (vertex_count + 1) gives the edges
  // whose lower vertex is v, which is what find_edge searches.
  std::vector<std::uint32_t> edge_vertices;
  std::vector<std::uint32_t> vertex_edge_offsets;
  // edge -> faces containing it (increasing face id). CSR: edge_count() + 1 offsets.
  std::vector<std::uint32_t> edge_face_offsets;
  std::vector<std::uint32_t> edge_faces;

  // Three per face: face_edges[3f+i] is the edge id of f's edge i (or kNoEdge);
  // face_neighbors[3f+i] the consistently oriented face across it (or kNoFace).
  std::vector<std::uint32_t> face_edges;
  std::vector<std::uint32_t> face_neighbors;

  std::uint32_t edge_count() const { return static_cast<std::uint32_t>(edge_vertices.size() / 2); }

  std::span<const std::uint32_t> faces_of_vertex(std::uint32_t v) const {
    return {vertex_faces.data() + vertex_face_offsets[v], vertex_faces.data() + vertex_face_offsets[v + 1]};
  }
  std::span<const std::uint32_t> faces_of_edge(std::uint32_t e) const {
    return {edge_faces.data() + edge_face_offsets[e], edge_faces.data() + edge_face_offsets[e + 1]};
  }
  std::uint32_t neighbor(std::uint32_t face, unsigned edge) const { return face_neighbors[3 * face + edge]; }
  // Number of neighbours (0..3) of a face.
  unsigned neighbor_count(std::uint32_t face) const {
    return (face_neighbors[3 * face] != kNoFace) + (face_neighbors[3 * face + 1] != kNoFace) +
           (face_neighbors[3 * face + 2] != kNoFace);
  }
  // The edge joining a and b (either order), or kNoEdge. O(log degree).
  std::uint32_t find_edge(std::uint32_t a, std::uint32_t b) const;
};

// Throws InputError (naming the mesh and the face) if an index is >= the vertex count or the
// index count is not a multiple of three.
MeshTopology build_mesh_topology(const Mesh& mesh);

// Which of face f's edges (0..2) is the undirected edge (a, b); -1 if none.
inline int edge_slot(const std::uint32_t* face_vertices, std::uint32_t a, std::uint32_t b) {
  for (int i = 0; i < 3; ++i) {
    const std::uint32_t p = face_vertices[i], q = face_vertices[(i + 1) % 3];
    if ((p == a && q == b) || (p == b && q == a)) return i;
  }
  return -1;
}

}  // namespace rastrace
