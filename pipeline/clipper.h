// Homogeneous clipping (Sutherland-Hodgman in clip space, before the perspective divide).
// The near (z >= -w) and far (z <= w) planes are clipped exactly, as GL requires. The sides are
// clipped against a guard band: planes |x| <= g_x w, |y| <= g_y w that lie guard_band pixels
// outside the viewport, so ordinary triangles crossing the screen edge are not cut (the
// rasterizer's bounding box does the scissoring) while the fixed-point range stays safe.
// A guard band of 0 pixels is full clipping at the viewport sides.
#pragma once

#include <array>
#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace rastrace {

struct ClipVertex {
  glm::vec4 position{0.0f};  // clip space
  glm::vec4 colour{1.0f};
  glm::vec2 uv{0.0f};
};

// A convex polygon: a triangle cut by up to six planes has at most nine vertices.
struct ClipPolygon {
  std::array<ClipVertex, 9> vertices;
  int count = 0;
};

class Clipper {
 public:
  // viewport in pixels; guard_band in pixels beyond each side (0 = clip at the viewport).
  Clipper(int viewport_width, int viewport_height, float guard_band);

  // Outcode bits of a clip-space position: one per plane it lies outside of. Inline: three per
  // triangle, and the six planes unroll into straight-line code.
  std::uint32_t outcode(const glm::vec4& p) const {
    std::uint32_t code = 0;
    for (int plane = 0; plane < 6; ++plane)
      if (!(distance(plane, p) >= 0.0f)) code |= 1u << plane;  // NaN counts as outside
    return code;
  }

  // Clips the triangle; returns the polygon (count 0 when nothing remains). Call only when
  // the outcodes' union is non-zero and their intersection zero (otherwise nothing to do).
  void clip(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, std::uint32_t planes,
            ClipPolygon& out) const;

 private:
  float gx_, gy_;  // guard-band planes: |x| <= gx w, |y| <= gy w
  // Planes: 0 near, 1 far, 2 left, 3 right, 4 bottom, 5 top; inside when distance >= 0.
  float distance(int plane, const glm::vec4& p) const {
    switch (plane) {
      case 0:
        return p.z + p.w;
      case 1:
        return p.w - p.z;
      case 2:
        return p.x + gx_ * p.w;
      case 3:
        return gx_ * p.w - p.x;
      case 4:
        return p.y + gy_ * p.w;
      default:
        return gy_ * p.w - p.y;
    }
  }
};

}  // namespace rastrace
