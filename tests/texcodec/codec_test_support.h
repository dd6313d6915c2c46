// Shared by the texcodec tests: random blocks, procedural test images, PSNR, and Mesa's decoder.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "core/texture_format.h"
#include "scenes/texture.h"

namespace rastrace::testing {

// count * bytes random bytes from a fixed seed.
std::vector<std::uint8_t> random_bytes(std::size_t count, std::uint32_t seed);

// Real images to encode: scenes' procedural textures, plus a noisy gradient with varied alpha
// (so BC3's and BC7's alpha paths see more than 255).
std::vector<Image> sample_images();

// PSNR over all four channels, in dB (inf when identical).
double psnr_rgba(std::span<const std::uint8_t> a, std::span<const std::uint8_t> b);

// Mesa's own decoding of a level of `format` blocks (glCompressedTexImage2D, then glGetTexImage
// as RGBA8), in a child process (texcodec/mesa_child.h).
std::vector<std::uint8_t> mesa_decode(TextureFormat format, int width, int height,
                                      std::span<const std::uint8_t> blocks);

}  // namespace rastrace::testing
