// Dinero IV din traces (traces/text_formats.cpp): "label hexaddress" lines. rastrace has no
// extended din reader (yet): this target covers the classic format, the only one it reads.
#include "fuzz/fuzz_target.h"
#include "traces/text_formats.h"

RASTRACE_FUZZ_TARGET(din) {
  const std::string path = rastrace::fuzz::write_input("input.din", data, size);
  rastrace::fuzz::expect_clean([&] {
    rastrace::EventSink ignore;
    rastrace::import_din(path, ignore);
  });
}
