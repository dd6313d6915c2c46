// What happens to one 2x2 quad of a set-up triangle: coverage with the fill rule, the depth test
// (early or late, optionally hierarchical Z first), shading, the level of detail and texturing,
// the writes. Internal to the raster module: the serial Rasterizer and each worker of the
// parallel one run the same code, so they write the same pixels and record the same events.
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

#include "raster/framebuffer.h"
#include "raster/framebuffer_recorder.h"
#include "raster/rasterizer.h"
#include "raster/sampler.h"
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
  void refresh(const Framebuffer& framebuffer, std::size_t tile) {
    const int tile_x = static_cast<int>(tile % columns_), tile_y = static_cast<int>(tile / columns_);
    const int width = framebuffer.width();
    const int x1 = std::min(width, (tile_x + 1) * kTraversalTile);
    const int y1 = std::min(framebuffer.height(), (tile_y + 1) * kTraversalTile);
    float farthest = 0.0f;
    for (int y = tile_y * kTraversalTile; y < y1; ++y)
      for (int x = tile_x * kTraversalTile; x < x1; ++x)
        farthest = std::max(farthest, framebuffer.depth()[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)]);
    tiles_[tile] = farthest;
  }

 private:
  std::vector<float> tiles_;
  std::size_t columns_ = 0;
};

// One thread's quad stage: its recorders and statistics, the shared framebuffer and hierarchical Z.
struct QuadStage {
  Framebuffer& framebuffer;
  const RasterOptions& options;
  HierarchicalZ* hiz;  // nullptr without hierarchical Z
  TexelRecorder& texels;
  FramebufferRecorder& framebuffer_events;
  RasterStats& stats;

  template <bool kTextured, bool kDebug>
  void quad(const TriangleSetup& s, const TriangleState& state, int qx, int qy, const std::int64_t* e);
};

template <bool kTextured, bool kDebug>
inline void QuadStage::quad(const TriangleSetup& s, const TriangleState& state, int qx, int qy,
                            const std::int64_t* e) {
  const int width = framebuffer.width(), height = framebuffer.height();
  // Pixels of a quad: 0 top-left, 1 top-right, 2 bottom-left, 3 bottom-right.
  unsigned mask = 0;
  std::int64_t pe[3][4];
  for (int k = 0; k < 3; ++k) {
    pe[k][0] = e[k];
    pe[k][1] = e[k] + s.step_x[k];
    pe[k][2] = e[k] + s.step_y[k];
    pe[k][3] = e[k] + s.step_x[k] + s.step_y[k];
  }
  for (int i = 0; i < 4; ++i) {
    const bool inside = (pe[0][i] + s.bias[0] >= 0) & (pe[1][i] + s.bias[1] >= 0) & (pe[2][i] + s.bias[2] >= 0);
    mask |= static_cast<unsigned>(inside) << i;
  }
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
        for (int k = 0; k < 3; ++k) {
          const bool near = std::fabs(static_cast<double>(pe[k][i])) <= s.length[k];
          const bool inside_others = pe[(k + 1) % 3][i] >= -static_cast<std::int64_t>(s.length[(k + 1) % 3]) &&
                                     pe[(k + 2) % 3][i] >= -static_cast<std::int64_t>(s.length[(k + 2) % 3]);
          if (near && inside_others) flag = 2;
        }
      }
    }
  }
  if (!mask) return;
  ++stats.quads;

  const unsigned covered = static_cast<unsigned>(std::popcount(mask));
  stats.fragments += covered;

  // Barycentric weights of vertices 1 and 2 at the four centres (helper pixels included).
  float l1[4], l2[4];
  for (int i = 0; i < 4; ++i) {
    l1[i] = static_cast<float>(pe[1][i]) * s.inv_area;
    l2[i] = static_cast<float>(pe[2][i]) * s.inv_area;
  }
  auto attribute = [&](int i, int j) { return s.base[j] + l1[i] * s.d1[j] + l2[i] * s.d2[j]; };
  auto pixel = [&](int i) {
    return static_cast<std::size_t>(qy + (i >> 1)) * width + static_cast<std::size_t>(qx + (i & 1));
  };
  float* depth = framebuffer.depth();
  float z[4];
  for (int i = 0; i < 4; ++i) z[i] = attribute(i, 7);
  // Hierarchical Z: no covered fragment can pass if none is nearer than the farthest depth of
  // the quad's 8x8 tile; the quad is rejected without reading the depth buffer.
  const std::size_t tile = hiz ? hiz->tile_of(qx, qy) : 0;
  if (hiz) {
    float nearest = 2.0f;
    for (int i = 0; i < 4; ++i)
      if (mask >> i & 1u) nearest = std::min(nearest, z[i]);
    if (nearest >= hiz->farthest(tile)) {
      ++stats.quads_rejected_hiz;
      stats.fragments_rejected_early += covered;
      return;
    }
  }
  auto depth_test = [&] {
    unsigned pass = 0;
    for (int i = 0; i < 4; ++i)
      if ((mask >> i & 1u) && z[i] < depth[pixel(i)]) pass |= 1u << i;
    framebuffer_events.record(FramebufferOp::DepthRead, qx, qy, mask, state.triangle);
    return pass;
  };
  // Early: the test runs before shading and texturing, so rejected fragments read no texel.
  // Late: every covered fragment is shaded and textured, then tested.
  const bool late = options.depth_test == DepthTest::Late;
  unsigned pass = late ? 0u : depth_test();
  if (!late) {
    stats.fragments_rejected_early += covered - static_cast<unsigned>(std::popcount(pass));
    if (!pass) return;
  }
  const unsigned shade = late ? mask : pass;
  float q[4];
  for (int i = 0; i < 4; ++i) q[i] = attribute(i, 0);

  float u[4], v[4];
  float lambda = 0.0f;
  const Texture* texture = state.texture;
  if constexpr (kTextured) {
    for (int i = 0; i < 4; ++i) {
      const float w = 1.0f / q[i];
      u[i] = attribute(i, 1) * w;
      v[i] = attribute(i, 2) * w;
    }
    lambda = compute_lod(options.sampler, texture->levels[0].width, texture->levels[0].height, u[1] - u[0],
                         v[1] - v[0], u[2] - u[0], v[2] - v[0]);
  }
  glm::vec4 shaded[4] = {};
  TexelSite site;
  site.texture = state.texture_id;
  site.triangle = state.triangle;
  for (int i = 0; i < 4; ++i) {
    if (!(shade >> i & 1u)) continue;
    ++stats.fragments_shaded;
    const float w = 1.0f / q[i];
    shaded[i] = glm::vec4(attribute(i, 3) * w, attribute(i, 4) * w, attribute(i, 5) * w, attribute(i, 6) * w);
    if constexpr (kTextured) {
      site.pixel_x = static_cast<std::uint16_t>(qx + (i & 1));
      site.pixel_y = static_cast<std::uint16_t>(qy + (i >> 1));
      shaded[i] *= sample_texture(*texture, options.sampler, u[i], v[i], lambda, texels, site);
    }
  }
  if (late) pass = depth_test();
  if (!pass) return;
  framebuffer_events.record(FramebufferOp::DepthWrite, qx, qy, pass, state.triangle);
  framebuffer_events.record(FramebufferOp::ColourWrite, qx, qy, pass, state.triangle);
  bool tile_maximum_written = false;
  std::uint8_t* colour = framebuffer.colour();
  for (int i = 0; i < 4; ++i) {
    if (!(pass >> i & 1u)) continue;
    ++stats.fragments_passed;
    const std::size_t p = pixel(i);
    if (hiz && depth[p] >= hiz->farthest(tile)) tile_maximum_written = true;
    depth[p] = z[i];
    std::uint8_t* out = colour + p * 4;
    for (int ch = 0; ch < 4; ++ch)
      out[ch] = static_cast<std::uint8_t>(std::clamp(shaded[i][ch], 0.0f, 1.0f) * 255.0f + 0.5f);
    if constexpr (kDebug) ++framebuffer.write_count()[p];
  }
  if (tile_maximum_written) hiz->refresh(framebuffer, tile);
}

}  // namespace rastrace
