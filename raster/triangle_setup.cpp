#include "raster/triangle_setup.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace rastrace {

namespace {

constexpr int kSubpixelBits = 8;
constexpr std::int64_t kOne = std::int64_t{1} << kSubpixelBits;  // one pixel in fixed point
constexpr std::int64_t kHalf = kOne / 2;                         // pixel centres

// Round half away from zero, as llround, without the library call (|v| < 2^22 is checked first).
inline std::int64_t to_fixed(float v) {
  const double scaled = static_cast<double>(v) * kOne;
  return static_cast<std::int64_t>(scaled >= 0.0 ? scaled + 0.5 : scaled - 0.5);
}

// floor(a / 256): C++20 defines >> on negative values as arithmetic (flooring) shift.
inline int floor_pixel(std::int64_t a) { return static_cast<int>(a >> kSubpixelBits); }

}  // namespace

bool setup_triangle(const RasterVertex& va, const RasterVertex& vb, const RasterVertex& vc, int width, int height,
                    int align, TriangleSetup& s) {
  const RasterVertex* v[3] = {&va, &vb, &vc};
  std::int64_t X[3], Y[3];
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(v[i]->x) || !std::isfinite(v[i]->y) || std::fabs(v[i]->x) > 4194304.0f ||
        std::fabs(v[i]->y) > 4194304.0f)
      return false;  // outside the fixed-point range: the pipeline's clipping never sends these
    X[i] = to_fixed(v[i]->x);
    Y[i] = to_fixed(v[i]->y);
  }
  std::int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (Y[1] - Y[0]) * (X[2] - X[0]);
  if (area == 0) return false;
  if (area < 0) {  // make the winding positive so that "inside" is E >= 0 on all three edges
    std::swap(v[1], v[2]);
    std::swap(X[1], X[2]);
    std::swap(Y[1], Y[2]);
    area = -area;
  }

  int min_x = floor_pixel(std::min({X[0], X[1], X[2]}) - kHalf + kOne - 1);  // ceil
  int min_y = floor_pixel(std::min({Y[0], Y[1], Y[2]}) - kHalf + kOne - 1);
  int max_x = floor_pixel(std::max({X[0], X[1], X[2]}) - kHalf);
  int max_y = floor_pixel(std::max({Y[0], Y[1], Y[2]}) - kHalf);
  min_x = std::max(min_x, 0);
  min_y = std::max(min_y, 0);
  max_x = std::min(max_x, width - 1);
  max_y = std::min(max_y, height - 1);
  if (min_x > max_x || min_y > max_y) return false;
  s.x0 = min_x - min_x % align;
  s.y0 = min_y - min_y % align;
  s.x1 = max_x;
  s.y1 = max_y;

  // Edge k is the one opposite vertex k, from vertex k+1 to vertex k+2; its function is
  // 2 * area * (barycentric weight of vertex k).
  const std::int64_t px = static_cast<std::int64_t>(s.x0) * kOne + kHalf;
  const std::int64_t py = static_cast<std::int64_t>(s.y0) * kOne + kHalf;
  for (int k = 0; k < 3; ++k) {
    const int from = (k + 1) % 3, to = (k + 2) % 3;
    const std::int64_t dx = X[to] - X[from], dy = Y[to] - Y[from];
    s.step_x[k] = -dy * kOne;
    s.step_y[k] = dx * kOne;
    s.origin[k] = -dy * (px - X[from]) + dx * (py - Y[from]);
    const bool top = dy == 0 && dx > 0;
    const bool left = dy < 0;
    s.bias[k] = (top || left) ? 0 : -1;
    s.length[k] = std::sqrt(static_cast<double>(dx) * static_cast<double>(dx) +
                            static_cast<double>(dy) * static_cast<double>(dy));
  }
  s.inv_area = static_cast<float>(1.0 / static_cast<double>(area));

  float attr[3][kRasterAttributes];
  for (int i = 0; i < 3; ++i) {
    const float q = v[i]->inv_w;
    attr[i][0] = q;
    attr[i][1] = v[i]->uv.x * q;
    attr[i][2] = v[i]->uv.y * q;
    attr[i][3] = v[i]->colour.r * q;
    attr[i][4] = v[i]->colour.g * q;
    attr[i][5] = v[i]->colour.b * q;
    attr[i][6] = v[i]->colour.a * q;
    attr[i][7] = v[i]->z;
  }
  for (int j = 0; j < kRasterAttributes; ++j) {
    s.base[j] = attr[0][j];
    s.d1[j] = attr[1][j] - attr[0][j];
    s.d2[j] = attr[2][j] - attr[0][j];
  }
  return true;
}

}  // namespace rastrace
