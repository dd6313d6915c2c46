// replay, sweep and lru_profile: traces through the cache simulator, as `rastrace replay` and
// `rastrace sweep` run them, with the results as numpy columns keyed like their JSON output.
// A sweep's rows go to numpy without passing through a Table: a sweep may have millions of rows
// (docs/PERFORMANCE.md measures the conversion).
#include <array>
#include <memory>

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include "cache_sim/cache_spec.h"
#include "cache_sim/profile_sink.h"
#include "column_memory.h"
#include "columns.h"
#include "core/error.h"
#include "core/units.h"
#include "experiments/cache_report.h"
#include "experiments/replay_tables.h"

namespace rastrace::python {

namespace {

// The columns of byte_cache_table (experiments/cache_report.h), in its order.
constexpr std::array<const char*, 13> kByteColumns = {
    "size_bytes", "line_bytes", "assoc",         "policy",     "layout",   "accesses", "hits",
    "misses",     "miss_rate",  "bytes_fetched", "compulsory", "capacity", "conflict"};

// A byte-cache sweep's rows with the parameters of its table; columns() converts them.
struct SweepRows {
  std::vector<SweepRow> rows;
  std::string title;
  std::vector<std::pair<std::string, TableCell>> parameters;

  py::object columns() const {
    // The table the command line prints, without rows: its column keys and parameters.
    const Table empty = byte_cache_table(title, parameters, {}, source);
    for (std::size_t c = 0; c < kByteColumns.size(); ++c)
      if (empty.columns.at(c).key != kByteColumns[c])
        throw std::logic_error("sweep columns differ from byte_cache_table's: " + empty.columns[c].key);
    const std::size_t n = rows.size();
    // The columns come uninitialized (a std::vector would zero 100 MB first for 10^6 rows), large
    // ones in huge pages (column_memory.h), and the loop fills them without the GIL.
    py::array_t<std::int64_t> size = new_column<std::int64_t>(n), line = new_column<std::int64_t>(n),
                              assoc = new_column<std::int64_t>(n), accesses = new_column<std::int64_t>(n),
                              hits = new_column<std::int64_t>(n), misses = new_column<std::int64_t>(n),
                              bytes = new_column<std::int64_t>(n), compulsory = new_column<std::int64_t>(n),
                              capacity = new_column<std::int64_t>(n), conflict = new_column<std::int64_t>(n);
    py::array_t<double> miss_rate = new_column<double>(n);
    bool three_c = true;
    {
      std::int64_t* const out[] = {size.mutable_data(),   line.mutable_data(),       assoc.mutable_data(),
                                   accesses.mutable_data(), hits.mutable_data(),     misses.mutable_data(),
                                   bytes.mutable_data(),  compulsory.mutable_data(), capacity.mutable_data(),
                                   conflict.mutable_data()};
      double* const rate = miss_rate.mutable_data();
      py::gil_scoped_release release;
      for (std::size_t i = 0; i < n; ++i) {
        const SweepRow& r = rows[i];
        out[0][i] = static_cast<std::int64_t>(r.cache.size_bytes);
        out[1][i] = r.cache.line_bytes;
        out[2][i] = r.cache.assoc;
        out[3][i] = static_cast<std::int64_t>(r.stats.accesses);
        out[4][i] = static_cast<std::int64_t>(r.stats.hits);
        out[5][i] = static_cast<std::int64_t>(r.stats.misses);
        rate[i] = r.stats.miss_rate();
        out[6][i] = static_cast<std::int64_t>(r.stats.bytes_fetched);
        out[7][i] = static_cast<std::int64_t>(r.stats.compulsory);
        out[8][i] = r.stats.capacity;
        out[9][i] = r.stats.conflict;
        three_c = three_c && r.stats.has_three_c;
      }
    }
    TextColumn policy(n), layout(n);
    for (std::size_t i = 0; i < n; ++i) {
      policy.set(i, to_string(rows[i].cache.policy));
      layout.set(i, rows[i].layout);
    }
    py::dict columns;
    columns["size_bytes"] = size;
    columns["line_bytes"] = line;
    columns["assoc"] = assoc;
    columns["policy"] = policy.release();
    columns["layout"] = layout.release();
    columns["accesses"] = accesses;
    columns["hits"] = hits;
    columns["misses"] = misses;
    columns["miss_rate"] = miss_rate;
    columns["bytes_fetched"] = bytes;
    if (three_c) {  // sweeps always compute the split; without it the JSON has nulls
      columns["compulsory"] = compulsory;
      columns["capacity"] = capacity;
      columns["conflict"] = conflict;
    }
    return make_columns(columns, empty.title, empty.parameters);
  }
  std::string source;
};

// `rastrace sweep TRACE --cache SPEC` for a byte-cache spec, rows repeated `repeat` times (1 for
// a sweep; more only to measure the conversion of a large result, bench/python_columns.cpp).
SweepRows byte_sweep(const std::string& trace, const CacheSpec& cache, unsigned threads, std::size_t repeat) {
  const TraceSummary summary = summarize_trace(trace);
  SweepRows out;
  out.parameters = trace_parameters(trace, summary);
  const SweepSpec spec = sweep_spec(cache, default_source(summary));
  const SweepResult result = run_sweep(trace, spec, threads, false);
  if (spec.source == SweepSource::Texel) {
    out.parameters.emplace_back("texel_bytes", spec.layouts.front().texel_bytes);
    out.parameters.emplace_back("level_alignment_bytes", spec.layouts.front().alignment);
  } else if (spec.source == SweepSource::VertexBuffer) {
    out.parameters.emplace_back("vertex_stride_bytes", spec.stride);
  }
  out.parameters.emplace_back("random_seed", spec.seed);
  out.title = "Cache sweep over " + std::string(to_string(spec.source)) + " accesses";
  out.source = to_string(spec.source);
  out.rows.reserve(result.rows.size() * repeat);
  for (std::size_t k = 0; k < repeat; ++k) out.rows.insert(out.rows.end(), result.rows.begin(), result.rows.end());
  return out;
}

py::object sweep(const std::string& trace, const std::string& cache_text, unsigned threads, bool keep_vertex_cache) {
  std::optional<SweepRows> byte_rows;
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
    } else {
      byte_rows = byte_sweep(trace, cache, threads, 1);
    }
  }
  return byte_rows ? byte_rows->columns() : table_columns(vertex_table);
}

py::dict replay(const std::string& trace, const std::vector<std::string>& caches, bool keep_vertex_cache) {
  std::vector<Table> tables;
  {
    py::gil_scoped_release release;
    tables = replay_tables(trace, caches, keep_vertex_cache, "--cache", false);
  }
  // Keyed by what the caches see: vertex (post-transform), texel, vertex_buffer, address.
  py::dict out;
  for (const Table& table : tables) {
    std::string key = "vertex";
    for (const auto& [name, value] : table.parameters)
      if (name == "source")
        key = std::get<std::string>(value.value) == "vertex" ? "vertex_buffer" : std::get<std::string>(value.value);
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
        "dict: source (vertex = post-transform caches, texel, vertex_buffer, address) -> Columns keyed\n"
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

  py::class_<SweepRows>(m, "_SweepRows")
      .def("__len__", [](const SweepRows& r) { return r.rows.size(); })
      .def("columns", &SweepRows::columns);
  m.def(
      "_sweep_rows",
      [](const std::string& trace, const std::string& cache_text, std::size_t repeat) {
        py::gil_scoped_release release;
        const CacheSpec cache = parse_cache_spec(cache_text, "--cache");
        if (cache.kind != CacheKind::Byte) throw InputError("_sweep_rows: expected a byte-cache spec");
        return byte_sweep(trace, cache, 0, repeat);
      },
      py::arg("trace"), py::arg("cache"), py::arg("repeat") = 1,
      "A byte-cache sweep's rows, repeated `repeat` times, not yet converted (to time columns()).");
}

}  // namespace rastrace::python
