// The fixed tables of BC7 (BPTC unorm), from the ARB_texture_compression_bptc specification
// (Khronos, 2010; the same tables as the Khronos Data Format Specification 1.3, section
// "BPTC compressed texture image formats").
#pragma once

#include <array>
#include <cstdint>

namespace rastrace::texcodec::bc7 {

// Table.P2: bit i of entry p is the subset (0 or 1) of texel i (row-major) in partition p.
extern const std::array<std::uint16_t, 64> kTwoSubsetPartitions;
// Table.P3: bits 2i+1..2i of entry p are the subset (0, 1 or 2) of texel i in partition p.
extern const std::array<std::uint32_t, 64> kThreeSubsetPartitions;
// Table.A2, Table.A3a, Table.A3b: the anchor texel of subset 1 (two subsets), and of subsets 1
// and 2 (three subsets); subset 0's anchor is always texel 0.
extern const std::array<std::uint8_t, 64> kAnchorSecondOfTwo;
extern const std::array<std::uint8_t, 64> kAnchorSecondOfThree;
extern const std::array<std::uint8_t, 64> kAnchorThirdOfThree;
// Interpolation weights out of 64 for 2-, 3- and 4-bit indices.
extern const std::array<std::uint8_t, 4> kWeights2;
extern const std::array<std::uint8_t, 8> kWeights3;
extern const std::array<std::uint8_t, 16> kWeights4;

}  // namespace rastrace::texcodec::bc7
