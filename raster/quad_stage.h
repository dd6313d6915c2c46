// What happens to one 2x2 quad of a set-up triangle: coverage with the fill rule, the depth test
// (early or late, optionally hierarchical Z first), shading, the level of detail and texturing,
// the writes. Internal to the raster module: the serial Rasterizer and each worker of the
// parallel one run the same code, so they write the same pixels and record the same events.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

#include "raster/framebuffer.h"
#include "raster/framebuffer_recorder.h"
#include "raster/quad_sampler.h"
#include "raster/rasterizer.h"
#include "raster/sampler.h"
#include "raster/simd.h"
#include "raster/texel_recorder.h"
#include "raster/traversal.h"
#include "raster/triangle_setup.h"

namespace rastrace {

// The farthest depth stored in each 8x8 tile, row-major. Tiles of the screen that are multiples of
// 8 pixels own disjoint entries, so workers on different screen tiles share it without locks.
class HierarchicalZ {
 public:
  void build(const Framebuffer& framebuffer) {
    columns_ = static_cast<std::size_t>((framebuffer.width() + kTraversalTile - 1) / kTraversalTile);
    const int rows = (framebuffer.height() + kTraversalTile - 1) / kTraversalTile;
    tiles_.resize(columns_ * static_cast<std::size_t>(rows));
    for (std::size_t t = 0; t < tiles_.size(); ++t) refresh(framebuffer, t);
  }
  std::size_t tile_of(int qx, int qy) const {
    return static_cast<std::size_t>(qy / kTraversalTile) * columns_ + static_cast<std::size_t>(qx / kTraversalTile);
  }
  float farthest(std::size_t tile) const { return tiles_[tile]; }
  // After a clear to `depth`: every tile's farthest depth is that.
  void reset(float depth) { std::fill(tiles_.begin(), tiles_.end(), depth); }
  void refresh(const Framebuffer& framebuffer, std::size_t tile) {
    const int tile_x = static_cast<int>(tile % columns_), tile_y = static_cast<int>(tile / columns_);
    const int width = framebuffer.width();
    const int x1 = std::min(width, (tile_x + 1) * kTraversalTile);
    const int y1 = std::min(framebuffer.height(), (tile_y + 1) * kTraversalTile);
    float farthest = 0.0f;
    for (int y = tile_y * kTraversalTile; y < y1; ++y)
      for (int x = tile_x * kTraversalTile; x < x1; ++x)
        farthest =
            std::max(farthest, framebuffer.depth()[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)]);
    tiles_[tile] = farthest;
  }

 private:
  std::vector<float> tiles_;
  std::size_t columns_ = 0;
};

// A triangle's interpolation coefficients broadcast to every lane, once per triangle: each
// quad's attributes are then vector operations on them, where broadcasting the 25 scalars per
// quad cost two instructions each.
struct QuadCoefficients {
  explicit QuadCoefficients(const TriangleSetup& s) : inv_area(simd::splat(s.inv_area)) {
    for (int j = 0; j < kRasterAttributes; ++j) {
      base[j] = simd::splat(s.base[j]);
      d1[j] = simd::splat(s.d1[j]);
      d2[j] = simd::splat(s.d2[j]);
    }
  }
  // Attribute j at the four centres whose barycentric weights of vertices 1 and 2 are l1, l2.
  simd::f32x4 attribute(int j, simd::f32x4 l1, simd::f32x4 l2) const { return base[j] + l1 * d1[j] + l2 * d2[j]; }

  simd::f32x4 inv_area;
  simd::f32x4 base[kRasterAttributes], d1[kRasterAttributes], d2[kRasterAttributes];
};

// What the front half of the quad stage leaves for the back half (QuadStage::front, ::back).
struct PendingQuad {
  int qx = 0, qy = 0;
  unsigned mask = 0;     // covered pixels
  unsigned pass = 0;     // early depth test: the covered pixels that pass it
  bool whole = false;    // the quad lies wholly inside the image
  std::size_t tile = 0;  // its hierarchical-Z tile
  simd::f32x4 l1, l2;    // barycentric weights of vertices 1 and 2 at the four centres
  simd::f32x4 z, w;      // depth; 1 / q, the perspective correction
  simd::f32x4 u, v;      // texture coordinates
  float lambda = 0.0f;   // level of detail (textured, isotropic filter)
};

// One thread's quad stage: its recorders and statistics, the shared framebuffer and hierarchical Z.
//
// A quad goes through two halves. front() decides coverage, interpolates depth and texture
// coordinates, runs the early depth test and computes the level of detail; back() records the
// quad's events, samples the texture, runs a late depth test and writes. front() writes nothing
// and records nothing, so the quad loop may run the front of the next quad of the same triangle
// before the back of this one (quad_loop.h): the next quad's pixels are other pixels, and its
// chain of dependent operations (the division by q, the square root and log2 of the level of
// detail) overlaps this quad's texture filter. The events come out in quad()'s order.
// Hierarchical Z is the exception: a back half may lower a tile's farthest depth, which the next
// front half reads (pipelined() is false then).
struct QuadStage {
  Framebuffer& framebuffer;
  const RasterOptions& options;
  HierarchicalZ* hiz;  // nullptr without hierarchical Z
  TexelRecorder& texels;
  FramebufferRecorder& framebuffer_events;
  RasterStats& stats;

  // front() then back() for one quad.
  template <bool kTextured, bool kDebug>
  [[gnu::always_inline]] void quad(const TriangleSetup& s, const QuadCoefficients& k, const TriangleState& state,
                                   int qx, int qy, const simd::i64x4* pe) {
    PendingQuad q;
    if (front<kTextured, kDebug>(s, k, state, qx, qy, pe, q)) back<kTextured, kDebug>(k, state, q);
  }
  // Whether the next quad's front may run before this quad's back.
  bool pipelined() const { return hiz == nullptr; }
  // False when the quad is done (no coverage, or rejected by hierarchical Z): back() would have
  // nothing to record or write.
  template <bool kTextured, bool kDebug>
  bool front(const TriangleSetup& s, const QuadCoefficients& k, const TriangleState& state, int qx, int qy,
             const simd::i64x4* pe, PendingQuad& q);
  template <bool kTextured, bool kDebug>
  void back(const QuadCoefficients& k, const TriangleState& state, const PendingQuad& q);

 private:
  std::size_t pixel(const PendingQuad& q, int i) const {
    return static_cast<std::size_t>(q.qy + (i >> 1)) * static_cast<std::size_t>(framebuffer.width()) +
           static_cast<std::size_t>(q.qx + (i & 1));
  }
  // The covered pixels of `q` that pass the depth test.
  [[gnu::always_inline]] unsigned depth_pass(const PendingQuad& q) const {
    const float* depth = framebuffer.depth();
    if (q.whole) {
      const float* const rows[2] = {depth + pixel(q, 0), depth + pixel(q, 2)};
      const simd::f32x4 stored{rows[0][0], rows[0][1], rows[1][0], rows[1][1]};
      return q.mask & simd::lanes_true(q.z < stored);
    }
    unsigned pass = 0;
    for (int i = 0; i < 4; ++i)
      if ((q.mask >> i & 1u) && q.z[i] < depth[pixel(q, i)]) pass |= 1u << i;
    return pass;
  }
};

template <bool kTextured, bool kDebug>
[[gnu::always_inline]] inline bool QuadStage::front(const TriangleSetup& s, const QuadCoefficients& k,
                                                    const TriangleState& state, int qx, int qy, const simd::i64x4* pe,
                                                    PendingQuad& q) {
  using simd::splat;
  const int width = framebuffer.width(), height = framebuffer.height();
  // pe[k]: edge function k at the pixels of the quad, one lane each: 0 top-left, 1 top-right,
  // 2 bottom-left, 3 bottom-right. Inside: every biased edge function >= 0, that is, their
  // bitwise or >= 0.
  unsigned mask = simd::non_negative_mask((pe[0] + s.bias[0]) | (pe[1] + s.bias[1]) | (pe[2] + s.bias[2]));
  if (qx + 1 >= width) mask &= ~0xAu;
  if (qy + 1 >= height) mask &= ~0xCu;
  if constexpr (kDebug) {
    for (int i = 0; i < 4; ++i) {
      const int x = qx + (i & 1), y = qy + (i >> 1);
      if (x >= width || y >= height) continue;
      // 1: exactly on an edge of the snapped triangle. 2: within 1/256 pixel of an edge, where
      // a rasterizer that does not snap vertices (softpipe) may decide the other way.
      std::uint8_t& flag = framebuffer.centre_on_edge()[static_cast<std::size_t>(y) * width + x];
      const bool closed = pe[0][i] >= 0 && pe[1][i] >= 0 && pe[2][i] >= 0;
      if (closed && (pe[0][i] == 0 || pe[1][i] == 0 || pe[2][i] == 0)) {
        flag = 1;
      } else if (flag == 0) {
        for (int e = 0; e < 3; ++e) {
          const bool near = std::fabs(static_cast<double>(pe[e][i])) <= s.length[e];
          const bool inside_others = pe[(e + 1) % 3][i] >= -static_cast<std::int64_t>(s.length[(e + 1) % 3]) &&
                                     pe[(e + 2) % 3][i] >= -static_cast<std::int64_t>(s.length[(e + 2) % 3]);
          if (near && inside_others) flag = 2;
        }
      }
    }
  }
  if (!mask) return false;
  ++stats.quads;
  const unsigned covered = simd::lanes_set(mask);
  stats.fragments += covered;
  q.qx = qx;
  q.qy = qy;
  q.mask = mask;

  // Barycentric weights of vertices 1 and 2 at the four centres (helper pixels included).
  q.l1 = simd::to_float(pe[1]) * k.inv_area;
  q.l2 = simd::to_float(pe[2]) * k.inv_area;
  auto attribute = [&](int j) { return k.attribute(j, q.l1, q.l2); };
  q.z = attribute(7);
  // Hierarchical Z: no covered fragment can pass if none is nearer than the farthest depth of
  // the quad's 8x8 tile; the quad is rejected without reading the depth buffer.
  if (hiz) {
    q.tile = hiz->tile_of(qx, qy);
    float nearest = 2.0f;
    for (int i = 0; i < 4; ++i)
      if (mask >> i & 1u) nearest = std::min(nearest, q.z[i]);
    if (nearest >= hiz->farthest(q.tile)) {
      ++stats.quads_rejected_hiz;
      stats.fragments_rejected_early += covered;
      return false;
    }
  }
  // A quad wholly inside the image reads and writes its pixels as two rows of two lanes; one on
  // the right or bottom border (odd sizes) pixel by pixel.
  q.whole = qx + 1 < width && qy + 1 < height;
  // Early: the test runs before shading and texturing, so rejected fragments read no texel.
  // Late: every covered fragment is shaded and textured, then tested (in back()).
  if (options.depth_test != DepthTest::Late) {
    q.pass = depth_pass(q);
    stats.fragments_rejected_early += covered - simd::lanes_set(q.pass);
    if (!q.pass) return true;  // back() records the depth read
  }
  // Perspective correction: every attribute but q and z is interpolated divided by w.
  q.w = splat(1.0f) / attribute(0);
  if constexpr (kTextured) {
    q.u = attribute(1) * q.w;
    q.v = attribute(2) * q.w;
    if (options.sampler.max_anisotropy <= 1) {
      const Image& base = state.texture->levels[0];
      q.lambda = compute_lod(options.sampler, base.width, base.height, q.u[1] - q.u[0], q.v[1] - q.v[0],
                             q.u[2] - q.u[0], q.v[2] - q.v[0]);
    }
  }
  return true;
}

template <bool kTextured, bool kDebug>
[[gnu::always_inline]] inline void QuadStage::back(const QuadCoefficients& k, const TriangleState& state,
                                                   const PendingQuad& q) {
  using simd::f32x4;
  using simd::splat;
  const bool late = options.depth_test == DepthTest::Late;
  if (!late) {
    framebuffer_events.record(FramebufferOp::DepthRead, q.qx, q.qy, q.mask, state.triangle);
    if (!q.pass) return;
  }
  const unsigned shade = late ? q.mask : q.pass;
  stats.fragments_shaded += simd::lanes_set(shade);
  auto attribute = [&](int j) { return k.attribute(j, q.l1, q.l2); };
  // Channels in vectors, pixels in lanes, as the sampler returns them.
  f32x4 shaded[4] = {attribute(3) * q.w, attribute(4) * q.w, attribute(5) * q.w, attribute(6) * q.w};
  if constexpr (kTextured) {
    const Texture* texture = state.texture;
    stats.fragments_textured += simd::lanes_set(shade);
    TexelSite site;
    site.texture = state.texture_id;
    site.triangle = state.triangle;
    // Lanes of pixels the sampler skips keep 1: their products are never written.
    f32x4 texel_colour[4] = {splat(1.0f), splat(1.0f), splat(1.0f), splat(1.0f)};
    if (options.sampler.max_anisotropy > 1) {
      const float dsdx = q.u[1] - q.u[0], dtdx = q.v[1] - q.v[0], dsdy = q.u[2] - q.u[0], dtdy = q.v[2] - q.v[0];
      if (options.sampler.aniso_rule == AnisotropyRule::Probes) {
        const ProbeFootprint footprint = probe_footprint(*texture, options.sampler, dsdx, dtdx, dsdy, dtdy);
        sample_quad_probes(*texture, options.sampler, footprint, q.u, q.v, shade, q.qx, q.qy, texels, site,
                           texel_colour);
      } else {
        const EllipticalFootprint footprint = elliptical_footprint(*texture, options.sampler, dsdx, dtdx, dsdy, dtdy);
        sample_quad_elliptical(*texture, options.sampler, footprint, q.u, q.v, shade, q.qx, q.qy, texels, site,
                               texel_colour);
      }
    } else {
      sample_quad(*texture, options.sampler, q.u, q.v, q.lambda, shade, q.qx, q.qy, texels, site, texel_colour);
    }
    for (int c = 0; c < 4; ++c) shaded[c] *= texel_colour[c];
  }
  unsigned pass = q.pass;
  if (late) {
    pass = depth_pass(q);
    framebuffer_events.record(FramebufferOp::DepthRead, q.qx, q.qy, q.mask, state.triangle);
  }
  if (!pass) return;
  framebuffer_events.record(FramebufferOp::DepthWrite, q.qx, q.qy, pass, state.triangle);
  framebuffer_events.record(FramebufferOp::ColourWrite, q.qx, q.qy, pass, state.triangle);
  bool tile_maximum_written = false;
  float* depth = framebuffer.depth();
  std::uint8_t* colour = framebuffer.colour();
  stats.fragments_passed += simd::lanes_set(pass);
  simd::i32x4 bytes[4];
  for (int c = 0; c < 4; ++c)
    bytes[c] = simd::truncate(simd::clamp(shaded[c], 0.0f, 1.0f) * splat(255.0f) + splat(0.5f));
  if (q.whole && !kDebug && std::endian::native == std::endian::little) {
    // The passing lanes' depths and RGBA words over the stored ones, two pixels per row.
    float* const depth_rows[2] = {depth + pixel(q, 0), depth + pixel(q, 2)};
    const simd::i32x4 write = simd::lanes_of(pass);
    const f32x4 stored{depth_rows[0][0], depth_rows[0][1], depth_rows[1][0], depth_rows[1][1]};
    if (hiz && (pass & simd::lanes_true(stored >= splat(hiz->farthest(q.tile))))) tile_maximum_written = true;
    const f32x4 depths = write ? q.z : stored;
    const simd::i32x4 mask8 = splat(0xFF);
    const simd::i32x4 words =
        (bytes[0] & mask8) | (bytes[1] & mask8) << 8 | (bytes[2] & mask8) << 16 | (bytes[3] & mask8) << 24;
    std::uint8_t* const colour_rows[2] = {colour + pixel(q, 0) * 4, colour + pixel(q, 2) * 4};
    std::int32_t stored_pixels[4];
    for (int row = 0; row < 2; ++row) std::memcpy(stored_pixels + 2 * row, colour_rows[row], 8);
    const simd::i32x4 stored_words{stored_pixels[0], stored_pixels[1], stored_pixels[2], stored_pixels[3]};
    const simd::i32x4 out = write ? words : stored_words;
    const std::int32_t out_pixels[4] = {out[0], out[1], out[2], out[3]};
    for (int row = 0; row < 2; ++row) {
      depth_rows[row][0] = depths[2 * row];
      depth_rows[row][1] = depths[2 * row + 1];
      std::memcpy(colour_rows[row], out_pixels + 2 * row, 8);
    }
    if (tile_maximum_written) hiz->refresh(framebuffer, q.tile);
    return;
  }
  for (int i = 0; i < 4; ++i) {
    if (!(pass >> i & 1u)) continue;
    const std::size_t p = pixel(q, i);
    if (hiz && depth[p] >= hiz->farthest(q.tile)) tile_maximum_written = true;
    depth[p] = q.z[i];
    std::uint8_t* out = colour + p * 4;
    for (int c = 0; c < 4; ++c) out[c] = static_cast<std::uint8_t>(bytes[c][i]);
    if constexpr (kDebug) ++framebuffer.write_count()[p];
  }
  if (tile_maximum_written) hiz->refresh(framebuffer, q.tile);
}

}  // namespace rastrace
