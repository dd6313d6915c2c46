#include "raster/quad_loop.h"

#include <atomic>

#include "raster/quad_filter.h"

namespace rastrace {

namespace {

bool processor_runs_wide_loop() {
#ifdef RASTRACE_WIDE_QUAD_LOOP
  __builtin_cpu_init();  // idempotent; needed if this runs before the library's own constructor
  return renderer_simd_level() != SimdLevel::Sse2 && __builtin_cpu_supports("x86-64-v4");
#else
  return false;
#endif
}

// Decided at first use, not during static initialisation (where the processor's features may not
// be read yet). Relaxed: written at first use or by a test between frames, read once per triangle.
std::atomic<bool>& wide() {
  static std::atomic<bool> flag{processor_runs_wide_loop()};
  return flag;
}

}  // namespace

bool wide_quad_loop() { return wide().load(std::memory_order_relaxed); }

void use_wide_quad_loop(bool on) { wide().store(on && processor_runs_wide_loop(), std::memory_order_relaxed); }

}  // namespace rastrace
