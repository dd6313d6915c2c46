// Procedural textures: checkerboard, Yang et al.'s four-colour map, UV gradient.
#include <string>

#include "core/error.h"
#include "scenes/texture_io.h"

namespace rastrace {

namespace {

Image blank(int size, const char* what) {
  if (size < 1 || size > 16384)
    throw InputError(std::string(what) + " texture size " + std::to_string(size) + ": expected 1 to 16384 texels");
  Image image;
  image.width = image.height = size;
  image.rgba.resize(static_cast<std::size_t>(size) * static_cast<std::size_t>(size) * 4);
  return image;
}

void put(Image& image, int x, int y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  std::uint8_t* texel =
      image.rgba.data() +
      (static_cast<std::size_t>(y) * static_cast<std::size_t>(image.width) + static_cast<std::size_t>(x)) * 4;
  texel[0] = r, texel[1] = g, texel[2] = b, texel[3] = 255;
}

}  // namespace

Image make_checker(int size, int checks) {
  Image image = blank(size, "checker");
  if (checks < 1 || checks > size)
    throw InputError("checker texture: " + std::to_string(checks) + " checks: expected 1 to " + std::to_string(size));
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      // Square boundaries at floor(i * size / checks): exact when checks divides size.
      const int cx = static_cast<int>(static_cast<long long>(x) * checks / size);
      const int cy = static_cast<int>(static_cast<long long>(y) * checks / size);
      const std::uint8_t value = ((cx + cy) & 1) == 0 ? 255 : 64;
      put(image, x, y, value, value, value);
    }
  return image;
}

Image make_four_colour(int size) {
  Image image = blank(size, "four-colour");
  const int half = size / 2;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x) {
      const bool right = x >= half && size > 1, bottom = y >= half && size > 1;
      if (!right && !bottom)
        put(image, x, y, 230, 40, 40);  // red
      else if (right && !bottom)
        put(image, x, y, 40, 200, 60);  // green
      else if (!right)
        put(image, x, y, 40, 80, 230);  // blue
      else
        put(image, x, y, 240, 220, 40);  // yellow
    }
  return image;
}

Image make_uv_gradient(int size) {
  Image image = blank(size, "gradient");
  const int span = size > 1 ? size - 1 : 1;
  for (int y = 0; y < size; ++y)
    for (int x = 0; x < size; ++x)
      put(image, x, y, static_cast<std::uint8_t>((x * 255 + span / 2) / span),
          static_cast<std::uint8_t>((y * 255 + span / 2) / span), 0);
  return image;
}

}  // namespace rastrace
