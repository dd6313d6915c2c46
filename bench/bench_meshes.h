// The CGAL meshes the benchmarks share (data/meshes, unpacked by scripts/setup.sh), each loaded
// once per process.
#pragma once

#include <map>
#include <string>

#include "scenes/mesh_io.h"

namespace rastrace::bench {

inline const Mesh& cgal_mesh(const std::string& name) {
  static std::map<std::string, Mesh> meshes;
  auto found = meshes.find(name);
  if (found == meshes.end())
    found = meshes.emplace(name, load_mesh(std::string(RASTRACE_DATA_DIR) + "/meshes/" + name + ".off")).first;
  return found->second;
}

// fandisk, triceratops and bunny00: the meshes of Hoppe's and Castaño's comparisons.
inline const char* const kComparisonMeshes[] = {"fandisk", "triceratops", "bunny00"};

}  // namespace rastrace::bench
