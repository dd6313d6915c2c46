#include "pipeline/clipper.h"

#include <algorithm>

namespace rastrace {

Clipper::Clipper(int viewport_width, int viewport_height, float guard_band)
    : gx_(1.0f + 2.0f * std::max(0.0f, guard_band) / static_cast<float>(std::max(1, viewport_width))),
      gy_(1.0f + 2.0f * std::max(0.0f, guard_band) / static_cast<float>(std::max(1, viewport_height))) {}

void Clipper::clip(const ClipVertex& a, const ClipVertex& b, const ClipVertex& c, std::uint32_t planes,
                   ClipPolygon& out) const {
  ClipPolygon buffer;
  ClipPolygon* in = &buffer;
  ClipPolygon* result = &out;
  in->vertices[0] = a;
  in->vertices[1] = b;
  in->vertices[2] = c;
  in->count = 3;
  for (int plane = 0; plane < 6; ++plane) {
    if (!(planes >> plane & 1u)) continue;
    result->count = 0;
    for (int i = 0; i < in->count; ++i) {
      const ClipVertex& p = in->vertices[static_cast<std::size_t>(i)];
      const ClipVertex& q = in->vertices[static_cast<std::size_t>((i + 1) % in->count)];
      const float dp = distance(plane, p.position), dq = distance(plane, q.position);
      if (dp >= 0.0f) result->vertices[static_cast<std::size_t>(result->count++)] = p;
      if ((dp >= 0.0f) != (dq >= 0.0f)) {
        // Interpolate from the inside vertex so that an edge shared by two triangles is cut at
        // exactly the same point whichever triangle it belongs to.
        const bool p_inside = dp >= 0.0f;
        const ClipVertex& from = p_inside ? p : q;
        const ClipVertex& to = p_inside ? q : p;
        const float df = p_inside ? dp : dq, dt = p_inside ? dq : dp;
        const float t = df / (df - dt);
        ClipVertex& v = result->vertices[static_cast<std::size_t>(result->count++)];
        v.position = from.position + (to.position - from.position) * t;
        v.colour = from.colour + (to.colour - from.colour) * t;
        v.uv = from.uv + (to.uv - from.uv) * t;
      }
    }
    std::swap(in, result);
    if (in->count < 3) {
      out.count = 0;
      return;
    }
  }
  if (in != &out) out = *in;
}

}  // namespace rastrace
