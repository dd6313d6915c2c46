// RASTRACE_CLONES("avx2", "default"): GCC's function multi-versioning (target_clones: one copy
// of the function per instruction set, chosen at load time by an ifunc resolver) where it is safe.
// Left out:
//   - under ThreadSanitizer (scripts/tsan.sh): the instrumented resolver runs while the dynamic
//     loader relocates the program, before TSan's runtime exists, and the program crashes before
//     main();
//   - with clang (14, the fuzz build, scripts/fuzz.sh): it names the dispatcher of an external
//     function "<name>.ifunc", and callers in other files find no symbol at link time;
//   - off x86-64, where the targets named here do not exist.
#pragma once

#if defined(__x86_64__) && !defined(__clang__) && !defined(__SANITIZE_THREAD__)
#define RASTRACE_CLONES(...) __attribute__((target_clones(__VA_ARGS__)))
#else
#define RASTRACE_CLONES(...)
#endif
