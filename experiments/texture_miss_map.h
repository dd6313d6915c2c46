// Where a frame's texture misses happen on screen, as Hakura and Gupta ("The design and analysis
// of a cache architecture for texture mapping", ISCA 1997) draw them: each pixel coloured by how
// many texture-cache misses its fragments caused, 0, 1, 2 or 3 and more (`rastrace replay TRACE
// --cache SPEC --miss-map FILE.png`, or live: `rastrace render SCENE --miss-map FILE.png`). Texel
// accesses carry their pixel, so a replay through one cache charges every miss to the pixel that
// asked.
// Image: the frame, pixels without texel accesses white, the others in kMissColours (green,
// yellow, orange, red for 0, 1, 2, 3+), above a legend strip of the four colours left to right;
// beside it, FILE.png.txt states the legend, the cache and the totals (PNG has no room for text
// we could draw without a font).
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "cache_sim/byte_cache.h"
#include "cache_sim/cache_config.h"
#include "cache_sim/texture_layout.h"
#include "traces/sink.h"

namespace rastrace {

struct TextureMissMap {
  std::uint32_t width = 0, height = 0;
  std::vector<std::uint32_t> misses;    // per pixel, row 0 at the top
  std::vector<std::uint8_t> textured;   // per pixel: 1 when a fragment there read texels
  CacheStats stats;                     // accesses, misses of the whole replay
  // Pixels by class: untextured, then 0, 1, 2, 3+ misses.
  std::uint64_t pixels_with(int misses) const;
};

// Charges the texel accesses it receives, through one cache, to their pixels: beside the pipeline
// (render --miss-map) or behind a trace reader. Throws InputError for an access outside the
// textures or the frame.
class TextureMissMapSink final : public EventSink {
 public:
  TextureMissMapSink(const CacheConfig& cache, const LayoutSpec& layout, const TextureLevels& textures,
                     std::uint32_t width, std::uint32_t height);
  void texel_accesses(std::span<const TexelAccess> accesses) override;
  void finish() override { map_.stats = cache_.stats(); }
  const TextureMissMap& map() const { return map_; }

 private:
  TextureMissMap map_;
  ByteCache cache_;
  TextureLayout layout_;
};

// Replays the trace's texel accesses through `cache` (fifo, lru or random) under `layout`.
// Throws InputError for a trace without texel accesses or frame size, or an invalid cache.
TextureMissMap texture_miss_map(const std::string& trace, const CacheConfig& cache, const LayoutSpec& layout);

// Writes the image (atomically, any format OpenImageIO writes by extension) and FILE.txt beside it
// with `description` (the cache spec) and the legend; returns the legend text.
std::string write_texture_miss_map(const TextureMissMap& map, const std::string& description,
                                   const std::string& path);

}  // namespace rastrace
