// Anisotropic filtering as llvmpipe does it in Mesa 22.3 (Debian 12): an elliptical weighted
// average (EWA) of the texels of one mip level, after Heckbert, "Fundamentals of Texture Mapping
// and Image Warping" (1989), and Greene & Heckbert, "Creating Raster Omnimax Images from Multiple
// Perspective Views Using the Elliptical Weighted Average Filter" (1986).
//
// The pixel's footprint in the texture is the ellipse spanned by the two derivative vectors
// (du/dx, dv/dx) and (du/dy, dv/dy), each axis grown by one texel so that it never shrinks below
// the reconstruction filter. Every texel whose centre lies inside the ellipse is read (one
// "probe": a NEAREST fetch) and weighted by a Gaussian exp(-2 r^2) of its elliptical radius r,
// looked up in a 1024-entry table; the colour is the weighted mean.
//
// Where EXT_texture_filter_anisotropic takes N = min(ceil(Pmax / Pmin), maxAniso) bilinear or
// trilinear probes along the major axis at lambda = log2(Pmax / N), this filter reads one level,
// the minor axis's: level floor(log2(Pmin)), no blend between levels, and as many texels as the
// ellipse covers there (about pi sqrt(a^2 + 1) sqrt(b^2 + 1) for axes a and b in texels of the
// level; docs/DESIGN.md, "Anisotropic filtering"). llvmpipe 22.3
// compares Pmin^2 with Pmin^2 * maxAniso^2 where Pmax^2 was meant, so the maximum never bounds
// Pmax / Pmin: any maximum above 1 gives the same image, and so it does here.
#pragma once

#include <glm/vec4.hpp>

#include "raster/sampler.h"
#include "raster/texel_recorder.h"
#include "scenes/texture.h"

namespace rastrace {

// The ellipse of one 2x2 quad (its derivatives are shared) in the texels of `level`:
// q(U, V) = a U^2 + b U V + c V^2 for an offset (U, V) from the sample, scaled so that the
// ellipse's edge is q = kEllipseEdge; half_u and half_v are half its bounding box.
struct EllipticalFootprint {
  unsigned level = 0;
  float a = 0.0f, b = 0.0f, c = 0.0f;
  float half_u = 0.0f, half_v = 0.0f;
  float width = 0.0f, height = 0.0f;  // the level-0 size scaled to `level`, for s and t to texels
  bool valid = false;                 // false: non-finite derivatives; the level is bilinear-filtered
};

inline constexpr int kEllipseEdge = 1023;  // the last entry of the weight table

// The level llvmpipe reads: floor(log2(Pmin)) with Pmin the shorter derivative vector in level-0
// texels, 0 for Pmin < 1, and at most `last_level`. A mipmap-less minification filter reads
// level 0 only. Computed from the exponent of Pmin^2, exactly as llvmpipe's truncated half log.
unsigned anisotropic_level(const SamplerState& state, int width, int height, unsigned last_level, float dsdx,
                           float dtdx, float dsdy, float dtdy);

// The footprint of a quad whose texture coordinates (s, t) change by (dsdx, dtdx) per pixel to
// the right and (dsdy, dtdy) per pixel down.
EllipticalFootprint elliptical_footprint(const Texture& texture, const SamplerState& state, float dsdx, float dtdx,
                                         float dsdy, float dtdy);

// The EWA sample at (s, t): every texel inside the footprint's ellipse, row by row, is recorded
// and weighted. Texel coordinates wrap as the sampler's wraps say.
glm::vec4 sample_elliptical(const Texture& texture, const SamplerState& state, const EllipticalFootprint& footprint,
                            float s, float t, TexelRecorder& recorder, const TexelSite& site);

}  // namespace rastrace
