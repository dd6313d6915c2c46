#include <squish.h>

#include "core/error.h"
#include "texcodec/encoders.h"

namespace rastrace::texcodec {

std::vector<std::uint8_t> squish_encode(TextureFormat format, int width, int height,
                                        std::span<const std::uint8_t> rgba) {
  int flags = 0;
  switch (format) {
    case TextureFormat::Bc1:
      flags = squish::kDxt1;
      break;
    case TextureFormat::Bc3:
      flags = squish::kDxt5;
      break;
    case TextureFormat::Bc4:
      flags = squish::kBc4;
      break;
    case TextureFormat::Bc5:
      flags = squish::kBc5;
      break;
    default:
      throw InputError(std::string("libsquish does not encode ") + to_string(format));
  }
  std::vector<std::uint8_t> blocks(static_cast<std::size_t>(squish::GetStorageRequirements(width, height, flags)));
  squish::CompressImage(rgba.data(), width, height, blocks.data(), flags);
  return blocks;
}

}  // namespace rastrace::texcodec
