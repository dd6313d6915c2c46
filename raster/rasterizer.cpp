#include "raster/rasterizer.h"

#include <algorithm>
#include <bit>
#include <cmath>

#include "core/enum_names.h"
#include "raster/hilbert_order.h"

namespace rastrace {

namespace {

constexpr EnumName<Traversal> kTraversals[] = {
    {Traversal::Scanline, "scanline"}, {Traversal::Tiled8, "tiled8"}, {Traversal::Tiled8, "tiled"},
    {Traversal::Hilbert8, "hilbert"}};

}  // namespace

Traversal parse_traversal(const std::string& text) { return parse_enum(text, kTraversals, "traversal order"); }

const char* to_string(Traversal traversal) { return enum_to_string(traversal, kTraversals); }

namespace {
constexpr EnumName<DepthTest> kDepthTests[] = {{DepthTest::Early, "early"}, {DepthTest::Late, "late"}};
}  // namespace

DepthTest parse_depth_test(const std::string& text) { return parse_enum(text, kDepthTests, "depth test"); }

const char* to_string(DepthTest test) { return enum_to_string(test, kDepthTests); }

namespace {

constexpr int kSubpixelBits = 8;
constexpr std::int64_t kOne = std::int64_t{1} << kSubpixelBits;  // one pixel in fixed point
constexpr std::int64_t kHalf = kOne / 2;                         // pixel centres
constexpr int kAttributes = 8;                                   // q = 1/w, s*q, t*q, r*q, g*q, b*q, a*q, z
constexpr int kTile = 8;

// Round half away from zero, as llround, without the library call (|v| < 2^22 is checked first).
inline std::int64_t to_fixed(float v) {
  const double scaled = static_cast<double>(v) * kOne;
  return static_cast<std::int64_t>(scaled >= 0.0 ? scaled + 0.5 : scaled - 0.5);
}

// floor(a / 256): C++20 defines >> on negative values as arithmetic (flooring) shift.
inline int floor_pixel(std::int64_t a) { return static_cast<int>(a >> kSubpixelBits); }

}  // namespace

struct Rasterizer::Setup {
  std::int64_t step_x[3], step_y[3];  // edge function change per pixel to the right / down
  std::int64_t bias[3];               // 0 for owned (top or left) edges, -1 for the others
  std::int64_t origin[3];             // edge functions at the centre of pixel (x0, y0)
  double length[3];                   // edge lengths in 1/256 pixels (debug planes only)
  int x0, y0, x1, y1;                 // pixels to visit (x0, y0 even), inclusive, in the image
  float inv_area;
  float base[kAttributes], d1[kAttributes], d2[kAttributes];
};

Rasterizer::Rasterizer(Framebuffer& framebuffer, const RasterOptions& options, EventSink* sink)
    : framebuffer_(framebuffer), options_(options), recorder_(sink), framebuffer_recorder_(sink) {
  if (!options_.hierarchical_z) return;
  hiz_columns_ = static_cast<std::size_t>((framebuffer_.width() + kTile - 1) / kTile);
  const int rows = (framebuffer_.height() + kTile - 1) / kTile;
  hiz_.resize(hiz_columns_ * static_cast<std::size_t>(rows));
  for (int ty = 0; ty < rows; ++ty)
    for (int tx = 0; tx < static_cast<int>(hiz_columns_); ++tx)
      hiz_[static_cast<std::size_t>(ty) * hiz_columns_ + static_cast<std::size_t>(tx)] = tile_max_depth(tx, ty);
}

float Rasterizer::tile_max_depth(int tile_x, int tile_y) const {
  const int width = framebuffer_.width();
  const int x1 = std::min(width, (tile_x + 1) * kTile), y1 = std::min(framebuffer_.height(), (tile_y + 1) * kTile);
  float farthest = 0.0f;
  for (int y = tile_y * kTile; y < y1; ++y)
    for (int x = tile_x * kTile; x < x1; ++x)
      farthest = std::max(farthest, framebuffer_.depth()[static_cast<std::size_t>(y) * width + static_cast<std::size_t>(x)]);
  return farthest;
}

void Rasterizer::draw(const RasterVertex& va, const RasterVertex& vb, const RasterVertex& vc,
                      const TriangleState& state) {
  const RasterVertex* v[3] = {&va, &vb, &vc};
  std::int64_t X[3], Y[3];
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(v[i]->x) || !std::isfinite(v[i]->y) || std::fabs(v[i]->x) > 4194304.0f ||
        std::fabs(v[i]->y) > 4194304.0f)
      return;  // outside the fixed-point range: the pipeline's clipping never sends these
    X[i] = to_fixed(v[i]->x);
    Y[i] = to_fixed(v[i]->y);
  }
  std::int64_t area = (X[1] - X[0]) * (Y[2] - Y[0]) - (Y[1] - Y[0]) * (X[2] - X[0]);
  if (area == 0) return;
  if (area < 0) {  // make the winding positive so that "inside" is E >= 0 on all three edges
    std::swap(v[1], v[2]);
    std::swap(X[1], X[2]);
    std::swap(Y[1], Y[2]);
    area = -area;
  }

  Setup s;
  int min_x = floor_pixel(std::min({X[0], X[1], X[2]}) - kHalf + kOne - 1);  // ceil
  int min_y = floor_pixel(std::min({Y[0], Y[1], Y[2]}) - kHalf + kOne - 1);
  int max_x = floor_pixel(std::max({X[0], X[1], X[2]}) - kHalf);
  int max_y = floor_pixel(std::max({Y[0], Y[1], Y[2]}) - kHalf);
  min_x = std::max(min_x, 0);
  min_y = std::max(min_y, 0);
  max_x = std::min(max_x, framebuffer_.width() - 1);
  max_y = std::min(max_y, framebuffer_.height() - 1);
  if (min_x > max_x || min_y > max_y) return;
  const int align = options_.traversal == Traversal::Scanline ? 2 : kTile;
  s.x0 = min_x - min_x % align;
  s.y0 = min_y - min_y % align;
  s.x1 = max_x;
  s.y1 = max_y;

  // Edge k is the one opposite vertex k, from vertex k+1 to vertex k+2; its function is
  // 2 * area * (barycentric weight of vertex k).
  const std::int64_t px = static_cast<std::int64_t>(s.x0) * kOne + kHalf;
  const std::int64_t py = static_cast<std::int64_t>(s.y0) * kOne + kHalf;
  for (int k = 0; k < 3; ++k) {
    const int from = (k + 1) % 3, to = (k + 2) % 3;
    const std::int64_t dx = X[to] - X[from], dy = Y[to] - Y[from];
    s.step_x[k] = -dy * kOne;
    s.step_y[k] = dx * kOne;
    s.origin[k] = -dy * (px - X[from]) + dx * (py - Y[from]);
    const bool top = dy == 0 && dx > 0;
    const bool left = dy < 0;
    s.bias[k] = (top || left) ? 0 : -1;
    s.length[k] = std::sqrt(static_cast<double>(dx) * static_cast<double>(dx) +
                            static_cast<double>(dy) * static_cast<double>(dy));
  }
  s.inv_area = static_cast<float>(1.0 / static_cast<double>(area));

  float attr[3][kAttributes];
  for (int i = 0; i < 3; ++i) {
    const float q = v[i]->inv_w;
    attr[i][0] = q;
    attr[i][1] = v[i]->uv.x * q;
    attr[i][2] = v[i]->uv.y * q;
    attr[i][3] = v[i]->colour.r * q;
    attr[i][4] = v[i]->colour.g * q;
    attr[i][5] = v[i]->colour.b * q;
    attr[i][6] = v[i]->colour.a * q;
    attr[i][7] = v[i]->z;
  }
  for (int j = 0; j < kAttributes; ++j) {
    s.base[j] = attr[0][j];
    s.d1[j] = attr[1][j] - attr[0][j];
    s.d2[j] = attr[2][j] - attr[0][j];
  }

  ++stats_.triangles;
  const bool textured = state.texture != nullptr && !state.texture->levels.empty();
  const bool debug = framebuffer_.has_debug_planes();
  if (textured) {
    if (debug)
      traverse<true, true>(s, state);
    else
      traverse<true, false>(s, state);
  } else {
    if (debug)
      traverse<false, true>(s, state);
    else
      traverse<false, false>(s, state);
  }
}

template <bool kTextured, bool kDebug>
void Rasterizer::traverse(const Setup& s, const TriangleState& state) {
  const int width = framebuffer_.width(), height = framebuffer_.height();
  std::uint8_t* colour = framebuffer_.colour();
  float* depth = framebuffer_.depth();
  const SamplerState sampler = options_.sampler;
  const Texture* texture = state.texture;
  const int tex_w = kTextured ? texture->levels[0].width : 1;
  const int tex_h = kTextured ? texture->levels[0].height : 1;
  const bool late = options_.depth_test == DepthTest::Late;
  const bool hierarchical_z = options_.hierarchical_z;
  TexelSite site;
  site.texture = state.texture_id;
  site.triangle = state.triangle;

  // Pixels of a quad: 0 top-left, 1 top-right, 2 bottom-left, 3 bottom-right.
  auto quad = [&](int qx, int qy, const std::int64_t* e) {
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
        std::uint8_t& flag = framebuffer_.centre_on_edge()[static_cast<std::size_t>(y) * width + x];
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
    ++stats_.quads;

    const unsigned covered = static_cast<unsigned>(std::popcount(mask));
    stats_.fragments += covered;

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
    float z[4];
    for (int i = 0; i < 4; ++i) z[i] = attribute(i, 7);
    // Hierarchical Z: no covered fragment can pass if none is nearer than the farthest depth of
    // the quad's 8x8 tile; the quad is rejected without reading the depth buffer.
    const std::size_t tile = hierarchical_z ? static_cast<std::size_t>(qy / kTile) * hiz_columns_ +
                                                  static_cast<std::size_t>(qx / kTile)
                                            : 0;
    if (hierarchical_z) {
      float nearest = 2.0f;
      for (int i = 0; i < 4; ++i)
        if (mask >> i & 1u) nearest = std::min(nearest, z[i]);
      if (nearest >= hiz_[tile]) {
        ++stats_.quads_rejected_hiz;
        stats_.fragments_rejected_early += covered;
        return;
      }
    }
    auto depth_test = [&] {
      unsigned pass = 0;
      for (int i = 0; i < 4; ++i)
        if ((mask >> i & 1u) && z[i] < depth[pixel(i)]) pass |= 1u << i;
      framebuffer_recorder_.record(FramebufferOp::DepthRead, qx, qy, mask, state.triangle);
      return pass;
    };
    // Early: the test runs before shading and texturing, so rejected fragments read no texel.
    // Late: every covered fragment is shaded and textured, then tested.
    unsigned pass = late ? 0u : depth_test();
    if (!late) {
      stats_.fragments_rejected_early += covered - static_cast<unsigned>(std::popcount(pass));
      if (!pass) return;
    }
    const unsigned shade = late ? mask : pass;
    float q[4];
    for (int i = 0; i < 4; ++i) q[i] = attribute(i, 0);

    float u[4], v[4];
    float lambda = 0.0f;
    if constexpr (kTextured) {
      for (int i = 0; i < 4; ++i) {
        const float w = 1.0f / q[i];
        u[i] = attribute(i, 1) * w;
        v[i] = attribute(i, 2) * w;
      }
      lambda = compute_lod(sampler, tex_w, tex_h, u[1] - u[0], v[1] - v[0], u[2] - u[0], v[2] - v[0]);
    }
    glm::vec4 shaded[4] = {};
    for (int i = 0; i < 4; ++i) {
      if (!(shade >> i & 1u)) continue;
      ++stats_.fragments_shaded;
      const float w = 1.0f / q[i];
      shaded[i] = glm::vec4(attribute(i, 3) * w, attribute(i, 4) * w, attribute(i, 5) * w, attribute(i, 6) * w);
      if constexpr (kTextured) {
        site.pixel_x = static_cast<std::uint16_t>(qx + (i & 1));
        site.pixel_y = static_cast<std::uint16_t>(qy + (i >> 1));
        shaded[i] *= sample_texture(*texture, sampler, u[i], v[i], lambda, recorder_, site);
      }
    }
    if (late) pass = depth_test();
    if (!pass) return;
    framebuffer_recorder_.record(FramebufferOp::DepthWrite, qx, qy, pass, state.triangle);
    framebuffer_recorder_.record(FramebufferOp::ColourWrite, qx, qy, pass, state.triangle);
    bool tile_maximum_written = false;
    for (int i = 0; i < 4; ++i) {
      if (!(pass >> i & 1u)) continue;
      ++stats_.fragments_passed;
      const std::size_t p = pixel(i);
      if (hierarchical_z && depth[p] >= hiz_[tile]) tile_maximum_written = true;
      depth[p] = z[i];
      std::uint8_t* out = colour + p * 4;
      for (int ch = 0; ch < 4; ++ch)
        out[ch] = static_cast<std::uint8_t>(std::clamp(shaded[i][ch], 0.0f, 1.0f) * 255.0f + 0.5f);
      if constexpr (kDebug) ++framebuffer_.write_count()[p];
    }
    if (tile_maximum_written) hiz_[tile] = tile_max_depth(static_cast<int>(tile % hiz_columns_), static_cast<int>(tile / hiz_columns_));
  };

  std::int64_t row[3];
  if (options_.traversal == Traversal::Scanline) {
    std::copy(s.origin, s.origin + 3, row);
    for (int qy = s.y0; qy <= s.y1; qy += 2) {
      std::int64_t e[3] = {row[0], row[1], row[2]};
      for (int qx = s.x0; qx <= s.x1; qx += 2) {
        quad(qx, qy, e);
        for (int k = 0; k < 3; ++k) e[k] += 2 * s.step_x[k];
      }
      for (int k = 0; k < 3; ++k) row[k] += 2 * s.step_y[k];
    }
    return;
  }
  // Tiled: skip a tile when one edge function is negative at all its pixel centres; the
  // maximum of a linear function over the tile is at the corner its gradient points to.
  std::int64_t tile_max[3];
  for (int k = 0; k < 3; ++k)
    tile_max[k] =
        std::max<std::int64_t>(0, s.step_x[k]) * (kTile - 1) + std::max<std::int64_t>(0, s.step_y[k]) * (kTile - 1);
  // The quads of one tile, row-major; `tile` holds the edge functions at its top-left pixel.
  const auto quads_of_tile = [&](int tx, int ty, const std::int64_t* tile) {
    std::int64_t quad_row[3] = {tile[0], tile[1], tile[2]};
    for (int qy = ty; qy < ty + kTile && qy <= s.y1; qy += 2) {
      std::int64_t e[3] = {quad_row[0], quad_row[1], quad_row[2]};
      for (int qx = tx; qx < tx + kTile && qx <= s.x1; qx += 2) {
        quad(qx, qy, e);
        for (int k = 0; k < 3; ++k) e[k] += 2 * s.step_x[k];
      }
      for (int k = 0; k < 3; ++k) quad_row[k] += 2 * s.step_y[k];
    }
  };
  if (options_.traversal == Traversal::Hilbert8) {
    // The same tiles and quads as tiled8, the tiles visited along the screen's Hilbert curve.
    const unsigned bits = hilbert_bits(static_cast<std::uint32_t>((framebuffer_.width() + kTile - 1) / kTile),
                                       static_cast<std::uint32_t>((framebuffer_.height() + kTile - 1) / kTile));
    hilbert_tiles(static_cast<std::uint32_t>(s.x0 / kTile), static_cast<std::uint32_t>(s.y0 / kTile),
                  static_cast<std::uint32_t>(s.x1 / kTile), static_cast<std::uint32_t>(s.y1 / kTile), bits,
                  hilbert_tiles_);
    for (const std::uint64_t packed : hilbert_tiles_) {
      const int tx = static_cast<int>(packed & 0xFFFFFFFFu) * kTile, ty = static_cast<int>(packed >> 32) * kTile;
      std::int64_t tile[3];
      for (int k = 0; k < 3; ++k) tile[k] = s.origin[k] + (tx - s.x0) * s.step_x[k] + (ty - s.y0) * s.step_y[k];
      const bool outside = tile[0] + tile_max[0] + s.bias[0] < 0 || tile[1] + tile_max[1] + s.bias[1] < 0 ||
                           tile[2] + tile_max[2] + s.bias[2] < 0;
      if (outside && !kDebug) continue;
      quads_of_tile(tx, ty, tile);
    }
    return;
  }
  std::copy(s.origin, s.origin + 3, row);
  for (int ty = s.y0; ty <= s.y1; ty += kTile) {
    std::int64_t tile[3] = {row[0], row[1], row[2]};
    for (int tx = s.x0; tx <= s.x1; tx += kTile) {
      const bool outside = tile[0] + tile_max[0] + s.bias[0] < 0 || tile[1] + tile_max[1] + s.bias[1] < 0 ||
                           tile[2] + tile_max[2] + s.bias[2] < 0;
      if (!outside || kDebug) quads_of_tile(tx, ty, tile);
      for (int k = 0; k < 3; ++k) tile[k] += kTile * s.step_x[k];
    }
    for (int k = 0; k < 3; ++k) row[k] += kTile * s.step_y[k];
  }
}

}  // namespace rastrace
