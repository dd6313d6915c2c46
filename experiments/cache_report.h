// Shared wiring of `rastrace replay` and `rastrace sweep`: cache specs from the command line,
// result tables (core/table.h) that state every parameter, gnuplot plots, output files.
#pragma once

#include <map>
#include <optional>
#include <span>
#include <string>
#include <vector>

#include "cache_sim/live_bank_sink.h"
#include "cache_sim/sweep.h"
#include "core/table.h"
#include "traces/replay_file.h"

namespace rastrace {

// The parameters every table about this trace states: the file and its metadata.
std::vector<std::pair<std::string, TableCell>> trace_parameters(const std::string& path, const TraceSummary& summary);

// A byte-cache sweep's title, and the parameters its table states beyond the trace's: the
// layout's texel size and level alignment (texel source) or the vertex stride, the random seed,
// and the sampling of a sampled sweep.
std::string sweep_title(const SweepSpec& spec);
void add_sweep_parameters(const SweepSpec& spec, std::vector<std::pair<std::string, TableCell>>& parameters);

// Byte-cache rows: size_bytes, line_bytes, assoc (0 = full), policy, layout, accesses, hits,
// misses, miss_rate, bytes_fetched, compulsory, capacity, conflict.
Table byte_cache_table(const std::string& title, std::vector<std::pair<std::string, TableCell>> parameters,
                       std::span<const SweepRow> rows, const std::string& source);
// Post-transform rows: policy, entries, lookups, misses, triangles, degenerate, vertices, acmr, atvr.
Table vertex_cache_table(const std::string& title, std::vector<std::pair<std::string, TableCell>> parameters,
                         const std::vector<VertexSweepRow>& rows);

// Depth and colour cache rows: source, size_bytes, line_bytes, assoc, policy, layout, pixel_bytes,
// reads, writes, read_misses, write_misses, bytes_read, bytes_written.
Table framebuffer_cache_table(std::vector<std::pair<std::string, TableCell>> parameters,
                              const std::vector<FramebufferCacheSpec>& caches, const std::vector<WriteBackStats>& stats);

// Writes to the file atomically, or to stdout when path is empty.
void write_output(const std::string& path, const std::string& text);

// Miss rate against cache size (log2 axis), one line per policy and layout (and line size and
// associativity when those vary). PNG or SVG by extension; written atomically through gnuplot.
void write_miss_rate_plot(const std::string& path, const std::string& title, std::span<const SweepRow> rows);

// Named series of (cache size in bytes, value), drawn against cache size on a log2 axis.
using PlotSeries = std::map<std::string, std::vector<std::pair<std::uint64_t, double>>>;
void write_size_plot(const std::string& path, const std::string& title, const std::string& y_label, PlotSeries series);

// The "set terminal" line for a .png or .svg path (InputError naming --plot otherwise), and a
// gnuplot run whose `script` (data blocks, settings) and `plot` commands write path atomically.
std::string gnuplot_terminal(const std::string& path, int width, int height);
void run_gnuplot(const std::string& path, const std::string& script, const std::string& plot);

// The default source for byte caches: texels when the trace has any, then addresses, then vertices.
SweepSource default_source(const TraceSummary& summary);

}  // namespace rastrace
