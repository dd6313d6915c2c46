// The peer, run in the same process: meshoptimizer 0.18 (Debian libmeshoptimizer-dev), whose
// meshopt_analyzeOverdraw measures the axis views (view_independent.h) and whose
// meshopt_optimizeOverdraw is the overdraw ordering to compare tipsy-overdraw with.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "overdraw/overdraw_rasterizer.h"

namespace rastrace {

// meshopt_analyzeOverdraw's pixels_shaded and pixels_covered for the triangle list.
OverdrawCounts meshopt_analyze_overdraw(std::span<const glm::vec3> positions,
                                        std::span<const std::uint32_t> triangle_list);

// meshopt_optimizeOverdraw(threshold) applied to a triangle list that is already in a vertex
// cache order: the same triangles, clusters of that order sorted (its cache model is a FIFO of 16).
std::vector<std::uint32_t> meshopt_optimize_overdraw(std::span<const glm::vec3> positions,
                                                     std::span<const std::uint32_t> triangle_list, float threshold);

}  // namespace rastrace
