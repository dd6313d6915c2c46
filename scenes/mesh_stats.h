// What `rastrace info` reports about a mesh: counts, bounding box, and the topology that decides
// how well a mesh can be ordered (boundary and non-manifold edges, connected components).
#pragma once

#include <cstddef>

#include <glm/vec3.hpp>

#include "scenes/mesh.h"

namespace rastrace {

struct MeshStats {
  std::size_t vertices = 0;
  std::size_t faces = 0;
  std::size_t materials = 0;   // mesh.materials.size() (0: the default material)
  std::size_t textures = 0;    // distinct texture sources among the materials
  glm::vec3 bounds_min{0.0f};  // over all positions; zero for an empty mesh
  glm::vec3 bounds_max{0.0f};
  std::size_t edges = 0;                 // distinct undirected edges
  std::size_t boundary_edges = 0;        // edges used by exactly one face
  std::size_t non_manifold_edges = 0;    // edges used by three or more faces
  std::size_t connected_components = 0;  // face sets connected through shared vertices
  std::size_t degenerate_faces = 0;      // faces with a repeated vertex index
  std::size_t unreferenced_vertices = 0;
};

// Linear in the mesh size (sort of the edge list + union-find over vertices).
MeshStats compute_mesh_stats(const Mesh& mesh);

}  // namespace rastrace
