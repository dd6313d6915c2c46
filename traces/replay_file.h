// One entry point for every trace format a user may hand to `replay` or `sweep`:
//   rastrace container (detected by its magic, whatever the extension), .csv (text_formats.h),
//   .din (Dinero IV). Unknown formats are InputErrors.
#pragma once

#include <string>

#include "traces/sink.h"
#include "traces/trace_metadata.h"
#include "traces/trace_reader.h"

namespace rastrace {

enum class TraceFileFormat { Container, Csv, Din };

// Throws InputError when the file is missing or of no known format.
TraceFileFormat detect_trace_format(const std::string& path);

struct TraceSummary {
  TraceFileFormat format = TraceFileFormat::Container;
  TraceMetadata metadata;
  // Record counts; for text formats these are known only after a pass (has_counts false).
  bool has_counts = false;
  std::uint64_t vertices = 0, texels = 0, addresses = 0, framebuffer = 0;
};

// Reads the header (container) or first line (CSV); din has no metadata.
TraceSummary summarize_trace(const std::string& path);

// Streams the whole file into the sink and calls sink.finish().
void replay_file(const std::string& path, EventSink& sink, ReplayKinds kinds = {}, Progress* progress = nullptr);

}  // namespace rastrace
