// Overdraw ordering and measure against meshoptimizer 0.18, same binary, same meshes (bunny00,
// the spider): tipsy-overdraw (Tipsy, fast linear clustering, occlusion-potential sort) against
// meshopt_optimizeVertexCacheFifo(16) + meshopt_optimizeOverdraw(1.05), the same paper from the
// same input; and the view-independent measure against meshopt_analyzeOverdraw. Items processed
// = triangles. Each ordering line reports its ACMR on a FIFO of 16 (acmr_fifo16) and its overdraw
// of the axis views (overdraw, exact rules) beside the time.
//   build/bench/bench_overdraw --benchmark_repetitions=5 --benchmark_report_aggregates_only=true
#include <map>
#include <string>

#include <benchmark/benchmark.h>
#include <meshoptimizer.h>

#include "cache_sim/vertex_cache.h"
#include "overdraw/meshopt_peer.h"
#include "overdraw/view_independent.h"
#include "reorder/ordering.h"
#include "scenes/mesh_io.h"

namespace {

const char* const kMeshes[] = {"meshes/bunny00.off", "assimp/OBJ/spider.obj"};
const char* const kLabels[] = {"bunny00", "spider"};

const rastrace::Mesh& bench_mesh(int which) {
  static std::map<int, rastrace::Mesh> meshes;
  auto found = meshes.find(which);
  if (found == meshes.end())
    found = meshes.emplace(which, rastrace::load_mesh(std::string(RASTRACE_DATA_DIR) + "/" + kMeshes[which])).first;
  return found->second;
}

template <typename Run>
void order_on(benchmark::State& state, Run run) {
  const rastrace::Mesh& mesh = bench_mesh(int(state.range(0)));
  state.SetLabel(kLabels[state.range(0)]);
  std::vector<std::uint32_t> last;
  for (auto _ : state) {
    last = run(mesh);
    benchmark::DoNotOptimize(last.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * mesh.face_count()));
  state.counters["acmr_fifo16"] = rastrace::simulate_vertex_stream(last, rastrace::PrimitiveType::TriangleList,
                                                                   rastrace::VertexCachePolicy::Fifo, 16)
                                      .acmr();
  state.counters["overdraw"] = rastrace::view_independent_overdraw(mesh.positions, last).overdraw();
}

void BM_tipsy(benchmark::State& state) {
  order_on(state, [](const rastrace::Mesh& mesh) { return rastrace::reorder_tipsy(mesh, {}).indices; });
}

void BM_tipsy_overdraw(benchmark::State& state) {
  order_on(state, [](const rastrace::Mesh& mesh) { return rastrace::reorder_tipsy_overdraw(mesh, {}).indices; });
}

void BM_meshopt_fifo_overdraw(benchmark::State& state) {
  order_on(state, [](const rastrace::Mesh& mesh) {
    std::vector<std::uint32_t> fifo(mesh.indices.size());
    meshopt_optimizeVertexCacheFifo(fifo.data(), mesh.indices.data(), mesh.indices.size(), mesh.vertex_count(), 16);
    return rastrace::meshopt_optimize_overdraw(mesh.positions, fifo, 1.05f);
  });
}

template <typename Measure>
void measure_on(benchmark::State& state, Measure measure) {
  const rastrace::Mesh& mesh = bench_mesh(int(state.range(0)));
  state.SetLabel(kLabels[state.range(0)]);
  const std::vector<std::uint32_t> order = rastrace::reorder_tipsy(mesh, {}).indices;
  double overdraw = 0;
  for (auto _ : state) {
    overdraw = measure(mesh, order).overdraw();
    benchmark::DoNotOptimize(overdraw);
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * mesh.face_count()));
  state.counters["overdraw"] = overdraw;
}

void BM_measure_exact(benchmark::State& state) {
  measure_on(state, [](const rastrace::Mesh& mesh, const std::vector<std::uint32_t>& order) {
    return rastrace::view_independent_overdraw(mesh.positions, order);
  });
}

void BM_meshopt_analyze(benchmark::State& state) {
  measure_on(state, [](const rastrace::Mesh& mesh, const std::vector<std::uint32_t>& order) {
    return rastrace::meshopt_analyze_overdraw(mesh.positions, order);
  });
}

BENCHMARK(BM_tipsy)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_tipsy_overdraw)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_meshopt_fifo_overdraw)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_measure_exact)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_meshopt_analyze)->DenseRange(0, 1)->Unit(benchmark::kMillisecond);

}  // namespace
