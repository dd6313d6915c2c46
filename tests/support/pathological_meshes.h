// Generated meshes that are legal but hostile to orderings and adjacency builders, each with
// about `faces` faces: degenerate faces, duplicated faces, many faces on few vertices, and a
// non-manifold fan (every face on one edge), beside a well-formed grid of the same face count.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "scenes/mesh.h"
#include "scenes/procedural.h"

namespace rastrace::testing {

inline Mesh pathological_base(const std::string& name, std::uint32_t vertices) {
  Mesh mesh;
  mesh.name = name;
  for (std::uint32_t v = 0; v < vertices; ++v)
    mesh.positions.emplace_back(static_cast<float>(v % 97) * 0.1f, static_cast<float>(v / 97) * 0.1f,
                                static_cast<float>((v * 37u) % 11u) * 0.05f);
  return mesh;
}

// name, mesh: the well-formed grid first.
inline std::vector<std::pair<std::string, Mesh>> pathological_meshes(std::uint32_t faces) {
  std::vector<std::pair<std::string, Mesh>> out;
  std::uint32_t side = 1;
  while (2 * side * side < faces) ++side;
  out.emplace_back("grid", make_grid(static_cast<int>(side), static_cast<int>(faces / (2 * side))));

  // Half the faces degenerate (two or three equal indices) among the faces of a strip.
  Mesh degenerate = pathological_base("degenerate", faces / 2 + 2);
  for (std::uint32_t f = 0; f < faces; ++f) {
    const std::uint32_t v = f / 2;
    if (f % 2 == 0)
      degenerate.indices.insert(degenerate.indices.end(), {v, v + 1, v + 2});
    else
      degenerate.indices.insert(degenerate.indices.end(), {v, v, f % 4 == 1 ? v : v + 1});
  }
  out.emplace_back("degenerate", std::move(degenerate));

  // Every face four times (the same triangle drawn again and again).
  Mesh duplicates = pathological_base("duplicates", faces / 4 + 2);
  for (std::uint32_t f = 0; f < faces; ++f) {
    const std::uint32_t v = f / 4;
    duplicates.indices.insert(duplicates.indices.end(), {v, v + 1, v + 2});
  }
  out.emplace_back("duplicates", std::move(duplicates));

  // All faces on 24 vertices: each vertex in about faces/8 faces, edges shared by many faces.
  Mesh dense = pathological_base("few-vertices", 24);
  std::uint32_t state = 12345;
  for (std::uint32_t f = 0; f < faces; ++f) {
    std::uint32_t v[3];
    for (std::uint32_t& x : v) {
      state = state * 1664525u + 1013904223u;
      x = (state >> 16) % 24;
    }
    if (v[0] == v[1]) v[1] = (v[1] + 1) % 24;
    if (v[2] == v[0] || v[2] == v[1]) v[2] = (v[2] + 2) % 24;
    if (v[2] == v[0] || v[2] == v[1]) v[2] = (v[2] + 3) % 24;
    dense.indices.insert(dense.indices.end(), {v[0], v[1], v[2]});
  }
  out.emplace_back("few-vertices", std::move(dense));

  // A non-manifold fan: every face on the edge 0-1.
  Mesh fan = pathological_base("edge-fan", faces + 2);
  for (std::uint32_t f = 0; f < faces; ++f) fan.indices.insert(fan.indices.end(), {0u, 1u, f + 2});
  out.emplace_back("edge-fan", std::move(fan));

  // A vertex fan: every face on vertex 0, neighbouring faces sharing an edge (a disc's star).
  Mesh star = pathological_base("vertex-fan", faces + 2);
  for (std::uint32_t f = 0; f < faces; ++f) star.indices.insert(star.indices.end(), {0u, f + 1, f + 2});
  out.emplace_back("vertex-fan", std::move(star));
  return out;
}

}  // namespace rastrace::testing
