#include "raster/quad_loop.h"

#include <atomic>

#include "raster/quad_filter.h"

namespace rastrace {

namespace {

bool processor_runs_wide_loop() {
#ifdef RASTRACE_WIDE_QUAD_LOOP
  return renderer_simd_level() != SimdLevel::Sse2 && __builtin_cpu_supports("x86-64-v4");
#else
  return false;
#endif
}

// Relaxed: set once at start-up (or by a test between frames), read once per triangle.
std::atomic<bool> wide{processor_runs_wide_loop()};

}  // namespace

bool wide_quad_loop() { return wide.load(std::memory_order_relaxed); }

void use_wide_quad_loop(bool on) { wide.store(on && processor_runs_wide_loop(), std::memory_order_relaxed); }

}  // namespace rastrace
