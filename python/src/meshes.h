// Meshes from Python: a rastrace.Mesh, or a mesh spec string (a file, builtin:NAME, grid:WxH).
#pragma once

#include <optional>

#include <pybind11/pybind11.h>

#include "scenes/mesh.h"

namespace rastrace::python {

// The mesh `object` names: a Mesh (no copy) or a spec, loaded into `storage`. Throws InputError
// for a bad spec, TypeError for anything else. Call with the GIL held.
const Mesh& mesh_argument(pybind11::handle object, std::optional<Mesh>& storage);

}  // namespace rastrace::python
