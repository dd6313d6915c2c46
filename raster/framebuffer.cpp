#include "raster/framebuffer.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <memory>
#include <vector>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/atomic_file.h"
#include "core/error.h"

namespace rastrace {

Framebuffer::Framebuffer(int width, int height, bool debug_planes) : width_(width), height_(height) {
  if (width < 1 || height < 1 || width > 16384 || height > 16384)
    throw InputError("image size " + std::to_string(width) + "x" + std::to_string(height) +
                     ": expected 1..16384 pixels on each side");
  const std::size_t pixels = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
  colour_.resize(pixels * 4);
  depth_.resize(pixels);
  if (debug_planes) {
    write_count_.resize(pixels);
    centre_on_edge_.resize(pixels);
  }
  clear(glm::vec4(0.0f, 0.0f, 0.0f, 1.0f));
}

void Framebuffer::set_clear(const glm::vec4& colour, float depth) {
  std::uint8_t c[4];
  for (int i = 0; i < 4; ++i) c[i] = static_cast<std::uint8_t>(std::lround(std::clamp(colour[i], 0.0f, 1.0f) * 255.0f));
  std::memcpy(&clear_colour_, c, 4);
  clear_depth_ = depth;
}

void Framebuffer::clear(const glm::vec4& colour, float depth) {
  set_clear(colour, depth);
  clear_rows(0, height_);
}

void Framebuffer::clear_rows(int y0, int y1) {
  y0 = std::max(y0, 0);
  y1 = std::min(y1, height_);
  if (y0 >= y1) return;
  const std::size_t first = static_cast<std::size_t>(y0) * static_cast<std::size_t>(width_);
  const std::size_t pixels = static_cast<std::size_t>(y1 - y0) * static_cast<std::size_t>(width_);
  // The first pixel, then the filled part copied after itself, doubling: a few large memcpy
  // calls instead of a store per pixel (the clear is a tenth of a small frame's time).
  std::uint8_t* out = colour_.data() + first * 4;
  const std::size_t size = pixels * 4;
  std::memcpy(out, &clear_colour_, 4);
  for (std::size_t filled = 4; filled < size; filled *= 2)
    std::memcpy(out + filled, out, std::min(filled, size - filled));
  std::fill_n(depth_.data() + first, pixels, clear_depth_);
  if (!write_count_.empty()) {
    std::fill_n(write_count_.data() + first, pixels, std::uint16_t{0});
    std::fill_n(centre_on_edge_.data() + first, pixels, std::uint8_t{0});
  }
}

std::uint64_t Framebuffer::covered_pixels() const {
  std::uint64_t covered = 0;
  for (const float z : depth_) covered += z < clear_depth_;
  return covered;
}

namespace {

void write_image(const std::string& path, const OIIO::ImageSpec& spec, const void* pixels) {
  std::string format = std::filesystem::path(path).extension().string();
  if (!format.empty()) format.erase(0, 1);
  if (format.empty()) format = "png";
  auto out = OIIO::ImageOutput::create(format);
  if (!out) throw InputError(path + ": cannot write images of this type (" + OIIO::geterror() + ")");
  if (out->supports("ioproxy")) {
    // Encoded in memory and written by rastrace's own checked writer: image libraries do not all
    // report a failed fwrite (a full disk gave a truncated PNG and exit 0), and reading a
    // truncated PNG back makes libpng longjmp past OpenImageIO's error string (a leak).
    std::vector<unsigned char> encoded;
    OIIO::Filesystem::IOVecOutput memory(encoded);
    if (!out->set_ioproxy(&memory) || !out->open(path, spec) || !out->write_image(spec.format, pixels) || !out->close())
      throw InputError(path + ": cannot encode the image: " + out->geterror());
    write_file_atomically(path, [&](std::ostream& file) {
      file.write(reinterpret_cast<const char*>(encoded.data()), static_cast<std::streamsize>(encoded.size()));
    });
    return;
  }
  write_via_temporary(path, [&](const std::filesystem::path& temporary) {
    if (!out->open(temporary.string(), spec) || !out->write_image(spec.format, pixels) || !out->close())
      throw InputError(path + ": write failed: " + out->geterror());
    // The file counts as written only when it reads back whole (see above). The reader's error is
    // taken here: left pending, OpenImageIO prints it from the destructor.
    auto in = OIIO::ImageInput::open(temporary.string());
    if (!in)
      throw InputError(path + ": write failed (disk full?): the image does not read back (" + OIIO::geterror() + ")");
    std::vector<unsigned char> check(spec.image_bytes());
    if (!in->read_image(0, 0, 0, spec.nchannels, spec.format, check.data()))
      throw InputError(path + ": write failed (disk full?): the image does not read back whole (" + in->geterror() +
                       ")");
  });
}

}  // namespace

void write_rgba8_image(const std::string& path, int width, int height, const std::uint8_t* rgba, int channels) {
  if (channels == 4) {
    write_image(path, OIIO::ImageSpec(width, height, 4, OIIO::TypeDesc::UINT8), rgba);
    return;
  }
  std::vector<std::uint8_t> rgb(static_cast<std::size_t>(width) * static_cast<std::size_t>(height) * 3);
  for (std::size_t i = 0, j = 0; j < rgb.size(); i += 4, j += 3) {
    rgb[j] = rgba[i];
    rgb[j + 1] = rgba[i + 1];
    rgb[j + 2] = rgba[i + 2];
  }
  write_image(path, OIIO::ImageSpec(width, height, 3, OIIO::TypeDesc::UINT8), rgb.data());
}

void Framebuffer::write_colour(const std::string& path, bool alpha) const {
  write_rgba8_image(path, width_, height_, colour_.data(), alpha ? 4 : 3);
}

void Framebuffer::write_depth(const std::string& path) const {
  OIIO::ImageSpec spec(width_, height_, 1, OIIO::TypeDesc::FLOAT);
  spec.channelnames = {"Z"};
  write_image(path, spec, depth_.data());
}

}  // namespace rastrace
