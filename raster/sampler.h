// Mipmapped texture sampling as the OpenGL 4.6 specification defines it (section 8.14):
// the level of detail from the derivatives of the texture coordinates, level selection, and
// the NEAREST / LINEAR filters with REPEAT or CLAMP_TO_EDGE wrapping. Every texel read is
// reported to a TexelRecorder, so a trilinear sample reports exactly 8 reads.
//
// Results are RGBA in [0, 1] computed in float from 8-bit texels (as softpipe does; llvmpipe
// filters 8-bit textures in 8.8 fixed point, so the two drivers differ by up to 1/255 here).
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

#include <glm/vec4.hpp>

#include "raster/texel_recorder.h"
#include "scenes/texture.h"

namespace rastrace {

enum class TextureFilter : std::uint8_t {
  Nearest,
  Linear,
  NearestMipmapNearest,
  LinearMipmapNearest,
  LinearMipmapLinear,  // trilinear: 8 texel reads
};
enum class TextureWrap : std::uint8_t { Repeat, ClampToEdge };

// How rho (the scale factor of equation 8.6) is computed from the four derivatives.
enum class LodFormula : std::uint8_t {
  // Equation 8.6: rho = max(length(du/dx, dv/dx), length(du/dy, dv/dy)). The default.
  Lengths,
  // The bound that equation 8.7 allows: rho = max(|du/dx|, |du/dy|, |dv/dx|, |dv/dy|).
  // softpipe computes exactly this, so the cross-check can match it texel for texel.
  MaxComponent,
};

// The anisotropic filter: llvmpipe's elliptical average of one level (raster/anisotropy.h), the
// cross-checked default, or EXT_texture_filter_anisotropic's probes along the major axis
// (raster/anisotropic_probes.h), the model of hardware texel traffic.
enum class AnisotropyRule : std::uint8_t { Ellipse, Probes };
// "ellipse", "probes"; InputError otherwise.
AnisotropyRule parse_anisotropy_rule(const std::string& text);
const char* to_string(AnisotropyRule rule);

struct SamplerState {
  TextureFilter min_filter = TextureFilter::LinearMipmapLinear;
  TextureFilter mag_filter = TextureFilter::Linear;  // Nearest or Linear only
  TextureWrap wrap_s = TextureWrap::Repeat;
  TextureWrap wrap_t = TextureWrap::Repeat;
  LodFormula lod = LodFormula::Lengths;
  // GL_TEXTURE_MAX_ANISOTROPY (EXT_texture_filter_anisotropic), 1 to kMaxAnisotropy. 1 is the
  // isotropic filter above; more switches to the elliptical filter of raster/anisotropy.h.
  int max_anisotropy = 1;
  AnisotropyRule aniso_rule = AnisotropyRule::Ellipse;  // above 1: which anisotropic filter
};

inline constexpr int kMaxAnisotropy = 16;  // what llvmpipe and softpipe advertise

// Command-line names: nearest, linear, nearest_mipmap_nearest, linear_mipmap_nearest,
// linear_mipmap_linear (alias trilinear); repeat, clamp_to_edge. Throw InputError otherwise.
// The magnification filter follows: NEAREST for the NEAREST* minification filters, else LINEAR.
SamplerState parse_filter(const std::string& text, SamplerState base = {});
TextureWrap parse_wrap(const std::string& text);
const char* to_string(TextureFilter filter);
const char* to_string(TextureWrap wrap);

// lambda = log2(rho) for one 2x2 quad. Derivatives are in normalised coordinates (s, t) per pixel;
// the level-0 size scales them to texels. Returns -inf-safe values (rho = 0 gives -128).
// Inline, with plan_levels: the quad stage calls both once per quad.
[[gnu::always_inline]] inline float compute_lod(const SamplerState& state, int width, int height, float dsdx,
                                                float dtdx, float dsdy, float dtdy) {
  const float w = static_cast<float>(width), h = static_cast<float>(height);
  const float dudx = dsdx * w, dvdx = dtdx * h, dudy = dsdy * w, dvdy = dtdy * h;
  float rho;
  if (state.lod == LodFormula::Lengths) {
    // max(sqrt(x), sqrt(y)) as sqrt(max(x, y)): the square root is correctly rounded and
    // monotonic, so the two are the same float (NaNs included: std::max keeps its first operand).
    rho = std::sqrt(std::max(dudx * dudx + dvdx * dvdx, dudy * dudy + dvdy * dvdy));
  } else {
    rho = std::max(std::max(std::fabs(dudx), std::fabs(dudy)), std::max(std::fabs(dvdx), std::fabs(dvdy)));
  }
  // rho = 0 (a constant coordinate) is the deepest magnification; NaN from a degenerate quad too.
  if (!(rho > 0.0f)) return -128.0f;
  return std::log2(rho);
}

// The levels a sample with level of detail lambda reads (section 8.14): one level with the
// filter within it, or, for LINEAR_MIPMAP_LINEAR between two levels, `first` and `first + 1`
// (LINEAR within each) mixed by `fraction`. The same for every pixel of a quad, whose lambda is
// shared.
struct LevelPlan {
  unsigned first = 0;
  TextureFilter filter = TextureFilter::Linear;  // Nearest or Linear
  bool blend = false;
  float fraction = 0.0f;
};
[[gnu::always_inline]] inline LevelPlan plan_levels(const Texture& texture, const SamplerState& state, float lambda) {
  LevelPlan plan;
  // Section 8.14: c = 0.5 only for a LINEAR magnification with a NEAREST_MIPMAP_* minification.
  const float c = (state.mag_filter == TextureFilter::Linear && state.min_filter == TextureFilter::NearestMipmapNearest)
                      ? 0.5f
                      : 0.0f;
  if (lambda <= c) {
    plan.filter = state.mag_filter;
    return plan;
  }
  const unsigned q = static_cast<unsigned>(texture.levels.size()) - 1;  // the last level
  switch (state.min_filter) {
    case TextureFilter::Nearest:
    case TextureFilter::Linear:
      plan.filter = state.min_filter;
      return plan;
    case TextureFilter::NearestMipmapNearest:
    case TextureFilter::LinearMipmapNearest:
      // Equation 8.10: d = ceil(lambda + 1/2) - 1 for lambda > 1/2, else the base level.
      if (lambda > 0.5f)
        plan.first = static_cast<unsigned>(std::min(std::ceil(lambda + 0.5f) - 1.0f, static_cast<float>(q)));
      plan.filter =
          state.min_filter == TextureFilter::NearestMipmapNearest ? TextureFilter::Nearest : TextureFilter::Linear;
      return plan;
    case TextureFilter::LinearMipmapLinear: {
      plan.filter = TextureFilter::Linear;
      if (lambda >= static_cast<float>(q)) {
        plan.first = q;
        return plan;
      }
      const float floor_lambda = std::floor(lambda);
      plan.first = static_cast<unsigned>(floor_lambda);
      plan.blend = true;
      plan.fraction = lambda - floor_lambda;
      return plan;
    }
  }
  return plan;
}

// Texture coordinates as the sampler may scale them: 0 where not finite, and clamped to +-2^16 so
// that s * 16384 fits an int. REPEAT only needs s modulo 1, which a float beyond +-2^16 has lost
// anyway, and CLAMP_TO_EDGE clamps such values to the edge texel either way.
inline constexpr float kCoordinateLimit = 65536.0f;

// The coordinate as sample_texture uses it: 0 where not finite, clamped to +-kCoordinateLimit.
float safe_coordinate(float s);

// Texel index i of a level `size` texels wide, wrapped: modulo size for REPEAT, clamped for
// CLAMP_TO_EDGE. Inline: the elliptical filter wraps every texel it reads.
inline int wrap_coordinate(int i, int size, TextureWrap wrap) {
  if (wrap == TextureWrap::Repeat) {
    if ((size & (size - 1)) == 0) return i & (size - 1);  // two's complement: right for i < 0 too
    const int m = i % size;
    return m < 0 ? m + size : m;
  }
  return std::clamp(i, 0, size - 1);
}

// One level's filter (Nearest or Linear) at (s, t), recording its reads (1 or 4).
glm::vec4 sample_level(const Texture& texture, unsigned level, TextureFilter filter, const SamplerState& state, float s,
                       float t, TexelRecorder& recorder, const TexelSite& site);

// Samples `texture` at (s, t) with level of detail lambda, recording every texel read.
// `texture_id` and the pixel and triangle in `site` go into the TexelAccess events.
glm::vec4 sample_texture(const Texture& texture, const SamplerState& state, float s, float t, float lambda,
                         TexelRecorder& recorder, const TexelSite& site);
// The same with the levels already planned (plan_levels), for filters that sample many points at
// one level of detail.
glm::vec4 sample_planned(const Texture& texture, const SamplerState& state, const LevelPlan& plan, float s, float t,
                         TexelRecorder& recorder, const TexelSite& site);

}  // namespace rastrace
