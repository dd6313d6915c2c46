#include "lod/surface_distance.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include <glm/geometric.hpp>

#include "core/error.h"
#include "core/rng.h"

namespace rastrace {
namespace {

using Triangle = std::array<std::uint32_t, 3>;

// Squared distance from p to triangle abc: the closest-point regions of Ericson, "Real-Time
// Collision Detection" (2005), section 5.1.5.
double point_triangle_distance2(const glm::dvec3& p, const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c) {
  const glm::dvec3 ab = b - a, ac = c - a, ap = p - a;
  const double d1 = glm::dot(ab, ap), d2 = glm::dot(ac, ap);
  auto dist2 = [&](const glm::dvec3& q) { return glm::dot(p - q, p - q); };
  if (d1 <= 0 && d2 <= 0) return dist2(a);
  const glm::dvec3 bp = p - b;
  const double d3 = glm::dot(ab, bp), d4 = glm::dot(ac, bp);
  if (d3 >= 0 && d4 <= d3) return dist2(b);
  const double vc = d1 * d4 - d3 * d2;
  if (vc <= 0 && d1 >= 0 && d3 <= 0) return dist2(a + ab * (d1 / (d1 - d3)));
  const glm::dvec3 cp = p - c;
  const double d5 = glm::dot(ab, cp), d6 = glm::dot(ac, cp);
  if (d6 >= 0 && d5 <= d6) return dist2(c);
  const double vb = d5 * d2 - d1 * d6;
  if (vb <= 0 && d2 >= 0 && d6 <= 0) return dist2(a + ac * (d2 / (d2 - d6)));
  const double va = d3 * d6 - d5 * d4;
  if (va <= 0 && (d4 - d3) >= 0 && (d5 - d6) >= 0) return dist2(b + (c - b) * ((d4 - d3) / ((d4 - d3) + (d5 - d6))));
  const double sum = va + vb + vc;
  if (sum <= 0) return std::min({dist2(a), dist2(b), dist2(c)});  // degenerate triangle
  return dist2(a + ab * (vb / sum) + ac * (vc / sum));
}

// Uniform grid of triangle ids (each triangle in every cell its bounding box touches).
class TriangleGrid {
 public:
  TriangleGrid(std::span<const glm::vec3> positions, std::span<const Triangle> triangles, const glm::dvec3& lo,
               const glm::dvec3& hi)
      : positions_(positions), triangles_(triangles), lo_(lo), stamp_(triangles.size(), 0) {
    const glm::dvec3 extent = glm::max(hi - lo, glm::dvec3(1e-12 * std::max(1.0, glm::length(hi - lo))));
    // Cells about twice the size of an average triangle, so a cell the surface crosses holds a
    // few triangles whatever the box's shape (a flat box must not get a fine grid); coarser if
    // that would make more than 4M cells.
    double area = 0;
    for (const Triangle& t : triangles) {
      const glm::dvec3 a(positions[t[0]]);
      area += 0.5 * glm::length(glm::cross(glm::dvec3(positions[t[1]]) - a, glm::dvec3(positions[t[2]]) - a));
    }
    double cell = 2.0 * std::sqrt(area / double(triangles.size()));
    cell = std::max(
        {cell, std::cbrt(extent.x * extent.y * extent.z / 4e6), 1e-6 * std::max({extent.x, extent.y, extent.z})});
    for (;; cell *= 1.5) {  // the cap again for boxes thin in one or two axes
      for (int i = 0; i < 3; ++i) size_[i] = int(std::clamp(std::ceil(extent[i] / cell), 1.0, 4e6));
      if (double(size_[0]) * size_[1] * size_[2] <= 4e6) break;
    }
    cell_ = cell;
    std::vector<std::uint32_t> counts(cell_count() + 1, 0);
    for_each_cell_of_triangles([&](std::size_t c, std::uint32_t) { ++counts[c + 1]; });
    for (std::size_t c = 0; c < cell_count(); ++c) counts[c + 1] += counts[c];
    offsets_ = counts;
    items_.resize(offsets_.back());
    for_each_cell_of_triangles([&](std::size_t c, std::uint32_t t) { items_[counts[c]++] = t; });
  }

  // Squared distance from p (inside the box) to the nearest triangle: search shells of cells of
  // growing radius r until the nearest triangle found is closer than any cell not yet searched.
  double nearest2(const glm::dvec3& p) {
    ++query_;
    std::array<int, 3> home;
    for (int i = 0; i < 3; ++i) home[i] = clamp_cell(i, p[i]);
    double best = std::numeric_limits<double>::infinity();
    const int max_r = std::max({size_[0], size_[1], size_[2]});
    for (int r = 0; r <= max_r; ++r) {
      // The shell of cells at Chebyshev distance r, clipped to the grid; on a flat grid (one
      // cell thick) the shell's two z faces fall outside, and only its rim is visited.
      const bool z_faces = home[2] - r >= 0 || home[2] + r < size_[2];
      for (int x = std::max(0, home[0] - r); x <= std::min(size_[0] - 1, home[0] + r); ++x) {
        const bool x_face = std::abs(x - home[0]) == r;
        const int y_step = (x_face || z_faces) ? 1 : std::max(1, 2 * r);
        for (int y = home[1] - r; y <= home[1] + r; y += y_step) {
          if (y < 0 || y >= size_[1]) continue;
          const bool face_xy = x_face || std::abs(y - home[1]) == r;
          const std::size_t column = std::size_t(y) * size_[0] + x, layer = std::size_t(size_[1]) * size_[0];
          if (face_xy) {
            for (int z = std::max(0, home[2] - r); z <= std::min(size_[2] - 1, home[2] + r); ++z)
              visit_cell(z * layer + column, p, best);
          } else {
            if (home[2] - r >= 0) visit_cell((home[2] - r) * layer + column, p, best);
            if (home[2] + r < size_[2]) visit_cell((home[2] + r) * layer + column, p, best);
          }
        }
      }
      // Cells at Chebyshev radius r + 1 and beyond are at least r cell widths away.
      const double reach = double(r) * cell_;
      if (best <= reach * reach) break;
    }
    return best;
  }

 private:
  void visit_cell(std::size_t c, const glm::dvec3& p, double& best) {
    for (std::uint32_t i = offsets_[c]; i < offsets_[c + 1]; ++i) {
      const std::uint32_t t = items_[i];
      if (stamp_[t] == query_) continue;
      stamp_[t] = query_;
      const Triangle& tri = triangles_[t];
      best = std::min(best, point_triangle_distance2(p, glm::dvec3(positions_[tri[0]]), glm::dvec3(positions_[tri[1]]),
                                                     glm::dvec3(positions_[tri[2]])));
    }
  }
  std::size_t cell_count() const { return std::size_t(size_[0]) * size_[1] * size_[2]; }
  int clamp_cell(int axis, double v) const {
    return std::clamp(int(std::floor((v - lo_[axis]) / cell_)), 0, size_[axis] - 1);
  }
  template <class F>
  void for_each_cell_of_triangles(F&& f) const {
    for (std::uint32_t t = 0; t < triangles_.size(); ++t) {
      std::array<int, 3> a, b;
      for (int i = 0; i < 3; ++i) {
        const double v0 = positions_[triangles_[t][0]][i], v1 = positions_[triangles_[t][1]][i],
                     v2 = positions_[triangles_[t][2]][i];
        a[i] = clamp_cell(i, std::min({v0, v1, v2}));
        b[i] = clamp_cell(i, std::max({v0, v1, v2}));
      }
      for (int z = a[2]; z <= b[2]; ++z)
        for (int y = a[1]; y <= b[1]; ++y)
          for (int x = a[0]; x <= b[0]; ++x) f((std::size_t(z) * size_[1] + y) * size_[0] + x, t);
    }
  }

  std::span<const glm::vec3> positions_;
  std::span<const Triangle> triangles_;
  glm::dvec3 lo_;
  double cell_ = 1.0;
  std::array<int, 3> size_{1, 1, 1};
  std::vector<std::uint32_t> offsets_, items_;
  std::vector<std::uint32_t> stamp_;  // last query that measured each triangle
  std::uint32_t query_ = 0;
};

// Mean and max distance from area-uniform samples on `from` to the surface in `grid`.
std::pair<double, double> one_way(std::span<const glm::vec3> positions, std::span<const Triangle> from,
                                  TriangleGrid& grid, std::uint32_t samples, std::uint64_t seed) {
  std::vector<double> cumulative(from.size());
  double total = 0;
  for (std::size_t t = 0; t < from.size(); ++t) {
    const glm::dvec3 a(positions[from[t][0]]), b(positions[from[t][1]]), c(positions[from[t][2]]);
    total += 0.5 * glm::length(glm::cross(b - a, c - a));
    cumulative[t] = total;
  }
  if (!(total > 0)) throw InputError("surface distance: a triangle set has no area");
  Rng random(seed);
  double sum = 0, max = 0;
  for (std::uint32_t s = 0; s < samples; ++s) {
    const double pick = random.uniform() * total;
    const std::size_t t = std::min<std::size_t>(
        std::size_t(std::upper_bound(cumulative.begin(), cumulative.end(), pick) - cumulative.begin()),
        from.size() - 1);
    const glm::dvec3 a(positions[from[t][0]]), b(positions[from[t][1]]), c(positions[from[t][2]]);
    // Uniform point in a triangle: Turk, "Generating Random Points in Triangles" (Graphics Gems, 1990).
    const double r1 = std::sqrt(random.uniform()), r2 = random.uniform();
    const glm::dvec3 p = a * (1 - r1) + b * (r1 * (1 - r2)) + c * (r1 * r2);
    const double d = std::sqrt(grid.nearest2(p));
    sum += d;
    max = std::max(max, d);
  }
  return {sum / samples, max};
}

void bounds(std::span<const glm::vec3> positions, std::span<const Triangle> triangles, glm::dvec3& lo, glm::dvec3& hi) {
  for (const Triangle& t : triangles)
    for (const std::uint32_t v : t) {
      lo = glm::min(lo, glm::dvec3(positions[v]));
      hi = glm::max(hi, glm::dvec3(positions[v]));
    }
}

}  // namespace

SurfaceDistance surface_distance(std::span<const glm::vec3> positions, std::span<const Triangle> a,
                                 std::span<const Triangle> b, const SurfaceDistanceParams& params) {
  if (a.empty() || b.empty()) throw InputError("surface distance: a triangle set is empty");
  if (params.samples == 0) throw InputError("surface distance: samples must be at least 1");
  for (const std::span<const Triangle> set : {a, b})
    for (const Triangle& t : set)
      for (const std::uint32_t v : t)
        if (v >= positions.size())
          throw InputError("surface distance: vertex index " + std::to_string(v) + " >= vertex count " +
                           std::to_string(positions.size()));
        else if (!std::isfinite(positions[v].x) || !std::isfinite(positions[v].y) || !std::isfinite(positions[v].z))
          throw InputError("surface distance: vertex " + std::to_string(v) + " has a non-finite position");
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  bounds(positions, a, lo, hi);
  bounds(positions, b, lo, hi);
  TriangleGrid grid_a(positions, a, lo, hi), grid_b(positions, b, lo, hi);
  const auto [ab_mean, ab_max] = one_way(positions, a, grid_b, params.samples, params.seed);
  const auto [ba_mean, ba_max] = one_way(positions, b, grid_a, params.samples, params.seed ^ 0xA5A5A5A5ull);
  SurfaceDistance d;
  d.mean_a_to_b = ab_mean;
  d.mean_b_to_a = ba_mean;
  d.mean = 0.5 * (ab_mean + ba_mean);
  d.max = std::max(ab_max, ba_max);
  return d;
}

double bounding_box_diagonal(std::span<const glm::vec3> positions, std::span<const Triangle> triangles) {
  glm::dvec3 lo(std::numeric_limits<double>::infinity()), hi(-std::numeric_limits<double>::infinity());
  bounds(positions, triangles, lo, hi);
  return triangles.empty() ? 0.0 : glm::length(hi - lo);
}

}  // namespace rastrace
