#include "overdraw/view_independent.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>

#include <glm/geometric.hpp>

#include "core/error.h"

namespace rastrace {

namespace {

void validate(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangle_list) {
  if (triangle_list.size() % 3 != 0)
    throw InputError("overdraw: " + std::to_string(triangle_list.size()) +
                     " indices is not a triangle list (expected a multiple of 3)");
  for (std::size_t i = 0; i < triangle_list.size(); ++i)
    if (triangle_list[i] >= positions.size())
      throw InputError("overdraw: index " + std::to_string(i) + " is " + std::to_string(triangle_list[i]) +
                       ", expected below the vertex count " + std::to_string(positions.size()));
  for (std::size_t v = 0; v < positions.size(); ++v)
    if (!std::isfinite(positions[v].x) || !std::isfinite(positions[v].y) || !std::isfinite(positions[v].z))
      throw InputError("overdraw: vertex " + std::to_string(v) + " has a position that is not finite");
}

// meshoptimizer's axis views: every vertex (referenced or not) sets the bounding box, the
// largest side spans R pixels, and axis a is drawn with screen (x, y, depth) = a permutation of
// the scaled coordinates; both facings at once (two layers).
OverdrawCounts axis_views(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangle_list,
                          const OverdrawOptions& options) {
  glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
  for (const glm::vec3& p : positions) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  const float extent = std::max(high.x - low.x, std::max(high.y - low.y, high.z - low.z));
  if (!std::isfinite(extent)) throw InputError("overdraw: the bounding box's size overflows float");
  if (!(extent > 0)) return {};
  const float scale = float(options.resolution) / extent;
  std::vector<glm::vec3> scaled(triangle_list.size());
  for (std::size_t i = 0; i < triangle_list.size(); ++i) {
    const glm::vec3& p = positions[triangle_list[i]];
    scaled[i] = glm::vec3((p.x - low.x) * scale, (p.y - low.y) * scale, (p.z - low.z) * scale);
  }
  // (screen x, screen y, depth) per axis: x seen as (z, y), y as (x, z), z as (y, x).
  constexpr int kAxes[3][3] = {{2, 1, 0}, {0, 2, 1}, {1, 0, 2}};
  OverdrawRasterizer rasterizer(options.resolution, float(options.resolution), options.rules);
  OverdrawCounts total;
  for (const auto& axis : kAxes) {
    rasterizer.clear();
    const auto vertex = [&](std::size_t i) {
      return OverdrawVertex{scaled[i][axis[0]], scaled[i][axis[1]], scaled[i][axis[2]]};
    };
    for (std::size_t i = 0; i < scaled.size(); i += 3) rasterizer.draw(vertex(i), vertex(i + 1), vertex(i + 2));
    total += rasterizer.counts();
  }
  return total;
}

// Views from the given directions: the bounding sphere of the box fills the view, screen
// axes (u, v) with (u, v, d) left-handed so that a front face (counter-clockwise seen from d)
// is clockwise on the screen and lands in layer 0; faces turned away are culled here.
OverdrawCounts directional_views(std::span<const glm::vec3> positions, std::span<const std::uint32_t> triangle_list,
                                 std::span<const glm::vec3> directions, const OverdrawOptions& options) {
  glm::vec3 low(std::numeric_limits<float>::max()), high(-std::numeric_limits<float>::max());
  for (const glm::vec3& p : positions) {
    low = glm::min(low, p);
    high = glm::max(high, p);
  }
  const glm::vec3 centre = (low + high) * 0.5f;
  const float radius = glm::length(high - low) * 0.5f;
  if (!std::isfinite(radius)) throw InputError("overdraw: the bounding box's size overflows float");
  if (!(radius > 0)) return {};
  const float half = float(options.resolution) * 0.5f;
  const float scale = half / radius * (1.0f - 1e-6f);  // keep the sphere's rim inside the grid
  OverdrawRasterizer rasterizer(options.resolution, float(options.resolution), options.rules);
  OverdrawCounts total;
  std::vector<OverdrawVertex> projected(positions.size());
  for (const glm::vec3& given : directions) {
    const float length = glm::length(given);
    if (!(length > 0) || !std::isfinite(length)) throw InputError("overdraw: a view direction is zero or not finite");
    const glm::vec3 d = given / length;
    const glm::vec3 helper = std::abs(d.x) < 0.9f ? glm::vec3(1, 0, 0) : glm::vec3(0, 1, 0);
    const glm::vec3 v = glm::normalize(glm::cross(d, helper));
    const glm::vec3 u = glm::cross(d, v);  // (u, v, d) left-handed: u = d x v
    for (std::size_t i = 0; i < positions.size(); ++i) {
      const glm::vec3 p = positions[i] - centre;
      projected[i] = OverdrawVertex{half + glm::dot(p, u) * scale, half + glm::dot(p, v) * scale,
                                    half + glm::dot(p, d) * scale};
    }
    rasterizer.clear();
    for (std::size_t i = 0; i < triangle_list.size(); i += 3) {
      const OverdrawVertex& a = projected[triangle_list[i]];
      const OverdrawVertex& b = projected[triangle_list[i + 1]];
      const OverdrawVertex& c = projected[triangle_list[i + 2]];
      if ((b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x) > 0) continue;  // back face
      rasterizer.draw(a, b, c);
    }
    total += rasterizer.counts();
  }
  return total;
}

}  // namespace

std::vector<glm::vec3> sphere_view_directions(unsigned count) {
  std::vector<glm::vec3> directions;
  directions.reserve(count);
  const double golden_angle = std::numbers::pi * (3.0 - std::sqrt(5.0));
  for (unsigned i = 0; i < count; ++i) {
    const double z = 1.0 - (2.0 * i + 1.0) / double(count);
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double phi = golden_angle * i;
    directions.emplace_back(float(r * std::cos(phi)), float(r * std::sin(phi)), float(z));
  }
  return directions;
}

OverdrawCounts view_independent_overdraw(std::span<const glm::vec3> positions,
                                         std::span<const std::uint32_t> triangle_list,
                                         const OverdrawOptions& options) {
  validate(positions, triangle_list);
  if (triangle_list.empty()) return {};
  if (!options.directions.empty()) return directional_views(positions, triangle_list, options.directions, options);
  if (options.sphere_views)
    return directional_views(positions, triangle_list, sphere_view_directions(options.sphere_views), options);
  return axis_views(positions, triangle_list, options);
}

}  // namespace rastrace
