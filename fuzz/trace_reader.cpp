// The .rtrace container (traces/trace_reader.cpp): header, metadata JSON and its checksum,
// footer, chunk index, then every chunk in file order as `rastrace replay` reads them. Random
// bytes rarely pass the checksums: this target covers the container's checks, and the
// trace_chunk target reaches the records behind a valid checksum. Read-ahead is off, so every
// run is deterministic (scripts/tsan.sh covers the read-ahead thread).
#include "fuzz/fuzz_target.h"
#include "traces/trace_reader.h"

RASTRACE_FUZZ_TARGET(trace_reader) {
  const std::string path = rastrace::fuzz::write_input("input.rtrace", data, size);
  rastrace::fuzz::expect_clean([&] {
    rastrace::TraceReader reader(path);
    reader.set_read_ahead(false);
    rastrace::EventSink ignore;
    rastrace::replay_trace(reader, ignore);
  });
}
