#include "reference/image_compare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <vector>

#include <OpenImageIO/imagebuf.h>
#include <OpenImageIO/imagebufalgo.h>

#include "raster/framebuffer.h"

namespace rastrace {

namespace {

OIIO::ImageBuf wrap_rgb(int width, int height, const std::uint8_t* rgba) {
  OIIO::ImageSpec spec(width, height, 4, OIIO::TypeDesc::UINT8);
  OIIO::ImageBuf rgba_buffer(spec, const_cast<std::uint8_t*>(rgba));  // read only
  return OIIO::ImageBufAlgo::channels(rgba_buffer, 3, {});
}

}  // namespace

ImageDifference compare_images(int width, int height, const std::uint8_t* ours, const std::uint8_t* reference,
                               const std::uint8_t* centre_on_edge) {
  ImageDifference d;
  d.pixels = static_cast<std::uint64_t>(width) * static_cast<std::uint64_t>(height);
  double squared = 0.0;
  for (std::uint64_t p = 0; p < d.pixels; ++p) {
    const std::uint8_t* a = ours + p * 4;
    const std::uint8_t* b = reference + p * 4;
    const bool covered_a = a[3] != 0, covered_b = b[3] != 0;
    if (!covered_a && !covered_b) continue;
    ++d.covered;
    if (covered_a != covered_b) {
      ++d.coverage_differs;
      if (centre_on_edge && centre_on_edge[p] == 2) ++d.coverage_differs_near_edge;
      if (centre_on_edge && centre_on_edge[p] == 0) ++d.coverage_differs_off_edge;
    }
    int largest = 0;
    for (int c = 0; c < 4; ++c) largest = std::max(largest, std::abs(int(a[c]) - int(b[c])));
    for (int c = 0; c < 3; ++c) {
      const double e = double(a[c]) - double(b[c]);
      squared += e * e;
    }
    d.max_difference = std::max(d.max_difference, largest);
    d.diff_gt_1 += largest > 1;
    if (centre_on_edge && largest > 1 && !centre_on_edge[p]) ++d.diff_gt_1_off_edge;
    d.diff_gt_2 += largest > 2;
    d.diff_gt_8 += largest > 8;
  }
  const double mse = d.covered ? squared / (3.0 * double(d.covered)) : 0.0;
  d.psnr = mse > 0.0 ? 10.0 * std::log10(255.0 * 255.0 / mse) : std::numeric_limits<double>::infinity();

  const OIIO::ImageBuf a = wrap_rgb(width, height, ours), b = wrap_rgb(width, height, reference);
  const auto result = OIIO::ImageBufAlgo::compare(a, b, 2.0f / 255.0f, 1.0f / 255.0f);
  d.psnr_image = result.PSNR;
  return d;
}

void write_difference_image(const std::string& path, int width, int height, const std::uint8_t* ours,
                            const std::uint8_t* reference) {
  const OIIO::ImageBuf a = wrap_rgb(width, height, ours), b = wrap_rgb(width, height, reference);
  OIIO::ImageBuf scaled = OIIO::ImageBufAlgo::mul(OIIO::ImageBufAlgo::absdiff(a, b), 16.0f);
  std::vector<std::uint8_t> out(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
  scaled.get_pixels(OIIO::ROI(0, width, 0, height, 0, 1, 0, 3), OIIO::TypeDesc::UINT8, out.data(), 4);
  for (std::size_t p = 0; p < out.size() / 4; ++p) {
    std::uint8_t* o = out.data() + p * 4;
    o[3] = 255;
    if ((ours[p * 4 + 3] != 0) != (reference[p * 4 + 3] != 0)) {
      o[0] = 255;
      o[1] = 0;
      o[2] = 255;
    }
  }
  write_rgba8_image(path, width, height, out.data(), 3);
}

}  // namespace rastrace
