#include "experiments/vipm_experiment.h"

#include <algorithm>
#include <cstdio>
#include <map>
#include <sstream>

#include <nlohmann/json.hpp>

#include "cache_sim/cache_spec.h"
#include "core/error.h"
#include "experiments/cache_report.h"
#include "lod/progressive_mesh.h"
#include "lod/vipm_measure_methods.h"

namespace rastrace {

namespace {

// Command-line name, the representation's method(), Forsyth's column.
struct MethodName {
  const char* cli;
  const char* representation;
  const char* column;
};
constexpr MethodName kMethods[] = {
    {"vanilla", "vanilla", "Vanilla"},
    {"skipstrips", "skip-strips-strip", "Skip Strips"},
    {"skiplists", "skip-strips-list", "Skip Strips"},
    {"mixed", "mixed-list", "Mixed-Mode"},
    {"mixedstrips", "mixed-strip", "Mixed-Mode"},
    {"sliding", "sliding-window", "Sliding Window"},
};

const MethodName& method_by_cli(const std::string& name, const char* flag = "--methods",
                                const char* expected = "all or a comma-separated list of") {
  for (const MethodName& m : kMethods)
    if (name == m.cli) return m;
  std::string accepted;
  for (const std::string& n : vipm_method_names()) accepted += (accepted.empty() ? "" : ", ") + n;
  throw InputError(std::string(flag) + " '" + name + "': expected " + expected + " " + accepted);
}

std::vector<std::string> parse_methods(const std::string& text) {
  if (text == "all") return vipm_method_names();
  std::vector<std::string> out;
  std::stringstream list(text);
  for (std::string name; std::getline(list, name, ',');) {
    method_by_cli(name);  // throws for an unknown name
    if (std::find(out.begin(), out.end(), name) == out.end()) out.push_back(name);
  }
  if (out.empty()) method_by_cli("");
  return out;
}

// Table 4.1.1 of Forsyth 2001, typed from the article: rows in forsyth_qualities' order, columns
// Vanilla, Skip Strips (multilevel), Mixed-Mode, Sliding Window.
const char* const kForsythWords[6][4] = {
    {"Poor", "Excellent", "Good", "Good"},   // vertex cache use
    {"Low", "Medium", "Medium", "High"},     // global memory use
    {"High", "High", "Medium", "Low"},       // instance memory use
    {"Medium", "Medium", "Medium", "Tiny"},  // LoD-change CPU cost
    {"Good", "Good", "Good", "Excellent"},   // API efficiency
    {"Poor", "Excellent", "Good", "Good"},   // list efficiency
};
int forsyth_column_index(const std::string& column) {
  const char* const columns[] = {"Vanilla", "Skip Strips", "Mixed-Mode", "Sliding Window"};
  for (int i = 0; i < 4; ++i)
    if (column == columns[i]) return i;
  throw std::logic_error("no Forsyth column " + column);
}

std::string method_heading(const std::string& method) { return method + " (" + forsyth_column(method) + ")"; }

}  // namespace

const std::vector<std::string>& vipm_method_names() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> out;
    for (const MethodName& m : kMethods) out.push_back(m.cli);
    return out;
  }();
  return names;
}

std::string forsyth_column(const std::string& method) { return method_by_cli(method).column; }

std::string vipm_representation_of(const std::string& method, const char* flag) {
  return method_by_cli(method, flag, "one of").representation;
}

VipmExperiment run_vipm_experiment(const Mesh& mesh, const std::string& mesh_name, const VipmExperimentSpec& spec) {
  VipmExperiment out;
  out.mesh = mesh_name;
  out.spec = spec;
  out.methods = parse_methods(spec.methods);
  if (spec.lod_step == 0) throw InputError("--lod-step 0: expected a positive number of collapses");
  if (spec.cache.entries == 0) throw InputError("--cache: expected at least 1 entry");

  ProgressiveMeshParams pm_params;
  pm_params.min_triangles = spec.min_triangles;
  const ProgressiveMesh pm = build_progressive_mesh(mesh, pm_params);
  out.collapses = static_cast<std::uint32_t>(pm.collapses.size());
  out.full_triangles = pm.triangles.size();
  VipmMethodsParams methods_params;
  methods_params.tolerance = spec.tolerance;
  VipmMethods methods = build_vipm_methods(pm, reordered_mesh(mesh, pm), methods_params);
  out.sliding_levels_strict = methods.sliding_window_strict_levels;
  out.sliding_levels_tolerance_0 = methods.sliding_window_levels_tolerance_0;
  out.sliding_levels = methods.sliding_window_order.levels;

  VipmMeasureParams measure;
  measure.policy = spec.cache.policy;
  measure.cache_entries = spec.cache.entries;
  measure.lod_step = spec.lod_step;
  for (const std::string& name : out.methods) {
    const std::string representation = method_by_cli(name).representation;
    for (auto& r : methods.representations) {
      if (r->method() != representation) continue;
      std::vector<VipmLodRow> rows = measure_vipm(*r, measure);
      VipmSummary summary = summarize_vipm(*r, rows);
      summary.method = name;
      for (VipmLodRow& row : rows) row.method = name;
      out.rows.insert(out.rows.end(), rows.begin(), rows.end());
      out.summaries.push_back(summary);
    }
  }
  return out;
}

namespace {

std::vector<std::pair<std::string, TableCell>> parameters(const VipmExperiment& e) {
  std::uint32_t bits = 16;
  for (const VipmSummary& s : e.summaries) bits = std::max(bits, s.index_bits);
  return {{"mesh", e.mesh},
          {"cache", format_cache_spec(e.spec.cache)},
          {"lod_step", e.spec.lod_step},
          {"collapses", e.collapses},
          {"full_triangles", e.full_triangles},
          {"index_width", std::to_string(bits) + "-bit"},
          {"tolerance", e.spec.tolerance},
          {"sliding_levels_builder_order", e.sliding_levels_strict},
          {"sliding_levels_tolerance_0", e.sliding_levels_tolerance_0},
          {"sliding_levels_at_tolerance", e.sliding_levels},
          {"frame", "caches cold per draw; ACMR over drawn (non-degenerate) triangles"}};
}

double lod_change_indices_per_collapse(const VipmExperiment& e, const std::string& method, std::uint32_t index_bytes) {
  // Indices rewritten by records plus indices copied by level switches, over the collapses.
  double writes = 0.0, collapses = 0.0;
  for (const VipmLodRow& row : e.rows) {
    if (row.method != method) continue;
    writes += double(row.collapse_cost.index_writes) + double(row.collapse_cost.bytes_copied) / index_bytes;
    collapses += double(row.collapse_cost.collapses);
  }
  return collapses > 0 ? writes / collapses : 0.0;
}

}  // namespace

Table vipm_lod_table(const VipmExperiment& e) {
  Table table;
  table.title = "VIPM per LoD: " + e.mesh;
  table.kind = "vipm_lod";
  table.parameters = parameters(e);
  table.columns = {{"method", "method", 0},
                   {"lod", "LoD", 0},
                   {"level", "level", 0},
                   {"triangles", "triangles", 0},
                   {"degenerate", "degenerate", 0},
                   {"acmr", "vertices/triangle", 3},
                   {"indices", "indices", 0},
                   {"index_bytes", "index bytes", 0},
                   {"draw_calls", "draws", 0},
                   {"instance_bytes", "instance bytes", 0},
                   {"collapse_index_writes", "collapse writes", 0},
                   {"split_index_writes", "split writes", 0}};
  for (const VipmLodRow& r : e.rows)
    table.add_row({r.method, r.lod, r.level, r.triangles, r.degenerate, r.vertices_per_triangle, r.indices,
                   r.index_bytes, r.draw_calls, r.instance_bytes, r.collapse_cost.index_writes,
                   r.split_cost.index_writes});
  return table;
}

Table vipm_summary_table(const VipmExperiment& e) {
  Table table;
  table.title = "VIPM summary: " + e.mesh;
  table.kind = "vipm_summary";
  table.parameters = parameters(e);
  table.columns = {{"method", "method", 0},
                   {"index_bits", "index bits", 0},
                   {"levels", "levels", 0},
                   {"lods", "LoDs measured", 0},
                   {"mean_acmr", "mean vertices/triangle", 3},
                   {"mean_degenerate_fraction", "degenerate fraction", 3},
                   {"mean_index_bytes", "index bytes/frame", 0},
                   {"mean_draw_calls", "draws/frame", 2},
                   {"global_bytes", "global bytes", 0},
                   {"instance_bytes", "mean instance bytes", 0},
                   {"max_instance_bytes", "max instance bytes", 0},
                   {"index_writes_per_collapse", "index writes/collapse", 3},
                   {"index_writes_per_split", "index writes/split", 3},
                   {"level_switches", "level switches", 0},
                   {"layout", "layout", 0}};
  for (const VipmSummary& s : e.summaries)
    table.add_row({s.method, s.index_bits, s.levels, s.lods_measured, s.mean_vertices_per_triangle,
                   s.mean_degenerate_fraction, s.mean_index_bytes, s.mean_draw_calls, s.global_bytes,
                   s.mean_instance_bytes, s.max_instance_bytes, s.index_writes_per_collapse, s.index_writes_per_split,
                   s.level_switches, s.layout});
  return table;
}

std::vector<ForsythQuality> forsyth_qualities(const VipmExperiment& e) {
  std::vector<ForsythQuality> q = {
      {"Vertex cache use", "v/tri", "mean vertices per drawn triangle over the LoDs", true, {}, {}},
      {"Global memory use", "B", "bytes shared by all instances (vertices, lists, records, tables)", true, {}, {}},
      {"Instance memory use", "B", "bytes per instance, mean over the LoDs", true, {}, {}},
      {"LoD-change CPU cost", "idx/collapse", "indices written per collapse (records and level copies)", true, {}, {}},
      {"API efficiency", "draws", "draw calls per frame, mean over the LoDs", true, {}, {}},
      {"List efficiency", "B/tri", "index bytes sent per drawn triangle (degenerates included)", true, {}, {}},
  };
  for (const VipmSummary& s : e.summaries) {
    double index_bytes = 0.0, triangles = 0.0;
    for (const VipmLodRow& r : e.rows)
      if (r.method == s.method) index_bytes += double(r.index_bytes), triangles += double(r.triangles);
    const double values[6] = {s.mean_vertices_per_triangle,
                              double(s.global_bytes),
                              s.mean_instance_bytes,
                              lod_change_indices_per_collapse(e, s.method, s.index_bits / 8),
                              s.mean_draw_calls,
                              triangles > 0 ? index_bytes / triangles : 0.0};
    const int column = forsyth_column_index(forsyth_column(s.method));
    for (int i = 0; i < 6; ++i) {
      q[i].values.push_back(values[i]);
      q[i].words.push_back(kForsythWords[i][column]);
    }
  }
  return q;
}

static int forsyth_word_score(const std::string& word) {
  static const std::map<std::string, int> scores = {{"Poor", 0}, {"High", 0}, {"Medium", 1},   {"Good", 2},
                                                    {"Low", 2},  {"Tiny", 3}, {"Excellent", 3}};
  return scores.at(word);
}

std::string forsyth_agreement(const ForsythQuality& q, std::size_t method, const std::vector<std::string>& names) {
  std::string against;
  for (std::size_t other = 0; other < q.values.size(); ++other) {
    const int a = forsyth_word_score(q.words[method]), b = forsyth_word_score(q.words[other]);
    if (a == b) continue;
    const bool measured_better =
        q.lower_is_better ? q.values[method] < q.values[other] : q.values[method] > q.values[other];
    if (measured_better != (a > b)) against += (against.empty() ? "" : ", ") + names[other];
  }
  return against.empty() ? "agrees" : "disagrees (vs " + against + ")";
}

static std::string format_quality_value(double value, const std::string& unit) {
  char text[64];
  if (unit == "B")
    std::snprintf(text, sizeof text, "%.0f %s", value, unit.c_str());
  else
    std::snprintf(text, sizeof text, "%.3f %s", value, unit.c_str());
  return text;
}

Table vipm_forsyth_table(const VipmExperiment& e) {
  Table table;
  table.title = "Forsyth's Table 4.1.1 beside the measurements: " + e.mesh;
  table.kind = "vipm_forsyth";
  table.parameters = parameters(e);
  const std::vector<ForsythQuality> qualities = forsyth_qualities(e);
  table.parameters.emplace_back("agreement", forsyth_agreement_rule());
  table.columns = {{"quality", "quality", 0}};
  for (const std::string& m : e.methods) table.columns.push_back({m, method_heading(m), 0});
  table.columns.push_back({"measure", "measured as", 0});
  for (const ForsythQuality& q : qualities) {
    std::vector<TableCell> row = {q.quality};
    for (std::size_t i = 0; i < q.values.size(); ++i)
      row.emplace_back(format_quality_value(q.values[i], q.unit) + " (" + q.words[i] + ")");
    row.emplace_back(q.measure);
    table.add_row(row);
  }
  return table;
}

std::string forsyth_agreement_rule() {
  return "a method agrees when, against every method Forsyth rates differently (Poor/High < Medium < Good/Low < "
         "Excellent/Tiny), our number ranks it the same way";
}

std::string vipm_json(const VipmExperiment& e) {
  nlohmann::ordered_json out;
  nlohmann::ordered_json params = nlohmann::ordered_json::object();
  for (const auto& [key, cell] : parameters(e)) {
    if (const auto* s = std::get_if<std::string>(&cell.value)) params[key] = *s;
    if (const auto* i = std::get_if<std::int64_t>(&cell.value)) params[key] = *i;
    if (const auto* d = std::get_if<double>(&cell.value)) params[key] = *d;
  }
  out["parameters"] = params;
  out["lods"] = nlohmann::ordered_json::array();
  for (const VipmLodRow& r : e.rows)
    out["lods"].push_back({{"method", r.method},
                           {"lod", r.lod},
                           {"level", r.level},
                           {"triangles", r.triangles},
                           {"degenerate", r.degenerate},
                           {"acmr", r.vertices_per_triangle},
                           {"indices", r.indices},
                           {"index_bytes", r.index_bytes},
                           {"draw_calls", r.draw_calls},
                           {"instance_bytes", r.instance_bytes},
                           {"collapse_index_writes", r.collapse_cost.index_writes},
                           {"split_index_writes", r.split_cost.index_writes}});
  out["summary"] = nlohmann::ordered_json::array();
  for (const VipmSummary& s : e.summaries)
    out["summary"].push_back({{"method", s.method},
                              {"index_bits", s.index_bits},
                              {"levels", s.levels},
                              {"lods_measured", s.lods_measured},
                              {"mean_acmr", s.mean_vertices_per_triangle},
                              {"mean_degenerate_fraction", s.mean_degenerate_fraction},
                              {"mean_index_bytes", s.mean_index_bytes},
                              {"mean_draw_calls", s.mean_draw_calls},
                              {"global_bytes", s.global_bytes},
                              {"instance_bytes", s.mean_instance_bytes},
                              {"max_instance_bytes", s.max_instance_bytes},
                              {"index_writes_per_collapse", s.index_writes_per_collapse},
                              {"index_writes_per_split", s.index_writes_per_split},
                              {"level_switches", s.level_switches},
                              {"layout", s.layout}});
  nlohmann::ordered_json forsyth = nlohmann::ordered_json::array();
  for (const ForsythQuality& q : forsyth_qualities(e)) {
    nlohmann::ordered_json row = {{"quality", q.quality}, {"unit", q.unit}, {"measure", q.measure}};
    for (std::size_t i = 0; i < q.values.size(); ++i)
      row[e.methods[i]] = {{"value", q.values[i]}, {"forsyth", q.words[i]}};
    forsyth.push_back(row);
  }
  out["forsyth"] = forsyth;
  return out.dump(2) + "\n";
}

void write_vipm_plot(const std::string& path, const VipmExperiment& e) {
  std::string script = gnuplot_terminal(path, 1400, 600);
  std::string plot = "set multiplot layout 1,2 title 'VIPM: " + e.mesh + " (" + format_cache_spec(e.spec.cache) +
                     ")'\nset grid\nset key top left\nset xlabel 'drawn triangles'\n"
                     "set ylabel 'vertices per triangle'\nset yrange [0:*]\nplot ";
  for (std::size_t m = 0; m < e.methods.size(); ++m) {
    script += "$m" + std::to_string(m) + " << EOD\n";
    for (const VipmLodRow& r : e.rows)
      if (r.method == e.methods[m]) {
        char line[64];
        std::snprintf(line, sizeof line, "%llu %.9g\n", static_cast<unsigned long long>(r.triangles),
                      r.vertices_per_triangle);
        script += line;
      }
    script += "EOD\n";
    plot +=
        (m ? ", " : "") + std::string("$m") + std::to_string(m) + " using 1:2 with lines title '" + e.methods[m] + "'";
  }
  script += "$memory << EOD\n";
  for (const VipmSummary& s : e.summaries) {
    char line[128];
    std::snprintf(line, sizeof line, "%s %.9g %.9g\n", s.method.c_str(), double(s.global_bytes) / 1024.0,
                  s.mean_instance_bytes / 1024.0);
    script += line;
  }
  script += "EOD\n";
  plot +=
      "\nset xlabel 'method'\nset ylabel 'KiB'\nset key top right\nset style data histograms\n"
      "set style histogram clustered\nset style fill solid 0.8\nset xtics rotate by -30\n"
      "plot $memory using 2:xtic(1) title 'global', '' using 3 title 'instance (mean)'\nunset multiplot";
  run_gnuplot(path, script, plot);
}

}  // namespace rastrace
