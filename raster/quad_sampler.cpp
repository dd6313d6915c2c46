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

// The texel each pixel reads with NEAREST in `image`: (x[i], y[i]).
struct NearestTexels {
  i32x4 x, y;
};

NearestTexels nearest_texels(const Image& image, const SamplerState& state, f32x4 s, f32x4 t) {
  const f32x4 width = splat(static_cast<float>(image.width)), height = splat(static_cast<float>(image.height));
  return {wrap_coordinates(simd::floor_int(s * width), image.width, state.wrap_s),
          wrap_coordinates(simd::floor_int(t * height), image.height, state.wrap_t)};
}

inline f32x4 fetch(const Image& image, std::int32_t x, std::int32_t y) {
  return simd::bytes_to_float(image.texel(x, y)) * splat(1.0f / 255.0f);
}

}  // namespace

void sample_quad_nearest(const Image& level, unsigned level_index, const SamplerState& state, f32x4 s, f32x4 t,
                         unsigned pixels, int qx, int qy, TexelRecorder& recorder, TexelSite site, f32x4 rgba[4]) {
  const NearestTexels texels = nearest_texels(level, state, s, t);
  for (int i = 0; i < 4; ++i) {
    if (!(pixels >> i & 1u)) continue;
    site.pixel_x = static_cast<std::uint16_t>(qx + (i & 1));
    site.pixel_y = static_cast<std::uint16_t>(qy + (i >> 1));
    recorder.record(site, level_index, texels.x[i], texels.y[i]);
    const f32x4 colour = fetch(level, texels.x[i], texels.y[i]);
    for (int c = 0; c < 4; ++c) rgba[c][i] = colour[c];
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
    for (int ch = 0; ch < 4; ++ch) rgba[ch][i] = c[ch];
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
