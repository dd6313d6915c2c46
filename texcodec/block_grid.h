// Moving texels between a level and its grid of blocks: the partial blocks at the right and
// bottom edges are filled by replicating the edge texels when encoding, and cropped when decoding.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

namespace rastrace::texcodec {

struct BlockGrid {
  int width = 0;  // the level's texels
  int height = 0;
  int block_width = 4;
  int block_height = 4;
  int columns() const { return (width + block_width - 1) / block_width; }
  int rows() const { return (height + block_height - 1) / block_height; }
};

// The level padded to whole blocks: columns()*block_width x rows()*block_height RGBA8 texels.
std::vector<std::uint8_t> pad_to_blocks(const BlockGrid& grid, std::span<const std::uint8_t> rgba);

// The inverse: the padded texels cropped to width x height.
std::vector<std::uint8_t> crop_from_blocks(const BlockGrid& grid, std::span<const std::uint8_t> padded);

// Decodes every block_bytes-long block with `decode_block` (16 RGBA texels of a 4x4 block) into
// width x height texels, dropping the padding.
template <typename DecodeBlock>
std::vector<std::uint8_t> decode_4x4_blocks(const BlockGrid& grid, std::span<const std::uint8_t> blocks,
                                            std::size_t block_bytes, DecodeBlock decode_block) {
  std::vector<std::uint8_t> out(static_cast<std::size_t>(grid.width) * static_cast<std::size_t>(grid.height) * 4);
  std::uint8_t texels[64];
  std::size_t at = 0;
  for (int by = 0; by < grid.rows(); ++by)
    for (int bx = 0; bx < grid.columns(); ++bx, at += block_bytes) {
      decode_block(blocks.data() + at, texels);
      for (int y = 0; y < 4 && by * 4 + y < grid.height; ++y)
        for (int x = 0; x < 4 && bx * 4 + x < grid.width; ++x) {
          const std::size_t to = (static_cast<std::size_t>(by * 4 + y) * static_cast<std::size_t>(grid.width) +
                                  static_cast<std::size_t>(bx * 4 + x)) *
                                 4;
          for (int c = 0; c < 4; ++c) out[to + static_cast<std::size_t>(c)] = texels[(y * 4 + x) * 4 + c];
        }
    }
  return out;
}

}  // namespace rastrace::texcodec
