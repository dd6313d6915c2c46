#include "raster/quad_filter.h"

#include <cstdlib>
#include <string_view>

namespace rastrace {

void quad_filter_sse2(const QuadFilterInput& in, QuadFilterOutput& out);
#if RASTRACE_HAS_AVX2_KERNEL
void quad_filter_avx2(const QuadFilterInput& in, QuadFilterOutput& out);
#endif

bool simd_level_supported(SimdLevel level) {
  if (level == SimdLevel::Sse2) return true;
#if RASTRACE_HAS_AVX2_KERNEL
  return __builtin_cpu_supports("avx2");
#else
  return false;
#endif
}

const char* to_string(SimdLevel level) { return level == SimdLevel::Avx2 ? "avx2" : "sse2"; }

QuadFilterKernel quad_filter_kernel(SimdLevel level) {
#if RASTRACE_HAS_AVX2_KERNEL
  if (level == SimdLevel::Avx2 && simd_level_supported(level)) return quad_filter_avx2;
#endif
  (void)level;
  return quad_filter_sse2;
}

SimdLevel renderer_simd_level() {
  static const SimdLevel level = [] {
    const char* forced = std::getenv("RASTRACE_SIMD");
    if (forced && std::string_view(forced) == "sse2") return SimdLevel::Sse2;
    return simd_level_supported(SimdLevel::Avx2) ? SimdLevel::Avx2 : SimdLevel::Sse2;
  }();
  return level;
}

QuadFilterKernel renderer_quad_filter() {
  static const QuadFilterKernel kernel = quad_filter_kernel(renderer_simd_level());
  return kernel;
}

}  // namespace rastrace
