// Text formats for traces, so users can inspect them and bring their own:
//   CSV (export and import): one event per row, fixed columns
//     event,draw,type,restart,vertex,primitive_start,texture,level,x,y,pixel_x,pixel_y,triangle,address,label
//   with event = begin_draw | end_draw | vertex | texel | address and the other columns empty when
//   they do not apply (restart is empty unless the draw is a strip with primitive restart); the
//   first line is "# rastrace metadata: <metadata JSON>".
//   Dinero IV din (import): "label hexaddress" per line, label 0 read, 1 write, 2 instruction
//   fetch (all three are accesses); 3 (escape) lines are skipped; 4 (cache flush) is refused.
//   Extended din, Dinero IV's default, adds a third field, the size in hexadecimal: it is checked
//   and the access counted once, at its first byte (cache_sim/trace_export.h writes this format).
// Malformed lines give an InputError "file:line: ..." saying what was expected.
#pragma once

#include <ostream>
#include <string>

#include "traces/sink.h"
#include "traces/trace_metadata.h"
#include "traces/trace_reader.h"

namespace rastrace {

// Writes every record of the trace as CSV (bounded memory: chunk by chunk). A trace of several
// frames is an InputError: CSV has no frame boundaries.
void export_csv(TraceReader& reader, std::ostream& out);
// The metadata in a CSV's first line (defaults when the line is absent).
TraceMetadata read_csv_metadata(const std::string& path);
// Feeds a CSV's events into the sink (in file order), then calls sink.finish().
void import_csv(const std::string& path, EventSink& sink);
// Feeds a din file's accesses into the sink as address accesses, then calls sink.finish().
// Returns the number of accesses.
std::uint64_t import_din(const std::string& path, EventSink& sink);

}  // namespace rastrace
