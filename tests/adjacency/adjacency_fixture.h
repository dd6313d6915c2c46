// Shared, computed-once constructions of the test meshes (the cover search is the slow part).
#pragma once

#include <map>
#include <memory>
#include <string>

#include "reorder/adjacency/bound.h"
#include "reorder/adjacency/build.h"
#include "scenes/mesh_io.h"
#include "tests/support/test_data.h"

namespace rastrace::testing {

struct BuiltMesh {
  Mesh mesh;
  AdjacencyBuild build;
};

// The default cover budget (20 iterations per face), seed 1: what `rastrace adjacency` runs.
inline const BuiltMesh& built_mesh(const std::string& name) {
  static std::map<std::string, std::unique_ptr<BuiltMesh>> cache;
  auto& slot = cache[name];
  if (!slot) {
    slot = std::make_unique<BuiltMesh>();
    slot->mesh = load_mesh(data_file("meshes/" + name));
    slot->build = build_adjacency_primitives(slot->mesh, CoverParams{});
  }
  return *slot;
}

}  // namespace rastrace::testing
