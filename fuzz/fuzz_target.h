// The fuzz targets: one file per parser (fuzz/<name>.cpp), each a function of the input bytes that
// returns normally on success and on a clean InputError, and lets everything else escape (a crash,
// a sanitizer report, any other exception: std::bad_alloc, nlohmann's, std::out_of_range, ...).
//
// A target is declared with RASTRACE_FUZZ_TARGET(name) { ... body using `data` and `size` ... }.
// The same sources build two ways:
//   fuzz_<name>        a libFuzzer executable (RASTRACE_FUZZ=ON, clang): fuzz/libfuzzer_main.cpp
//   test_fuzz          the GoogleTest that runs every committed seed and regression file through
//                      every target (tests/fuzz/), in the ordinary builds and under ASan + UBSan.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace rastrace::fuzz {

using TargetFunction = void (*)(const std::uint8_t* data, std::size_t size);

struct Target {
  const char* name;
  TargetFunction run;
};

// Every target linked into this executable, in registration order.
std::vector<Target>& targets();

struct Registrar {
  Registrar(const char* name, TargetFunction run) { targets().push_back({name, run}); }
};

// Writes the bytes to `name` inside this process's scratch folder (created on first use under
// $TMPDIR, removed at exit) and returns its path: for the parsers that take paths.
std::string write_input(const std::string& name, const std::uint8_t* data, std::size_t size);
std::string write_input(const std::string& name, const std::string& text);
// The scratch folder itself.
const std::string& scratch_folder();

// Runs `body`, swallowing only the clean error (InputError).
template <typename Body>
void expect_clean(Body&& body);

}  // namespace rastrace::fuzz

#include "core/error.h"

template <typename Body>
void rastrace::fuzz::expect_clean(Body&& body) {
  try {
    body();
  } catch (const rastrace::InputError&) {
  }
}

#define RASTRACE_FUZZ_TARGET(name)                                                     \
  static void rastrace_fuzz_##name(const std::uint8_t* data, std::size_t size);       \
  static const ::rastrace::fuzz::Registrar rastrace_fuzz_registrar_##name(#name,      \
                                                                          rastrace_fuzz_##name); \
  static void rastrace_fuzz_##name(const std::uint8_t* data, std::size_t size)
