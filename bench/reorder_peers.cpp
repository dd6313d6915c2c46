// Ordering speed against meshoptimizer 0.18, same binary, same meshes: tipsy against
// meshopt_optimizeVertexCacheFifo (the same algorithm), forsyth against meshopt_optimizeVertexCache
// (Forsyth-style with tuned scores), kcache for reference. Items processed = triangles, so
// Google Benchmark prints triangles per second. Cache 16 throughout; each line also reports the
// ACMR of the order on a FIFO of 16 (acmr_fifo16).
//   build-reorder/bench/bench_reorder_peers --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <map>
#include <string>

#include <benchmark/benchmark.h>
#include <meshoptimizer.h>

#include "cache_sim/vertex_cache.h"
#include "reorder/kcache.h"
#include "reorder/ordering.h"
#include "bench/bench_meshes.h"

namespace {

using rastrace::bench::cgal_mesh;
const auto& kMeshes = rastrace::bench::kComparisonMeshes;

// run(mesh) returns the triangle list it made; its ACMR on FIFO 16 is reported beside the time.
template <typename Run>
void run_on(benchmark::State& state, Run run) {
  const rastrace::Mesh& mesh = cgal_mesh(kMeshes[state.range(0)]);
  state.SetLabel(kMeshes[state.range(0)]);
  std::vector<std::uint32_t> last;
  for (auto _ : state) last = run(mesh);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * mesh.face_count()));
  state.counters["acmr_fifo16"] = rastrace::simulate_vertex_stream(last, rastrace::PrimitiveType::TriangleList,
                                                                   rastrace::VertexCachePolicy::Fifo, 16)
                                      .acmr();
}

void ours(benchmark::State& state,
          rastrace::Ordering (*algorithm)(const rastrace::Mesh&, const rastrace::ReorderParams&)) {
  rastrace::ReorderParams params;
  params.cache_size = 16;
  run_on(state, [&](const rastrace::Mesh& mesh) {
    rastrace::Ordering ordering = algorithm(mesh, params);
    benchmark::DoNotOptimize(ordering.indices.data());
    return std::move(ordering.indices);
  });
}

void BM_tipsy(benchmark::State& state) { ours(state, rastrace::reorder_tipsy); }
void BM_forsyth(benchmark::State& state) { ours(state, rastrace::reorder_forsyth); }
void BM_kcache(benchmark::State& state) { ours(state, rastrace::reorder_kcache); }

void BM_meshopt_fifo(benchmark::State& state) {
  run_on(state, [](const rastrace::Mesh& mesh) {
    std::vector<unsigned> out(mesh.indices.size());
    meshopt_optimizeVertexCacheFifo(out.data(), mesh.indices.data(), mesh.indices.size(), mesh.vertex_count(), 16);
    benchmark::DoNotOptimize(out.data());
    return out;
  });
}

void BM_meshopt_vcache(benchmark::State& state) {
  run_on(state, [](const rastrace::Mesh& mesh) {
    std::vector<unsigned> out(mesh.indices.size());
    meshopt_optimizeVertexCache(out.data(), mesh.indices.data(), mesh.indices.size(), mesh.vertex_count());
    benchmark::DoNotOptimize(out.data());
    return out;
  });
}

BENCHMARK(BM_tipsy)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_meshopt_fifo)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_forsyth)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_meshopt_vcache)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_kcache)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);

}  // namespace
