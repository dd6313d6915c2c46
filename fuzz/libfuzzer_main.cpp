// libFuzzer's entry point for a fuzz_<name> executable: the one target linked beside it.
#include <cstdio>
#include <cstdlib>

#include "fuzz/fuzz_target.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  static const rastrace::fuzz::TargetFunction run = [] {
    if (rastrace::fuzz::targets().size() != 1) {
      std::fprintf(stderr, "fuzz: expected exactly one target in this executable\n");
      std::abort();
    }
    return rastrace::fuzz::targets().front().run;
  }();
  run(data, size);
  return 0;
}
