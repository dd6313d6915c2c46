#include "experiments/texture_miss_map.h"

#include <algorithm>
#include <cstdio>
#include <sstream>

#include "cache_sim/byte_cache.h"
#include "core/atomic_file.h"
#include "core/error.h"
#include "experiments/miss_image.h"
#include "raster/framebuffer.h"
#include "traces/replay_file.h"

namespace rastrace {

namespace {

std::uint8_t channel(float v) { return static_cast<std::uint8_t>(std::clamp(v, 0.0f, 1.0f) * 255.0f + 0.5f); }

}  // namespace

TextureMissMapSink::TextureMissMapSink(const CacheConfig& cache, const LayoutSpec& layout, const TextureLevels& textures,
                                       std::uint32_t width, std::uint32_t height)
    : cache_(cache), layout_(layout, textures) {
  map_.width = width;
  map_.height = height;
  map_.misses.assign(std::size_t{width} * height, 0);
  map_.textured.assign(map_.misses.size(), 0);
}

void TextureMissMapSink::texel_accesses(std::span<const TexelAccess> accesses) {
  for (const TexelAccess& t : accesses) {
    if (!layout_.contains(t.texture, t.level, t.x, t.y))
      throw InputError("texel access (texture " + std::to_string(t.texture) + ", level " + std::to_string(t.level) +
                       ", x " + std::to_string(t.x) + ", y " + std::to_string(t.y) +
                       ") lies outside the textures the trace metadata lists");
    if (t.pixel_x >= map_.width || t.pixel_y >= map_.height)
      throw InputError("texel access at pixel (" + std::to_string(t.pixel_x) + ", " + std::to_string(t.pixel_y) +
                       ") lies outside the " + std::to_string(map_.width) + "x" + std::to_string(map_.height) +
                       " frame the trace metadata gives");
    const std::size_t p = std::size_t{t.pixel_y} * map_.width + t.pixel_x;
    map_.textured[p] = 1;
    if (!cache_.access(layout_.address(t.texture, t.level, t.x, t.y))) ++map_.misses[p];
  }
}

std::uint64_t TextureMissMap::pixels_with(int count) const {
  std::uint64_t n = 0;
  for (std::size_t p = 0; p < misses.size(); ++p) {
    if (count < 0)
      n += textured[p] == 0;
    else
      n += textured[p] && std::min<std::uint32_t>(misses[p], 3) == static_cast<std::uint32_t>(count);
  }
  return n;
}

TextureMissMap texture_miss_map(const std::string& trace, const CacheConfig& cache, const LayoutSpec& layout) {
  const TraceSummary summary = summarize_trace(trace);
  if (summary.metadata.width == 0 || summary.metadata.height == 0)
    throw_in_file(trace, "no frame size in the metadata: a miss map needs a rendered trace (rastrace render --trace)");
  TextureMissMapSink sink(cache, layout, summary.metadata.textures, summary.metadata.width, summary.metadata.height);
  ReplayKinds kinds;
  kinds.vertices = kinds.addresses = kinds.framebuffer = false;
  replay_file(trace, sink, kinds);
  const TextureMissMap& map = sink.map();
  if (map.stats.accesses == 0) throw_in_file(trace, "no texel accesses: expected a textured frame's trace");
  return map;
}

std::string write_texture_miss_map(const TextureMissMap& map, const std::string& description,
                                   const std::string& path) {
  const int w = static_cast<int>(map.width);
  const int legend = std::max(12, static_cast<int>(map.height) / 16);
  const int h = static_cast<int>(map.height) + legend;
  std::vector<std::uint8_t> rgba(std::size_t(w) * h * 4, 255);
  for (std::size_t p = 0; p < map.misses.size(); ++p) {
    if (!map.textured[p]) continue;
    const float* c = kMissColours[std::min<std::uint32_t>(map.misses[p], 3)];
    for (int ch = 0; ch < 3; ++ch) rgba[p * 4 + ch] = channel(c[ch]);
  }
  // Legend: four swatches, 0 1 2 3+ from left to right, a 2-pixel white gap between them.
  for (int y = static_cast<int>(map.height) + 2; y < h - 2; ++y)
    for (int x = 0; x < w; ++x) {
      const int k = x * 4 / w;
      if (x - k * w / 4 < 2) continue;
      for (int ch = 0; ch < 3; ++ch) rgba[(std::size_t(y) * w + x) * 4 + ch] = channel(kMissColours[k][ch]);
    }
  write_rgba8_image(path, w, h, rgba.data(), 3);

  std::ostringstream text;
  text << "Texture misses per pixel: " << path << "\n"
       << "cache: " << description << "\n"
       << "accesses " << map.stats.accesses << ", misses " << map.stats.misses << " (miss rate "
       << map.stats.miss_rate() << ")\n"
       << "legend (the strip below the frame, left to right) and pixel counts:\n"
       << "  green   0 misses   " << map.pixels_with(0) << "\n"
       << "  yellow  1 miss     " << map.pixels_with(1) << "\n"
       << "  orange  2 misses   " << map.pixels_with(2) << "\n"
       << "  red     3 or more  " << map.pixels_with(3) << "\n"
       << "  white   no texel accesses " << map.pixels_with(-1) << "\n";
  write_file_atomically(path + ".txt", [&](std::ostream& o) { o << text.str(); }, false);
  return text.str();
}

}  // namespace rastrace
