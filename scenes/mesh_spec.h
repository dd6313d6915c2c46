// The MESH argument of `reorder` and `vcache`: a mesh file (any format load_mesh reads), a
// built-in scene ("builtin:grid", "builtin:bunny", ...; a scene of several objects is merged into
// one mesh in object order, in model space) or a procedural grid "grid:WxH" (make_grid, the layout
// of Castano's article; the only meshes the `grid` order accepts).
#pragma once

#include <string>

#include "scenes/mesh.h"

namespace rastrace {

// Throws InputError naming the spec and what was expected.
Mesh load_mesh_spec(const std::string& spec);

}  // namespace rastrace
