// A synthetic, frame-like texel trace for tests and benchmarks while no rendered frame is at hand:
// a textured quad seen in perspective (tilted away from the viewer, rotated 30 degrees in its
// plane) rasterized in 2x2 pixel quads, row by row; each pixel samples bilinearly at the mip level
// its texel footprint selects (GL_LINEAR_MIPMAP_NEAREST): 4 texel accesses per pixel. It has the
// locality structure of a real frame (neighbouring pixels share texels, minification grows with
// depth) but it is not one: figures measured on it are labelled "synthetic" in PERFORMANCE.md.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "traces/events.h"
#include "traces/trace_metadata.h"

namespace rastrace::testing {

struct SyntheticFrame {
  TextureLevels textures;
  std::vector<TexelAccess> texels;
};

inline SyntheticFrame make_synthetic_frame(std::uint32_t width, std::uint32_t height, std::uint32_t texture_size) {
  SyntheticFrame frame;
  std::vector<LevelSize> levels;
  for (std::uint32_t s = texture_size; s >= 1; s /= 2) levels.push_back({s, s});
  frame.textures.push_back(levels);
  const double angle = 0.5235987755982988;  // 30 degrees
  const double c = std::cos(angle), s = std::sin(angle);
  // Screen (px, py) -> texture (u, v) in texels at level 0: a plane receding towards the top.
  const auto uv = [&](double px, double py, double& u, double& v) {
    const double sx = (px + 0.5) / width - 0.5;
    const double sy = (py + 0.5) / height;          // 0 at the top (far), 1 at the bottom (near)
    const double depth = 1.0 / (0.15 + 0.85 * sy);  // farther rows are smaller on screen
    const double x = sx * depth * 2.0, y = depth * 1.5;
    u = (c * x - s * y) * texture_size * 0.6 + texture_size * 4.0;
    v = (s * x + c * y) * texture_size * 0.6;
  };
  frame.texels.reserve(std::size_t{width} * height * 4);
  std::uint32_t triangle = 0;
  for (std::uint32_t qy = 0; qy < height; qy += 2)
    for (std::uint32_t qx = 0; qx < width; qx += 2) {
      triangle = (qy * width / 2 + qx) / 4096;  // a new "triangle" every few thousand quads
      double u0, v0, ux, vx, uy, vy;
      uv(qx, qy, u0, v0);
      uv(qx + 1, qy, ux, vx);
      uv(qx, qy + 1, uy, vy);
      const double rho = std::max(std::hypot(ux - u0, vx - v0), std::hypot(uy - u0, vy - v0));
      const int max_level = static_cast<int>(levels.size()) - 1;
      const int level = std::clamp(static_cast<int>(std::floor(std::log2(std::max(rho, 1.0)) + 0.5)), 0, max_level);
      const std::int64_t size = levels[static_cast<std::size_t>(level)].width;
      for (std::uint32_t dy = 0; dy < 2; ++dy)
        for (std::uint32_t dx = 0; dx < 2; ++dx) {
          double u, v;
          uv(qx + dx, qy + dy, u, v);
          u = u / std::ldexp(1.0, level) - 0.5;
          v = v / std::ldexp(1.0, level) - 0.5;
          const std::int64_t x0 = static_cast<std::int64_t>(std::floor(u)),
                             y0 = static_cast<std::int64_t>(std::floor(v));
          for (std::int64_t ty = 0; ty < 2; ++ty)
            for (std::int64_t tx = 0; tx < 2; ++tx) {
              // GL_REPEAT wrapping.
              const std::int64_t x = ((x0 + tx) % size + size) % size, y = ((y0 + ty) % size + size) % size;
              frame.texels.push_back({0, static_cast<std::uint8_t>(level), static_cast<std::uint16_t>(x),
                                      static_cast<std::uint16_t>(y), static_cast<std::uint16_t>(qx + dx),
                                      static_cast<std::uint16_t>(qy + dy), triangle});
            }
        }
    }
  return frame;
}

}  // namespace rastrace::testing
