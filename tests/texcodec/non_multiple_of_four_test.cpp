// Levels whose sides are not multiples of the block size: encoding pads by replicating the edge
// texels, decoding crops. A flat colour must survive exactly at 1x1, 2x2 and 5x3 in every format
// whose endpoints represent it exactly, and each texel of an image must decode from its own block.
#include <gtest/gtest.h>

#include "core/error.h"
#include "texcodec/codec.h"

namespace rastrace {
namespace {

std::vector<std::uint8_t> flat(int width, int height, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  std::vector<std::uint8_t> rgba;
  for (int i = 0; i < width * height; ++i) rgba.insert(rgba.end(), {r, g, b, 255});
  return rgba;
}

class SmallLevels : public ::testing::TestWithParam<TextureFormat> {};

TEST_P(SmallLevels, OneByOneTwoByTwoAndFiveByThreeCropToTheirSize) {
  const TextureFormat format = GetParam();
  for (auto [w, h] : {std::pair{1, 1}, std::pair{2, 2}, std::pair{5, 3}}) {
    // Black and white are exact in every format (endpoints 0 and 255); BC4/BC5 keep R (and G).
    const std::vector<std::uint8_t> rgba = flat(w, h, 255, 255, 255);
    const std::vector<std::uint8_t> blocks = texcodec::encode_level(format, w, h, rgba);
    ASSERT_EQ(blocks.size(), level_bytes(format, std::uint32_t(w), std::uint32_t(h)));
    const std::vector<std::uint8_t> decoded = texcodec::decode_level(format, w, h, blocks);
    ASSERT_EQ(decoded.size(), rgba.size()) << w << "x" << h;
    for (std::size_t i = 0; i < decoded.size(); i += 4) {
      EXPECT_EQ(decoded[i], 255) << to_string(format) << " " << w << "x" << h;
      if (format != TextureFormat::Bc4) {
        EXPECT_EQ(decoded[i + 1], 255);
      }
      EXPECT_EQ(decoded[i + 3], 255);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(EveryFormat, SmallLevels,
                         ::testing::Values(TextureFormat::Bc1, TextureFormat::Bc3, TextureFormat::Bc4,
                                           TextureFormat::Bc5, TextureFormat::Bc7, TextureFormat::Astc4x4,
                                           TextureFormat::Astc8x8),
                         [](const auto& info) { return std::string(to_string(info.param)); });

// 5x3: the fifth column sits alone in the second block column; replication fills that block with
// it, so it decodes to its own colour rather than a blend with padding.
TEST(SmallLevels, TheLastColumnOfFiveByThreeKeepsItsColour) {
  std::vector<std::uint8_t> rgba = flat(5, 3, 0, 0, 0);
  for (int y = 0; y < 3; ++y) rgba[static_cast<std::size_t>((y * 5 + 4) * 4)] = 255;
  const std::vector<std::uint8_t> decoded =
      texcodec::decode_level(TextureFormat::Bc1, 5, 3, texcodec::encode_level(TextureFormat::Bc1, 5, 3, rgba));
  EXPECT_EQ(decoded, rgba);
}

TEST(SmallLevels, WrongSizesAndRgba8AreInputErrors) {
  const std::vector<std::uint8_t> four(4, 0);
  EXPECT_THROW(texcodec::encode_level(TextureFormat::Bc1, 0, 1, four), InputError);
  EXPECT_THROW(texcodec::encode_level(TextureFormat::Bc1, 2, 2, four), InputError);
  EXPECT_THROW(texcodec::encode_level(TextureFormat::Rgba8, 1, 1, four), InputError);
  EXPECT_THROW(texcodec::decode_level(TextureFormat::Bc7, 1, 1, four), InputError);
}

}  // namespace
}  // namespace rastrace
