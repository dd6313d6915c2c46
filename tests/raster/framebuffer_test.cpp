// The framebuffer's clear, whole and in bands of rows (the parallel rasterizer shares a clear out
// between threads a band each).
#include <cstdint>
#include <vector>

#include <gtest/gtest.h>

#include "raster/framebuffer.h"

namespace rastrace {
namespace {

// A different value in every byte and depth, so that a missed or extra row shows.
void scribble(Framebuffer& fb) {
  const std::size_t pixels = static_cast<std::size_t>(fb.width()) * static_cast<std::size_t>(fb.height());
  for (std::size_t i = 0; i < pixels * 4; ++i) fb.colour()[i] = static_cast<std::uint8_t>(i * 37 + 11);
  for (std::size_t i = 0; i < pixels; ++i) {
    fb.depth()[i] = 0.001f * static_cast<float>(i % 997);
    fb.write_count()[i] = static_cast<std::uint16_t>(i);
    fb.centre_on_edge()[i] = static_cast<std::uint8_t>(i % 3);
  }
}

bool same_pixels(const Framebuffer& a, const Framebuffer& b) {
  const std::size_t pixels = static_cast<std::size_t>(a.width()) * static_cast<std::size_t>(a.height());
  for (std::size_t i = 0; i < pixels; ++i)
    if (a.depth()[i] != b.depth()[i] || a.write_count()[i] != b.write_count()[i] ||
        a.centre_on_edge()[i] != b.centre_on_edge()[i])
      return false;
  for (std::size_t i = 0; i < pixels * 4; ++i)
    if (a.colour()[i] != b.colour()[i]) return false;
  return true;
}

TEST(Framebuffer, ClearRowsInBandsEqualsOneClearAndLeavesOtherRowsAlone) {
  const glm::vec4 colour(0.2f, 0.4f, 0.6f, 1.0f);
  Framebuffer whole(37, 23, true), bands(37, 23, true);
  scribble(whole);
  scribble(bands);
  whole.clear(colour, 0.75f);
  bands.set_clear(colour, 0.75f);
  // Uneven bands, one reaching past each end of the image (clipped), one empty.
  bands.clear_rows(-5, 4);
  bands.clear_rows(4, 4);
  bands.clear_rows(4, 17);
  EXPECT_FALSE(same_pixels(whole, bands));     // rows 17.. are not cleared yet
  EXPECT_EQ(bands.colour()[16 * 37 * 4], 51);  // 0.2 * 255, rounded: the last cleared row
  EXPECT_EQ(bands.depth()[17 * 37], 0.001f * static_cast<float>(17 * 37 % 997));  // the first not
  bands.clear_rows(17, 100);
  EXPECT_TRUE(same_pixels(whole, bands));
  EXPECT_EQ(whole.covered_pixels(), 0u);
}

}  // namespace
}  // namespace rastrace
