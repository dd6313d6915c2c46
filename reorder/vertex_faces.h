// The vertex -> faces part of MeshTopology alone, for the fan-based orders (tipsy, forsyth,
// kcache) that need nothing else: one counting sort, no edges. build_mesh_topology's edge and
// face-adjacency passes cost about three times as much as Tipsy itself on bunny00, and Tipsy must
// keep pace with meshoptimizer's. Same conventions as build_mesh_topology: each face listed once
// per distinct vertex, in increasing face id; the edge and neighbour arrays are left empty.
#pragma once

#include "reorder/mesh_topology.h"

namespace rastrace {

// Throws InputError (naming the mesh and the face) for an index >= the vertex count or an index
// count that is not a multiple of three.
MeshTopology build_vertex_faces(const Mesh& mesh);

}  // namespace rastrace
