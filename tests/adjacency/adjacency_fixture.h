// The adjacency suites' computed-once constructions of the test meshes (the cover search is the
// slow part). The meshes themselves come from the shared test kit.
#pragma once

#include <map>
#include <memory>
#include <string>

#include "reorder/adjacency/bound.h"
#include "reorder/adjacency/build.h"
#include "tests/support/test_meshes.h"

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
    slot->mesh = cached_mesh(name);
    slot->build = build_adjacency_primitives(slot->mesh, CoverParams{});
  }
  return *slot;
}

}  // namespace rastrace::testing
