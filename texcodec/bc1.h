// BC1 (DXT1) colour blocks, decoded bit-exactly as libsquish 1.15 decodes them (S. Brown, "squish"
// DXT compression library, 2006-2019), since squish is the encoder we use. Endpoints are RGB565
// widened to 8 bits by bit replication; the interpolated colours are computed on those 8-bit
// values with truncating division: (2*c0 + c1) / 3 and (c0 + 2*c1) / 3, or (c0 + c1) / 2 in the
// three-colour mode. Other decoders round (the DirectX specification allows either), so a
// decoder matched to a different encoder would differ by one in some channels.
#pragma once

#include <cstdint>

namespace rastrace::texcodec {

// 8 bytes -> 16 RGBA texels, row-major. When `allow_three_colour` (BC1 proper) and c0 <= c1 the
// block is in the three-colour mode: index 2 is the midpoint and index 3 transparent black
// (0, 0, 0, 0), as GL's COMPRESSED_RGBA_S3TC_DXT1_EXT returns. BC3's colour half always uses
// four colours.
void decode_bc1_block(const std::uint8_t* block, std::uint8_t* rgba, bool allow_three_colour = true);

}  // namespace rastrace::texcodec
