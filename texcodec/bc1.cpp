#include "texcodec/bc1.h"

namespace rastrace::texcodec {

namespace {

struct Endpoint {
  unsigned value = 0;  // the packed RGB565 word, compared to choose the mode
  unsigned rgb[3] = {0, 0, 0};
};

Endpoint unpack_565(const std::uint8_t* bytes) {
  Endpoint e;
  e.value = static_cast<unsigned>(bytes[0]) | (static_cast<unsigned>(bytes[1]) << 8);
  const unsigned r = (e.value >> 11) & 31, g = (e.value >> 5) & 63, b = e.value & 31;
  e.rgb[0] = (r << 3) | (r >> 2);
  e.rgb[1] = (g << 2) | (g >> 4);
  e.rgb[2] = (b << 3) | (b >> 2);
  return e;
}

}  // namespace

void decode_bc1_block(const std::uint8_t* block, std::uint8_t* rgba, bool allow_three_colour) {
  const Endpoint c0 = unpack_565(block), c1 = unpack_565(block + 2);
  const bool three_colour = allow_three_colour && c0.value <= c1.value;
  std::uint8_t palette[4][4];
  for (int c = 0; c < 3; ++c) {
    const unsigned a = c0.rgb[c], b = c1.rgb[c];
    palette[0][c] = static_cast<std::uint8_t>(a);
    palette[1][c] = static_cast<std::uint8_t>(b);
    palette[2][c] = static_cast<std::uint8_t>(three_colour ? (a + b) / 2 : (2 * a + b) / 3);
    palette[3][c] = static_cast<std::uint8_t>(three_colour ? 0 : (a + 2 * b) / 3);
  }
  palette[0][3] = palette[1][3] = palette[2][3] = 255;
  palette[3][3] = three_colour ? 0 : 255;
  for (int i = 0; i < 16; ++i) {
    const unsigned index = (block[4 + i / 4] >> (2 * (i % 4))) & 3;
    for (int c = 0; c < 4; ++c) rgba[4 * i + c] = palette[index][c];
  }
}

}  // namespace rastrace::texcodec
