#include "experiments/vcache_table.h"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <map>
#include <sstream>

#include "cache_sim/cache_spec.h"
#include "cache_sim/eviction_charged.h"
#include "cache_sim/vertex_cache.h"
#include "cache_sim/vertex_cache_sizes.h"
#include "core/error.h"
#include "experiments/cache_report.h"
#include "experiments/miss_image.h"
#include "reorder/strip.h"

namespace rastrace {

std::vector<const ReorderAlgorithm*> select_algorithms(const std::string& list, const Mesh& mesh) {
  std::vector<const ReorderAlgorithm*> selected;
  if (list == "all") {
    for (const ReorderAlgorithm& algorithm : reorder_algorithms())
      if (reorder_algorithm_applies(algorithm, mesh)) selected.push_back(&algorithm);
    return selected;
  }
  std::stringstream names(list);
  std::string name;
  while (std::getline(names, name, ',')) {
    if (name.empty()) throw InputError("--algo '" + list + "': empty algorithm name");
    selected.push_back(&find_reorder_algorithm(name));
  }
  return selected;
}

namespace {

Table vcache_model_table(const Mesh& mesh, const std::string& mesh_spec, const VcacheTableSpec& spec,
                        const std::vector<const ReorderAlgorithm*>& algorithms) {
  if (spec.eviction_charged)
    throw InputError("--accounting evictions models NVIDIA Mesh Tools' FIFO, not warp or batch models");
  const unsigned target = spec.target ? spec.target : 16;
  Table table;
  table.title = "Vertex reuse models: " + mesh_spec;
  table.kind = "vertex_reuse_model";
  table.parameters = {{"mesh", mesh_spec},
                      {"mesh_faces", mesh.face_count()},
                      {"mesh_vertices", mesh.vertex_count()},
                      {"seed", static_cast<std::int64_t>(spec.seed)},
                      {"target", target},
                      {"bandwidth_formula", "acmr * 32 + indices_per_triangle * 2 bytes/triangle"},
                      {"lane_use", "invocations / (warps x lanes per warp)"}};
  if (spec.iteration_budget) table.parameters.emplace_back("local_iterations", spec.iteration_budget);
  for (const VertexCacheSpec& model : spec.models)
    table.parameters.emplace_back("model " + vertex_reuse_name(model), vertex_reuse_parameters(model));
  table.columns = {{"algo", "algorithm", 0},
                   {"model", "model", 0},
                   {"triangles", "triangles", 0},
                   {"vertices", "vertices", 0},
                   {"misses", "invocations", 0},
                   {"acmr", "ACMR", 3},
                   {"atvr", "ATVR", 3},
                   {"warps", "warps", 0},
                   {"lane_slots", "lane slots", 0},
                   {"lane_use", "lane use", 3},
                   {"indices_per_triangle", "indices/triangle", 3},
                   {"bandwidth", "bytes/triangle", 2}};
  if (spec.with_time) table.columns.push_back({"seconds", "seconds", 4});
  for (const ReorderAlgorithm* algorithm : algorithms) {
    ReorderParams params;
    params.cache_size = target;
    params.seed = spec.seed;
    params.time_budget_seconds = spec.time_budget;
    params.iteration_budget = spec.iteration_budget;
    const auto start = std::chrono::steady_clock::now();
    const Ordering ordering = algorithm->run(mesh, params);
    const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    for (const VertexCacheSpec& model : spec.models) {
      const VertexStreamStats stats =
          simulate_vertex_reuse(ordering.indices, ordering.type, model, ordering.restart_index);
      std::vector<TableCell> row = {algorithm->name,
                                    vertex_reuse_name(model),
                                    stats.triangles,
                                    stats.vertices,
                                    stats.misses,
                                    stats.acmr(),
                                    stats.atvr(),
                                    stats.warps,
                                    stats.lane_slots ? TableCell(stats.lane_slots) : TableCell(),
                                    stats.lane_slots ? TableCell(stats.lane_use()) : TableCell(),
                                    stats.indices_per_triangle(),
                                    stats.acmr() * 32.0 + stats.indices_per_triangle() * 2.0};
      if (spec.with_time) row.emplace_back(seconds);
      table.add_row(std::move(row));
    }
  }
  return table;
}

std::size_t column_of(const Table& table, const std::string& key) {
  for (std::size_t i = 0; i < table.columns.size(); ++i)
    if (table.columns[i].key == key) return i;
  throw std::logic_error("vcache model table without column " + key);
}

const std::string& text_of(const TableCell& cell) { return std::get<std::string>(cell.value); }

// The algorithms and the models of a model table, each in first-seen order.
struct ModelTableAxes {
  std::size_t algo, model, acmr;  // columns
  std::vector<std::string> algorithms, models;
};

ModelTableAxes model_table_axes(const Table& model_table) {
  ModelTableAxes axes{column_of(model_table, "algo"), column_of(model_table, "model"), column_of(model_table, "acmr"),
                      {}, {}};
  for (const auto& row : model_table.rows) {
    if (std::find(axes.algorithms.begin(), axes.algorithms.end(), text_of(row[axes.algo])) == axes.algorithms.end())
      axes.algorithms.push_back(text_of(row[axes.algo]));
    if (std::find(axes.models.begin(), axes.models.end(), text_of(row[axes.model])) == axes.models.end())
      axes.models.push_back(text_of(row[axes.model]));
  }
  return axes;
}

}  // namespace

Table vcache_model_pivot(const Table& model_table) {
  const auto [algo, model, acmr, algorithms, models] = model_table_axes(model_table);
  Table pivot;
  pivot.kind = "vertex_cache_by_model";
  pivot.title = "ACMR (shader invocations per triangle) by model, rank in brackets: " +
                model_table.title.substr(model_table.title.find(':') + 2);
  pivot.parameters = model_table.parameters;
  pivot.columns = {{"algo", "algorithm", 0}};
  for (const std::string& m : models) pivot.columns.push_back({m, m, 3});
  std::vector<std::vector<double>> values(algorithms.size(), std::vector<double>(models.size(), 0.0));
  for (const auto& row : model_table.rows) {
    const auto a = std::find(algorithms.begin(), algorithms.end(), text_of(row[algo])) - algorithms.begin();
    const auto m = std::find(models.begin(), models.end(), text_of(row[model])) - models.begin();
    values[static_cast<std::size_t>(a)][static_cast<std::size_t>(m)] = std::get<double>(row[acmr].value);
  }
  for (std::size_t a = 0; a < algorithms.size(); ++a) {
    std::vector<TableCell> row = {algorithms[a]};
    for (std::size_t m = 0; m < models.size(); ++m) {
      std::size_t rank = 1;
      for (std::size_t b = 0; b < algorithms.size(); ++b) rank += values[b][m] < values[a][m];
      char cell[48];
      std::snprintf(cell, sizeof(cell), "%.3f (%zu)", values[a][m], rank);
      row.emplace_back(std::string(cell));
    }
    pivot.add_row(std::move(row));
  }
  return pivot;
}

void write_vcache_model_plot(const std::string& path, const Table& model_table) {
  const auto [algo, model, acmr, algorithms, models] = model_table_axes(model_table);
  std::string script = gnuplot_terminal(path, 1100, 650);
  std::string title = model_table.title;
  for (char& c : title)
    if (c == '\'' || c == '\n') c = ' ';
  script += "set title '" + title + "'\nset ylabel 'shader invocations per triangle (ACMR)'\n"
            "set style data histograms\nset style histogram clustered gap 1\nset style fill solid 0.85 border -1\n"
            "set boxwidth 0.9\nset key outside right\nset grid ytics\nset yrange [0:*]\nset xtics rotate by -30\n";
  script += "$d << EOD\nalgorithm";
  for (const std::string& m : models) script += " \"" + m + "\"";
  script += "\n";
  for (const std::string& a : algorithms) {
    script += a;
    for (const std::string& m : models)
      for (const auto& row : model_table.rows)
        if (text_of(row[algo]) == a && text_of(row[model]) == m) {
          char value[32];
          std::snprintf(value, sizeof(value), " %.6f", std::get<double>(row[acmr].value));
          script += value;
        }
    script += "\n";
  }
  script += "EOD\n";
  std::string plot = "plot ";
  for (std::size_t m = 0; m < models.size(); ++m)
    plot += (m ? ", " : "") + std::string("$d using ") + std::to_string(m + 2) + (m ? "" : ":xtic(1)") +
            " title columnheader(" + std::to_string(m + 2) + ")";
  run_gnuplot(path, script, plot);
}

Table vcache_table(const Mesh& mesh, const std::string& mesh_spec, const VcacheTableSpec& spec) {
  if (!spec.models.empty()) return vcache_model_table(mesh, mesh_spec, spec, select_algorithms(spec.algorithms, mesh));
  for (const unsigned cache : spec.caches)
    if (cache == 0) throw InputError("--cache 0: a vertex cache needs at least 1 entry");
  if (spec.eviction_charged)
    for (const VertexCachePolicy policy : spec.policies)
      if (policy != VertexCachePolicy::Fifo)
        throw InputError("--accounting evictions models NVIDIA Mesh Tools' FIFO: expected --policy fifo");
  const std::vector<const ReorderAlgorithm*> algorithms = select_algorithms(spec.algorithms, mesh);
  if (!spec.miss_image.empty() && (algorithms.size() != 1 || spec.policies.size() != 1 || spec.caches.size() != 1))
    throw InputError("--miss-image " + spec.miss_image + ": the image shows one ordering in one cache: expected one " +
                     "algorithm and one cache size and policy, got " + std::to_string(algorithms.size()) +
                     " algorithms, " + std::to_string(spec.caches.size()) + " sizes and " +
                     std::to_string(spec.policies.size()) + " policies");

  Table table;
  table.title = "Post-transform vertex cache: " + mesh_spec;
  table.parameters = {{"mesh", mesh_spec},
                      {"mesh_faces", mesh.face_count()},
                      {"mesh_vertices", mesh.vertex_count()},
                      {"seed", static_cast<std::int64_t>(spec.seed)},
                      {"bandwidth_formula", "acmr * " + std::to_string(spec.vertex_bytes) +
                                                " + indices_per_triangle * 2 bytes/triangle (restart indices count)"},
                      {"vertex_bytes", spec.vertex_bytes},
                      {"fetch_cache", format_cache_spec(spec.fetch_cache)},
                      {"accounting", spec.eviction_charged ? "evictions (NVIDIA Mesh Tools)" : "misses"}};
  if (spec.iteration_budget) table.parameters.emplace_back("local_iterations", spec.iteration_budget);
  table.columns = {{"algo", "algorithm", 0},
                   {"policy", "policy", 0},
                   {"cache", "cache", 0},
                   {"target", "target", 0},
                   {"triangles", "triangles", 0},
                   {"vertices", "vertices", 0},
                   {"misses", "misses", 0},
                   {"acmr", "ACMR", 3},
                   {"atvr", "ATVR", 3},
                   {"indices_per_triangle", "indices/triangle", 3},
                   {"vertices_sent", "vertices sent", 0},  // Yang et al.'s strip cost (reorder/strip.h)
                   {"restarts", "restarts", 0},            // restart indices sent (strips after the first)
                   {"bandwidth", "bytes/triangle", 2},
                   {"fetch_bytes", "bytes fetched", 0},  // vertex-buffer fetch (cache_sim/vertex_fetch.h)
                   {"overfetch", "overfetch", 3}};
  if (spec.with_time) table.columns.push_back({"seconds", "seconds", 4});

  // An ordering depends on (algorithm, target, policy) only: computed once, simulated per size.
  struct Run {
    Ordering ordering;
    double seconds;
    VertexFetchStats fetch;
    std::vector<VertexStreamStats> by_size;  // per spec.caches entry, when --target fixes the ordering
  };
  for (const ReorderAlgorithm* algorithm : algorithms) {
    for (const VertexCachePolicy policy : spec.policies) {
      std::map<unsigned, Run> runs;
      for (const unsigned& cache : spec.caches) {
        const unsigned target = spec.target ? spec.target : cache;
        auto found = runs.find(target);
        if (found == runs.end()) {
          ReorderParams params;
          params.cache_size = target;
          params.policy = policy;
          params.seed = spec.seed;
          params.time_budget_seconds = spec.time_budget;
          params.iteration_budget = spec.iteration_budget;
          const auto start = std::chrono::steady_clock::now();
          Ordering ordering = algorithm->run(mesh, params);
          const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          const VertexFetchStats fetch = simulate_vertex_fetch(ordering.indices, ordering.type, ordering.restart_index,
                                                               spec.vertex_bytes, spec.fetch_cache);
          found = runs.emplace(target, Run{std::move(ordering), seconds, fetch, {}}).first;
        }
        const Ordering& ordering = found->second.ordering;
        // One ordering for every size (--target): all sizes in one pass over it, the same misses.
        if (spec.target && found->second.by_size.empty())
          found->second.by_size = simulate_vertex_stream_sizes(ordering.indices, ordering.type, policy, spec.caches,
                                                               ordering.restart_index);
        VertexStreamStats stats =
            spec.target ? found->second.by_size[static_cast<std::size_t>(&cache - spec.caches.data())]
                        : simulate_vertex_stream(ordering.indices, ordering.type, policy, cache, ordering.restart_index);
        if (spec.eviction_charged)
          stats.misses = eviction_charged_transforms(ordering.indices, ordering.type, cache, ordering.restart_index);
        std::vector<TableCell> row = {
            algorithm->name,
            to_string(policy),
            cache,
            target,
            stats.triangles,
            stats.vertices,
            stats.misses,
            stats.acmr(),
            stats.atvr(),
            stats.indices_per_triangle(),
            strip_stats(ordering.indices, ordering.type, ordering.restart_index).vertices_sent,
            stats.indices_sent - stats.lookups,
            stats.acmr() * spec.vertex_bytes + stats.indices_per_triangle() * 2.0,
            found->second.fetch.bytes_fetched,
            found->second.fetch.overfetch()};
        if (spec.with_time) row.emplace_back(found->second.seconds);
        table.add_row(std::move(row));
        if (!spec.miss_image.empty())
          write_miss_image(mesh, face_miss_counts(mesh, ordering, policy, cache), spec.miss_image);
      }
    }
  }
  return table;
}

}  // namespace rastrace
