// How a texture's texels are stored in memory: uncompressed RGBA8, or a block-compressed format
// (BC1-BC7, ASTC) where every block of bw x bh texels takes a fixed number of bytes. The renderer
// samples decoded texels and records logical texel coordinates whatever the format; the cache
// simulator turns a texel into the bytes of its block (cache_sim/texture_layout.h), so one trace
// replays as any format. Shared by scenes (a texture's format), traces (the format recorded in a
// trace's metadata) and cache_sim (block addresses).
#pragma once

#include <cstdint>
#include <string_view>

namespace rastrace {

enum class TextureFormat : std::uint8_t {
  Rgba8,    // 4 bytes per texel, uncompressed
  Bc1,      // DXT1: 8 bytes per 4x4 block, RGB with 1-bit alpha
  Bc3,      // DXT5: 16 bytes per 4x4 block, BC1 colour + BC4 alpha
  Bc4,      // RGTC1: 8 bytes per 4x4 block, one channel
  Bc5,      // RGTC2: 16 bytes per 4x4 block, two channels
  Bc7,      // BPTC: 16 bytes per 4x4 block, RGBA, eight modes
  Astc4x4,  // ASTC LDR: 16 bytes per 4x4 block (8 bits per texel)
  Astc8x8,  // ASTC LDR: 16 bytes per 8x8 block (2 bits per texel)
};

// A format's storage unit: a texel for Rgba8 (1 x 1 texels, 4 bytes), else a block.
struct BlockShape {
  std::uint32_t width = 1;   // texels per block, horizontally
  std::uint32_t height = 1;  // and vertically
  std::uint32_t bytes = 4;   // bytes per block
};

BlockShape block_shape(TextureFormat format);
inline bool is_compressed(TextureFormat format) { return format != TextureFormat::Rgba8; }

// Names as typed and printed: rgba8, bc1, bc3, bc4, bc5, bc7, astc4x4, astc8x8. parse throws
// InputError naming `what` (the option or JSON path) and listing the accepted names.
TextureFormat parse_texture_format(std::string_view text, std::string_view what = "texture format");
const char* to_string(TextureFormat format);

// Bytes of a level of width x height texels: whole blocks, the last row and column of blocks
// padded (a 2x2 level of BC1 is one 8-byte block).
std::uint64_t level_bytes(TextureFormat format, std::uint32_t width, std::uint32_t height);

}  // namespace rastrace
