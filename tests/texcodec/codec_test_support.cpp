#include "codec_test_support.h"

#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <stdexcept>

#include "reference/gl_texture_format.h"
#include "scenes/texture_io.h"
#include "texcodec/mesa_child.h"

namespace rastrace::testing {

std::vector<std::uint8_t> random_bytes(std::size_t count, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<std::uint8_t> bytes(count);
  for (std::uint8_t& b : bytes) b = static_cast<std::uint8_t>(rng() & 255);
  return bytes;
}

std::vector<Image> sample_images() {
  std::vector<Image> images = {make_checker(64, 8), make_four_colour(64), make_uv_gradient(128)};
  Image noisy = make_uv_gradient(96);
  std::mt19937 rng(7);
  for (std::size_t i = 0; i < noisy.rgba.size(); ++i) {
    const int value = noisy.rgba[i] + static_cast<int>(rng() % 41) - 20;
    noisy.rgba[i] = static_cast<std::uint8_t>(std::clamp(value, 0, 255));
  }
  images.push_back(noisy);
  return images;
}

double psnr_rgba(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b) {
  double sum = 0.0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const double d = double(a[i]) - double(b[i]);
    sum += d * d;
  }
  if (sum == 0.0) return std::numeric_limits<double>::infinity();
  return 10.0 * std::log10(255.0 * 255.0 / (sum / double(a.size())));
}

std::vector<std::uint8_t> mesa_decode(TextureFormat format, int width, int height,
                                      std::span<const std::uint8_t> blocks) {
  return texcodec::run_in_gl_child("Mesa decoder", [&] {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glCompressedTexImage2D(GL_TEXTURE_2D, 0, gl_compressed_format(format).internal_format, width, height, 0,
                           static_cast<GLsizei>(blocks.size()), blocks.data());
    if (glGetError() != GL_NO_ERROR) throw std::runtime_error("glCompressedTexImage2D failed");
    std::vector<std::uint8_t> rgba(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 4);
    glPixelStorei(GL_PACK_ALIGNMENT, 1);
    glGetTexImage(GL_TEXTURE_2D, 0, GL_RGBA, GL_UNSIGNED_BYTE, rgba.data());
    return rgba;
  });
}

}  // namespace rastrace::testing
