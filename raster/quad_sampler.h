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

#include "raster/anisotropic_probes.h"
#include "raster/anisotropy.h"
#include "raster/sampler.h"
#include "raster/simd.h"
#include "raster/texel_recorder.h"
#include "scenes/texture.h"

namespace rastrace {

// Samples `texture` at (s[i], t[i]) for each pixel i of the quad at (qx, qy) whose bit is set in
// `pixels` (0 top-left, 1 top-right, 2 bottom-left, 3 bottom-right), with the quad's level of
// detail `lambda`. rgba[c] receives channel c (red, green, blue, alpha), lane i pixel i's; the
// lanes of pixels not in `pixels` are unspecified. `site` gives the texture and triangle of the events; their pixel is set
// per pixel.
void sample_quad(const Texture& texture, const SamplerState& state, simd::f32x4 s, simd::f32x4 t, float lambda,
                 unsigned pixels, int qx, int qy, TexelRecorder& recorder, TexelSite site, simd::f32x4 rgba[4]);

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
