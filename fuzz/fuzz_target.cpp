#include "fuzz/fuzz_target.h"

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <stdexcept>
#include <system_error>

namespace rastrace::fuzz {

namespace fs = std::filesystem;

std::vector<Target>& targets() {
  static std::vector<Target> all;
  return all;
}

namespace {

struct ScratchFolder {
  std::string path;
  ScratchFolder() {
    std::string pattern = (fs::temp_directory_path() / "rastrace-fuzz-XXXXXX").string();
    if (!mkdtemp(pattern.data())) throw std::runtime_error("fuzz: cannot create a scratch folder in " + pattern);
    path = pattern;
  }
  ~ScratchFolder() {
    std::error_code ignored;
    fs::remove_all(path, ignored);
  }
};

// libFuzzer stops at 1 GiB of RSS (scripts/fuzz.sh), far below the limit rastrace applies to one
// input-sized allocation (half the machine). An input asking for 4 GiB is legitimate but would
// read as an out-of-memory finding, so the fuzzers lower the limit to 256 MiB: a finding is then
// an allocation that bypasses checked_bytes(), and an input over the limit must be a clean error.
// Set before any target runs; an explicit RASTRACE_MEMORY_LIMIT in the environment wins.
// Likewise the CPU time assimp may take in its contained child (scenes/assimp_io.cpp): 1 s, so a
// file assimp grinds on under ASan is a clean error well inside libFuzzer's 5 s.
[[maybe_unused]] const bool limits_lowered = [] {
  ::setenv("RASTRACE_MEMORY_LIMIT", "268435456", 0);
  ::setenv("RASTRACE_ASSIMP_CPU_SECONDS", "1", 0);
  return true;
}();

}  // namespace

const std::string& scratch_folder() {
  static const ScratchFolder folder;
  return folder.path;
}

std::string write_input(const std::string& name, const std::uint8_t* data, std::size_t size) {
  const std::string path = scratch_folder() + "/" + name;
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data), static_cast<std::streamsize>(size));
  out.close();
  // A harness that cannot write its input would fuzz nothing: stop loudly.
  if (!out) throw std::runtime_error("fuzz: cannot write " + path);
  return path;
}

std::string write_input(const std::string& name, const std::string& text) {
  return write_input(name, reinterpret_cast<const std::uint8_t*>(text.data()), text.size());
}

}  // namespace rastrace::fuzz

// LeakSanitizer (the fuzzers, and test_fuzz under ASan): assimp 5.2 leaks a few objects on some
// malformed files inside its importers (a 1-byte .3mf, fuzz/regressions/assimp/). That is
// assimp's memory, not rastrace's: suppressed by library, nothing else. Its zlib streams (zipped
// 3MF, compressed .x) leak the same way, but the stack ends in libz (built without frame
// pointers, the fast unwinder stops there): inflateInit2_ too. rastrace itself calls no zlib.
extern "C" const char* __lsan_default_suppressions() { return "leak:libassimp.so\nleak:inflateInit2_\n"; }
