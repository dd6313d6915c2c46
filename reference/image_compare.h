// Compares rastrace's image with the OSMesa reference, pixel by pixel, with OpenImageIO.
// Both images are RGBA8 with row 0 at the top, rendered over a clear colour with alpha 0 while
// every fragment is opaque, so alpha > 0 marks a covered pixel in either image.
//
// Reported over the covered pixels (covered in either image): the fraction whose largest
// channel difference exceeds 1, 2 and 8 (of 255), and the PSNR of RGB (inf when identical).
// Coverage differences are split into those at pixel centres exactly on a triangle edge (where
// the drivers' fill rules legitimately disagree) and the others (which would be bugs).
#pragma once

#include <cstdint>
#include <string>

namespace rastrace {

struct ImageDifference {
  std::uint64_t pixels = 0;
  std::uint64_t covered = 0;           // covered in either image
  std::uint64_t coverage_differs = 0;  // covered in exactly one image
  // ... of which at centres within 1/256 pixel of an edge but not on it: a rasterizer that does
  // not snap vertices to 1/256 pixel (softpipe) may decide these either way.
  std::uint64_t coverage_differs_near_edge = 0;
  std::uint64_t coverage_differs_off_edge = 0;                // ... neither on nor near an edge (needs the plane)
  std::uint64_t diff_gt_1 = 0, diff_gt_2 = 0, diff_gt_8 = 0;  // covered pixels, any channel
  std::uint64_t diff_gt_1_off_edge = 0;                       // ... of diff_gt_1, centres neither on nor near an edge
  int max_difference = 0;
  double psnr = 0.0;        // dB, RGB over the covered pixels
  double psnr_image = 0.0;  // dB, OpenImageIO's over the whole image (RGB)

  double fraction(std::uint64_t count) const { return covered ? double(count) / double(covered) : 0.0; }
};

// `centre_on_edge` (optional, Framebuffer::centre_on_edge() of rastrace's debug planes)
// classifies coverage differences.
ImageDifference compare_images(int width, int height, const std::uint8_t* ours, const std::uint8_t* reference,
                               const std::uint8_t* centre_on_edge = nullptr);

// The absolute difference of RGB scaled by 16 (so 1/255 shows), coverage differences in
// magenta; written atomically (PNG by the extension).
void write_difference_image(const std::string& path, int width, int height, const std::uint8_t* ours,
                            const std::uint8_t* reference);

}  // namespace rastrace
