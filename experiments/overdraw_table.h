// View-independent overdraw beside the vertex cache, as `rastrace overdraw` prints it: one row
// per ordering with ACMR (FIFO of `cache` entries, the size the orderings optimize for) and the
// overdraw of the axis views (overdraw/view_independent.h), plus meshoptimizer 0.18's own
// measure of the same index buffer (meshopt_analyzeOverdraw, same process) and, with
// sphere_views, Tootle-style views from N directions. Two peer rows run meshoptimizer's overdraw
// optimizer in the same process: meshopt-overdraw (meshopt_optimizeOverdraw on Tipsy's order,
// threshold lambda: the same paper's overdraw pass on the same input) and meshopt-full
// (meshopt_optimizeVertexCache, then meshopt_optimizeOverdraw: meshoptimizer's recommended
// pipeline).
#pragma once

#include <cstdint>
#include <string>

#include <glm/vec3.hpp>

#include "core/table.h"
#include "overdraw/overdraw_rasterizer.h"
#include "reorder/ordering.h"

namespace rastrace {

struct OverdrawTableSpec {
  std::string algorithms = "original,tipsy,tipsy-overdraw";  // "all" or "a,b,c"
  unsigned cache = 16;
  double lambda = 1.05;
  glm::vec3 view_direction{0.0f, 0.0f, -1.0f};  // front-to-back, back-to-front
  int resolution = 256;
  unsigned sphere_views = 0;  // > 0: an overdraw_sphere column from that many directions
  OverdrawRules rules = OverdrawRules::exact();
  bool peers = true;  // the meshopt-overdraw and meshopt-full rows
  std::uint64_t seed = 1;
  bool with_time = true;
};

// The triangle list an ordering draws (strips unrolled, degenerate triangles dropped).
std::vector<std::uint32_t> drawn_triangle_list(const Ordering& ordering);

// Throws InputError for an unknown algorithm, a cache of 0 entries, a bad lambda or resolution.
Table overdraw_table(const Mesh& mesh, const std::string& mesh_spec, const OverdrawTableSpec& spec);

}  // namespace rastrace
