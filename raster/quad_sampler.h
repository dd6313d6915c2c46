// Texture sampling for the four pixels of a 2x2 quad at once: the quad shares one level of
// detail, so it shares the levels read. LINEAR filters (bilinear, and trilinear's two levels)
// run in the eight lanes of raster/quad_filter.h, a lane per pixel and level; NEAREST ones
// compute the four pixels' coordinates in the lanes of one vector. The texel reads are recorded
// pixel by pixel, each as sample_texture records it, and the filtered colours equal
// sample_texture's bit for bit (the same operations on the same values:
// tests/raster/quad_sampler_test.cpp checks every filter and wrap against it).
//
// Colours come out a channel per vector, a lane per pixel: rgba[0] holds the four pixels' red.
#pragma once

#include <algorithm>
#include <cstdint>

#include "raster/anisotropic_probes.h"
#include "raster/anisotropy.h"
#include "raster/quad_filter.h"
#include "raster/sampler.h"
#include "raster/simd.h"
#include "raster/texel_recorder.h"
#include "scenes/texture.h"

namespace rastrace {

// NEAREST within one level of the quad (sample_quad's other path): `level` is texture level
// `level_index`.
void sample_quad_nearest(const Image& level, unsigned level_index, const SamplerState& state, simd::f32x4 s,
                         simd::f32x4 t, unsigned pixels, int qx, int qy, TexelRecorder& recorder, TexelSite site,
                         simd::f32x4 rgba[4]);

// safe_coordinate (sampler.h) of each lane.
[[gnu::always_inline]] inline simd::f32x4 safe_coordinates(simd::f32x4 s) {
  return simd::clamp(simd::finite_or_zero(s), -kCoordinateLimit, kCoordinateLimit);
}

// Samples `texture` at (s[i], t[i]) for each pixel i of the quad at (qx, qy) whose bit is set in
// `pixels` (0 top-left, 1 top-right, 2 bottom-left, 3 bottom-right), with the quad's level of
// detail `lambda`. rgba[c] receives channel c (red, green, blue, alpha), lane i pixel i's; the
// lanes of pixels not in `pixels` are unspecified. `site` gives the texture and triangle of the
// events; their pixel is set per pixel. Inline: the quad stage calls it once per quad, and as a
// call it spilled the stage's vectors around it and passed the colours back through memory.
[[gnu::always_inline]] inline void sample_quad(const Texture& texture, const SamplerState& state, simd::f32x4 s,
                                               simd::f32x4 t, float lambda, unsigned pixels, int qx, int qy,
                                               TexelRecorder& recorder, TexelSite site, simd::f32x4 rgba[4]) {
  using simd::f32x4;
  using simd::i32x4;
  s = safe_coordinates(s);
  t = safe_coordinates(t);
  const LevelPlan plan = plan_levels(texture, state, lambda);
  const Image& first = texture.levels[plan.first];
  if (plan.filter == TextureFilter::Linear) {
    QuadFilterInput in;
    in.levels[0] = {first.rgba.data(), first.width, first.height};
    if (plan.blend) {
      const Image& second = texture.levels[plan.first + 1];
      in.levels[1] = {second.rgba.data(), second.width, second.height};
    }
    in.repeat_s = state.wrap_s == TextureWrap::Repeat;
    in.repeat_t = state.wrap_t == TextureWrap::Repeat;
    in.blend = plan.blend;
    in.fraction = plan.fraction;
    // The sampled pixels in order; a blend of one or two of them is filtered in their lanes alone.
    int sampled[4], count = 0;
    for (int i = 0; i < 4; ++i)
      if (pixels >> i & 1u) sampled[count++] = i;
    if (count == 0) return;
    in.two_pixels = plan.blend && count <= 2;
    // Vectors are assembled in registers and stored whole: stored lane by lane, the kernel's
    // vector loads (and the caller's, of rgba) would wait on stores they cannot forward from.
    const int last = sampled[count - 1];
    if (in.two_pixels) {
      in.s = f32x4{s[sampled[0]], s[last], 0.0f, 0.0f};
      in.t = f32x4{t[sampled[0]], t[last], 0.0f, 0.0f};
    } else {
      in.s = s;
      in.t = t;
    }
    QuadFilterOutput out;
    renderer_quad_filter()(in, out);
    const int second_level_lane = in.two_pixels ? 2 : 4;
    if (!recorder.sink()) {
      recorder.count_unrecorded(static_cast<std::uint64_t>(count) * (plan.blend ? 8 : 4));
    } else if (count == 4 && plan.blend) {
      recorder.record_quad<true>(site, plan.first, qx, qy, out.x0, out.x1, out.y0, out.y1);
    } else if (count == 4) {
      recorder.record_quad<false>(site, plan.first, qx, qy, out.x0, out.x1, out.y0, out.y1);
    } else {
      for (int j = 0; j < count; ++j) {
        const int i = sampled[j], lane = in.two_pixels ? j : i;
        site.pixel_x = static_cast<std::uint16_t>(qx + (i & 1));
        site.pixel_y = static_cast<std::uint16_t>(qy + (i >> 1));
        recorder.record_footprint(site, plan.first, out.x0[lane], out.x1[lane], out.y0[lane], out.y1[lane]);
        if (plan.blend) {
          const int second = lane + second_level_lane;
          recorder.record_footprint(site, plan.first + 1, out.x0[second], out.x1[second], out.y0[second],
                                    out.y1[second]);
        }
      }
    }
    if (in.two_pixels) {
      // Pixel `last` takes lane 1, every other lane lane 0: the lanes of skipped pixels are
      // unspecified, so only the sampled ones need to be right.
      const i32x4 is_last = simd::lanes_of(1u << last);
      for (int c = 0; c < 4; ++c) {
        const f32x4 lane0 = __builtin_shufflevector(out.rgba[c], out.rgba[c], 0, 0, 0, 0);
        const f32x4 lane1 = __builtin_shufflevector(out.rgba[c], out.rgba[c], 1, 1, 1, 1);
        rgba[c] = is_last ? lane1 : lane0;
      }
    } else {
      for (int c = 0; c < 4; ++c) rgba[c] = out.rgba[c];
    }
    return;
  }
  // NEAREST within one level (NEAREST, NEAREST_MIPMAP_NEAREST, or a NEAREST magnification).
  sample_quad_nearest(first, plan.first, state, s, t, pixels, qx, qy, recorder, site, rgba);
}

// The same for the anisotropic filter with the quad's shared footprint. Each pixel's ellipse
// holds its own number of texels, so the pixels are filtered one after another by
// sample_elliptical itself: bits and events are the scalar sampler's by construction.
void sample_quad_elliptical(const Texture& texture, const SamplerState& state, const EllipticalFootprint& footprint,
                            simd::f32x4 s, simd::f32x4 t, unsigned pixels, int qx, int qy, TexelRecorder& recorder,
                            TexelSite site, simd::f32x4 rgba[4]);

// And for EXT_texture_filter_anisotropic's probes (raster/anisotropic_probes.h), pixel by pixel
// through sample_probes, for the same reason.
void sample_quad_probes(const Texture& texture, const SamplerState& state, const ProbeFootprint& footprint,
                        simd::f32x4 s, simd::f32x4 t, unsigned pixels, int qx, int qy, TexelRecorder& recorder,
                        TexelSite site, simd::f32x4 rgba[4]);

}  // namespace rastrace
