#include "experiments/vcache_table.h"

#include <chrono>
#include <map>
#include <sstream>

#include "cache_sim/cache_spec.h"
#include "cache_sim/eviction_charged.h"
#include "cache_sim/vertex_cache.h"
#include "cache_sim/vertex_cache_sizes.h"
#include "core/error.h"
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

Table vcache_table(const Mesh& mesh, const std::string& mesh_spec, const VcacheTableSpec& spec) {
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
