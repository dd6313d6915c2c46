// The bilinear and trilinear filter of a 2x2 quad in eight lanes: lanes 0-3 are the quad's four
// pixels in the first level read, lanes 4-7 the same pixels in the second level of a
// LINEAR_MIPMAP_LINEAR blend (four lanes for one level, or for a blend of two pixels). Texels are loaded as 32-bit words and split into channels in
// integer lanes, so every channel of every pixel and level is filtered by the same vector
// operation (llvmpipe's layout: pixels in lanes, one register per channel).
//
// The arithmetic is the scalar sampler's, operation for operation (sampler.cpp: u = s * width -
// 1/2, floor, the weights, byte / 255 as byte * (1 / 255), two horizontal lerps and one vertical,
// then the blend between levels), each an IEEE operation on one lane: the result equals
// sample_texture's bit for bit on any instruction set. The kernel is compiled twice, for the
// baseline (SSE2) and for AVX2, and the renderer takes the widest the processor has; tests
// compare the two.
//
// The kernel's translation units see only this header: no inline function of the rest of the
// renderer is compiled with AVX2 (the linker could otherwise keep an AVX2 copy for every caller).
#pragma once

#include <cstdint>

namespace rastrace {

using QuadFilterF32x4 = float __attribute__((vector_size(16)));
using QuadFilterI32x8 = std::int32_t __attribute__((vector_size(32)));

// One level as the kernel reads it: RGBA8 texels row-major.
struct QuadFilterLevel {
  const std::uint8_t* rgba = nullptr;
  std::int32_t width = 0;
  std::int32_t height = 0;
};

struct QuadFilterInput {
  QuadFilterLevel levels[2];  // the second is read only when `blend`
  bool repeat_s = true;       // REPEAT, else CLAMP_TO_EDGE
  bool repeat_t = true;
  bool blend = false;         // LINEAR_MIPMAP_LINEAR between levels[0] and levels[1]
  float fraction = 0.0f;      // the blend's weight of levels[1]
  // A blend of at most two pixels, in lanes 0 and 1 of s and t: it runs in four lanes (two
  // pixels, two levels) instead of eight. The small triangles of a dense mesh shade one or two
  // pixels of most of their quads.
  bool two_pixels = false;
  QuadFilterF32x4 s, t;       // per pixel, already finite and within +-kCoordinateLimit
};

struct QuadFilterOutput {
  // Each lane's 2x2 footprint (x0..x1, y0..y1), wrapped: what the recorder reports. Pixel i's
  // lane in the first level is i, in the second i + 4 (i + 2 with two_pixels).
  QuadFilterI32x8 x0, x1, y0, y1;
  QuadFilterF32x4 rgba[4];  // red, green, blue, alpha; a lane per pixel (lanes 0 and 1 with two_pixels)
};

// Vectors cross this interface by reference only: a 32-byte vector passed by value has different
// calling conventions with and without AVX.
using QuadFilterKernel = void (*)(const QuadFilterInput& in, QuadFilterOutput& out);

enum class SimdLevel : std::uint8_t { Sse2, Avx2 };

// The kernel for `level`; Avx2 only where the processor has it (simd_level_supported).
QuadFilterKernel quad_filter_kernel(SimdLevel level);
bool simd_level_supported(SimdLevel level);
const char* to_string(SimdLevel level);

// The level the renderer uses: the widest supported, unless the environment variable
// RASTRACE_SIMD names a narrower one ("sse2"), to compare the two paths end to end.
SimdLevel renderer_simd_level();
// The kernel of renderer_simd_level(), chosen once per process.
QuadFilterKernel renderer_quad_filter();

}  // namespace rastrace
