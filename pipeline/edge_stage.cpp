#include "pipeline/edge_stage.h"

#include <algorithm>
#include <cmath>
#include <span>

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

namespace rastrace {
namespace {

// Orientation in window space of the projected triangle (positive: counter-clockwise), from the
// clip positions without dividing: det[x y w] has the sign of the NDC area when every w > 0.
float clip_orientation(const glm::vec4& a, const glm::vec4& b, const glm::vec4& c) {
  return a.x * (b.y * c.w - b.w * c.y) - a.y * (b.x * c.w - b.w * c.x) + a.w * (b.x * c.y - b.y * c.x);
}

// Facing of face (a, b, c), evaluated from its lowest vertex id so that every primitive that
// sees the face rounds the same way: silhouettes then always close into loops.
bool front_facing(std::span<const ShadedVertex> shaded, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  if (b < a && b < c) return front_facing(shaded, b, c, a);
  if (c < a && c < b) return front_facing(shaded, c, a, b);
  return clip_orientation(shaded[a].clip, shaded[b].clip, shaded[c].clip) > 0.0f;
}

// GL's diamond-exit rule: the segment makes fragment (x, y) when it meets the open diamond
// |px - cx| + |py - cy| < 1/2 around the pixel centre and does not end inside it.
bool meets_diamond(float x0, float y0, float x1, float y1, float cx, float cy) {
  const float dx = x1 - x0, dy = y1 - y0;
  auto l1 = [&](float t) { return std::fabs(x0 + t * dx - cx) + std::fabs(y0 + t * dy - cy); };
  // The L1 distance along the segment is convex and piecewise linear: its minimum is at an end or
  // where the segment crosses the centre's row or column.
  float best = std::min(l1(0.0f), l1(1.0f));
  if (dx != 0.0f) best = std::min(best, l1(std::clamp((cx - x0) / dx, 0.0f, 1.0f)));
  if (dy != 0.0f) best = std::min(best, l1(std::clamp((cy - y0) / dy, 0.0f, 1.0f)));
  return best < 0.5f && std::fabs(x1 - cx) + std::fabs(y1 - cy) >= 0.5f;
}

}  // namespace

EdgeStage::EdgeStage(const Mesh& mesh, const EdgeStageOptions& options, Framebuffer* lines)
    : mesh_(mesh), options_(options), sharp_cosine_(std::cos(glm::radians(options.sharp_degrees))), lines_(lines) {}

void EdgeStage::primitive(const AssembledPrimitive& p) {
  if (p.indices.size() != 6) return;
  ++stats_.primitives;
  const std::uint32_t* i = p.indices.data();
  if (p.degenerate) return;  // a degenerate cover face carries no face and no edge
  ++stats_.cover_faces;
  if (options_.record) faces_.push_back({i[0], i[2], i[4]});

  const bool cover_front = front_facing(p.shaded, i[0], i[2], i[4]);
  const glm::vec3 cover_normal =
      glm::cross(mesh_.positions[i[2]] - mesh_.positions[i[0]], mesh_.positions[i[4]] - mesh_.positions[i[0]]);
  if (i[1] != i[0] && i[1] != i[2]) {
    ++stats_.assigned_faces;
    if (options_.record) faces_.push_back({i[0], i[1], i[2]});
  }
  for (unsigned e = 0; e < 3; ++e) {
    const std::uint32_t from = i[2 * e], across = i[2 * e + 1], to = i[(2 * e + 2) % 6];
    if (across == to) continue;
    ++stats_.edges;
    std::uint8_t flags = 0;
    if (across == from) {
      flags = kEdgeBoundary;
      ++stats_.boundary_edges;
    } else {
      const bool other_front = front_facing(p.shaded, from, across, to);
      if (other_front != cover_front) {
        flags |= kEdgeSilhouette;
        ++stats_.silhouette_edges;
      }
      const glm::vec3 other_normal =
          glm::cross(mesh_.positions[across] - mesh_.positions[from], mesh_.positions[to] - mesh_.positions[from]);
      const float lengths = glm::length(cover_normal) * glm::length(other_normal);
      if (lengths > 0.0f && glm::dot(cover_normal, other_normal) < sharp_cosine_ * lengths) {
        flags |= kEdgeSharp;
        ++stats_.sharp_edges;
      }
    }
    if (options_.record) edges_.push_back({from, to, flags});
    const bool draw = ((flags & kEdgeSilhouette) && options_.draw_silhouettes) ||
                      ((flags & kEdgeSharp) && options_.draw_sharp) ||
                      ((flags & kEdgeBoundary) && options_.draw_boundary);
    if (draw && lines_) draw_line(p.shaded[from].clip, p.shaded[to].clip);
  }
}

void EdgeStage::draw_line(const glm::vec4& a, const glm::vec4& b) {
  if (a.w <= 0.0f || b.w <= 0.0f) {
    ++stats_.lines_rejected;
    return;
  }
  ++stats_.lines_drawn;
  const int width = lines_->width(), height = lines_->height();
  // GL window coordinates (origin at the bottom left).
  const float x0 = (a.x / a.w * 0.5f + 0.5f) * width, y0 = (a.y / a.w * 0.5f + 0.5f) * height;
  const float x1 = (b.x / b.w * 0.5f + 0.5f) * width, y1 = (b.y / b.w * 0.5f + 0.5f) * height;
  const float dx = x1 - x0, dy = y1 - y0;
  std::uint8_t* rgba = lines_->colour();
  auto plot = [&](int x, int y) {
    if (x < 0 || y < 0 || x >= width || y >= height) return;
    std::uint8_t* pixel = rgba + 4 * (std::size_t(height - 1 - y) * width + x);
    for (int c = 0; c < 4; ++c) pixel[c] = options_.colour[c];
    ++stats_.pixels;
  };
  // Candidates: along the major axis, the pixel the line passes through and its two neighbours
  // across; each is kept by the diamond test. Far-off spans are clamped to the viewport.
  const bool x_major = std::fabs(dx) >= std::fabs(dy);
  const float extent = float(x_major ? width : height);
  const float lo = std::clamp(std::floor(std::min(x_major ? x0 : y0, x_major ? x1 : y1)) - 1.0f, -1.0f, extent + 1.0f);
  const float hi = std::clamp(std::floor(std::max(x_major ? x0 : y0, x_major ? x1 : y1)) + 1.0f, -2.0f, extent);
  for (int major = int(lo); major <= int(hi); ++major) {
    const float centre = float(major) + 0.5f;
    const float along =
        x_major ? (dx != 0.0f ? y0 + (centre - x0) * dy / dx : y0) : (dy != 0.0f ? x0 + (centre - y0) * dx / dy : x0);
    if (!(std::fabs(along) < 1e8f)) continue;  // far off the viewport (or NaN)
    const int minor = int(std::floor(along));
    for (int m = minor - 1; m <= minor + 1; ++m) {
      const int x = x_major ? major : m, y = x_major ? m : major;
      if (meets_diamond(x0, y0, x1, y1, float(x) + 0.5f, float(y) + 0.5f)) plot(x, y);
    }
  }
}

}  // namespace rastrace
