// Adjacency primitives (Sander, Nehab, Chlamtac, Hoppe 2008) on bunny00 (75,408 faces): the
// cover search, the lower bound, the restricted assignment and the four orderings at cache 24.
// The paper (bunny, 69,473 faces, 2008 hardware): cover 8.47 s, assignment 0.92 s, careful
// 9.33 s, fast 0.023 s.
#include <benchmark/benchmark.h>

#include "reorder/adjacency/bound.h"
#include "reorder/adjacency/build.h"
#include "reorder/adjacency/order.h"
#include "scenes/mesh_io.h"

namespace rastrace {
namespace {

struct Bunny {
  Mesh mesh;
  AdjacencyBuild build;
};

const Bunny& bunny() {
  static const Bunny b = [] {
    Bunny result;
    result.mesh = load_mesh(RASTRACE_DATA_DIR "/meshes/bunny00.off");
    result.build = build_adjacency_primitives(result.mesh);
    return result;
  }();
  return b;
}

void BM_DualGraph(benchmark::State& state) {
  const Mesh& mesh = bunny().mesh;
  for (auto _ : state) benchmark::DoNotOptimize(build_adjacency_dual(mesh));
}
BENCHMARK(BM_DualGraph)->Unit(benchmark::kMillisecond);

void BM_Cover(benchmark::State& state) {
  const AdjacencyDual& dual = bunny().build.dual;
  CoverResult cover;
  for (auto _ : state) cover = find_adjacency_cover(dual);  // 20 iterations per face
  state.counters["cover"] = cover.size;
  state.counters["iterations"] = double(cover.iterations);
}
BENCHMARK(BM_Cover)->Unit(benchmark::kMillisecond);

void BM_LowerBound(benchmark::State& state) {
  const Bunny& b = bunny();
  CoverBound bound;
  for (auto _ : state) bound = adjacency_cover_lower_bound(b.mesh, b.build.dual);
  state.counters["bound"] = bound.bound;
  state.counters["pruned_edges"] = double(bound.pruned_edges);
}
BENCHMARK(BM_LowerBound)->Unit(benchmark::kMillisecond);

void BM_Assignment(benchmark::State& state) {
  const AdjacencyBuild& build = bunny().build;
  for (auto _ : state) benchmark::DoNotOptimize(assign_uncovered_faces(build.dual, build.cover.in_cover));
}
BENCHMARK(BM_Assignment)->Unit(benchmark::kMillisecond);

void BM_Encode(benchmark::State& state) {
  const Bunny& b = bunny();
  for (auto _ : state)
    benchmark::DoNotOptimize(
        encode_adjacency_primitives(b.mesh, b.build.dual, b.build.cover.in_cover, b.build.assignment));
}
BENCHMARK(BM_Encode)->Unit(benchmark::kMillisecond);

void BM_Order(benchmark::State& state) {
  const Bunny& b = bunny();
  const auto order = static_cast<AdjacencyOrder>(state.range(0));
  for (auto _ : state) benchmark::DoNotOptimize(order_adjacency(order, b.mesh, b.build.primitives, 24));
  state.SetLabel(to_string(order));
}
BENCHMARK(BM_Order)
    ->Arg(static_cast<int>(AdjacencyOrder::Fast))
    ->Arg(static_cast<int>(AdjacencyOrder::Careful))
    ->Arg(static_cast<int>(AdjacencyOrder::Baseline))
    ->Arg(static_cast<int>(AdjacencyOrder::BaselineMesh))
    ->Unit(benchmark::kMillisecond);

}  // namespace
}  // namespace rastrace
