#include <gtest/gtest.h>

#include "cache_sim/texture_layout.h"
#include "core/error.h"
#include "core/units.h"

namespace rastrace {
namespace {

TEST(Units, ByteSizesWithBinaryPrefixes) {
  EXPECT_EQ(parse_byte_size("64B"), 64u);
  EXPECT_EQ(parse_byte_size("16KiB"), 16384u);
  EXPECT_EQ(parse_byte_size("1MiB"), 1048576u);
  EXPECT_EQ(parse_byte_size("4096"), 4096u);
  EXPECT_EQ(format_byte_size(16384), "16KiB");
  EXPECT_EQ(format_byte_size(1536), "1536B");
  for (const char* bad : {"", "16KB", "KiB", "0B", "-4", "1.5KiB", "16 KiB"})
    EXPECT_THROW(parse_byte_size(bad), InputError) << bad;
}

TEST(Units, RangesArePowersOfTwoAndListsMayMixThem) {
  EXPECT_EQ(parse_byte_size_list("1KiB..8KiB"), (std::vector<std::uint64_t>{1024, 2048, 4096, 8192}));
  EXPECT_EQ(parse_byte_size_list("64B,1KiB..2KiB,64B"), (std::vector<std::uint64_t>{64, 1024, 2048}));
  EXPECT_EQ(parse_count_list("1,2,4..16"), (std::vector<std::uint64_t>{1, 2, 4, 8, 16}));
  EXPECT_THROW(parse_byte_size_list("3KiB..64KiB"), InputError);
  EXPECT_THROW(parse_byte_size_list("64KiB..1KiB"), InputError);
  EXPECT_THROW(parse_byte_size_list("1KiB,,2KiB"), InputError);
  try {
    parse_byte_size_list("1KiB,banana", "--size");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_STREQ(e.what(), "--size: 'banana': expected a byte size such as 64B, 16KiB, 1MiB, 2GiB or 4096");
  }
}

TEST(TextureLayout, LinearIsRowMajorWithAlignedLevels) {
  const TextureLayout layout(parse_layout("linear"), {mip_chain_sizes(8, 4), {{3, 3}}});
  EXPECT_EQ(layout.address(0, 0, 0, 0), 0u);
  EXPECT_EQ(layout.address(0, 0, 5, 2), (2u * 8 + 5) * 4);
  EXPECT_EQ(layout.address(0, 1, 1, 1), 4096u + (1 * 4 + 1) * 4);      // level 1 is 4x2 on the next page
  EXPECT_EQ(layout.address(1, 0, 2, 2), 4u * 4096 + (2 * 3 + 2) * 4);  // levels 8x4 4x2 2x1 1x1, then texture 1
  EXPECT_TRUE(layout.contains(0, 3, 0, 0));
  EXPECT_FALSE(layout.contains(0, 4, 0, 0));
  EXPECT_FALSE(layout.contains(0, 0, 8, 0));
  EXPECT_FALSE(layout.contains(2, 0, 0, 0));
}

TEST(TextureLayout, BlocksAreStoredBlockAfterBlock) {
  LayoutSpec spec = parse_layout("block4");
  spec.texel_bytes = 1;
  const TextureLayout layout(spec, {{{10, 8}}});  // 3 blocks per row (the last padded)
  EXPECT_EQ(layout.address(0, 0, 0, 0), 0u);
  EXPECT_EQ(layout.address(0, 0, 3, 3), 15u);
  EXPECT_EQ(layout.address(0, 0, 4, 0), 16u);
  EXPECT_EQ(layout.address(0, 0, 9, 1), 2u * 16 + 1 * 4 + 1);
  EXPECT_EQ(layout.address(0, 0, 0, 4), 3u * 16);
  EXPECT_EQ(layout.address(0, 0, 6, 5), 4u * 16 + 1 * 4 + 2);
  EXPECT_EQ(layout.total_bytes(), 6u * 16);
  for (const char* name : {"block2", "block8", "block16"}) EXPECT_EQ(layout_name(parse_layout(name)), name);
  EXPECT_THROW(parse_layout("block3"), InputError);
}

TEST(TextureLayout, MortonInterleavesXInTheEvenBits) {
  LayoutSpec spec = parse_layout("morton");
  spec.texel_bytes = 1;
  const TextureLayout square(spec, {{{8, 8}}});
  EXPECT_EQ(square.address(0, 0, 1, 0), 1u);
  EXPECT_EQ(square.address(0, 0, 0, 1), 2u);
  EXPECT_EQ(square.address(0, 0, 3, 5), 0b100111u);  // x=011, y=101 -> y2x2 y1x1 y0x0 = 10 01 11
  const TextureLayout wide(spec, {{{8, 2}}});        // two 2x2... four 2x2 Morton tiles side by side
  EXPECT_EQ(wide.address(0, 0, 2, 0), 4u);
  EXPECT_EQ(wide.address(0, 0, 7, 1), 15u);
  const TextureLayout npot(spec, {{{5, 3}}});  // padded to 8x4
  EXPECT_EQ(npot.total_bytes(), 32u);
}

}  // namespace
}  // namespace rastrace
