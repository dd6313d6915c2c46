// Hoppe 1999's greedy strip-growing and local optimization, and the `strip` stripifier, on the
// CGAL meshes. Faces per second are reported as items_per_second.
//   bench_reorder_hoppe --benchmark_filter='Greedy|MeshTopology' --benchmark_repetitions=5
//   --benchmark_report_aggregates_only=true
#include <benchmark/benchmark.h>

#include <map>
#include <string>

#include "reorder/greedy.h"
#include "reorder/local_opt.h"
#include "reorder/strip.h"
#include "scenes/mesh_io.h"

namespace rastrace {
namespace {

const Mesh& mesh(const std::string& name) {
  static std::map<std::string, Mesh> meshes;
  auto found = meshes.find(name);
  if (found == meshes.end())
    found = meshes.emplace(name, load_mesh(std::string(RASTRACE_DATA_DIR) + "/meshes/" + name + ".off")).first;
  return found->second;
}

// Greedy strip-growing alone (topology built once, outside the timing), FIFO or LRU 16.
void BM_Greedy(benchmark::State& state, const std::string& name, VertexCachePolicy policy) {
  const Mesh& m = mesh(name);
  const MeshTopology topology = build_mesh_topology(m);
  ReorderParams params;
  params.policy = policy;
  GreedyStats stats;
  for (auto _ : state) benchmark::DoNotOptimize(hoppe_greedy_order(m, topology, params, &stats));
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(m.face_count()));
  state.counters["sims_per_face"] = double(stats.simulations) / double(m.face_count());
}
BENCHMARK_CAPTURE(BM_Greedy, fandisk_fifo, std::string("fandisk"), VertexCachePolicy::Fifo)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Greedy, triceratops_fifo, std::string("triceratops"), VertexCachePolicy::Fifo)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Greedy, bunny00_fifo, std::string("bunny00"), VertexCachePolicy::Fifo)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Greedy, fandisk_lru, std::string("fandisk"), VertexCachePolicy::Lru)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_Greedy, bunny00_lru, std::string("bunny00"), VertexCachePolicy::Lru)
    ->Unit(benchmark::kMillisecond);

// The whole `greedy` algorithm as registered (what `rastrace reorder MESH --algo greedy` runs):
// topology, greedy, strip emission.
void BM_GreedyWhole(benchmark::State& state, const std::string& name, VertexCachePolicy policy) {
  const Mesh& m = mesh(name);
  ReorderParams params;
  params.policy = policy;
  for (auto _ : state) benchmark::DoNotOptimize(reorder_greedy(m, params));
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(m.face_count()));
}
BENCHMARK_CAPTURE(BM_GreedyWhole, fandisk_fifo, std::string("fandisk"), VertexCachePolicy::Fifo)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GreedyWhole, triceratops_fifo, std::string("triceratops"), VertexCachePolicy::Fifo)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GreedyWhole, bunny00_fifo, std::string("bunny00"), VertexCachePolicy::Fifo)
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_GreedyWhole, bunny00_lru, std::string("bunny00"), VertexCachePolicy::Lru)
    ->Unit(benchmark::kMillisecond);

// Mesh connectivity alone (part of every whole run above).
void BM_MeshTopology(benchmark::State& state, const std::string& name) {
  const Mesh& m = mesh(name);
  for (auto _ : state) benchmark::DoNotOptimize(build_mesh_topology(m));
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(m.face_count()));
}
BENCHMARK_CAPTURE(BM_MeshTopology, fandisk, std::string("fandisk"))->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(BM_MeshTopology, bunny00, std::string("bunny00"))->Unit(benchmark::kMillisecond);

// Local optimization of a mesh's greedy order at FIFO 16, run until a whole pass finds nothing
// (no iteration budget; a 600 s safety cap the runs stay far below: converged = 1).
void BM_LocalToConvergence(benchmark::State& state, const std::string& name) {
  const Mesh& m = mesh(name);
  const MeshTopology topology = build_mesh_topology(m);
  ReorderParams params;
  params.time_budget_seconds = 600.0;
  const std::vector<std::uint32_t> greedy = hoppe_greedy_order(m, topology, params);
  LocalStats stats;
  double acmr = 0.0;
  for (auto _ : state) {
    std::vector<std::uint32_t> order = greedy;
    hoppe_local_optimize(m, topology, params, order, &stats);
    const Ordering o = strip_ordering(m, topology, order);
    acmr = simulate_vertex_stream(o.indices, o.type, VertexCachePolicy::Fifo, 16, o.restart_index).acmr();
  }
  state.counters["acmr"] = acmr;
  state.counters["passes"] = double(stats.passes);
  state.counters["applied"] = double(stats.applied);
  state.counters["converged"] = stats.converged ? 1.0 : 0.0;
}
BENCHMARK_CAPTURE(BM_LocalToConvergence, fandisk, std::string("fandisk"))->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK_CAPTURE(BM_LocalToConvergence, bunny00, std::string("bunny00"))->Unit(benchmark::kSecond)->Iterations(1);

void BM_Strip(benchmark::State& state, const std::string& name) {
  const Mesh& m = mesh(name);
  std::uint64_t sent = 0;
  for (auto _ : state) {
    const Ordering o = reorder_strip(m, ReorderParams{});
    sent = strip_stats(o.indices, o.type, o.restart_index).vertices_sent;
  }
  state.SetItemsProcessed(std::int64_t(state.iterations()) * std::int64_t(m.face_count()));
  state.counters["vertices_sent"] = double(sent);
}
BENCHMARK_CAPTURE(BM_Strip, triceratops, std::string("triceratops"))->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rastrace
