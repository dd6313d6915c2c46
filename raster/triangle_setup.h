// Triangle setup: the snapped vertices' edge functions (24.8 fixed point, exact in 64 bits), the
// fill rule's biases, the pixel box to visit and the plane equations of the interpolated
// attributes. The rasterizer's traversal (raster/traversal.h) and its quads read only this.
#pragma once

#include <cstdint>

#include <glm/vec2.hpp>
#include <glm/vec4.hpp>

namespace rastrace {

// A vertex after the perspective divide and the viewport transform.
struct RasterVertex {
  float x = 0.0f, y = 0.0f;  // image coordinates in pixels
  float z = 0.0f;            // window depth in [0, 1]
  float inv_w = 1.0f;        // 1 / clip-space w
  glm::vec4 colour{1.0f};
  glm::vec2 uv{0.0f};
};

inline constexpr int kRasterAttributes = 8;  // q = 1/w, s*q, t*q, r*q, g*q, b*q, a*q, z

struct TriangleSetup {
  std::int64_t step_x[3], step_y[3];  // edge function change per pixel to the right / down
  std::int64_t bias[3];               // 0 for owned (top or left) edges, -1 for the others
  std::int64_t origin[3];             // edge functions at the centre of pixel (x0, y0)
  double length[3];                   // edge lengths in 1/256 pixels (debug planes only)
  int x0, y0, x1, y1;                 // pixels to visit (x0, y0 aligned), inclusive, in the image
  float inv_area;
  float base[kRasterAttributes], d1[kRasterAttributes], d2[kRasterAttributes];
};

// Sets `s` up for a width x height image, the box's corner aligned down to `align` pixels.
// Returns false when nothing is to be drawn: a vertex outside +-2^22 pixels or not finite, zero
// area, or a box outside the image.
bool setup_triangle(const RasterVertex& a, const RasterVertex& b, const RasterVertex& c, int width, int height,
                    int align, TriangleSetup& s);

}  // namespace rastrace
