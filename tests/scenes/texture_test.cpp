// Procedural textures, image loading and GL-style mip chains.
#include <string>

#include <gtest/gtest.h>

#include "core/error.h"
#include "scenes/texture_io.h"
#include "tests/support/temp_dir.h"
#include "tests/support/test_data.h"

namespace rastrace {
namespace {

std::array<int, 4> rgba(const Image& image, int x, int y) {
  const std::uint8_t* t = image.texel(x, y);
  return {t[0], t[1], t[2], t[3]};
}

TEST(ProceduralTexture, CheckerAlternatesWhiteAndDarkSquares) {
  const Image checker = make_checker(64, 8);
  EXPECT_EQ(checker.width, 64);
  EXPECT_EQ(rgba(checker, 0, 0), (std::array<int, 4>{255, 255, 255, 255}));
  EXPECT_EQ(rgba(checker, 7, 7), (std::array<int, 4>{255, 255, 255, 255}));
  EXPECT_EQ(rgba(checker, 8, 0), (std::array<int, 4>{64, 64, 64, 255}));
  EXPECT_EQ(rgba(checker, 8, 8), (std::array<int, 4>{255, 255, 255, 255}));
  EXPECT_THROW(make_checker(8, 9), InputError);
}

TEST(ProceduralTexture, FourColourHasFourDistinctQuadrants) {
  const Image four = make_four_colour(256);
  const auto tl = rgba(four, 10, 10), tr = rgba(four, 200, 10), bl = rgba(four, 10, 200), br = rgba(four, 200, 200);
  EXPECT_NE(tl, tr);
  EXPECT_NE(tl, bl);
  EXPECT_NE(tl, br);
  EXPECT_NE(tr, bl);
  EXPECT_NE(tr, br);
  EXPECT_NE(bl, br);
  EXPECT_EQ(rgba(four, 127, 127), tl);
  EXPECT_EQ(rgba(four, 128, 127), tr);
  EXPECT_EQ(rgba(four, 127, 128), bl);
  EXPECT_EQ(rgba(four, 128, 128), br);
}

TEST(ProceduralTexture, GradientEncodesUInRedAndVInGreen) {
  const Image g = make_uv_gradient(256);
  EXPECT_EQ(rgba(g, 0, 0), (std::array<int, 4>{0, 0, 0, 255}));
  EXPECT_EQ(rgba(g, 255, 17), (std::array<int, 4>{255, 17, 0, 255}));
}

TEST(MipChain, PowerOfTwoGoesDownTo1x1WithTwoByTwoAverages) {
  const auto levels = build_mip_chain(make_checker(256, 8));
  ASSERT_EQ(levels.size(), 9u);
  EXPECT_EQ(levels[8].width, 1);
  EXPECT_EQ(levels[8].height, 1);
  // 32x32 squares: level 5 (8x8) still resolves them; level 6 (4x4) averages white and dark.
  EXPECT_EQ(rgba(levels[5], 0, 0)[0], 255);
  EXPECT_EQ(rgba(levels[5], 1, 0)[0], 64);
  EXPECT_EQ(rgba(levels[8], 0, 0)[0], 160);  // (255 + 64) / 2 = 159.5, rounded to nearest
}

TEST(MipChain, NonPowerOfTwoHalvesWithFloorAndAreaWeightsOddTexels) {
  Image base;
  base.width = 5;
  base.height = 3;
  base.rgba.assign(5 * 3 * 4, 0);
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 5; ++x)
      base.rgba[static_cast<std::size_t>((y * 5 + x) * 4)] = static_cast<std::uint8_t>(x * 50);
  const auto levels = build_mip_chain(base);
  ASSERT_EQ(levels.size(), 3u);  // 5x3 -> 2x1 -> 1x1
  EXPECT_EQ(levels[1].width, 2);
  EXPECT_EQ(levels[1].height, 1);
  // Columns 0 50 100 150 200; texel 0 covers [0, 2.5): (0 + 50 + 0.5 * 100) / 2.5 = 40.
  EXPECT_EQ(rgba(levels[1], 0, 0)[0], 40);
  // Texel 1 covers [2.5, 5): (0.5 * 100 + 150 + 200) / 2.5 = 160.
  EXPECT_EQ(rgba(levels[1], 1, 0)[0], 160);
  EXPECT_EQ(rgba(levels[2], 0, 0)[0], 100);
  EXPECT_EQ(rgba(levels[1], 0, 0)[3], 0);
}

TEST(MipChain, OneByNStripsKeepWidthOne) {
  Image strip;
  strip.width = 1;
  strip.height = 6;
  strip.rgba.assign(24, 100);
  const auto levels = build_mip_chain(strip);
  ASSERT_EQ(levels.size(), 3u);  // 1x6 -> 1x3 -> 1x1
  EXPECT_EQ(levels[1].height, 3);
  EXPECT_EQ(rgba(levels[2], 0, 0)[0], 100);
}

TEST(ImageLoading, JpegPngAndTgaBecomeRgbaWithRowZeroAtTheTop) {
  const Image jpg = load_image(testing::data_file("assimp/OBJ/SpiderTex.jpg"));
  EXPECT_GT(jpg.width, 0);
  EXPECT_EQ(jpg.rgba.size(), static_cast<std::size_t>(jpg.width * jpg.height * 4));
  EXPECT_EQ(rgba(jpg, 0, 0)[3], 255);
  const Image png = load_image(testing::data_file("assimp/glTF/CesiumMilkTruck/CesiumMilkTruck.png"));
  EXPECT_GT(png.width, 0);
  const Image tga = load_image(testing::data_file("assimp/Collada/duckCM.tga"));
  EXPECT_EQ(tga.width, 512);
  EXPECT_EQ(tga.height, 512);
}

TEST(ImageLoading, WrittenPngReadsBackTopRowFirst) {
  testing::TempDir dir;
  // A 2x2 PGM-free check: write a tiny binary PPM (OpenImageIO reads it) with a red top row.
  const std::string ppm =
      std::string("P6\n2 2\n255\n") + std::string("\xff\x00\x00\xff\x00\x00\x00\x00\xff\x00\x00\xff", 12);
  const Image image = load_image(dir.write("top.ppm", ppm));
  EXPECT_EQ(rgba(image, 1, 0), (std::array<int, 4>{255, 0, 0, 255}));
  EXPECT_EQ(rgba(image, 0, 1), (std::array<int, 4>{0, 0, 255, 255}));
}

// Texel events hold 16-bit coordinates: an image wider or taller than 65536 texels is refused
// when it is read (a 65537x1 PPM is 192 kB), and 65536 itself is read.
TEST(ImageLoading, ImagesWiderThanTexelEventsHoldAreInputErrorsNamingTheFile) {
  testing::TempDir dir;
  const auto ppm = [](int width) {
    return "P6\n" + std::to_string(width) + " 1\n255\n" + std::string(static_cast<std::size_t>(width) * 3, '\x7f');
  };
  const std::string wide = dir.write("wide.ppm", ppm(65537));
  try {
    load_image(wide);
    FAIL() << "no error";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()), wide +
                                         ": image of 65537x1 texels: expected at most 65536 texels a side (texel "
                                         "events hold 16-bit coordinates)");
  }
  EXPECT_EQ(load_image(dir.write("widest.ppm", ppm(65536))).width, 65536);
}

TEST(ImageLoading, MissingAndCorruptImagesAreInputErrors) {
  testing::TempDir dir;
  EXPECT_THROW(load_image(dir.file("missing.png")), InputError);
  EXPECT_THROW(load_image(dir.write("bad.png", "\x89PNG\r\n\x1a\n not really")), InputError);
}

}  // namespace
}  // namespace rastrace
