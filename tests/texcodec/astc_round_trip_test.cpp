// ASTC through astcenc (encoder and reference decoder) at the quality preset texcodec uses: the
// round trip keeps the sample images above a PSNR floor measured with astcenc 4.2's "fastest"
// preset (the figures are printed; the floors sit about 1 dB under the worst image).
#include <cstdio>

#include <gtest/gtest.h>

#include "codec_test_support.h"
#include "texcodec/codec.h"

namespace rastrace {
namespace {

constexpr double kAstc4x4FloorDb = 32.5;  // worst measured: 33.38 dB (the noisy 96x96 gradient)
constexpr double kAstc8x8FloorDb = 28.5;  // worst measured: 29.62 dB (the same image)

double worst_round_trip_psnr(TextureFormat format) {
  double worst = 1e9;
  for (const Image& image : testing::sample_images()) {
    const std::vector<std::uint8_t> blocks = texcodec::encode_level(format, image.width, image.height, image.rgba);
    EXPECT_EQ(blocks.size(),
              level_bytes(format, static_cast<std::uint32_t>(image.width), static_cast<std::uint32_t>(image.height)));
    const double psnr =
        testing::psnr_rgba(image.rgba, texcodec::decode_level(format, image.width, image.height, blocks));
    std::printf("%s %dx%d: PSNR %.2f dB\n", to_string(format), image.width, image.height, psnr);
    worst = std::min(worst, psnr);
  }
  return worst;
}

TEST(Astc, FourByFourRoundTripKeepsThePsnrFloor) {
  EXPECT_GE(worst_round_trip_psnr(TextureFormat::Astc4x4), kAstc4x4FloorDb);
}

TEST(Astc, EightByEightRoundTripKeepsThePsnrFloor) {
  EXPECT_GE(worst_round_trip_psnr(TextureFormat::Astc8x8), kAstc8x8FloorDb);
}

}  // namespace
}  // namespace rastrace
