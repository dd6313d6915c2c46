// replay, sweep and lru_profile: traces through the cache simulator, as `rastrace replay` and
// `rastrace sweep` run them, with the results as numpy columns keyed like their JSON output.
// A byte sweep's rows go to numpy without passing through a Table, written into the columns by
// the sweep's workers: a sweep may have millions of rows (docs/PERFORMANCE.md measures the rest).
#include <array>
#include <memory>
#include <optional>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "cache_sim/cache_spec.h"
#include "cache_sim/profile_sink.h"
#include "columns.h"
#include "core/error.h"
#include "core/units.h"
#include "experiments/cache_report.h"
#include "experiments/replay_tables.h"
#include "sweep_columns.h"

namespace rastrace::python {

namespace {

// The column keys of byte_cache_table (experiments/cache_report.h), in its order.
constexpr std::array<const char*, 13> kByteColumns = {
    "size_bytes", "line_bytes", "assoc",         "policy",     "layout",   "accesses", "hits",
    "misses",     "miss_rate",  "bytes_fetched", "compulsory", "capacity", "conflict"};

// A byte-cache sweep: run() sweeps, its workers writing the numpy columns as rows finish
// (sweep_columns.h); columns() then hands them over. Everything columns() does is what a result
// costs beyond the sweep itself (bench/python_columns.cpp times it).
class ByteSweep {
 public:
  // GIL held (the columns' text objects are made here).
  ByteSweep(std::string trace, const TraceSummary& summary, SweepSpec spec)
      : trace_(std::move(trace)), spec_(std::move(spec)), columns_(std::make_unique<SweepColumns>(spec_)) {
    parameters_ = trace_parameters(trace_, summary);
    add_sweep_parameters(spec_, parameters_);
    title_ = sweep_title(spec_);
  }

  // Without the GIL. The rows are in the columns by now: freeing them is the sweep's last step
  // (the old conversion freed them after itself; the benchmark times neither).
  void run(unsigned threads, bool keep_rows) {
    rows_ = run_sweep(trace_, spec_, threads, false, columns_.get()).rows;
    if (!keep_rows) free_rows();
  }

  // Without the GIL: 10^6 rows are 190 MB of 4 KiB pages (docs/PERFORMANCE.md measures this).
  void free_rows() { SweepRows().swap(rows_); }

  std::size_t size() const { return columns_ ? columns_->rows() : 0; }

  // GIL held, once: the columns as rastrace.Columns, their memory handed to numpy.
  py::object columns() {
    if (!columns_) throw std::logic_error("a sweep's columns are handed over once");
    // The table the command line prints, without rows: its column keys and parameters.
    const Table empty = byte_cache_table(title_, parameters_, {}, to_string(spec_.source));
    for (std::size_t c = 0; c < kByteColumns.size(); ++c)
      if (empty.columns.at(c).key != kByteColumns[c])
        throw std::logic_error("sweep columns differ from byte_cache_table's: " + empty.columns[c].key);
    py::dict columns = columns_->release();
    columns_.reset();
    return make_columns(columns, empty.title, empty.parameters);
  }

  // The state run() ends in for a sweep of `repeat` times these rows, without a sweep of that
  // many configurations (the benchmark's 10^6-row result): the rows repeated, each repetition
  // written into fresh columns right after it is copied, as a worker writes its job's rows right
  // after their simulation (one sink call per repetition), then freed unless `keep_rows`.
  // write_columns = false copies the rows alone (the benchmark's baseline for the writes' cost).
  // Without the GIL but for the text objects.
  std::unique_ptr<ByteSweep> repeated(std::size_t repeat, bool write_columns, bool keep_rows) const {
    std::unique_ptr<ByteSweep> out(new ByteSweep(*this));
    py::gil_scoped_release release;
    out->rows_.reserve(rows_.size() * repeat);
    if (write_columns) out->columns_->begin(rows_.size() * repeat);
    std::vector<std::size_t> job(rows_.size());
    for (std::size_t k = 0; k < repeat; ++k) {
      out->rows_.insert(out->rows_.end(), rows_.begin(), rows_.end());
      for (std::size_t i = 0; i < job.size(); ++i) job[i] = k * rows_.size() + i;
      if (write_columns) out->columns_->done(out->rows_, job);
    }
    if (!keep_rows) out->free_rows();
    return out;
  }

 private:
  // A copy with the same parameters and new, empty columns (GIL held).
  ByteSweep(const ByteSweep& other)
      : trace_(other.trace_), spec_(other.spec_), columns_(std::make_unique<SweepColumns>(spec_)),
        title_(other.title_), parameters_(other.parameters_) {}

  std::string trace_;
  SweepSpec spec_;
  std::unique_ptr<SweepColumns> columns_;
  SweepRows rows_;
  std::string title_;
  std::vector<std::pair<std::string, TableCell>> parameters_;
};

// `rastrace sweep TRACE --cache SPEC` for a byte-cache spec, not yet handed over; keep_rows for
// repeated(). GIL held.
std::unique_ptr<ByteSweep> byte_sweep(const std::string& trace, const std::string& cache_text, unsigned threads,
                                      bool keep_rows) {
  std::optional<TraceSummary> summary;
  SweepSpec spec;
  {
    py::gil_scoped_release release;
    const CacheSpec cache = parse_cache_spec(cache_text, "--cache");
    if (cache.kind != CacheKind::Byte) throw InputError("_sweep_rows: expected a byte-cache spec");
    summary = summarize_trace(trace);
    spec = sweep_spec(cache, default_source(*summary));
  }
  auto sweep = std::make_unique<ByteSweep>(trace, *summary, std::move(spec));
  {
    py::gil_scoped_release release;
    sweep->run(threads, keep_rows);
  }
  return sweep;
}

py::object sweep(const std::string& trace, const std::string& cache_text, unsigned threads, bool keep_vertex_cache) {
  Table vertex_table;
  {
    py::gil_scoped_release release;
    const CacheSpec cache = parse_cache_spec(cache_text, "--cache");
    if (cache.kind == CacheKind::Vertex) {
      const TraceSummary summary = summarize_trace(trace);
      auto parameters = trace_parameters(trace, summary);
      const auto rows = run_vertex_sweep(trace, vertex_caches(cache), !keep_vertex_cache);
      parameters.emplace_back("vertex_cache_per_draw", keep_vertex_cache ? "kept" : "flushed");
      vertex_table = vertex_cache_table("Post-transform vertex cache sweep", parameters, rows);
    }
  }
  if (!vertex_table.columns.empty()) return table_columns(vertex_table);
  return byte_sweep(trace, cache_text, threads, false)->columns();
}

py::dict replay(const std::string& trace, const std::vector<std::string>& caches, bool keep_vertex_cache) {
  std::vector<Table> tables;
  {
    py::gil_scoped_release release;
    tables = replay_tables(trace, caches, keep_vertex_cache, "--cache", false);
  }
  // Keyed by what the caches see: vertex (post-transform), texel, vertex_buffer, address,
  // framebuffer, sectored, hierarchy: each table's kind without its "_cache" (a key per kind, so
  // no table replaces another).
  py::dict out;
  for (const Table& table : tables) {
    std::string key = table.kind == "texture_cache" ? "texel" : table.kind;
    if (key.ends_with("_cache")) key.resize(key.size() - 6);
    if (key == "hierarchy_level") key = "hierarchy";
    out[key.c_str()] = table_columns(table);
  }
  return out;
}

py::dict lru_profile(const std::string& trace, const std::string& line, const std::string& layout,
                     const std::string& source, const std::string& texel, const std::string& align,
                     const std::string& stride, std::uint64_t sets, std::uint32_t max_ways, std::uint32_t units,
                     std::uint32_t tile) {
  std::vector<std::uint64_t> histogram, misses, set_misses;
  std::uint64_t accesses = 0, compulsory = 0;
  LruProfileSpec spec;
  {
    py::gil_scoped_release release;
    const TraceSummary summary = summarize_trace(trace);
    spec.source = source.empty() ? default_source(summary) : parse_sweep_source(source);
    spec.line_bytes = static_cast<std::uint32_t>(parse_byte_size(line, "line"));
    spec.layout = parse_layout(layout);
    spec.layout.texel_bytes = static_cast<std::uint32_t>(parse_byte_size(texel, "texel"));
    spec.layout.alignment = parse_byte_size(align, "align");
    spec.stride = static_cast<std::uint32_t>(parse_byte_size(stride, "stride"));
    spec.sets = sets;
    spec.max_ways = max_ways;
    spec.units = units;
    spec.tile = tile;
    LruProfileSink sink(spec, summary.metadata.textures);
    replay_file(trace, sink);
    accesses = sink.accesses();
    compulsory = sink.compulsory();
    histogram = sink.histogram();
    // misses[c]: a fully associative LRU cache of c lines misses the first references and every
    // re-reference at stack distance c or more.
    misses.assign(histogram.size() + 1, compulsory);
    for (std::size_t c = histogram.size(); c-- > 0;) misses[c] = misses[c + 1] + histogram[c];
    if (sink.has_set_associative())
      for (std::uint32_t w = 1; w <= max_ways; ++w) set_misses.push_back(sink.set_misses(w));
  }
  py::dict out;
  out["source"] = to_string(spec.source);
  out["line_bytes"] = spec.line_bytes;
  out["accesses"] = accesses;
  out["compulsory"] = compulsory;
  out["histogram"] = to_array(std::move(histogram));
  out["misses"] = to_array(std::move(misses));
  if (sets) {
    out["sets"] = sets;
    out["set_misses"] = to_array(std::move(set_misses));
  }
  return out;
}

}  // namespace

void bind_caches(py::module_& m) {
  m.def("replay", &replay, py::arg("trace"), py::arg("caches"), py::arg("keep_vertex_cache") = false,
        "Replays a trace (.rtrace, .csv or .din) once through every cache of the cache specs (a list,\n"
        "as `rastrace replay --cache SPEC ...`), with the LiveBankSink live rendering uses. Returns a\n"
        "dict: source (vertex = post-transform caches, texel, vertex_buffer, address, framebuffer, sectored,\n"
        "hierarchy) -> Columns keyed\n"
        "like the JSON output.");
  m.def("sweep", &sweep, py::arg("trace"), py::arg("cache") = "size=1KiB..64KiB", py::arg("threads") = 0,
        py::arg("keep_vertex_cache") = false,
        "Every combination of a cache spec with alternatives over a trace, in parallel, as `rastrace\n"
        "sweep`: byte caches (size_bytes, line_bytes, assoc (0 = full), policy, layout, accesses, hits,\n"
        "misses, miss_rate, bytes_fetched, compulsory, capacity, conflict) or post-transform vertex\n"
        "caches (entries=...). Returns Columns, which pandas.DataFrame takes as is.");
  m.def("lru_profile", &lru_profile, py::arg("trace"), py::arg("line") = "64B", py::arg("layout") = "linear",
        py::arg("source") = "", py::arg("texel") = "4B", py::arg("align") = "4KiB", py::arg("stride") = "32B",
        py::arg("sets") = 0, py::arg("max_ways") = 16, py::arg("units") = 1, py::arg("tile") = 16,
        "The one-pass LRU profiles of a trace's address stream (source: texel, vertex or address; default\n"
        "what the trace holds): histogram[d] = re-references at stack distance d, misses[c] = misses of a\n"
        "fully associative LRU cache of c lines (every c at once, Mattson et al. 1970), and with sets > 0,\n"
        "set_misses[w-1] = misses of the LRU cache of that many sets and w ways, w = 1..max_ways.\n"
        "units > 1 (texel source): the accesses are dealt out by screen tile (tile pixels) to that many\n"
        "texture units, each with its own cache, as `rastrace replay --level ... --units N --tile T`;\n"
        "the figures are sums over the units: a hierarchy's first level at every size at once.");

  py::class_<ByteSweep>(m, "_SweepRows")
      .def("__len__", &ByteSweep::size)
      .def("repeated", &ByteSweep::repeated, py::arg("repeat"), py::arg("write_columns") = true,
           py::arg("keep_rows") = false,
           "The state of a sweep of `repeat` times these rows, columns written as the sweep writes them.")
      .def("free_rows", &ByteSweep::free_rows, py::call_guard<py::gil_scoped_release>(),
           "Frees the rows kept by repeated(keep_rows=True), as the sweep's last step does.")
      .def("columns", &ByteSweep::columns, "The Columns (once): what a result costs beyond the sweep.");
  m.def(
      "_sweep_rows",
      [](const std::string& trace, const std::string& cache_text) { return byte_sweep(trace, cache_text, 0, true); },
      py::arg("trace"), py::arg("cache"),
      "A byte-cache sweep whose columns are not yet handed over and whose rows are kept (for repeated()).");
}

}  // namespace rastrace::python
