// The input a progressive mesh can be built from: a non-empty, consistently oriented
// two-manifold triangle mesh (with or without boundary). Half-edge collapses and their
// manifoldness checks are only meaningful on such a mesh, so anything else is refused up front.
#pragma once

#include "scenes/mesh.h"

namespace rastrace::lod_detail {

// Throws InputError naming the mesh and the first offending face, edge or vertex: no triangles,
// an index count not a multiple of 3, an index out of range, a non-finite position, a face
// repeating a vertex, an edge shared by more than two faces or by two faces with the same
// direction (inconsistent winding), or a vertex whose faces do not form a single fan (two cones
// touching at a vertex).
void check_manifold_input(const Mesh& mesh);

}  // namespace rastrace::lod_detail
