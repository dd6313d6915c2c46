// The spatial builder: recursive bisection of the triangles' centroids, blind to connectivity.
// A set of triangles that fits both limits is one meshlet; a larger set is split at the median
// along the longest axis of its centroids' bounding box, the median chosen so that the first half
// holds a whole number of full meshlets' worth of triangles when it can (fewer, fuller meshlets
// than a split at the middle). It is the cluster hierarchy of a ray tracer's BVH, and the
// baseline of connectivity-aware builders: a meshlet's vertices are those its box encloses.
#include <algorithm>

#include <glm/common.hpp>

#include "reorder/meshlets/meshlet.h"

namespace rastrace {

namespace {

struct SpatialBuilder {
  std::span<const std::uint32_t> indices;
  std::vector<glm::vec3> centroid;
  MeshletAccumulator& meshlets;
  std::vector<std::uint8_t> seen;  // per vertex: counted in the current fit test
  std::vector<std::uint32_t> touched;

  // True if the triangles share at most max_vertices vertices (and are few enough).
  bool fits(std::span<const std::uint32_t> triangles) {
    if (triangles.size() > meshlets.limits().max_triangles) return false;
    touched.clear();
    for (const std::uint32_t t : triangles)
      for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = indices[3 * t + k];
        if (!seen[v]) {
          seen[v] = 1;
          touched.push_back(v);
        }
      }
    for (const std::uint32_t v : touched) seen[v] = 0;
    return touched.size() <= meshlets.limits().max_vertices;
  }

  void build(std::span<std::uint32_t> triangles) {
    if (fits(triangles)) {
      for (const std::uint32_t t : triangles) meshlets.append(indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]);
      meshlets.close();
      return;
    }
    glm::vec3 low = centroid[triangles[0]], high = low;
    for (const std::uint32_t t : triangles) {
      low = glm::min(low, centroid[t]);
      high = glm::max(high, centroid[t]);
    }
    const glm::vec3 extent = high - low;
    const int axis = extent.x >= extent.y && extent.x >= extent.z ? 0 : extent.y >= extent.z ? 1 : 2;
    // The first half: a multiple of max_triangles near the middle, or the middle itself.
    const std::size_t full = meshlets.limits().max_triangles;
    std::size_t half = (triangles.size() / 2 + full - 1) / full * full;
    if (half == 0 || half >= triangles.size()) half = triangles.size() / 2;
    std::nth_element(triangles.begin(), triangles.begin() + static_cast<std::ptrdiff_t>(half), triangles.end(),
                     [&](std::uint32_t a, std::uint32_t b) {
                       return centroid[a][axis] < centroid[b][axis] || (centroid[a][axis] == centroid[b][axis] && a < b);
                     });
    build(triangles.first(half));
    build(triangles.subspan(half));
  }
};

}  // namespace

MeshletSet build_meshlets_spatial(std::span<const std::uint32_t> indices, std::span<const glm::vec3> positions,
                                  const MeshletLimits& limits) {
  validate_triangle_list(indices, positions.size());
  MeshletAccumulator meshlets(positions.size(), limits);
  const std::size_t triangle_count = indices.size() / 3;
  SpatialBuilder builder{indices, std::vector<glm::vec3>(triangle_count), meshlets,
                         std::vector<std::uint8_t>(positions.size(), 0), {}};
  for (std::size_t t = 0; t < triangle_count; ++t)
    builder.centroid[t] =
        (positions[indices[3 * t]] + positions[indices[3 * t + 1]] + positions[indices[3 * t + 2]]) / 3.0f;
  std::vector<std::uint32_t> order(triangle_count);
  for (std::size_t t = 0; t < triangle_count; ++t) order[t] = static_cast<std::uint32_t>(t);
  if (!order.empty()) builder.build(order);
  return meshlets.finish();
}

}  // namespace rastrace
