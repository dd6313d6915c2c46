// A minimal OFF reader for the reorder tests until scenes/mesh_io.h's load_mesh is built:
// positions and triangles (polygons fan-triangulated), nothing else. Fails the test on bad input.
#pragma once

#include <fstream>
#include <string>

#include <gtest/gtest.h>

#include "scenes/mesh.h"

namespace rastrace::testing {

inline Mesh read_off_for_test(const std::string& path) {
  Mesh mesh;
  mesh.name = path;
  std::ifstream in(path);
  std::string magic;
  in >> magic;
  EXPECT_EQ(magic, "OFF") << path;
  std::size_t vertices = 0, faces = 0, edges = 0;
  in >> vertices >> faces >> edges;
  mesh.positions.resize(vertices);
  for (auto& p : mesh.positions) in >> p.x >> p.y >> p.z;
  for (std::size_t f = 0; f < faces && in; ++f) {
    std::size_t count = 0;
    in >> count;
    std::uint32_t first = 0, previous = 0, current = 0;
    for (std::size_t i = 0; i < count; ++i) {
      in >> current;
      if (i >= 2) mesh.indices.insert(mesh.indices.end(), {first, previous, current});
      if (i == 0) first = current;
      previous = current;
    }
    std::string rest;
    std::getline(in, rest);
  }
  EXPECT_TRUE(static_cast<bool>(in)) << path << ": truncated OFF";
  return mesh;
}

}  // namespace rastrace::testing
