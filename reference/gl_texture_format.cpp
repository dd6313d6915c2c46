#include "reference/gl_texture_format.h"

#include <GL/glext.h>

#include <string_view>

namespace rastrace {

GlCompressedFormat gl_compressed_format(TextureFormat format) {
  switch (format) {
    case TextureFormat::Bc1:
      return {GL_COMPRESSED_RGBA_S3TC_DXT1_EXT, "GL_EXT_texture_compression_s3tc"};
    case TextureFormat::Bc3:
      return {GL_COMPRESSED_RGBA_S3TC_DXT5_EXT, "GL_EXT_texture_compression_s3tc"};
    case TextureFormat::Bc4:
      return {GL_COMPRESSED_RED_RGTC1, "GL_ARB_texture_compression_rgtc"};
    case TextureFormat::Bc5:
      return {GL_COMPRESSED_RG_RGTC2, "GL_ARB_texture_compression_rgtc"};
    case TextureFormat::Bc7:
      return {GL_COMPRESSED_RGBA_BPTC_UNORM, "GL_ARB_texture_compression_bptc"};
    case TextureFormat::Astc4x4:
      return {GL_COMPRESSED_RGBA_ASTC_4x4_KHR, "GL_KHR_texture_compression_astc_ldr"};
    case TextureFormat::Astc8x8:
      return {GL_COMPRESSED_RGBA_ASTC_8x8_KHR, "GL_KHR_texture_compression_astc_ldr"};
    case TextureFormat::Rgba8:
      break;
  }
  return {GL_RGBA8, ""};
}

bool has_gl_extension(const char* name) {
  const auto* list = reinterpret_cast<const char*>(glGetString(GL_EXTENSIONS));
  if (!list) return false;
  const std::string_view extensions(list), wanted(name);
  for (std::size_t at = extensions.find(wanted); at != std::string_view::npos; at = extensions.find(wanted, at + 1)) {
    const std::size_t end = at + wanted.size();
    if ((at == 0 || extensions[at - 1] == ' ') && (end == extensions.size() || extensions[end] == ' ')) return true;
  }
  return false;
}

}  // namespace rastrace
