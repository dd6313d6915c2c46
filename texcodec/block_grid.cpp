#include "texcodec/block_grid.h"

#include <algorithm>
#include <cstring>

namespace rastrace::texcodec {

std::vector<std::uint8_t> pad_to_blocks(const BlockGrid& grid, std::span<const std::uint8_t> rgba) {
  const int padded_width = grid.columns() * grid.block_width, padded_height = grid.rows() * grid.block_height;
  std::vector<std::uint8_t> padded(static_cast<std::size_t>(padded_width) * static_cast<std::size_t>(padded_height) *
                                   4);
  for (int y = 0; y < padded_height; ++y) {
    const int sy = std::min(y, grid.height - 1);
    for (int x = 0; x < padded_width; ++x) {
      const int sx = std::min(x, grid.width - 1);
      std::memcpy(
          &padded[(static_cast<std::size_t>(y) * static_cast<std::size_t>(padded_width) + static_cast<std::size_t>(x)) *
                  4],
          &rgba[(static_cast<std::size_t>(sy) * static_cast<std::size_t>(grid.width) + static_cast<std::size_t>(sx)) *
                4],
          4);
    }
  }
  return padded;
}

std::vector<std::uint8_t> crop_from_blocks(const BlockGrid& grid, std::span<const std::uint8_t> padded) {
  const auto padded_row = static_cast<std::size_t>(grid.columns() * grid.block_width) * 4;
  const auto row = static_cast<std::size_t>(grid.width) * 4;
  std::vector<std::uint8_t> out(row * static_cast<std::size_t>(grid.height));
  for (std::size_t y = 0; y < static_cast<std::size_t>(grid.height); ++y)
    std::memcpy(&out[y * row], &padded[y * padded_row], row);
  return out;
}

}  // namespace rastrace::texcodec
