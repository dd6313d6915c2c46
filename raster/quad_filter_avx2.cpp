// The quad filter compiled for AVX2 (raster/CMakeLists.txt adds -mavx2 to this file alone, and
// keeps fused multiply-adds off: a*b+c rounded once would change the bits).
#include "raster/quad_filter_kernel.inc"

namespace rastrace {
void quad_filter_avx2(const QuadFilterInput& in, QuadFilterOutput& out) { filter_quad(in, out); }
}  // namespace rastrace
