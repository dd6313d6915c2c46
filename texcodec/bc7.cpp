#include "texcodec/bc7.h"

#include <array>

#include "texcodec/bc7_tables.h"

namespace rastrace::texcodec {

namespace {

// Table.M of the specification: one row per mode.
struct ModeInfo {
  int subsets;
  int partition_bits;
  int rotation_bits;
  int index_selection_bits;
  int colour_bits;
  int alpha_bits;
  int endpoint_pbits;  // one P-bit per endpoint
  int shared_pbits;    // one P-bit per subset, shared by its two endpoints
  int index_bits;
  int secondary_index_bits;
};

constexpr std::array<ModeInfo, 8> kModes = {{
    {3, 4, 0, 0, 4, 0, 1, 0, 3, 0},
    {2, 6, 0, 0, 6, 0, 0, 1, 3, 0},
    {3, 6, 0, 0, 5, 0, 0, 0, 2, 0},
    {2, 6, 0, 0, 7, 0, 1, 0, 2, 0},
    {1, 0, 2, 1, 5, 6, 0, 0, 2, 3},
    {1, 0, 2, 0, 7, 8, 0, 0, 2, 2},
    {1, 0, 0, 0, 7, 7, 1, 0, 4, 0},
    {2, 6, 0, 0, 5, 5, 1, 0, 2, 0},
}};

// Fields are packed from the least significant bit of byte 0 upwards.
class BitReader {
 public:
  explicit BitReader(const std::uint8_t* block) : block_(block) {}
  unsigned read(int count) {
    unsigned value = 0;
    for (int i = 0; i < count; ++i, ++position_)
      value |= static_cast<unsigned>((block_[position_ / 8] >> (position_ % 8)) & 1) << i;
    return value;
  }
  void skip(int count) { position_ += count; }

 private:
  const std::uint8_t* block_;
  int position_ = 0;
};

int subset_of(const ModeInfo& mode, unsigned partition, int texel) {
  if (mode.subsets == 2) return (bc7::kTwoSubsetPartitions[partition] >> texel) & 1;
  if (mode.subsets == 3) return static_cast<int>((bc7::kThreeSubsetPartitions[partition] >> (2 * texel)) & 3);
  return 0;
}

bool is_anchor(const ModeInfo& mode, unsigned partition, int texel) {
  if (texel == 0) return true;
  if (mode.subsets == 2) return texel == bc7::kAnchorSecondOfTwo[partition];
  if (mode.subsets == 3)
    return texel == bc7::kAnchorSecondOfThree[partition] || texel == bc7::kAnchorThirdOfThree[partition];
  return false;
}

// A quantized endpoint channel, with its P-bit below it when the mode has one, widened to 8 bits
// by replicating its top bits into the low bits.
unsigned widen(unsigned value, int bits) {
  value <<= 8 - bits;
  return value | (value >> bits);
}

unsigned interpolate(unsigned e0, unsigned e1, int index, int bits) {
  const unsigned w = bits == 2   ? bc7::kWeights2[static_cast<std::size_t>(index)]
                     : bits == 3 ? bc7::kWeights3[static_cast<std::size_t>(index)]
                                 : bc7::kWeights4[static_cast<std::size_t>(index)];
  return ((64 - w) * e0 + w * e1 + 32) >> 6;
}

// endpoints[subset][end][channel], 8-bit values.
using Endpoints = std::array<std::array<std::array<unsigned, 4>, 2>, 3>;

Endpoints read_endpoints(const ModeInfo& mode, BitReader& bits) {
  Endpoints e{};
  const int channels = mode.alpha_bits ? 4 : 3;
  for (int c = 0; c < channels; ++c) {
    const int width = c < 3 ? mode.colour_bits : mode.alpha_bits;
    for (int s = 0; s < mode.subsets; ++s)
      for (int end = 0; end < 2; ++end) e[s][end][c] = bits.read(width);
  }
  unsigned pbits[3][2] = {};
  for (int s = 0; s < mode.subsets; ++s)
    for (int end = 0; end < 2; ++end)
      if (mode.endpoint_pbits) pbits[s][end] = bits.read(1);
  for (int s = 0; s < mode.subsets; ++s)
    if (mode.shared_pbits) pbits[s][0] = pbits[s][1] = bits.read(1);
  const bool has_pbit = mode.endpoint_pbits || mode.shared_pbits;
  for (int s = 0; s < mode.subsets; ++s)
    for (int end = 0; end < 2; ++end)
      for (int c = 0; c < 4; ++c) {
        if (c == 3 && !mode.alpha_bits) {
          e[s][end][c] = 255;
          continue;
        }
        const int width = c < 3 ? mode.colour_bits : mode.alpha_bits;
        e[s][end][c] = has_pbit ? widen((e[s][end][c] << 1) | pbits[s][end], width + 1) : widen(e[s][end][c], width);
      }
  return e;
}

std::array<int, 16> read_indices(const ModeInfo& mode, unsigned partition, int index_bits, BitReader& bits) {
  std::array<int, 16> indices{};
  for (int i = 0; i < 16; ++i)
    indices[static_cast<std::size_t>(i)] =
        static_cast<int>(bits.read(is_anchor(mode, partition, i) ? index_bits - 1 : index_bits));
  return indices;
}

}  // namespace

int bc7_mode(const std::uint8_t* block) {
  int mode = 0;
  while (mode < 8 && !(block[0] & (1u << mode))) ++mode;
  return mode;
}

void decode_bc7_block(const std::uint8_t* block, std::uint8_t* rgba) {
  const int mode_number = bc7_mode(block);
  if (mode_number == 8) {
    for (int i = 0; i < 64; ++i) rgba[i] = 0;
    return;
  }
  const ModeInfo& mode = kModes[static_cast<std::size_t>(mode_number)];
  BitReader bits(block);
  bits.skip(mode_number + 1);
  const unsigned partition = bits.read(mode.partition_bits);
  const unsigned rotation = bits.read(mode.rotation_bits);
  const unsigned selection = bits.read(mode.index_selection_bits);
  const Endpoints e = read_endpoints(mode, bits);
  const std::array<int, 16> primary = read_indices(mode, partition, mode.index_bits, bits);
  std::array<int, 16> secondary{};
  if (mode.secondary_index_bits) secondary = read_indices(mode, 0, mode.secondary_index_bits, bits);

  // Colour from the secondary indices when the selection bit is set; alpha from the secondary
  // indices whenever they exist and the selection bit is clear.
  const bool colour_secondary = selection == 1;
  const bool alpha_secondary = mode.secondary_index_bits && selection == 0;
  const int colour_bits = colour_secondary ? mode.secondary_index_bits : mode.index_bits;
  const int alpha_bits = alpha_secondary ? mode.secondary_index_bits : mode.index_bits;
  for (int i = 0; i < 16; ++i) {
    const auto& ends = e[static_cast<std::size_t>(subset_of(mode, partition, i))];
    const auto t = static_cast<std::size_t>(i);
    const int ci = colour_secondary ? secondary[t] : primary[t];
    const int ai = alpha_secondary ? secondary[t] : primary[t];
    unsigned texel[4];
    for (int c = 0; c < 3; ++c) texel[c] = interpolate(ends[0][c], ends[1][c], ci, colour_bits);
    texel[3] = interpolate(ends[0][3], ends[1][3], ai, alpha_bits);
    if (rotation) {
      const unsigned swapped = texel[rotation - 1];
      texel[rotation - 1] = texel[3];
      texel[3] = swapped;
    }
    for (int c = 0; c < 4; ++c) rgba[4 * i + c] = static_cast<std::uint8_t>(texel[c]);
  }
}

}  // namespace rastrace::texcodec
