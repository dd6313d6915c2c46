// RASTRACE_ASAN is 1 when the code is built with AddressSanitizer, by GCC (which defines
// __SANITIZE_ADDRESS__) or by clang (which answers __has_feature(address_sanitizer) and defines
// nothing: the fuzz build, scripts/fuzz.sh). Code that must not limit the address space (ASan
// reserves terabytes of it for its shadow memory) asks this, not one compiler's macro.
#pragma once

#if defined(__SANITIZE_ADDRESS__)
#define RASTRACE_ASAN 1
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define RASTRACE_ASAN 1
#endif
#endif
#ifndef RASTRACE_ASAN
#define RASTRACE_ASAN 0
#endif
