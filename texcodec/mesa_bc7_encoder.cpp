#define GL_GLEXT_PROTOTYPES 1
#include <GL/gl.h>
#include <GL/glext.h>

#include <stdexcept>
#include <string>

#include "texcodec/encoders.h"
#include "texcodec/mesa_child.h"

namespace rastrace::texcodec {

std::vector<std::uint8_t> mesa_bc7_encode(int width, int height, std::span<const std::uint8_t> rgba) {
  return run_in_gl_child("BC7 encoder (Mesa)", [&] {
    GLuint texture = 0;
    glGenTextures(1, &texture);
    glBindTexture(GL_TEXTURE_2D, texture);
    glPixelStorei(GL_UNPACK_ALIGNMENT, 1);
    glTexImage2D(GL_TEXTURE_2D, 0, GL_COMPRESSED_RGBA_BPTC_UNORM, width, height, 0, GL_RGBA, GL_UNSIGNED_BYTE,
                 rgba.data());
    GLint compressed = 0, size = 0;
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED, &compressed);
    glGetTexLevelParameteriv(GL_TEXTURE_2D, 0, GL_TEXTURE_COMPRESSED_IMAGE_SIZE, &size);
    if (!compressed || size <= 0 || glGetError() != GL_NO_ERROR)
      throw std::runtime_error("Mesa did not compress the level to BPTC");
    std::vector<std::uint8_t> blocks(static_cast<std::size_t>(size));
    glGetCompressedTexImage(GL_TEXTURE_2D, 0, blocks.data());
    glDeleteTextures(1, &texture);
    return blocks;
  });
}

}  // namespace rastrace::texcodec
