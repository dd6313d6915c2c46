// Texture memory layouts: where a logical texel (texture, level, x, y) lives in bytes.
// The trace records logical texels; the layout is applied at replay (DESIGN.md), so one trace
// serves every layout study.
//   linear   row-major, row 0 first
//   blockB   B x B texel blocks (B = 2, 4, 8, 16), blocks row-major, texels row-major inside a block
//            (the classic tiled layout of Hakura & Gupta 1997); partial edge blocks are padded
//   morton   Z order: bits of x and y interleaved (x in the even bits); a non-square level is a row
//            or column of square Morton tiles; levels padded to powers of two
// Each level starts on a multiple of `alignment` bytes (default 4 KiB, a page); textures follow one
// another, level 0 first. Addresses start at 0. Texel size defaults to 4 bytes (RGBA8).
//
// Block-compressed textures (core/texture_format.h: BC1-BC7, ASTC): the layout orders the format's
// blocks instead of texels (linear: blocks row-major; blockB: tiles of B x B blocks; morton: blocks
// in Z order), and a texel's address is the first byte of its block, 8 or 16 bytes that a cache
// holds whole. A texture's format comes from the trace (LevelSize::format) unless the spec names
// one for every texture (LayoutSpec::format), so one trace replays as RGBA8, BC1 or BC7.
// decoded_address() places the same texels in a decoded space for a cache of decoded texels in
// front of a cache of compressed blocks (cache_hierarchy.h): a block at compressed address A
// decodes to bw x bh texels of texel_bytes at A << decode_shift, row-major inside the block.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "traces/trace_metadata.h"  // LevelSize, TextureLevels: carried in the trace metadata

namespace rastrace {

enum class LayoutKind : std::uint8_t { Linear, Block, Morton };

struct LayoutSpec {
  LayoutKind kind = LayoutKind::Linear;
  std::uint32_t block = 4;         // Block only: 2, 4, 8 or 16
  std::uint32_t texel_bytes = 4;   // 1..16, power of two
  std::uint64_t alignment = 4096;  // power of two >= texel_bytes
  std::optional<TextureFormat> format;  // every texture stored as this; unset: the trace's formats
  bool operator==(const LayoutSpec&) const = default;
};

// "linear", "block2".."block16", "morton", each optionally with ":FORMAT" (block4:bc1); throws
// InputError otherwise.
LayoutSpec parse_layout(const std::string& text);
// The short name: "linear", "block4", "morton"; with a format, "block4:bc1".
std::string layout_name(const LayoutSpec& spec);

// The full mip chain of a width x height texture (halving with floor, down to 1x1), as GL builds it.
std::vector<LevelSize> mip_chain_sizes(std::uint32_t width, std::uint32_t height);

class TextureLayout {
 public:
  // Throws InputError on an invalid spec or a zero-sized level.
  TextureLayout(const LayoutSpec& spec, const TextureLevels& textures);

  // Byte address of the texel's first byte. The texel must exist: check with contains() first
  // when the input is untrusted (replay does, and reports the record).
  std::uint64_t address(std::uint32_t texture, std::uint32_t level, std::uint32_t x, std::uint32_t y) const {
    const Level& l = levels_[first_level_[texture] + level];
    x >>= l.unit_shift_x;  // a compressed texture's blocks are the units laid out
    y >>= l.unit_shift_y;
    std::uint64_t offset;
    switch (spec_.kind) {
      case LayoutKind::Linear:
        offset = std::uint64_t{y} * l.units_per_row + x;
        break;
      case LayoutKind::Block: {
        const std::uint32_t bx = x >> block_shift_, by = y >> block_shift_;
        const std::uint32_t mask = spec_.block - 1;
        offset = ((std::uint64_t{by} * l.blocks_per_row + bx) << (2 * block_shift_)) + ((y & mask) << block_shift_) +
                 (x & mask);
        break;
      }
      default: {
        const std::uint32_t m = l.square_bits;
        const std::uint32_t low = (1u << m) - 1;
        offset = interleave(x & low, y & low) + (std::uint64_t{(x >> m) | (y >> m)} << (2 * m));
        break;
      }
    }
    return l.base + (offset << l.unit_bytes_shift);
  }

  // The texel's address in the decoded space (see the file comment); address() for RGBA8.
  std::uint64_t decoded_address(std::uint32_t texture, std::uint32_t level, std::uint32_t x, std::uint32_t y) const {
    const Level& l = levels_[first_level_[texture] + level];
    if (l.unit_shift_x == 0 && l.unit_shift_y == 0) return address(texture, level, x, y);
    const std::uint32_t inside = ((y & ((1u << l.unit_shift_y) - 1)) << l.unit_shift_x) | (x & ((1u << l.unit_shift_x) - 1));
    return (address(texture, level, x, y) << l.decode_shift) + (std::uint64_t{inside} << texel_shift_);
  }
  // log2 of decoded bytes per compressed byte for the texture's format (0 for RGBA8).
  std::uint32_t decode_shift(std::uint32_t texture) const { return levels_[first_level_[texture]].decode_shift; }
  // The format the layout stores the texture in.
  TextureFormat format(std::uint32_t texture) const { return levels_[first_level_[texture]].format; }

  bool contains(std::uint32_t texture, std::uint32_t level, std::uint32_t x, std::uint32_t y) const {
    if (texture >= first_level_.size() - 1) return false;
    if (level >= first_level_[texture + 1] - first_level_[texture]) return false;
    const Level& l = levels_[first_level_[texture] + level];
    return x < l.width && y < l.height;
  }

  const LayoutSpec& spec() const { return spec_; }
  // One past the last byte of the last level.
  std::uint64_t total_bytes() const { return total_bytes_; }

  static std::uint64_t interleave(std::uint32_t x, std::uint32_t y) { return spread(x) | (spread(y) << 1); }

 private:
  static std::uint64_t spread(std::uint32_t v) {
    std::uint64_t s = v;
    s = (s | (s << 16)) & 0x0000FFFF0000FFFFull;
    s = (s | (s << 8)) & 0x00FF00FF00FF00FFull;
    s = (s | (s << 4)) & 0x0F0F0F0F0F0F0F0Full;
    s = (s | (s << 2)) & 0x3333333333333333ull;
    s = (s | (s << 1)) & 0x5555555555555555ull;
    return s;
  }

  struct Level {
    std::uint64_t base = 0;
    std::uint32_t width = 0;  // texels
    std::uint32_t height = 0;
    std::uint32_t units_per_row = 0;     // texels, or compressed blocks, a row
    std::uint32_t blocks_per_row = 0;    // Block layout: tiles of units a row
    std::uint32_t square_bits = 0;       // Morton: log2 of the side of the square tiles
    std::uint32_t unit_shift_x = 0;      // log2 of the format's block width (0: texels)
    std::uint32_t unit_shift_y = 0;      // and height
    std::uint32_t unit_bytes_shift = 2;  // log2 of the bytes of a unit (texel or block)
    std::uint32_t decode_shift = 0;      // log2 of decoded bytes per compressed byte
    TextureFormat format = TextureFormat::Rgba8;
  };

  LayoutSpec spec_;
  std::uint32_t texel_shift_ = 2;
  std::uint32_t block_shift_ = 2;
  std::vector<Level> levels_;
  std::vector<std::uint32_t> first_level_;  // per texture, index into levels_; one extra at the end
  std::uint64_t total_bytes_ = 0;
};

}  // namespace rastrace
