#include "raster/sampler.h"

#include <algorithm>
#include <cmath>

#include "core/enum_names.h"

namespace rastrace {

namespace {

// The minification filters by their GL names, then the usual aliases.
constexpr EnumName<TextureFilter> kFilters[] = {{TextureFilter::Nearest, "nearest"},
                                                {TextureFilter::Linear, "linear"},
                                                {TextureFilter::NearestMipmapNearest, "nearest_mipmap_nearest"},
                                                {TextureFilter::LinearMipmapNearest, "linear_mipmap_nearest"},
                                                {TextureFilter::LinearMipmapLinear, "linear_mipmap_linear"},
                                                {TextureFilter::LinearMipmapLinear, "trilinear"},
                                                {TextureFilter::LinearMipmapNearest, "bilinear"}};

constexpr EnumName<TextureWrap> kWraps[] = {
    {TextureWrap::Repeat, "repeat"}, {TextureWrap::ClampToEdge, "clamp_to_edge"}, {TextureWrap::ClampToEdge, "clamp"}};

constexpr EnumName<AnisotropyRule> kAnisotropyRules[] = {{AnisotropyRule::Ellipse, "ellipse"},
                                                         {AnisotropyRule::Probes, "probes"}};

}  // namespace

AnisotropyRule parse_anisotropy_rule(const std::string& text) {
  return parse_enum(text, kAnisotropyRules, "anisotropy rule");
}
const char* to_string(AnisotropyRule rule) { return enum_to_string(rule, kAnisotropyRules); }

SamplerState parse_filter(const std::string& text, SamplerState base) {
  base.min_filter = parse_enum(text, kFilters, "texture filter");
  // Magnification has no mipmaps: the filter within a level.
  const bool nearest =
      base.min_filter == TextureFilter::Nearest || base.min_filter == TextureFilter::NearestMipmapNearest;
  base.mag_filter = nearest ? TextureFilter::Nearest : TextureFilter::Linear;
  return base;
}

TextureWrap parse_wrap(const std::string& text) { return parse_enum(text, kWraps, "texture wrap"); }

const char* to_string(TextureFilter filter) { return enum_to_string(filter, kFilters); }

const char* to_string(TextureWrap wrap) { return enum_to_string(wrap, kWraps); }

float safe_coordinate(float s) {
  if (!std::isfinite(s)) return 0.0f;
  return std::clamp(s, -kCoordinateLimit, kCoordinateLimit);
}

namespace {

// floor() for |u| < 2^31 without a library call (the coordinates are clamped well inside).
inline int floor_int(float u) {
  const int i = static_cast<int>(u);
  return i - (static_cast<float>(i) > u);
}

inline glm::vec4 fetch(const Image& image, int x, int y) {
  const std::uint8_t* p = image.texel(x, y);
  constexpr float k = 1.0f / 255.0f;
  return glm::vec4(p[0] * k, p[1] * k, p[2] * k, p[3] * k);
}

glm::vec4 sample_nearest(const Image& image, unsigned level, const SamplerState& state, float s, float t,
                         TexelRecorder& recorder, const TexelSite& site) {
  const float u = s * static_cast<float>(image.width);
  const float v = t * static_cast<float>(image.height);
  const int x = wrap_coordinate(floor_int(u), image.width, state.wrap_s);
  const int y = wrap_coordinate(floor_int(v), image.height, state.wrap_t);
  recorder.record(site, level, x, y);
  return fetch(image, x, y);
}

glm::vec4 sample_linear(const Image& image, unsigned level, const SamplerState& state, float s, float t,
                        TexelRecorder& recorder, const TexelSite& site) {
  const float u = s * static_cast<float>(image.width) - 0.5f;
  const float v = t * static_cast<float>(image.height) - 0.5f;
  const int iu = floor_int(u), iv = floor_int(v);
  const float a = u - static_cast<float>(iu), b = v - static_cast<float>(iv);
  const int x0 = wrap_coordinate(iu, image.width, state.wrap_s);
  const int x1 = wrap_coordinate(iu + 1, image.width, state.wrap_s);
  const int y0 = wrap_coordinate(iv, image.height, state.wrap_t);
  const int y1 = wrap_coordinate(iv + 1, image.height, state.wrap_t);
  recorder.record_footprint(site, level, x0, x1, y0, y1);
  const glm::vec4 t00 = fetch(image, x0, y0), t10 = fetch(image, x1, y0);
  const glm::vec4 t01 = fetch(image, x0, y1), t11 = fetch(image, x1, y1);
  const glm::vec4 top = t00 + (t10 - t00) * a;
  const glm::vec4 bottom = t01 + (t11 - t01) * a;
  return top + (bottom - top) * b;
}

}  // namespace

glm::vec4 sample_level(const Texture& texture, unsigned level, TextureFilter filter, const SamplerState& state, float s,
                       float t, TexelRecorder& recorder, const TexelSite& site) {
  const Image& image = texture.levels[level];
  return filter == TextureFilter::Nearest ? sample_nearest(image, level, state, s, t, recorder, site)
                                          : sample_linear(image, level, state, s, t, recorder, site);
}

glm::vec4 sample_texture(const Texture& texture, const SamplerState& state, float s, float t, float lambda,
                         TexelRecorder& recorder, const TexelSite& site) {
  return sample_planned(texture, state, plan_levels(texture, state, lambda), s, t, recorder, site);
}

glm::vec4 sample_planned(const Texture& texture, const SamplerState& state, const LevelPlan& plan, float s, float t,
                         TexelRecorder& recorder, const TexelSite& site) {
  s = safe_coordinate(s);
  t = safe_coordinate(t);
  const glm::vec4 t1 = sample_level(texture, plan.first, plan.filter, state, s, t, recorder, site);
  if (!plan.blend) return t1;
  const glm::vec4 t2 = sample_level(texture, plan.first + 1, TextureFilter::Linear, state, s, t, recorder, site);
  return t1 + (t2 - t1) * plan.fraction;
}

}  // namespace rastrace
