#include "raster/anisotropy.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace rastrace {

namespace {

// Beyond this many texel positions in one bounding box the filter gives up on the ellipse and
// filters bilinearly: a footprint more than about 2,000:1 at its level (llvmpipe would loop over
// them all). Every texel read is a trace record: a million per pixel would make a thin, stretched
// triangle a terabyte trace.
constexpr double kMaxBoxTexels = 1 << 14;

// exp(-alpha r^2) for r^2 = i / kEllipseEdge with alpha = 2, llvmpipe's Gaussian: the weight at
// the ellipse's edge is exp(-2), about 0.135, so every texel inside counts.
const std::array<float, kEllipseEdge + 1>& weight_table() {
  static const std::array<float, kEllipseEdge + 1> table = [] {
    std::array<float, kEllipseEdge + 1> t{};
    for (int i = 0; i <= kEllipseEdge; ++i)
      t[static_cast<std::size_t>(i)] = std::exp(-2.0f * (static_cast<float>(i) / static_cast<float>(kEllipseEdge)));
    return t;
  }();
  return table;
}

bool mipmapped(TextureFilter filter) { return filter != TextureFilter::Nearest && filter != TextureFilter::Linear; }

inline glm::vec4 fetch(const Image& image, int x, int y) {
  const std::uint8_t* p = image.texel(x, y);
  constexpr float k = 1.0f / 255.0f;
  return glm::vec4(p[0] * k, p[1] * k, p[2] * k, p[3] * k);
}

}  // namespace

unsigned anisotropic_level(const SamplerState& state, int width, int height, unsigned last_level, float dsdx,
                           float dtdx, float dsdy, float dtdy) {
  if (!mipmapped(state.min_filter)) return 0;
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  const float ux = dsdx * w, vx = dtdx * h, uy = dsdy * w, vy = dtdy * h;
  const float pmin2 = std::min(ux * ux + vx * vx, uy * uy + vy * vy);
  // llvmpipe truncates half its fast log2 of Pmin^2 toward zero. That approximation is exact at
  // powers of two and monotonic between them, so the truncation is floor(floor(log2 Pmin^2) / 2)
  // for Pmin >= 1 and level 0 below (truncation toward zero, then the clamp).
  if (!(pmin2 >= 1.0f)) return 0;  // NaN too
  if (std::isinf(pmin2)) return last_level;
  int exponent = 0;
  std::frexp(pmin2, &exponent);  // pmin2 = m 2^exponent, m in [0.5, 1)
  return std::min(static_cast<unsigned>((exponent - 1) / 2), last_level);
}

EllipticalFootprint elliptical_footprint(const Texture& texture, const SamplerState& state, float dsdx, float dtdx,
                                         float dsdy, float dtdy) {
  EllipticalFootprint f;
  const Image& base = texture.levels[0];
  const unsigned last = static_cast<unsigned>(texture.levels.size()) - 1;
  f.level = anisotropic_level(state, base.width, base.height, last, dsdx, dtdx, dsdy, dtdy);
  // The derivatives in texels of the chosen level, with llvmpipe's order of operations so that
  // the ellipse matches it to the rounding.
  const float scaling = 1.0f / static_cast<float>(1u << f.level);
  const float w = static_cast<float>(base.width), h = static_cast<float>(base.height);
  const float ux = dsdx * w * scaling, uy = dsdy * w * scaling;
  const float vx = dtdx * h * scaling, vy = dtdy * h * scaling;
  f.width = w * scaling;
  f.height = h * scaling;
  // Heckbert (1989), section 3.5.8: the implicit ellipse A u^2 + B u v + C v^2 = F of the
  // Jacobian, each axis widened by one texel (the "+ 1"), F = A C - B^2 / 4.
  float a = (vx * vx + vy * vy) + 1.0f;
  float b = (ux * vx + uy * vy) * -2.0f;
  float c = (ux * ux + uy * uy) + 1.0f;
  const float f_value = a * c - b * b / 4.0f;
  const float d = (0.0f - b * b) + a * c * 4.0f;  // 4F: the discriminant's negation
  f.half_u = 2.0f / d * std::sqrt(d * c * f_value);
  f.half_v = 2.0f / d * std::sqrt(a * d * f_value);
  // Scaled so that q = kEllipseEdge on the edge: q indexes the weight table directly.
  const float form_scale = static_cast<float>(kEllipseEdge) / f_value;
  f.a = a * form_scale;
  f.b = b * form_scale;
  f.c = c * form_scale;
  const double box = (2.0 * f.half_u + 2.0) * (2.0 * f.half_v + 2.0);
  f.valid = std::isfinite(f.a) && std::isfinite(f.b) && std::isfinite(f.c) && box <= kMaxBoxTexels;
  return f;
}

glm::vec4 sample_elliptical(const Texture& texture, const SamplerState& state, const EllipticalFootprint& footprint,
                            float s, float t, TexelRecorder& recorder, const TexelSite& site) {
  s = safe_coordinate(s);
  t = safe_coordinate(t);
  if (!footprint.valid)
    return sample_level(texture, footprint.level, TextureFilter::Linear, state, s, t, recorder, site);
  const Image& image = texture.levels[footprint.level];
  const auto& weights = weight_table();
  const float a = footprint.a, b = footprint.b, c = footprint.c;
  // Texel centres are at integers in these coordinates.
  const float tex_u = s * footprint.width + -0.5f;
  const float tex_v = t * footprint.height + -0.5f;
  const int u0 = static_cast<int>(std::floor(tex_u - footprint.half_u));
  const int u1 = static_cast<int>(std::ceil(tex_u + footprint.half_u));
  const int v0 = static_cast<int>(std::floor(tex_v - footprint.half_v));
  const int v1 = static_cast<int>(std::ceil(tex_v + footprint.half_v));
  // q is updated by forward differences along each row (Heckbert 1989, the EWA inner loop), as
  // llvmpipe does: its rounding decides which texels on the edge are in.
  const float u_first = static_cast<float>(u0) - tex_u;
  const float dq_first = (u_first * 2.0f + 1.0f) * a;
  const float q_first = (u_first * u_first) * a;
  const float ddq = a * 2.0f;
  glm::vec4 sum(0.0f);
  float total = 0.0f;
  for (int v = v0; v <= v1; ++v) {
    const float dv = static_cast<float>(v) - tex_v;
    float dq = dv * b + dq_first;
    float q = (c * dv + b * u_first) * dv + q_first;
    const int y = wrap_coordinate(v, image.height, state.wrap_t);
    bool entered = false;
    for (int u = u0; u <= u1; ++u, q += dq, dq += ddq) {
      if (!(q < static_cast<float>(kEllipseEdge + 1))) {
        // Leaving the ellipse takes dq > 0, and dq only grows (ddq > 0): rounded additions of
        // a positive dq never lower q again, so no later texel of the row is inside. The texels
        // read are exactly those of the whole row's scan.
        if (entered) break;
        continue;
      }
      entered = true;
      const float weight = weights[q > 0.0f ? static_cast<std::size_t>(q) : 0u];
      const int x = wrap_coordinate(u, image.width, state.wrap_s);
      recorder.record(site, footprint.level, x, y);
      sum = sum + fetch(image, x, y) * weight;
      total = total + weight;
    }
  }
  // No texel inside (only rounding can empty an ellipse at least a texel wide): llvmpipe falls
  // back to the bilinear filter of the level.
  if (total == 0.0f) return sample_level(texture, footprint.level, TextureFilter::Linear, state, s, t, recorder, site);
  return sum / total;
}

}  // namespace rastrace
