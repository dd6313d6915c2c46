// The whole frame's traffic between the GPU and its memory, the table rastrace exists to produce:
// per ordering, the four streams side by side, in bytes per frame and per pixel of the frame:
//   vertex   vertices shaded x vertex bytes + indices sent x index bytes (Hoppe's bandwidth model,
//            32-byte vertices and 2-byte indices by default) through the post-transform cache
//   texture  bytes the texture cache fetches (a byte cache over a texture layout)
//   depth    bytes the depth cache reads (depth-test misses) and writes back (dirty lines)
//   colour   bytes the colour cache writes back (colour is written, never read: no blending)
// and the frame's overdraw figures: covered pixels, shaded fragments / covered pixels, depth writes
// per covered pixel, fragments rejected before shading (early depth test, hierarchical Z).
// One live cache bank (cache_sim/live_bank_sink.h) measures all four in the render's single pass;
// the replay of its trace gives the same bytes.
#pragma once

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "cache_sim/cache_spec.h"
#include "cache_sim/live_bank_sink.h"
#include "core/table.h"
#include "pipeline/render_scene.h"

namespace rastrace {

struct FrameCaches {
  VertexCacheSpec vertex = vertex_cache_spec(VertexCachePolicy::Fifo, 16);
  std::uint32_t vertex_bytes = 32;  // per shaded vertex
  std::uint32_t index_bytes = 2;    // per index sent
  TextureCacheSpec texture = default_texture_cache();
  FramebufferCacheSpec depth = attila_framebuffer_cache(FramebufferBuffer::Depth);
  FramebufferCacheSpec colour = attila_framebuffer_cache(FramebufferBuffer::Colour);

  // size=16KiB,line=64B,assoc=4,policy=lru,layout=block4 (render's default --tcache).
  static TextureCacheSpec default_texture_cache();
};

// The bank that measures a frame: vertex[0], texture[0], framebuffer {depth, colour}.
CacheBankConfig frame_bank_config(const FrameCaches& caches);

struct FrameTraffic {
  std::uint64_t pixels = 0;          // of the frame (width x height)
  std::uint64_t covered_pixels = 0;  // written at least once
  std::uint64_t fragments = 0;       // rasterized (covered pixels of every triangle)
  std::uint64_t fragments_shaded = 0;
  std::uint64_t depth_writes = 0;
  std::uint64_t rejected_early = 0;  // early depth test and hierarchical Z, before shading
  std::uint64_t vertex_bytes = 0;
  std::uint64_t texture_bytes = 0;
  std::uint64_t depth_read_bytes = 0;
  std::uint64_t depth_write_bytes = 0;
  std::uint64_t colour_write_bytes = 0;

  std::uint64_t total_bytes() const {
    return vertex_bytes + texture_bytes + depth_read_bytes + depth_write_bytes + colour_write_bytes;
  }
  double per_pixel(std::uint64_t bytes) const { return pixels ? double(bytes) / double(pixels) : 0.0; }
  double overdraw() const { return covered_pixels ? double(fragments_shaded) / double(covered_pixels) : 0.0; }
  double depth_writes_per_pixel() const {
    return covered_pixels ? double(depth_writes) / double(covered_pixels) : 0.0;
  }
};

// The bank must be finished (render_scene finishes its sink) and built by frame_bank_config.
FrameTraffic measure_frame_traffic(const FrameCaches& caches, const LiveBankSink& bank, const RenderResult& result);

// Every cache and byte model in full, for a table's parameters.
std::vector<std::pair<std::string, TableCell>> frame_cache_parameters(const FrameCaches& caches);

// The traffic columns (bytes per frame, then per pixel, then the overdraw figures) and a row's
// cells for them, for tables that put them beside their own columns.
std::vector<TableColumn> frame_traffic_columns();
std::vector<TableCell> frame_traffic_cells(const FrameTraffic& traffic);

struct FrameTrafficRow {
  std::string order;
  std::string raster;
  FrameTraffic traffic;
};
// One row per ordering and raster: order, raster, then frame_traffic_columns().
Table frame_traffic_table(const std::string& title, std::vector<std::pair<std::string, TableCell>> parameters,
                          const std::vector<FrameTrafficRow>& rows);
// Bytes per pixel per ordering, the four streams stacked (gnuplot; PNG or SVG by extension).
void write_frame_traffic_plot(const std::string& path, const std::string& title,
                              const std::vector<FrameTrafficRow>& rows);

}  // namespace rastrace
