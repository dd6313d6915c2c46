// One BC4 (RGTC1, unsigned) channel block: two 8-bit endpoints and sixteen 3-bit indices, the
// alpha half of BC3 and each half of BC5. Decoded as libsquish 1.15's DXT5 alpha decoder does:
// interpolants with truncating division, ((7 - i) * a0 + i * a1) / 7 when a0 > a1, else
// ((5 - i) * a0 + i * a1) / 5 with index 6 = 0 and 7 = 255. (libsquish encodes kBc4/kBc5 but its
// DecompressImage decodes them as colour blocks, so its alpha decoder is the reference.)
#pragma once

#include <cstdint>

namespace rastrace::texcodec {

// 8 bytes -> 16 values written to out[i * stride], i row-major in the 4x4 block.
void decode_bc4_block(const std::uint8_t* block, std::uint8_t* out, int stride);

}  // namespace rastrace::texcodec
