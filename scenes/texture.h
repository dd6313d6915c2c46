// Textures as the renderer samples them: 8-bit RGBA levels, level 0 first, down to 1x1. A
// block-compressed texture keeps its storage format and its blocks beside the decoded texels the
// sampler reads, so traces, cache models and the reference renderer see the same data.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "core/texture_format.h"

namespace rastrace {

// The widest and tallest texture the renderer takes: texel events (traces/events.h) hold 16-bit
// texel coordinates. (GL implementations allow 16384 or 32768.)
inline constexpr std::uint32_t kMaxTextureSide = 65536;

struct Image {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // 4 bytes per texel, row 0 is the top row (t = 0 in GL terms)

  const std::uint8_t* texel(int x, int y) const {
    return rgba.data() +
           (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) + static_cast<std::size_t>(x)) * 4;
  }
};

struct Texture {
  std::string name;
  std::vector<Image> levels;                      // levels[0] is the base; each next level halves with floor, to 1x1
  TextureFormat format = TextureFormat::Rgba8;    // how the texels are stored in memory
  std::vector<std::vector<std::uint8_t>> blocks;  // per level, when compressed: the encoded level
};

}  // namespace rastrace
