// BC7 (BPTC unorm) block decoding, written from the ARB_texture_compression_bptc specification
// (Khronos, 2010): all eight modes with their partitions, anchor indices, endpoint and shared
// P-bits, rotation and index selection.
#pragma once

#include <cstdint>

namespace rastrace::texcodec {

// 16 bytes -> 16 RGBA texels, row-major. A block whose first byte is 0 uses no mode (reserved):
// every texel is transparent black, as the DirectX specification and Mesa decode it.
void decode_bc7_block(const std::uint8_t* block, std::uint8_t* rgba);

// The mode (0-7) of a block, or 8 for the reserved encoding.
int bc7_mode(const std::uint8_t* block);

}  // namespace rastrace::texcodec
