// The real meshes of the data folder, loaded once per test process: many tests read the same CGAL
// meshes (fandisk, triceratops, bunny00, ...) and parsing them again in every test is the slow part.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "scenes/mesh_io.h"
#include "support/test_data.h"

namespace rastrace::testing {

// meshes/<file> (e.g. "fandisk.off"), loaded on first use. The reference stays valid for the whole
// process; a test that changes the mesh copies it first.
inline const Mesh& cached_mesh(const std::string& file) {
  static std::map<std::string, std::unique_ptr<const Mesh>> cache;
  auto& slot = cache[file];
  if (!slot) slot = std::make_unique<const Mesh>(load_mesh(data_file("meshes/" + file)));
  return *slot;
}

}  // namespace rastrace::testing
