// `rastrace vcache MESH --algo all|a,b,c --cache 8,12,16,20,24,32 --policy fifo,lru [--target K]
//  --format md|csv|latex|json [--no-time]`: the post-transform vertex cache under every ordering.
// One row per algorithm, policy and cache size: ACMR, ATVR, misses, indices per triangle, Hoppe's
// bandwidth (ACMR * 32 + indices per triangle * 2 bytes per triangle) and the ordering's run time.
// An algorithm orders for the simulated cache unless --target fixes the size it orders for.
#include <chrono>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

#include "apps/commands.h"
#include "apps/mesh_spec.h"
#include "cache_sim/vertex_cache.h"
#include "core/error.h"
#include "core/table.h"
#include "reorder/ordering.h"

namespace rastrace {

namespace {

struct VcacheOptions {
  std::string mesh;
  std::string algorithms = "all";
  std::vector<unsigned> caches = {8, 12, 16, 20, 24, 32};
  std::vector<std::string> policies = {"fifo"};
  unsigned target = 0;  // 0: the simulated size
  std::uint64_t seed = 1;
  double time_budget = 60.0;
  std::string format = "md";
  bool no_time = false;
};

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

void run_vcache(const VcacheOptions& options) {
  const TableFormat format = parse_table_format(options.format);
  std::vector<VertexCachePolicy> policies;
  for (const std::string& text : options.policies) policies.push_back(parse_vertex_cache_policy(text));
  for (const unsigned cache : options.caches)
    if (cache == 0) throw InputError("--cache 0: a vertex cache needs at least 1 entry");
  const Mesh mesh = load_mesh_spec(options.mesh);
  const std::vector<const ReorderAlgorithm*> algorithms = select_algorithms(options.algorithms, mesh);

  Table table;
  table.title = "Post-transform vertex cache: " + mesh.name;
  table.parameters = {{"mesh", options.mesh},
                      {"mesh_faces", mesh.face_count()},
                      {"mesh_vertices", mesh.vertex_count()},
                      {"seed", static_cast<std::int64_t>(options.seed)},
                      {"bandwidth_formula", "acmr * 32 + indices_per_triangle * 2 bytes/triangle"}};
  table.columns = {{"algo", "algorithm", 0},         {"policy", "policy", 0},
                   {"cache", "cache", 0},            {"target", "target", 0},
                   {"triangles", "triangles", 0},    {"vertices", "vertices", 0},
                   {"misses", "misses", 0},          {"acmr", "ACMR", 3},
                   {"atvr", "ATVR", 3},              {"indices_per_triangle", "indices/triangle", 3},
                   {"bandwidth", "bytes/triangle", 2}};
  if (!options.no_time) table.columns.push_back({"seconds", "seconds", 4});

  // An ordering depends on (algorithm, target, policy) only: computed once, simulated per size.
  struct Run {
    Ordering ordering;
    double seconds;
  };
  for (const ReorderAlgorithm* algorithm : algorithms) {
    for (const VertexCachePolicy policy : policies) {
      std::map<unsigned, Run> runs;
      for (const unsigned cache : options.caches) {
        const unsigned target = options.target ? options.target : cache;
        auto found = runs.find(target);
        if (found == runs.end()) {
          ReorderParams params;
          params.cache_size = target;
          params.policy = policy;
          params.seed = options.seed;
          params.time_budget_seconds = options.time_budget;
          const auto start = std::chrono::steady_clock::now();
          Ordering ordering = algorithm->run(mesh, params);
          const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
          found = runs.emplace(target, Run{std::move(ordering), seconds}).first;
        }
        const Ordering& ordering = found->second.ordering;
        const VertexStreamStats stats =
            simulate_vertex_stream(ordering.indices, ordering.type, policy, cache, ordering.restart_index);
        std::vector<TableCell> row = {algorithm->name, to_string(policy), cache, target, stats.triangles,
                                      stats.vertices, stats.misses, stats.acmr(), stats.atvr(),
                                      stats.indices_per_triangle(),
                                      stats.acmr() * 32.0 + stats.indices_per_triangle() * 2.0};
        if (!options.no_time) row.emplace_back(found->second.seconds);
        table.add_row(std::move(row));
      }
    }
  }
  std::cout << render_table(table, format);
}

}  // namespace

void add_vcache_command(CLI::App& app) {
  CLI::App* command = app.add_subcommand("vcache", "Post-transform vertex cache misses under each triangle ordering");
  auto options = std::make_shared<VcacheOptions>();
  command->add_option("mesh", options->mesh, "Mesh file, builtin:<scene> or grid:WxH")->required();
  command->add_option("--algo", options->algorithms, "all, or a comma-separated list of orderings")
      ->capture_default_str();
  command->add_option("--cache", options->caches, "Simulated cache sizes (entries)")
      ->delimiter(',')
      ->capture_default_str();
  command->add_option("--policy", options->policies, "fifo, lru, or both")->delimiter(',')->capture_default_str();
  command->add_option("--target", options->target, "Cache size the orderings optimize for (default: the simulated size)");
  command->add_option("--seed", options->seed, "Seed of the randomized orderings")->capture_default_str();
  command->add_option("--time-budget", options->time_budget, "Seconds for iterative orderings (local)")
      ->capture_default_str();
  command->add_option("--format", options->format, "md, csv, latex or json")->capture_default_str();
  command->add_flag("--no-time", options->no_time, "Leave out the run-time column so outputs compare byte for byte");
  command->footer(
      "Examples:\n"
      "  rastrace vcache grid:16x16 --algo scanline,grid,tipsy --cache 12,16,20\n"
      "  rastrace vcache data/meshes/fandisk.off --algo all --cache 16 --policy fifo,lru --format csv --no-time\n"
      "  rastrace vcache grid:16x16 --algo grid --target 8 --cache 8,16");
  command->callback([options] { run_vcache(*options); });
}

}  // namespace rastrace
