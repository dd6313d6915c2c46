// Image files through OpenImageIO, converted to 8-bit RGBA with row 0 at the top.
#include "scenes/texture_io.h"

#include <array>
#include <cstring>
#include <filesystem>
#include <limits>

#include <OpenImageIO/filesystem.h>
#include <OpenImageIO/imageio.h>

#include "core/error.h"
#include "core/input_guard.h"
#include "scenes/text_parse.h"
#include "texcodec/codec.h"

namespace rastrace {

namespace {

// Reads the first subimage of an opened image as 8-bit RGBA (grey -> g g g 255, RGB -> alpha 255).
Image decode(OIIO::ImageInput& input, const std::string& name) {
  const OIIO::ImageSpec spec = input.spec();
  if (spec.width < 1 || spec.height < 1 || spec.nchannels < 1 || spec.depth > 1)
    throw_in_file(name, "image of " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + "x" +
                            std::to_string(spec.nchannels) + " channels: expected a 2D image with 1 to 4 channels");
  if (static_cast<std::uint64_t>(spec.width) > kMaxTextureSide ||
      static_cast<std::uint64_t>(spec.height) > kMaxTextureSide)
    throw_in_file(name, "image of " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                            " texels: expected at most " + std::to_string(kMaxTextureSide) +
                            " texels a side (texel events hold 16-bit coordinates)");
  if (static_cast<std::uint64_t>(spec.width) * static_cast<std::uint64_t>(spec.height) > (std::uint64_t{1} << 28))
    throw_in_file(name, "image of " + std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                            " texels: expected at most 2^28 texels");
  const int channels = spec.nchannels;
  // The header's size, not the file's bytes, sizes both buffers (a few hundred compressed bytes
  // can claim 2^28 texels): through the allocation limit before either is made.
  checked_bytes(static_cast<std::uint64_t>(spec.width) * static_cast<std::uint64_t>(spec.height),
                static_cast<std::uint64_t>(channels) + 4,
                name + ": image of " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " texels");
  std::vector<std::uint8_t> pixels(static_cast<std::size_t>(spec.width) * static_cast<std::size_t>(spec.height) *
                                   static_cast<std::size_t>(channels));
  if (!input.read_image(0, 0, 0, channels, OIIO::TypeDesc::UINT8, pixels.data()))
    throw_in_file(name, "cannot decode image (truncated or corrupt?): " + input.geterror());
  input.close();

  Image image;
  image.width = spec.width;
  image.height = spec.height;
  image.rgba.resize(static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height) * 4);
  const std::size_t texels = static_cast<std::size_t>(image.width) * static_cast<std::size_t>(image.height);
  for (std::size_t i = 0; i < texels; ++i) {
    const std::uint8_t* in = pixels.data() + i * static_cast<std::size_t>(channels);
    std::uint8_t* out = image.rgba.data() + i * 4;
    if (channels <= 2) {
      out[0] = out[1] = out[2] = in[0];
      out[3] = channels == 2 ? in[1] : 255;
    } else {
      out[0] = in[0], out[1] = in[1], out[2] = in[2];
      out[3] = channels >= 4 ? in[3] : 255;
    }
  }
  return image;
}

// libpng reports errors by longjmp through OpenImageIO, which leaks what the skipped frames
// owned; so PNG files are checked chunk by chunk (lengths, CRCs, the final IEND) before decoding.
std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
  static const auto table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1) ? 0xedb88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  std::uint32_t c = 0xffffffffu;
  for (std::size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xff] ^ (c >> 8);
  return c ^ 0xffffffffu;
}

std::uint32_t big_endian32(const std::uint8_t* p) {
  return (std::uint32_t{p[0]} << 24) | (std::uint32_t{p[1]} << 16) | (std::uint32_t{p[2]} << 8) | std::uint32_t{p[3]};
}

void check_png_chunks(const std::string& name, const std::uint8_t* data, std::size_t size) {
  static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1a, '\n'};
  if (size < 8 || std::memcmp(data, kSignature, 8) != 0) return;  // not a PNG: nothing to check
  std::size_t position = 8;
  while (true) {
    if (size - position < 12)
      throw_at_byte(name, position,
                    "truncated PNG: expected a chunk header (length, type) and CRC, found " +
                        std::to_string(size - position) + " bytes");
    const std::uint32_t length = big_endian32(data + position);
    const std::string type(reinterpret_cast<const char*>(data + position + 4), 4);
    if (length > 0x7fffffffu || size - position - 12 < length)
      throw_at_byte(
          name, position,
          "truncated PNG: chunk '" + type + "' of " + std::to_string(length) + " bytes runs past the end of the file");
    if (crc32(data + position + 4, length + 4) != big_endian32(data + position + 8 + length))
      throw_at_byte(name, position, "corrupt PNG: chunk '" + type + "' fails its CRC check");
    if (type == "IEND") return;
    position += 12 + length;
  }
}

}  // namespace

Image load_image(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::exists(path, error)) throw_in_file(path, "no such file (expected a texture image)");
  if (std::filesystem::is_directory(path, error)) throw_in_file(path, "is a directory, expected an image file");
  {
    const std::string bytes = read_whole_file(path);
    check_png_chunks(path, reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size());
  }
  auto input = OIIO::ImageInput::open(path);
  if (!input) throw_in_file(path, "cannot read image (expected PNG, JPEG, TGA...): " + OIIO::geterror());
  return decode(*input, path);
}

Image load_image_from_memory(const std::vector<std::uint8_t>& bytes, const std::string& name) {
  check_png_chunks(name, bytes.data(), bytes.size());
  OIIO::Filesystem::IOMemReader reader(bytes.data(), bytes.size());
  auto input = OIIO::ImageInput::open(name, nullptr, &reader);
  if (!input) throw_in_file(name, "cannot read embedded image (expected PNG, JPEG...): " + OIIO::geterror());
  return decode(*input, name);
}

Texture load_texture(const TextureSource& source) {
  Texture texture;
  Image base;
  switch (source.kind) {
    case TextureSource::Kind::None:
      throw InputError("load_texture: the material has no texture");
    case TextureSource::Kind::File:
      base = source.embedded ? load_image_from_memory(*source.embedded, source.path) : load_image(source.path);
      texture.name = source.path;
      break;
    case TextureSource::Kind::Checker:
      base = make_checker(source.size, source.checks);
      texture.name = "checker" + std::to_string(source.size) + "/" + std::to_string(source.checks);
      break;
    case TextureSource::Kind::FourColour:
      base = make_four_colour(source.size);
      texture.name = "four_colour" + std::to_string(source.size);
      break;
    case TextureSource::Kind::Gradient:
      base = make_uv_gradient(source.size);
      texture.name = "gradient" + std::to_string(source.size);
      break;
  }
  texture.levels = build_mip_chain(std::move(base));
  return compress_texture(std::move(texture), source.format);
}

Texture compress_texture(Texture texture, TextureFormat format) {
  if (texture.format != TextureFormat::Rgba8)
    throw InputError("compress_texture: " + texture.name + " is already " + to_string(texture.format));
  texture.format = format;
  if (!is_compressed(format)) return texture;
  texture.blocks.clear();
  for (Image& level : texture.levels) {
    texture.blocks.push_back(texcodec::encode_level(format, level.width, level.height, level.rgba));
    level.rgba = texcodec::decode_level(format, level.width, level.height, texture.blocks.back());
  }
  return texture;
}

}  // namespace rastrace
