// The sampled surface distance against distances known in closed form.
#include "lod/surface_distance.h"

#include <cmath>

#include <gtest/gtest.h>

#include "core/error.h"

namespace rastrace {
namespace {

using Triangles = std::vector<std::array<std::uint32_t, 3>>;

TEST(SurfaceDistance, IdenticalSurfacesAreAtZero) {
  const std::vector<glm::vec3> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}};
  const Triangles square{{0, 1, 2}, {0, 2, 3}};
  const SurfaceDistance d = surface_distance(p, square, square);
  EXPECT_LT(d.max, 1e-6);
}

TEST(SurfaceDistance, ParallelSquaresAreAtTheirGap) {
  // Two unit squares 0.25 apart: every point of each is exactly 0.25 from the other.
  const std::vector<glm::vec3> p{{0, 0, 0},     {1, 0, 0},     {1, 1, 0},     {0, 1, 0},
                                 {0, 0, 0.25f}, {1, 0, 0.25f}, {1, 1, 0.25f}, {0, 1, 0.25f}};
  const SurfaceDistance d = surface_distance(p, Triangles{{0, 1, 2}, {0, 2, 3}}, Triangles{{4, 5, 6}, {4, 6, 7}});
  EXPECT_NEAR(d.mean, 0.25, 1e-6);
  EXPECT_NEAR(d.max, 0.25, 1e-6);
}

TEST(SurfaceDistance, OneSidedGapIsAsymmetric) {
  // A unit square and its left half: from the half every point is on the square (0); from the
  // square, the right half's points are at their distance to x = 0.5, uniform on [0, 0.5]:
  // mean 0.125 over the whole square, max 0.5.
  const std::vector<glm::vec3> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5f, 0, 0}, {0.5f, 1, 0}};
  SurfaceDistanceParams params;
  params.samples = 100000;
  const SurfaceDistance d =
      surface_distance(p, Triangles{{0, 1, 2}, {0, 2, 3}}, Triangles{{0, 4, 5}, {0, 5, 3}}, params);
  EXPECT_NEAR(d.mean_a_to_b, 0.125, 0.002);
  EXPECT_LT(d.mean_b_to_a, 1e-6);
  EXPECT_NEAR(d.mean, 0.0625, 0.001);
  EXPECT_NEAR(d.max, 0.5, 0.005);
}

TEST(SurfaceDistance, BadInputIsAnInputError) {
  const std::vector<glm::vec3> p{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}};
  EXPECT_THROW(surface_distance(p, Triangles{}, Triangles{{0, 1, 2}}), InputError);
  EXPECT_THROW(surface_distance(p, Triangles{{0, 1, 5}}, Triangles{{0, 1, 2}}), InputError);
  EXPECT_THROW(surface_distance(p, Triangles{{0, 1, 1}}, Triangles{{0, 1, 2}}), InputError);
  const std::vector<glm::vec3> nan{{0, 0, 0}, {1, 0, 0}, {1, std::nanf(""), 0}};
  EXPECT_THROW(surface_distance(nan, Triangles{{0, 1, 2}}, Triangles{{0, 1, 2}}), InputError);
}

}  // namespace
}  // namespace rastrace
