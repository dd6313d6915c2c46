// Our BC7 decoder against Mesa's (the decoder of the BC7 encoder we use), bit for bit: random
// blocks forced into each of the eight modes (so partitions, anchors, P-bits, rotations and index
// selection all vary), and real images encoded by Mesa.
#include <array>
#include <cstdio>

#include <gtest/gtest.h>

#include "codec_test_support.h"
#include "texcodec/bc7.h"
#include "texcodec/codec.h"

namespace rastrace {
namespace {

constexpr int kSide = 256;  // 4096 blocks a mode

void expect_matches_mesa(int width, int height, const std::vector<std::uint8_t>& blocks, const std::string& what) {
  const std::vector<std::uint8_t> ours = texcodec::decode_level(TextureFormat::Bc7, width, height, blocks);
  const std::vector<std::uint8_t> mesa = testing::mesa_decode(TextureFormat::Bc7, width, height, blocks);
  ASSERT_EQ(ours.size(), mesa.size());
  std::size_t mismatches = 0, first = ours.size();
  for (std::size_t i = 0; i < ours.size(); ++i)
    if (ours[i] != mesa[i]) {
      ++mismatches;
      first = std::min(first, i);
    }
  EXPECT_EQ(mismatches, 0u) << what << ": first at byte " << first << " (block " << (first / 4 % width) / 4 << ", "
                            << first / 4 / width / 4 << ")";
}

class Bc7Modes : public ::testing::TestWithParam<int> {};

TEST_P(Bc7Modes, RandomBlocksOfTheModeDecodeBitExactlyAsMesa) {
  const int mode = GetParam();
  std::vector<std::uint8_t> blocks =
      testing::random_bytes(level_bytes(TextureFormat::Bc7, kSide, kSide), 100u + unsigned(mode));
  // The mode is the number of zero bits below the first one bit of byte 0.
  const auto mask = static_cast<std::uint8_t>((2u << mode) - 1u);
  for (std::size_t at = 0; at < blocks.size(); at += 16)
    blocks[at] = static_cast<std::uint8_t>((blocks[at] & ~mask) | (1u << mode));
  ASSERT_EQ(texcodec::bc7_mode(blocks.data()), mode);
  expect_matches_mesa(kSide, kSide, blocks, "mode " + std::to_string(mode));
}

INSTANTIATE_TEST_SUITE_P(AllEight, Bc7Modes, ::testing::Range(0, 8),
                         [](const auto& info) { return "Mode" + std::to_string(info.param); });

TEST(Bc7, ReservedModeDecodesToTransparentBlackAsMesa) {
  std::vector<std::uint8_t> blocks = testing::random_bytes(16 * 4, 5);
  for (std::size_t at = 0; at < blocks.size(); at += 16) blocks[at] = 0;
  expect_matches_mesa(8, 8, blocks, "reserved");
  for (std::uint8_t v : texcodec::decode_level(TextureFormat::Bc7, 8, 8, blocks)) ASSERT_EQ(v, 0);
}

TEST(Bc7, MesaEncodedRealImagesDecodeBitExactlyAsMesaAndReportTheModes) {
  std::array<std::size_t, 9> modes{};
  for (const Image& image : testing::sample_images()) {
    const std::vector<std::uint8_t> blocks =
        texcodec::encode_level(TextureFormat::Bc7, image.width, image.height, image.rgba);
    for (std::size_t at = 0; at < blocks.size(); at += 16)
      ++modes[static_cast<std::size_t>(texcodec::bc7_mode(&blocks[at]))];
    expect_matches_mesa(image.width, image.height, blocks,
                        std::to_string(image.width) + "x" + std::to_string(image.height));
    const double psnr =
        testing::psnr_rgba(image.rgba, texcodec::decode_level(TextureFormat::Bc7, image.width, image.height, blocks));
    std::printf("BC7 (Mesa) %dx%d: PSNR %.2f dB\n", image.width, image.height, psnr);
  }
  std::printf("BC7 modes Mesa's encoder emitted:");
  for (std::size_t m = 0; m < modes.size(); ++m)
    if (modes[m]) std::printf(" mode %zu: %zu blocks", m, modes[m]);
  std::printf("\n");
}

}  // namespace
}  // namespace rastrace
