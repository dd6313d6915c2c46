#include <gtest/gtest.h>

#include <string>

#include "core/error.h"
#include "core/texture_format.h"

namespace rastrace {
namespace {

TEST(TextureFormat, BlockShapesAreTheFormatsOwn) {
  EXPECT_EQ(block_shape(TextureFormat::Rgba8).bytes, 4u);
  EXPECT_EQ(block_shape(TextureFormat::Rgba8).width, 1u);
  EXPECT_EQ(block_shape(TextureFormat::Bc1).bytes, 8u);
  EXPECT_EQ(block_shape(TextureFormat::Bc4).bytes, 8u);
  for (TextureFormat f : {TextureFormat::Bc3, TextureFormat::Bc5, TextureFormat::Bc7, TextureFormat::Astc4x4}) {
    EXPECT_EQ(block_shape(f).bytes, 16u) << to_string(f);
    EXPECT_EQ(block_shape(f).width, 4u) << to_string(f);
    EXPECT_EQ(block_shape(f).height, 4u) << to_string(f);
  }
  EXPECT_EQ(block_shape(TextureFormat::Astc8x8).width, 8u);
  EXPECT_EQ(block_shape(TextureFormat::Astc8x8).bytes, 16u);
}

TEST(TextureFormat, LevelBytesPadTheLastBlocks) {
  EXPECT_EQ(level_bytes(TextureFormat::Rgba8, 1024, 1024), 4u << 20);
  EXPECT_EQ(level_bytes(TextureFormat::Bc1, 1024, 1024), 512u << 10);  // 4 bits per texel
  EXPECT_EQ(level_bytes(TextureFormat::Bc7, 1024, 1024), 1u << 20);    // 8 bits per texel
  EXPECT_EQ(level_bytes(TextureFormat::Bc1, 2, 2), 8u);
  EXPECT_EQ(level_bytes(TextureFormat::Bc1, 5, 1), 16u);
  EXPECT_EQ(level_bytes(TextureFormat::Astc8x8, 9, 8), 32u);
}

TEST(TextureFormat, NamesRoundTripAndUnknownNamesListTheAccepted) {
  for (TextureFormat f : {TextureFormat::Rgba8, TextureFormat::Bc1, TextureFormat::Bc3, TextureFormat::Bc4,
                          TextureFormat::Bc5, TextureFormat::Bc7, TextureFormat::Astc4x4, TextureFormat::Astc8x8})
    EXPECT_EQ(parse_texture_format(to_string(f)), f);
  try {
    parse_texture_format("dxt9", "--texture-format");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()),
              "unknown --texture-format 'dxt9': expected rgba8, bc1, bc3, bc4, bc5, bc7, astc4x4 or astc8x8");
  }
}

}  // namespace
}  // namespace rastrace
