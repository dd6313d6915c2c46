// Block-compressed texture levels: encoding RGBA8 texels into a TextureFormat's blocks and
// decoding them back, one mip level at a time, as a GPU stores each level of a texture.
//
// Decoders: BC1, BC3, BC4, BC5 and BC7 are our own (bc1.h, bc4.h, bc7.h), bit-exact with the
// encoders' own decoders (libsquish for BC1-5; Mesa's for BC7). ASTC is decoded by the ARM
// reference codec, astcenc, which also encodes it: writing our own ASTC decoder is out of scope.
// Encoders: libsquish (BC1, BC3, BC4, BC5), Mesa's BPTC compressor through OSMesa (BC7; no other
// Debian library encodes BC7), astcenc (ASTC 4x4 and 8x8).
//
// A level whose sides are not multiples of the block size is padded by replicating its last
// column and row into the partial blocks (as encoders and GPU drivers do), and decoding crops
// the padding away. BC4 decodes to (r, 0, 0, 255) and BC5 to (r, g, 0, 255), as GL's RGTC1 and
// RGTC2 return them; their encoders read the red (and green) channel.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/texture_format.h"

namespace rastrace::texcodec {

// width x height RGBA8 texels, row-major -> level_bytes(format, width, height) bytes of blocks.
// InputError for Rgba8 (nothing to encode), a size below 1x1 or a texel array of the wrong size;
// std::runtime_error if the BC7 or ASTC library fails.
std::vector<std::uint8_t> encode_level(TextureFormat format, int width, int height, std::span<const std::uint8_t> rgba);

// The inverse: blocks -> width x height RGBA8 texels. InputError if `blocks` is not exactly
// level_bytes(format, width, height) long.
std::vector<std::uint8_t> decode_level(TextureFormat format, int width, int height,
                                       std::span<const std::uint8_t> blocks);

}  // namespace rastrace::texcodec
