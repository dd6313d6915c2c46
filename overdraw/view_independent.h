// View-independent overdraw of a triangle order, as meshoptimizer (meshopt_analyzeOverdraw) and
// AMD Tootle measure it: the mesh drawn in orthographic views from several directions with back
// faces culled and an early depth test, overdraw = fragments shaded / pixels covered, summed over
// all views. 1.0 means every covered pixel was shaded once (a perfect front-to-back order); a
// convex mesh scores 1.0 in any order; real meshes in a cache-optimized order score about 1.1-1.6.
//
// Views (ViewSet):
// - Axes (meshoptimizer's, the default): the mesh scaled uniformly so its largest bounding-box
//   side spans the R pixels, viewed along x, y and z from both sides (front and back faces of each
//   axis in separate layers, i.e. six views). With OverdrawRules::meshopt_018() and R = 256 the
//   counts equal Debian's meshoptimizer 0.18 exactly.
// - Sphere: N directions (or any given directions) spread evenly over the sphere (a Fibonacci lattice), as Tootle measures
//   from hundreds of viewpoints; each view fits the bounding sphere in R x R pixels and draws only
//   the faces turned towards it.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

#include "overdraw/overdraw_rasterizer.h"

namespace rastrace {

struct OverdrawOptions {
  int resolution = 256;       // pixels per side of every view
  unsigned sphere_views = 0;  // 0: the axis views; N > 0: N directions on the sphere
  // When not empty, replaces the views above: one view from each direction (pointing from the
  // mesh towards the viewer, any length but not zero), as the sphere views are drawn. A camera
  // looking along L is the direction -L.
  std::vector<glm::vec3> directions;
  OverdrawRules rules = OverdrawRules::exact();
};

// The triangle list's overdraw (three indices per triangle, counter-clockwise front faces; a
// degenerate triangle draws nothing). Throws InputError for an index out of range, an index
// count that is not a multiple of three, or a position that is not finite.
OverdrawCounts view_independent_overdraw(std::span<const glm::vec3> positions,
                                         std::span<const std::uint32_t> triangle_list,
                                         const OverdrawOptions& options = {});

// The unit view directions of the sphere views, pointing from the mesh towards the viewer.
std::vector<glm::vec3> sphere_view_directions(unsigned count);

}  // namespace rastrace
