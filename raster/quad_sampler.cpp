#include "raster/quad_sampler.h"

namespace rastrace {

namespace {

using simd::f32x4;
using simd::i32x4;
using simd::splat;

// The scalar sampler's wrap_coordinate, lane by lane.
i32x4 wrap_coordinates(i32x4 i, int size, TextureWrap wrap) {
  if (wrap == TextureWrap::Repeat) {
    if ((size & (size - 1)) == 0) return i & splat(size - 1);  // two's complement: right for i < 0 too
    const i32x4 m = i % splat(size);
    return m < splat(0) ? m + splat(size) : m;
  }
  return simd::clamp(i, 0, size - 1);
}

// The texels of one level for the four pixels: (x0, y0) alone for NEAREST; the 2x2 footprint
// (x0..x1, y0..y1) and the weights (a, b) of x1 and y1 for LINEAR.
struct LevelTexels {
  i32x4 x0, x1, y0, y1;
  f32x4 a, b;
};

LevelTexels level_texels(const Image& image, TextureFilter filter, const SamplerState& state, f32x4 s, f32x4 t) {
  LevelTexels texels{};
  const f32x4 width = splat(static_cast<float>(image.width)), height = splat(static_cast<float>(image.height));
  if (filter == TextureFilter::Nearest) {
    texels.x0 = wrap_coordinates(simd::floor_int(s * width), image.width, state.wrap_s);
    texels.y0 = wrap_coordinates(simd::floor_int(t * height), image.height, state.wrap_t);
    return texels;
  }
  const f32x4 u = s * width - splat(0.5f), v = t * height - splat(0.5f);
  const i32x4 iu = simd::floor_int(u), iv = simd::floor_int(v);
  texels.a = u - simd::to_float(iu);
  texels.b = v - simd::to_float(iv);
  texels.x0 = wrap_coordinates(iu, image.width, state.wrap_s);
  texels.x1 = wrap_coordinates(iu + splat(1), image.width, state.wrap_s);
  texels.y0 = wrap_coordinates(iv, image.height, state.wrap_t);
  texels.y1 = wrap_coordinates(iv + splat(1), image.height, state.wrap_t);
  return texels;
}

inline f32x4 fetch(const Image& image, std::int32_t x, std::int32_t y) {
  return simd::bytes_to_float(image.texel(x, y)) * splat(1.0f / 255.0f);
}

// Records pixel `i`'s reads of `level` and returns its filtered colour.
f32x4 filter_pixel(const Image& image, unsigned level, TextureFilter filter, const LevelTexels& texels, int i,
                   TexelRecorder& recorder, const TexelSite& site) {
  if (filter == TextureFilter::Nearest) {
    recorder.record(site, level, texels.x0[i], texels.y0[i]);
    return fetch(image, texels.x0[i], texels.y0[i]);
  }
  const std::int32_t x0 = texels.x0[i], x1 = texels.x1[i], y0 = texels.y0[i], y1 = texels.y1[i];
  recorder.record_footprint(site, level, x0, x1, y0, y1);
  const f32x4 t00 = fetch(image, x0, y0), t10 = fetch(image, x1, y0);
  const f32x4 t01 = fetch(image, x0, y1), t11 = fetch(image, x1, y1);
  const f32x4 a = splat(texels.a[i]), b = splat(texels.b[i]);
  const f32x4 top = t00 + (t10 - t00) * a;
  const f32x4 bottom = t01 + (t11 - t01) * a;
  return top + (bottom - top) * b;
}

f32x4 safe_coordinates(f32x4 s) { return simd::clamp(simd::finite_or_zero(s), -kCoordinateLimit, kCoordinateLimit); }

}  // namespace

void sample_quad(const Texture& texture, const SamplerState& state, f32x4 s, f32x4 t, float lambda, unsigned pixels,
                 int qx, int qy, TexelRecorder& recorder, TexelSite site, f32x4 rgba[4]) {
  s = safe_coordinates(s);
  t = safe_coordinates(t);
  const LevelPlan plan = plan_levels(texture, state, lambda);
  const Image& first = texture.levels[plan.first];
  const LevelTexels first_texels = level_texels(first, plan.filter, state, s, t);
  // LINEAR_MIPMAP_LINEAR between two levels: the second level's texels too.
  const Image& second = texture.levels[plan.blend ? plan.first + 1 : plan.first];
  const LevelTexels second_texels = plan.blend ? level_texels(second, TextureFilter::Linear, state, s, t) : LevelTexels{};
  for (int i = 0; i < 4; ++i) {
    if (!(pixels >> i & 1u)) continue;
    site.pixel_x = static_cast<std::uint16_t>(qx + (i & 1));
    site.pixel_y = static_cast<std::uint16_t>(qy + (i >> 1));
    rgba[i] = filter_pixel(first, plan.first, plan.filter, first_texels, i, recorder, site);
    if (!plan.blend) continue;
    const f32x4 t2 = filter_pixel(second, plan.first + 1, TextureFilter::Linear, second_texels, i, recorder, site);
    rgba[i] = rgba[i] + (t2 - rgba[i]) * splat(plan.fraction);
  }
}

namespace {

// The quad's pixels one after another through a per-pixel filter `sample(s, t, site)`.
template <typename PixelFilter>
void sample_quad_per_pixel(f32x4 s, f32x4 t, unsigned pixels, int qx, int qy, TexelSite site, f32x4 rgba[4],
                           PixelFilter sample) {
  for (int i = 0; i < 4; ++i) {
    if (!(pixels >> i & 1u)) continue;
    site.pixel_x = static_cast<std::uint16_t>(qx + (i & 1));
    site.pixel_y = static_cast<std::uint16_t>(qy + (i >> 1));
    const glm::vec4 c = sample(s[i], t[i], site);
    rgba[i] = f32x4{c.r, c.g, c.b, c.a};
  }
}

}  // namespace

void sample_quad_elliptical(const Texture& texture, const SamplerState& state, const EllipticalFootprint& footprint,
                            f32x4 s, f32x4 t, unsigned pixels, int qx, int qy, TexelRecorder& recorder, TexelSite site,
                            f32x4 rgba[4]) {
  sample_quad_per_pixel(s, t, pixels, qx, qy, site, rgba, [&](float ps, float pt, const TexelSite& where) {
    return sample_elliptical(texture, state, footprint, ps, pt, recorder, where);
  });
}

void sample_quad_probes(const Texture& texture, const SamplerState& state, const ProbeFootprint& footprint, f32x4 s,
                        f32x4 t, unsigned pixels, int qx, int qy, TexelRecorder& recorder, TexelSite site,
                        f32x4 rgba[4]) {
  sample_quad_per_pixel(s, t, pixels, qx, qy, site, rgba, [&](float ps, float pt, const TexelSite& where) {
    return sample_probes(texture, state, footprint, ps, pt, recorder, where);
  });
}

}  // namespace rastrace
