// Our BC1/BC3/BC4/BC5 decoders against libsquish's decoder, bit for bit, on random blocks and on
// real images encoded by libsquish. libsquish 1.15 decodes kBc4/kBc5 as colour blocks (its
// DecompressImage only implements DXT1/3/5), so BC4 and BC5 are checked against its DXT5 alpha
// decoder, which decodes the same 8-byte channel block.
#include <squish.h>

#include <gtest/gtest.h>

#include "codec_test_support.h"
#include "texcodec/codec.h"

namespace rastrace {
namespace {

constexpr int kSide = 256;  // 64 x 64 = 4096 blocks a level

std::vector<std::uint8_t> squish_decode(int flags, int width, int height, const std::vector<std::uint8_t>& blocks) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  squish::DecompressImage(rgba.data(), width, height, blocks.data(), flags);
  return rgba;
}

// A DXT5 level whose alpha blocks are the given 8-byte channel blocks (colour blocks zero).
std::vector<std::uint8_t> as_dxt5_alpha(const std::vector<std::uint8_t>& channel_blocks, std::size_t stride,
                                        std::size_t offset) {
  std::vector<std::uint8_t> dxt5;
  for (std::size_t at = offset; at < channel_blocks.size(); at += stride) {
    dxt5.insert(dxt5.end(), channel_blocks.begin() + static_cast<std::ptrdiff_t>(at),
                channel_blocks.begin() + static_cast<std::ptrdiff_t>(at + 8));
    dxt5.insert(dxt5.end(), 8, 0);
  }
  return dxt5;
}

// Channel `ours_channel` of our decoding equals channel 3 (alpha) of squish's DXT5 decoding of the
// channel blocks at `offset` in every `stride` bytes.
void expect_channel_matches_squish_alpha(const std::vector<std::uint8_t>& blocks, TextureFormat format, int width,
                                         int height, std::size_t stride, std::size_t offset, int ours_channel) {
  const std::vector<std::uint8_t> ours = texcodec::decode_level(format, width, height, blocks);
  const std::vector<std::uint8_t> theirs =
      squish_decode(squish::kDxt5, width, height, as_dxt5_alpha(blocks, stride, offset));
  std::size_t mismatches = 0;
  for (std::size_t i = 0; i < ours.size() / 4; ++i)
    mismatches += ours[4 * i + static_cast<std::size_t>(ours_channel)] != theirs[4 * i + 3];
  EXPECT_EQ(mismatches, 0u) << to_string(format) << " channel " << ours_channel;
}

void expect_bc4_bc5_match(TextureFormat format, int width, int height, const std::vector<std::uint8_t>& blocks) {
  if (format == TextureFormat::Bc4) {
    expect_channel_matches_squish_alpha(blocks, format, width, height, 8, 0, 0);
  } else {
    expect_channel_matches_squish_alpha(blocks, format, width, height, 16, 0, 0);
    expect_channel_matches_squish_alpha(blocks, format, width, height, 16, 8, 1);
  }
  const std::vector<std::uint8_t> ours = texcodec::decode_level(format, width, height, blocks);
  for (std::size_t i = 0; i < ours.size(); i += 4) {
    if (format == TextureFormat::Bc4) {
      ASSERT_EQ(ours[i + 1], 0);
    }
    ASSERT_EQ(ours[i + 2], 0);
    ASSERT_EQ(ours[i + 3], 255);
  }
}

void expect_colour_match(TextureFormat format, int width, int height, const std::vector<std::uint8_t>& blocks) {
  const int flags = format == TextureFormat::Bc1 ? squish::kDxt1 : squish::kDxt5;
  EXPECT_EQ(texcodec::decode_level(format, width, height, blocks), squish_decode(flags, width, height, blocks))
      << to_string(format);
}

void expect_match(TextureFormat format, int width, int height, const std::vector<std::uint8_t>& blocks) {
  if (format == TextureFormat::Bc4 || format == TextureFormat::Bc5)
    expect_bc4_bc5_match(format, width, height, blocks);
  else
    expect_colour_match(format, width, height, blocks);
}

class SquishFormats : public ::testing::TestWithParam<TextureFormat> {};

TEST_P(SquishFormats, RandomBlocksDecodeBitExactlyAsLibsquish) {
  const TextureFormat format = GetParam();
  const std::vector<std::uint8_t> blocks = testing::random_bytes(level_bytes(format, kSide, kSide), 11);
  expect_match(format, kSide, kSide, blocks);
}

TEST_P(SquishFormats, EncodedRealImagesDecodeBitExactlyAsLibsquish) {
  const TextureFormat format = GetParam();
  for (const Image& image : testing::sample_images())
    expect_match(format, image.width, image.height,
                 texcodec::encode_level(format, image.width, image.height, image.rgba));
}

INSTANTIATE_TEST_SUITE_P(Bc1To5, SquishFormats,
                         ::testing::Values(TextureFormat::Bc1, TextureFormat::Bc3, TextureFormat::Bc4,
                                           TextureFormat::Bc5),
                         [](const auto& info) { return std::string(to_string(info.param)); });

// Random endpoints hit the three-colour mode (c0 <= c1) in about half the blocks; make sure the
// test above covers it, with transparent black at index 3.
TEST(Bc1, ThreeColourModeGivesTransparentBlackAtIndexThree) {
  const std::uint8_t block[8] = {0x00, 0x00, 0xff, 0xff, 0xff, 0xff, 0xff, 0xff};  // c0 < c1, all index 3
  const std::vector<std::uint8_t> rgba = texcodec::decode_level(TextureFormat::Bc1, 4, 4, block);
  for (std::uint8_t v : rgba) EXPECT_EQ(v, 0);
}

}  // namespace
}  // namespace rastrace
