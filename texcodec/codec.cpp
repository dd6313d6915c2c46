#include "texcodec/codec.h"

#include <string>

#include "core/error.h"
#include "texcodec/bc1.h"
#include "texcodec/bc4.h"
#include "texcodec/bc7.h"
#include "texcodec/block_grid.h"
#include "texcodec/encoders.h"

namespace rastrace::texcodec {

namespace {

BlockGrid grid_of(TextureFormat format, int width, int height, const char* what) {
  if (!is_compressed(format)) throw InputError(std::string(what) + ": rgba8 is not a block-compressed format");
  if (width < 1 || height < 1)
    throw InputError(std::string(what) + ": a level of " + std::to_string(width) + "x" + std::to_string(height) +
                     " texels; expected at least 1x1");
  const BlockShape shape = block_shape(format);
  return BlockGrid{width, height, static_cast<int>(shape.width), static_cast<int>(shape.height)};
}

void decode_bc3_block(const std::uint8_t* block, std::uint8_t* rgba) {
  decode_bc1_block(block + 8, rgba, false);
  decode_bc4_block(block, rgba + 3, 4);
}

void decode_bc4_rgba(const std::uint8_t* block, std::uint8_t* rgba) {
  for (int i = 0; i < 16; ++i) rgba[4 * i + 1] = rgba[4 * i + 2] = 0, rgba[4 * i + 3] = 255;
  decode_bc4_block(block, rgba, 4);
}

void decode_bc5_rgba(const std::uint8_t* block, std::uint8_t* rgba) {
  decode_bc4_rgba(block, rgba);
  decode_bc4_block(block + 8, rgba + 1, 4);
}

}  // namespace

std::vector<std::uint8_t> encode_level(TextureFormat format, int width, int height,
                                       std::span<const std::uint8_t> rgba) {
  const BlockGrid grid = grid_of(format, width, height, "encode_level");
  if (rgba.size() != static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4)
    throw InputError("encode_level: " + std::to_string(rgba.size()) + " bytes for a " + std::to_string(width) + "x" +
                     std::to_string(height) + " RGBA8 level");
  const std::vector<std::uint8_t> padded = pad_to_blocks(grid, rgba);
  const int padded_width = grid.columns() * grid.block_width, padded_height = grid.rows() * grid.block_height;
  switch (format) {
    case TextureFormat::Bc7:
      // Mesa's encoder works through a GL texture: llvmpipe's and softpipe's limit is 16384 a side.
      if (padded_width > 16384 || padded_height > 16384)
        throw InputError("encode_level: a " + std::to_string(width) + "x" + std::to_string(height) +
                         " level: the BC7 encoder (Mesa) takes at most 16384 texels a side");
      return mesa_bc7_encode(padded_width, padded_height, padded);
    case TextureFormat::Astc4x4:
      return astc_encode(4, padded_width, padded_height, padded);
    case TextureFormat::Astc8x8:
      return astc_encode(8, padded_width, padded_height, padded);
    default:
      return squish_encode(format, padded_width, padded_height, padded);
  }
}

std::vector<std::uint8_t> decode_level(TextureFormat format, int width, int height,
                                       std::span<const std::uint8_t> blocks) {
  const BlockGrid grid = grid_of(format, width, height, "decode_level");
  const std::uint64_t expected =
      level_bytes(format, static_cast<std::uint32_t>(width), static_cast<std::uint32_t>(height));
  if (blocks.size() != expected)
    throw InputError("decode_level: " + std::to_string(blocks.size()) + " bytes of " + to_string(format) +
                     " blocks for a " + std::to_string(width) + "x" + std::to_string(height) + " level; expected " +
                     std::to_string(expected));
  switch (format) {
    case TextureFormat::Bc1:
      return decode_4x4_blocks(grid, blocks, 8, [](const std::uint8_t* b, std::uint8_t* t) { decode_bc1_block(b, t); });
    case TextureFormat::Bc3:
      return decode_4x4_blocks(grid, blocks, 16, decode_bc3_block);
    case TextureFormat::Bc4:
      return decode_4x4_blocks(grid, blocks, 8, decode_bc4_rgba);
    case TextureFormat::Bc5:
      return decode_4x4_blocks(grid, blocks, 16, decode_bc5_rgba);
    case TextureFormat::Bc7:
      return decode_4x4_blocks(grid, blocks, 16, decode_bc7_block);
    default: {
      const int size = grid.block_width;
      return crop_from_blocks(grid, astc_decode(size, grid.columns() * size, grid.rows() * size, blocks));
    }
  }
}

}  // namespace rastrace::texcodec
