#include "experiments/cache_report.h"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <iterator>
#include <fstream>
#include <iostream>
#include <map>
#include <set>

#include "core/atomic_file.h"
#include "core/error.h"
#include "core/units.h"

namespace rastrace {

std::vector<std::pair<std::string, TableCell>> trace_parameters(const std::string& path, const TraceSummary& s) {
  std::vector<std::pair<std::string, TableCell>> p;
  p.emplace_back("trace", std::filesystem::path(path).filename().string());
  const char* format = s.format == TraceFileFormat::Container ? "rastrace"
                       : s.format == TraceFileFormat::Csv     ? "csv"
                                                              : "din";
  p.emplace_back("trace_format", format);
  if (s.format != TraceFileFormat::Din) {
    p.emplace_back("scene", s.metadata.scene);
    p.emplace_back("ordering", s.metadata.ordering);
    p.emplace_back("resolution", std::to_string(s.metadata.width) + "x" + std::to_string(s.metadata.height));
    p.emplace_back("filter", s.metadata.filter);
    p.emplace_back("trace_tool_version", s.metadata.tool_version);
    // A layout without ":format" replays the trace's formats: say which they are.
    std::string formats;
    bool compressed = false;
    for (const auto& levels : s.metadata.textures) {
      const TextureFormat f = levels.empty() ? TextureFormat::Rgba8 : levels.front().format;
      compressed = compressed || is_compressed(f);
      formats += (formats.empty() ? "" : ",") + std::string(to_string(f));
    }
    if (compressed) p.emplace_back("texture_formats", formats);
  }
  return p;
}

std::string sweep_title(const SweepSpec& spec) {
  return "Cache sweep over " + std::string(to_string(spec.source)) + " accesses";
}

void add_sweep_parameters(const SweepSpec& spec, std::vector<std::pair<std::string, TableCell>>& parameters) {
  if (spec.source == SweepSource::Texel) {
    parameters.emplace_back("texel_bytes", spec.layouts.front().texel_bytes);
    parameters.emplace_back("level_alignment_bytes", spec.layouts.front().alignment);
  } else if (spec.source == SweepSource::VertexBuffer) {
    parameters.emplace_back("vertex_stride_bytes", spec.stride);
  }
  parameters.emplace_back("random_seed", spec.seed);
  if (spec.sample)
    parameters.emplace_back("sampling", describe(*spec.sample) +
                                            " of the lines by spatial hash: fully associative LRU by SHARDS "
                                            "(Waldspurger et al. 2015), other caches by miniature simulation "
                                            "(Waldspurger et al. 2017); expected error = 3.499 s / sqrt(8) + |full - mean| "
                                            "of 8 independent part samples (s their standard deviation: 99% confidence "
                                            "for the noise; the shift of the full sample from their mean for the bias); "
                                            "simulated exactly instead: the whole sweep when records x rows <= " +
                                            std::to_string(spec.sample_guards.exact_accesses) +
                                            ", a row whose scaled cache holds under " +
                                            std::to_string(spec.sample_guards.min_sampled_lines) +
                                            " sampled lines, a set-associative row of under " +
                                            std::to_string(spec.sample_guards.min_sampled_assoc) + " ways");
}

Table byte_cache_table(const std::string& title, std::vector<std::pair<std::string, TableCell>> parameters,
                       std::span<const SweepRow> rows, const std::string& source) {
  Table t;
  t.title = title;
  t.parameters = std::move(parameters);
  t.parameters.emplace_back("source", source);
  t.columns = {{"size_bytes", "size (B)", 0},
               {"line_bytes", "line (B)", 0},
               {"assoc", "assoc (0=full)", 0},
               {"policy", "policy", 0},
               {"layout", "layout", 0},
               {"accesses", "accesses", 0},
               {"hits", "hits", 0},
               {"misses", "misses", 0},
               {"miss_rate", "miss rate", 5},
               {"bytes_fetched", "bytes fetched", 0},
               {"compulsory", "compulsory", 0},
               {"capacity", "capacity", 0},
               {"conflict", "conflict", 0}};
  // A sampled sweep (sweep --sample) says how each row was estimated and its expected error.
  const bool sampled = std::any_of(rows.begin(), rows.end(), [](const SweepRow& r) { return r.expected_error >= 0; });
  if (sampled) {
    t.parameters.emplace_back("method", sweep_method(rows));
    t.columns.push_back({"estimated_by", "estimated by", 0});
    t.columns.push_back({"expected_error", "expected error", 5});
  }
  for (const SweepRow& r : rows) {
    const CacheStats& s = r.stats;
    std::vector<TableCell> cells = {r.cache.size_bytes, r.cache.line_bytes, r.cache.assoc, to_string(r.cache.policy),
                                    r.layout,           s.accesses,         s.hits,        s.misses,
                                    s.miss_rate(),      s.bytes_fetched};
    if (s.has_three_c) {
      cells.emplace_back(s.compulsory);
      cells.emplace_back(s.capacity);
      cells.emplace_back(s.conflict);
    } else {
      cells.resize(13);
    }
    if (sampled) {
      cells.emplace_back(r.sampled_as);
      cells.emplace_back(r.expected_error);
    }
    t.add_row(std::move(cells));
  }
  return t;
}

Table vertex_cache_table(const std::string& title, std::vector<std::pair<std::string, TableCell>> parameters,
                         const std::vector<VertexSweepRow>& rows) {
  Table t;
  t.title = title;
  t.parameters = std::move(parameters);
  t.columns = {{"policy", "policy", 0},     {"entries", "entries", 0},     {"lookups", "lookups", 0},
               {"misses", "misses", 0},     {"triangles", "triangles", 0}, {"degenerate", "degenerate", 0},
               {"vertices", "vertices", 0}, {"acmr", "ACMR", 3},           {"atvr", "ATVR", 3}};
  // Warp and batch models (cache_sim/vertex_reuse.h) add their name, warps and lane use; their
  // full parameters go into the table's parameters.
  const bool batched = std::any_of(rows.begin(), rows.end(), [](const VertexSweepRow& r) { return r.cache.batched(); });
  if (batched) {
    t.columns.insert(t.columns.begin(), TableColumn{"model", "model", 0});
    t.columns.push_back({"warps", "warps", 0});
    t.columns.push_back({"lane_slots", "lane slots", 0});
    t.columns.push_back({"lane_use", "lane use", 3});
    std::set<std::string> stated;
    for (const VertexSweepRow& r : rows)
      if (const std::string name = vertex_reuse_name(r.cache); stated.insert(name).second)
        t.parameters.emplace_back("model " + name, vertex_reuse_parameters(r.cache));
  }
  for (const VertexSweepRow& r : rows) {
    const bool fifo_family = r.cache.kind != VertexReuseKind::KerblBatch;
    std::vector<TableCell> row = {fifo_family ? TableCell(to_string(r.cache.policy)) : TableCell(),
                                  fifo_family ? TableCell(r.cache.entries) : TableCell(),
                                  r.stats.lookups,
                                  r.stats.misses,
                                  r.stats.triangles,
                                  r.stats.degenerate,
                                  r.stats.vertices,
                                  r.stats.acmr(),
                                  r.stats.atvr()};
    if (batched) {
      row.insert(row.begin(), vertex_reuse_name(r.cache));
      row.emplace_back(r.stats.warps);
      row.push_back(r.stats.lane_slots ? TableCell(r.stats.lane_slots) : TableCell());
      row.push_back(r.stats.lane_slots ? TableCell(r.stats.lane_use()) : TableCell());
    }
    t.add_row(std::move(row));
  }
  return t;
}

void write_output(const std::string& path, const std::string& text) {
  if (path.empty()) {
    std::cout << text;
    if (!text.empty() && text.back() != '\n') std::cout << '\n';
    return;
  }
  write_file_atomically(
      path, [&](std::ostream& out) { out << text; }, false);
}

Table framebuffer_cache_table(std::vector<std::pair<std::string, TableCell>> parameters,
                              const std::vector<FramebufferCacheSpec>& caches, const std::vector<WriteBackStats>& stats) {
  Table table;
  table.title = "Depth and colour caches (write-back; write misses allocate without reading)";
  table.parameters = std::move(parameters);
  table.columns = {{"source", "buffer", 0},         {"size_bytes", "size", 0},         {"line_bytes", "line", 0},
                   {"assoc", "assoc (0=full)", 0},  {"policy", "policy", 0},           {"layout", "layout", 0},
                   {"pixel_bytes", "pixel", 0},     {"reads", "reads", 0},             {"writes", "writes", 0},
                   {"read_misses", "read misses", 0}, {"write_misses", "write misses", 0},
                   {"bytes_read", "bytes read", 0}, {"bytes_written", "bytes written", 0}};
  for (std::size_t i = 0; i < caches.size(); ++i) {
    const FramebufferCacheSpec& c = caches[i];
    const WriteBackStats& s = stats.at(i);
    table.add_row({to_string(c.buffer), c.cache.size_bytes, c.cache.line_bytes,
                   c.cache.assoc, to_string(c.cache.policy),
                   layout_name(c.layout), c.layout.texel_bytes, s.reads, s.writes, s.read_misses, s.write_misses,
                   s.bytes_read, s.bytes_written});
  }
  return table;
}

SweepSource default_source(const TraceSummary& s) {
  if (s.format == TraceFileFormat::Din) return SweepSource::Address;
  if (s.has_counts) {
    if (s.texels) return SweepSource::Texel;
    if (s.addresses) return SweepSource::Address;
    return SweepSource::VertexBuffer;
  }
  return s.metadata.textures.empty() ? SweepSource::VertexBuffer : SweepSource::Texel;
}

void write_miss_rate_plot(const std::string& path, const std::string& title, std::span<const SweepRow> rows) {
  std::set<std::uint32_t> lines, assocs;
  for (const SweepRow& r : rows) {
    lines.insert(r.cache.line_bytes);
    assocs.insert(r.cache.assoc);
  }
  // Series keyed by everything but the size.
  PlotSeries series;
  for (const SweepRow& r : rows) {
    std::string name = std::string(to_string(r.cache.policy)) + " " + r.layout;
    if (lines.size() > 1) name += " " + format_byte_size(r.cache.line_bytes) + " lines";
    if (assocs.size() > 1) name += r.cache.assoc == 0 ? " full" : " " + std::to_string(r.cache.assoc) + "-way";
    series[name].emplace_back(r.cache.size_bytes, r.stats.miss_rate());
  }
  write_size_plot(path, title, "miss rate", series);
}

std::string gnuplot_terminal(const std::string& path, int width, int height) {
  std::string extension = std::filesystem::path(path).extension().string();
  for (char& c : extension) c = static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  if (extension != ".png" && extension != ".svg")
    throw InputError("--plot " + path + ": expected a .png or .svg file name");
  const std::string size = " size " + std::to_string(width) + "," + std::to_string(height) + " noenhanced\n";
  return (extension == ".png" ? "set terminal pngcairo" : "set terminal svg") + size;
}

namespace {

// gnuplot exits 0 when its output file could not be written whole (a full disk): a plot counts
// as written only when it ends as its format ends (PNG's IEND chunk, SVG's closing tag).
bool plot_is_whole(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  static const std::string png_end("\0\0\0\0IEND\xAE\x42\x60\x82", 12);
  if (bytes.starts_with("\x89PNG")) return bytes.ends_with(png_end);
  const std::size_t end = bytes.rfind("</svg>");
  return end != std::string::npos && bytes.find_first_not_of(" \r\n", end + 6) == std::string::npos;
}

}  // namespace

void run_gnuplot(const std::string& path, const std::string& script, const std::string& plot) {
  // gnuplot writes a PNG it cannot open on its stdout: never let it get that far.
  const std::filesystem::path folder = std::filesystem::path(path).parent_path();
  if (!folder.empty() && !std::filesystem::is_directory(folder))
    throw InputError("--plot " + path + ": folder " + folder.string() + " does not exist");
  write_via_temporary(path, [&](const std::filesystem::path& temporary) {
    const std::string full = script + "set output '" + temporary.string() + "'\n" + plot + "\nunset output\n";
    // gnuplot's messages go to stderr; its stdout (nothing, or image bytes) never reaches ours.
    FILE* gnuplot = popen("gnuplot >/dev/null", "w");
    if (!gnuplot) throw InputError("--plot: cannot run gnuplot (install gnuplot-nox)");
    std::fwrite(full.data(), 1, full.size(), gnuplot);
    const int status = pclose(gnuplot);
    if (status != 0 || !std::filesystem::exists(temporary) || std::filesystem::file_size(temporary) == 0)
      throw InputError("--plot " + path + ": gnuplot failed (exit status " + std::to_string(status) + ")");
    if (!plot_is_whole(temporary)) throw InputError("--plot " + path + ": write failed (disk full?): the plot is cut short");
  });
}

void write_size_plot(const std::string& path, const std::string& title, const std::string& y_label, PlotSeries series) {
  std::string script = gnuplot_terminal(path, 1000, 650);
  script += "set logscale x 2\nset xlabel 'cache size'\nset ylabel '" + y_label + "'\n";
  std::set<std::uint64_t> sizes;
  for (const auto& entry : series)
    for (const auto& point : entry.second) sizes.insert(point.first);
  std::string tics;
  for (const std::uint64_t size : sizes)
    tics += (tics.empty() ? "" : ", ") + std::string("'") + format_byte_size(size) + "' " + std::to_string(size);
  script += "set xtics (" + tics + ")\n";
  // Margins left and right so the first and last size tics keep their labels.
  script += "set key outside right\nset grid\nset yrange [0:*]\nset offsets graph 0.03, graph 0.03, 0, 0\n";
  std::string quoted_title = title;
  for (char& c : quoted_title)
    if (c == '\'' || c == '\n') c = ' ';
  script += "set title '" + quoted_title + "'\n";
  int index = 0;
  for (auto& [name, points] : series) {
    std::sort(points.begin(), points.end());
    script += "$s" + std::to_string(index++) + " << EOD\n";
    for (const auto& [size, rate] : points) {
      char line[64];
      std::snprintf(line, sizeof(line), "%llu %.9g\n", static_cast<unsigned long long>(size), rate);
      script += line;
    }
    script += "EOD\n";
  }
  std::string plot = "plot ";
  index = 0;
  for (const auto& entry : series) {
    if (index) plot += ", ";
    plot += "$s" + std::to_string(index++) + " using 1:2 with linespoints title '" + entry.first + "'";
  }
  run_gnuplot(path, script, plot);
}

}  // namespace rastrace
