#include "overdraw/overdraw_rasterizer.h"

#include <algorithm>
#include <string>
#include <utility>

#include "core/error.h"

namespace rastrace {

namespace {

// 28.4 fixed point, rounded to the nearest sixteenth (coordinates are never negative here).
int snap(float coordinate) { return int(16.0f * coordinate + 0.5f); }

// The top-left rule as a bias: an edge that is not a top or left edge does not own the pixel
// centres exactly on it (its edge function must be strictly positive there).
int fill_bias(int dx, int dy) { return (dy < 0 || (dy == 0 && dx > 0)) ? 0 : -1; }

}  // namespace

OverdrawRasterizer::OverdrawRasterizer(int resolution, float depth_range, OverdrawRules rules)
    : resolution_(resolution), depth_range_(depth_range), rules_(rules) {
  if (resolution < 1 || resolution > 4096)
    throw InputError("overdraw resolution " + std::to_string(resolution) + ": expected 1 to 4096 pixels per side");
  depth_.resize(std::size_t(resolution) * std::size_t(resolution) * 2);
  count_.resize(depth_.size());
}

void OverdrawRasterizer::clear() {
  std::fill(depth_.begin(), depth_.end(), 0.0);
  std::fill(count_.begin(), count_.end(), 0u);
}

void OverdrawRasterizer::draw(OverdrawVertex v1, OverdrawVertex v2, OverdrawVertex v3) {
  // The depth plane z = z1 + gx (x - x1) + gy (y - y1), by Cramer's rule on the two edges from v1.
  const float ex2 = v2.x - v1.x, ey2 = v2.y - v1.y, ez2 = v2.z - v1.z;
  const float ex3 = v3.x - v1.x, ey3 = v3.y - v1.y, ez3 = v3.z - v1.z;
  const float det = ex2 * ey3 - ey2 * ex3;
  const float inverse = det == 0 ? 0.0f : 1.0f / det;
  float gx, gy;
  if (rules_.meshopt_018_gradient) {
    gx = ez2 * ey3 - ey2 * ez3 * inverse;
    gy = ex2 * ez3 - ez2 * ex3 * inverse;
  } else {
    gx = (ez2 * ey3 - ey2 * ez3) * inverse;
    gy = (ex2 * ez3 - ez2 * ex3) * inverse;
  }
  const int layer = det > 0;
  // The same plane in double precision from the unsnapped vertices, for the exact rule.
  const double det_d = double(ex2) * ey3 - double(ey2) * ex3;
  const double gx_d = det_d == 0 ? 0.0 : (double(ez2) * ey3 - double(ey2) * ez3) / det_d;
  const double gy_d = det_d == 0 ? 0.0 : (double(ex2) * ez3 - double(ez2) * ex3) / det_d;
  const double x1_d = v1.x, y1_d = v1.y, z1_d = v1.z;

  float z1 = v1.z;
  if (layer) {
    // Counter-clockwise: swap two corners so the edge functions below see one winding, and
    // reverse depth so that "larger wins" keeps the fragment nearest to the opposite viewer.
    std::swap(v2, v3);
    z1 = depth_range_ - z1;
    gx = -gx;
    gy = -gy;
  }

  const int X1 = snap(v1.x), X2 = snap(v2.x), X3 = snap(v3.x);
  const int Y1 = snap(v1.y), Y2 = snap(v2.y), Y3 = snap(v3.y);
  // Pixels whose centre may be inside: a centre at 16 i + 8 is left of a bound b iff i < (b + 7) / 16.
  const int min_x = std::max((std::min({X1, X2, X3}) + 7) >> 4, 0);
  const int max_x = std::min((std::max({X1, X2, X3}) + 7) >> 4, resolution_);
  const int min_y = std::max((std::min({Y1, Y2, Y3}) + 7) >> 4, 0);
  const int max_y = std::min((std::max({Y1, Y2, Y3}) + 7) >> 4, resolution_);
  if (min_x >= max_x || min_y >= max_y) return;

  const std::int64_t dx12 = X1 - X2, dx23 = X2 - X3, dx31 = X3 - X1;
  const std::int64_t dy12 = Y1 - Y2, dy23 = Y2 - Y3, dy31 = Y3 - Y1;
  const int bias1 = fill_bias(int(dx12), int(dy12)), bias2 = fill_bias(int(dx23), int(dy23)),
            bias3 = fill_bias(int(dx31), int(dy31));
  // Edge function of edge a->b at pixel centre (px, py), 24.8 fixed point: >= 0 inside.
  const auto edge = [](std::int64_t dx, std::int64_t dy, int xa, int ya, std::int64_t px, std::int64_t py, int bias) {
    return dx * (py - ya) - dy * (px - xa) + bias;
  };

  const int first_px = (min_x << 4) + 8, first_py = (min_y << 4) + 8;
  // meshoptimizer's float stepping: the depth at the first pixel centre, then + gx per pixel and
  // + gy per row (the rounding of each addition is part of the rule).
  float row_depth = z1 + (gx * float(first_px - X1) + gy * float(first_py - Y1)) * (1 / 16.f);
  const double reversed = layer ? -1.0 : 1.0, offset = layer ? double(depth_range_) : 0.0;

  for (int y = min_y; y < max_y; ++y) {
    const std::int64_t py = (std::int64_t(y) << 4) + 8;
    float step_depth = row_depth;
    for (int x = min_x; x < max_x; ++x, step_depth += gx) {
      const std::int64_t px = (std::int64_t(x) << 4) + 8;
      if (edge(dx12, dy12, X1, Y1, px, py, bias1) < 0 || edge(dx23, dy23, X2, Y2, px, py, bias2) < 0 ||
          edge(dx31, dy31, X3, Y3, px, py, bias3) < 0)
        continue;
      double depth;
      if (rules_.incremental_float_depth) {
        depth = step_depth;
      } else {
        const double z = z1_d + gx_d * (x + 0.5 - x1_d) + gy_d * (y + 0.5 - y1_d);
        depth = offset + reversed * z;
      }
      const std::size_t slot = (std::size_t(y) * std::size_t(resolution_) + std::size_t(x)) * 2 + std::size_t(layer);
      const bool empty = count_[slot] == 0 && !rules_.zero_depth_clear;
      if (empty || depth >= depth_[slot]) {
        depth_[slot] = depth;
        ++count_[slot];
      }
    }
    row_depth += gy;
  }
}

OverdrawCounts OverdrawRasterizer::counts() const {
  OverdrawCounts counts;
  for (const std::uint32_t fragments : count_) {
    counts.shaded += fragments;
    counts.covered += fragments > 0;
  }
  return counts;
}

}  // namespace rastrace
