// CSV traces (traces/text_formats.cpp): the metadata line, the header, every event kind, as
// `rastrace trace convert` and `replay` import them.
#include "fuzz/fuzz_target.h"
#include "traces/text_formats.h"

RASTRACE_FUZZ_TARGET(csv_trace) {
  const std::string path = rastrace::fuzz::write_input("input.csv", data, size);
  rastrace::fuzz::expect_clean([&] {
    rastrace::read_csv_metadata(path);
    rastrace::EventSink ignore;
    rastrace::import_csv(path, ignore);
  });
}
