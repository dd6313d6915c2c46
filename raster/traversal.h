// The order in which a triangle's 2x2 quads are visited, as one loop per order, restricted to a
// clip rectangle so that a tile of the screen can visit its part of a triangle alone. A quad's
// edge functions are computed from the setup's origin by exact integer steps, so a quad visited
// from any tile has the same values (and so the same coverage, attributes and texels) as in a
// visit of the whole triangle.
//
// Every order also has a key (quad_order_key): increasing along the order, so that the events of a
// triangle drawn in several tiles merge back into the order of one whole-triangle visit. A new
// order adds its enum value, its loop in for_each_quad and its key.
#pragma once

#include <algorithm>
#include <cstdint>
#include <string>

#include <vector>

#include "raster/hilbert_order.h"
#include "raster/simd.h"
#include "raster/triangle_setup.h"

namespace rastrace {

enum class Traversal : std::uint8_t {
  Scanline,  // quad rows top to bottom, left to right in each
  Tiled8,    // 8x8-pixel tiles row-major over the bounding box, quads row-major inside a tile
  Hilbert8,  // the same tiles in the screen's Hilbert-curve order (hilbert_order.h), quads row-major inside
};
// "scanline", "tiled8" (alias "tiled") or "hilbert"; throws InputError otherwise.
Traversal parse_traversal(const std::string& text);
const char* to_string(Traversal traversal);

// Pixels x0..x1, y0..y1 inclusive; x0 and y0 multiples of 8 (whole 8x8 tiles and whole quads).
struct PixelRect {
  int x0 = 0, y0 = 0, x1 = 0, y1 = 0;
};

inline constexpr int kTraversalTile = 8;  // the 8x8 tiles of Tiled8 and Hilbert8 (and of hierarchical Z)
// Rows of more quads than this are cut to the quads their edges may let a pixel into.
inline constexpr int kSpanMinimumColumns = 4;

// How far the bounding box's corner is aligned down (setup_triangle's `align`).
inline int traversal_alignment(Traversal traversal) { return traversal == Traversal::Scanline ? 2 : kTraversalTile; }

// The order of the Hilbert curve that covers a width x height screen with 8x8 tiles (the curve is
// the screen's, so every triangle visits shared tiles in the same relative order).
inline unsigned traversal_hilbert_bits(int width, int height) {
  return hilbert_bits(static_cast<std::uint32_t>((width + kTraversalTile - 1) / kTraversalTile),
                      static_cast<std::uint32_t>((height + kTraversalTile - 1) / kTraversalTile));
}

// Increasing along the traversal order within one triangle; quads of any image up to 16384 pixels.
// `hilbert_bits`: traversal_hilbert_bits of the screen (Hilbert8 only).
inline std::uint32_t quad_order_key(Traversal traversal, int qx, int qy, unsigned hilbert_bits = 0) {
  const auto x = static_cast<std::uint32_t>(qx), y = static_cast<std::uint32_t>(qy);
  if (traversal == Traversal::Scanline) return (y >> 1) << 13 | (x >> 1);
  if (traversal == Traversal::Hilbert8)  // tile index along the curve (22 bits at most), quad in the tile
    return static_cast<std::uint32_t>(hilbert_index(x >> 3, y >> 3, hilbert_bits)) << 4 | ((y & 7) >> 1) << 2 |
           ((x & 7) >> 1);
  // Tile row, tile column, quad row in the tile, quad column in the tile.
  return (y >> 3) << 15 | (x >> 3) << 4 | ((y & 7) >> 1) << 2 | ((x & 7) >> 1);
}

// Calls visit(qx, qy, e) for every quad of the triangle's box inside `clip`, in the traversal's
// order; e[k] holds edge function k at the quad's four pixel centres (lanes: top-left, top-right,
// bottom-left, bottom-right), stepped from quad to quad by vector additions. Tiled8 skips 8x8
// tiles that one edge excludes entirely, unless kVisitAll (the debug planes look at every quad).
// Hilbert8 visits the same tiles as Tiled8 along the screen's curve of order `hilbert_bits`.
template <bool kVisitAll, typename Visit>
[[gnu::always_inline]] inline void for_each_quad(const TriangleSetup& s, Traversal traversal, const PixelRect& clip,
                                                 Visit&& visit, unsigned hilbert_bits = 0) {
  using simd::i64x4;
  const int x_begin = std::max(s.x0, clip.x0), y_begin = std::max(s.y0, clip.y0);
  const int x_end = std::min(s.x1, clip.x1), y_end = std::min(s.y1, clip.y1);
  if (x_begin > x_end || y_begin > y_end) return;
  // Per edge: the four pixels relative to the quad's top-left one, and the steps between quads.
  i64x4 pixel_offsets[3], quad_step_x[3], quad_step_y[3];
  for (int k = 0; k < 3; ++k) {
    pixel_offsets[k] = i64x4{0, s.step_x[k], s.step_y[k], s.step_x[k] + s.step_y[k]};
    quad_step_x[k] = i64x4{} + 2 * s.step_x[k];
    quad_step_y[k] = i64x4{} + 2 * s.step_y[k];
  }
  // Per edge: the largest of its four pixels' values over the quad's top-left one (the maximum
  // of a linear function over the quad is at the pixel its gradient points to), fill-rule bias
  // included.
  std::int64_t quad_reach[3];
  for (int k = 0; k < 3; ++k)
    quad_reach[k] = std::max<std::int64_t>(0, s.step_x[k]) + std::max<std::int64_t>(0, s.step_y[k]) + s.bias[k];
  // The quads of the rectangle whose top-left quad has edge functions `first`, row-major.
  const auto quads_of_rectangle = [&](int x0, int y0, int x1, int y1, const std::int64_t* first)
      __attribute__((always_inline)) {
    i64x4 row[3];
    for (int k = 0; k < 3; ++k) row[k] = pixel_offsets[k] + first[k];
    const std::int64_t columns = (x1 - x0) / 2 + 1;
    for (int qy = y0; qy <= y1; qy += 2) {
      // The row's quads j in [begin, end) that may cover a pixel: for every edge, the best pixel
      // of quad j, row[k][0] (the row's top-left pixel) + reach + 2 step_x j, is >= 0. Quads outside cover nothing, and
      // the quad stage would leave them at once; skipping them visits the same quads with
      // coverage in the same order (llvmpipe and hardware skip them in blocks the same way).
      std::int64_t begin = 0, end = columns;
      // Rows of a few quads (the small triangles of a dense mesh) are visited whole: three 64-bit
      // divisions cost more than the quad stage's rejection of the empty quads.
      if (!kVisitAll && columns > kSpanMinimumColumns) {
        for (int k = 0; k < 3 && begin < end; ++k) {
          const std::int64_t best = row[k][0] + quad_reach[k], step = 2 * s.step_x[k];
          if (step == 0) {
            if (best < 0) end = 0;
          } else if (step > 0) {  // best + step j >= 0 from j = ceil(-best / step)
            if (best < 0) begin = std::max(begin, (-best + step - 1) / step);
          } else {  // up to j = floor(best / -step)
            end = best < 0 ? 0 : std::min(end, best / -step + 1);
          }
        }
      }
      i64x4 e[3];
      for (int k = 0; k < 3; ++k) e[k] = begin == 0 ? row[k] : row[k] + quad_step_x[k] * begin;
      for (std::int64_t j = begin; j < end; ++j) {
        visit(x0 + 2 * static_cast<int>(j), qy, static_cast<const i64x4*>(e));
        for (int k = 0; k < 3; ++k) e[k] += quad_step_x[k];
      }
      for (int k = 0; k < 3; ++k) row[k] += quad_step_y[k];
    }
  };
  std::int64_t corner[3];
  for (int k = 0; k < 3; ++k) corner[k] = s.origin[k] + s.step_x[k] * (x_begin - s.x0) + s.step_y[k] * (y_begin - s.y0);
  if (traversal == Traversal::Scanline) {
    quads_of_rectangle(x_begin, y_begin, x_end, y_end, corner);
    return;
  }
  // Tiled: skip a tile when one edge function is negative at all its pixel centres; the
  // maximum of a linear function over the tile is at the corner its gradient points to.
  constexpr int kTile = kTraversalTile;
  std::int64_t tile_max[3];
  for (int k = 0; k < 3; ++k)
    tile_max[k] =
        std::max<std::int64_t>(0, s.step_x[k]) * (kTile - 1) + std::max<std::int64_t>(0, s.step_y[k]) * (kTile - 1);
  // The quads of one tile inside the clip; `tile` holds the edge functions at its top-left pixel.
  const auto quads_of_tile = [&](int tx, int ty, const std::int64_t* tile) __attribute__((always_inline)) {
    quads_of_rectangle(tx, ty, std::min(tx + kTile - 2, x_end), std::min(ty + kTile - 2, y_end), tile);
  };
  if (traversal == Traversal::Hilbert8) {
    thread_local std::vector<std::uint64_t> tiles;  // reused: allocates only when a triangle is bigger
    hilbert_tiles(static_cast<std::uint32_t>(x_begin / kTile), static_cast<std::uint32_t>(y_begin / kTile),
                  static_cast<std::uint32_t>(x_end / kTile), static_cast<std::uint32_t>(y_end / kTile), hilbert_bits,
                  tiles);
    for (const std::uint64_t packed : tiles) {
      const int tx = static_cast<int>(packed & 0xFFFFFFFFu) * kTile, ty = static_cast<int>(packed >> 32) * kTile;
      std::int64_t tile[3];
      for (int k = 0; k < 3; ++k) tile[k] = s.origin[k] + (tx - s.x0) * s.step_x[k] + (ty - s.y0) * s.step_y[k];
      const bool outside = tile[0] + tile_max[0] + s.bias[0] < 0 || tile[1] + tile_max[1] + s.bias[1] < 0 ||
                           tile[2] + tile_max[2] + s.bias[2] < 0;
      if (!outside || kVisitAll) quads_of_tile(tx, ty, tile);
    }
    return;
  }
  for (int ty = y_begin; ty <= y_end; ty += kTile) {
    std::int64_t tile[3] = {corner[0], corner[1], corner[2]};
    for (int tx = x_begin; tx <= x_end; tx += kTile) {
      const bool outside = tile[0] + tile_max[0] + s.bias[0] < 0 || tile[1] + tile_max[1] + s.bias[1] < 0 ||
                           tile[2] + tile_max[2] + s.bias[2] < 0;
      if (!outside || kVisitAll) quads_of_tile(tx, ty, tile);
      for (int k = 0; k < 3; ++k) tile[k] += kTile * s.step_x[k];
    }
    for (int k = 0; k < 3; ++k) corner[k] += kTile * s.step_y[k];
  }
}

}  // namespace rastrace
