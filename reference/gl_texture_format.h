// A rastrace storage format as GL names it: the internal format a texture's blocks are uploaded
// with (glCompressedTexImage2D) and the extension that must expose it. Shared by the reference
// renderer and the tests that decode blocks with Mesa.
#pragma once

#include <GL/gl.h>

#include "core/texture_format.h"

namespace rastrace {

// BC1 is RGBA DXT1 because texcodec decodes the three-colour mode's index 3 to transparent black,
// as COMPRESSED_RGBA_S3TC_DXT1_EXT does (the RGB variant returns opaque black). RGBA8 is GL_RGBA8
// with no extension.
struct GlCompressedFormat {
  GLenum internal_format;
  const char* extension;
};
GlCompressedFormat gl_compressed_format(TextureFormat format);

// Whether the current context's GL_EXTENSIONS lists `name` as a whole word (a prefix of another
// extension's name, e.g. ..._s3tc of ..._s3tc_srgb, does not count).
bool has_gl_extension(const char* name);

}  // namespace rastrace
