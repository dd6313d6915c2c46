// The quad filter for baseline x86-64 (SSE2), or whatever the build's target is elsewhere.
#include "raster/quad_filter_kernel.inc"

namespace rastrace {
void quad_filter_sse2(const QuadFilterInput& in, QuadFilterOutput& out) { filter_quad(in, out); }
}  // namespace rastrace
