// The geometric error of a simplified mesh: the symmetric distance between two triangle
// surfaces (in the spirit of the Metro tool of Cignoni, Rocchini and Scopigno, "Metro:
// Measuring Error on Simplified Surfaces", 1998), estimated by sampling points uniformly by area
// on each surface and measuring each point's distance to the nearest triangle of the other,
// found through a uniform grid over both surfaces' bounding box.
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include <glm/vec3.hpp>

namespace rastrace {

struct SurfaceDistanceParams {
  std::uint32_t samples = 20000;  // per surface
  std::uint64_t seed = 1;
};

struct SurfaceDistance {
  double mean = 0.0;  // mean over both surfaces' samples (each surface weighs the same)
  double max = 0.0;   // largest sampled distance either way (a sampled Hausdorff distance)
  double mean_a_to_b = 0.0, mean_b_to_a = 0.0;
};

// The two surfaces share one vertex array (a simplified mesh's triangles index the original's
// vertices). Zero-area triangles are never sampled, but count as surface for the distance.
// Throws InputError if either triangle set has no area.
SurfaceDistance surface_distance(std::span<const glm::vec3> positions, std::span<const std::array<std::uint32_t, 3>> a,
                                 std::span<const std::array<std::uint32_t, 3>> b,
                                 const SurfaceDistanceParams& params = {});

// The length of the bounding box diagonal of the vertices the triangles use: the usual scale to
// quote distances as a fraction of the model's size.
double bounding_box_diagonal(std::span<const glm::vec3> positions,
                             std::span<const std::array<std::uint32_t, 3>> triangles);

}  // namespace rastrace
