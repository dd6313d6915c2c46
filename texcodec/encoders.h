// The third-party encoders behind encode_level (codec.h); each takes a level already padded to
// whole blocks (block_grid.h) and returns its blocks in row-major block order.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/texture_format.h"

namespace rastrace::texcodec {

// libsquish, BC1/BC3/BC4/BC5 with its default cluster fit (one thread): a noisy 1024x1024 level
// takes about 1.2 s of CPU for BC1 and BC3, 0.04-0.06 s for BC4 and BC5 (docs/PERFORMANCE.md).
// The range fit is faster and visibly worse; the iterative cluster fit slower still.
std::vector<std::uint8_t> squish_encode(TextureFormat format, int width, int height,
                                        std::span<const std::uint8_t> rgba);

// Mesa's BPTC compressor, run by uploading RGBA8 texels to a GL_COMPRESSED_RGBA_BPTC_UNORM
// texture through OSMesa and reading the blocks back with glGetCompressedTexImage. Runs in a
// forked child process (mesa_child.h), so the calling process never creates a GL context.
std::vector<std::uint8_t> mesa_bc7_encode(int width, int height, std::span<const std::uint8_t> rgba);

// astcenc 4.2 (ARM's reference codec), LDR profile, block_size x block_size blocks.
std::vector<std::uint8_t> astc_encode(int block_size, int width, int height, std::span<const std::uint8_t> rgba);
std::vector<std::uint8_t> astc_decode(int block_size, int width, int height, std::span<const std::uint8_t> blocks);

}  // namespace rastrace::texcodec
