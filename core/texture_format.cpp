#include "core/texture_format.h"

#include "core/enum_names.h"

namespace rastrace {

namespace {

constexpr EnumName<TextureFormat> kTextureFormats[] = {
    {TextureFormat::Rgba8, "rgba8"},     {TextureFormat::Bc1, "bc1"},         {TextureFormat::Bc3, "bc3"},
    {TextureFormat::Bc4, "bc4"},         {TextureFormat::Bc5, "bc5"},         {TextureFormat::Bc7, "bc7"},
    {TextureFormat::Astc4x4, "astc4x4"}, {TextureFormat::Astc8x8, "astc8x8"},
};

}  // namespace

BlockShape block_shape(TextureFormat format) {
  switch (format) {
    case TextureFormat::Rgba8:
      return {1, 1, 4};
    case TextureFormat::Bc1:
    case TextureFormat::Bc4:
      return {4, 4, 8};
    case TextureFormat::Bc3:
    case TextureFormat::Bc5:
    case TextureFormat::Bc7:
    case TextureFormat::Astc4x4:
      return {4, 4, 16};
    case TextureFormat::Astc8x8:
      return {8, 8, 16};
  }
  return {1, 1, 4};
}

TextureFormat parse_texture_format(std::string_view text, std::string_view what) {
  return parse_enum(text, kTextureFormats, what);
}

const char* to_string(TextureFormat format) { return enum_to_string(format, kTextureFormats); }

std::uint64_t level_bytes(TextureFormat format, std::uint32_t width, std::uint32_t height) {
  const BlockShape shape = block_shape(format);
  const std::uint64_t columns = (static_cast<std::uint64_t>(width) + shape.width - 1) / shape.width;
  const std::uint64_t rows = (static_cast<std::uint64_t>(height) + shape.height - 1) / shape.height;
  return columns * rows * shape.bytes;
}

}  // namespace rastrace
