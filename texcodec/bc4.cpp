#include "texcodec/bc4.h"

namespace rastrace::texcodec {

void decode_bc4_block(const std::uint8_t* block, std::uint8_t* out, int stride) {
  const unsigned a0 = block[0], a1 = block[1];
  unsigned palette[8] = {a0, a1, 0, 0, 0, 0, 0, 255};
  if (a0 > a1) {
    for (unsigned i = 1; i < 7; ++i) palette[i + 1] = ((7 - i) * a0 + i * a1) / 7;
  } else {
    for (unsigned i = 1; i < 5; ++i) palette[i + 1] = ((5 - i) * a0 + i * a1) / 5;
  }
  // Sixteen 3-bit indices in the 48 bits after the endpoints, little-endian.
  std::uint64_t bits = 0;
  for (int i = 0; i < 6; ++i) bits |= static_cast<std::uint64_t>(block[2 + i]) << (8 * i);
  for (int i = 0; i < 16; ++i) out[i * stride] = static_cast<std::uint8_t>(palette[(bits >> (3 * i)) & 7]);
}

}  // namespace rastrace::texcodec
