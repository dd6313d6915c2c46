// Meshlet build speed and quality against meshoptimizer 0.18, same binary, same meshes (file
// order): rastrace's greedy, spatial and scan builders against meshopt_buildMeshlets (cone weight
// 0) and meshopt_buildMeshletsScan. Arguments: mesh (0 fandisk, 1 triceratops, 2 bunny00) and
// max triangles (124 or 64; 64 vertices throughout). Items processed = triangles; each line also
// reports the sum of meshlet vertices per triangle (vertices_per_triangle) and the meshlet count.
//   build/bench/bench_meshlets --benchmark_repetitions=3 --benchmark_report_aggregates_only=true
#include <map>
#include <string>

#include <benchmark/benchmark.h>

#include "reorder/meshlets/meshlet.h"
#include "reorder/meshlets/meshlet_peer.h"
#include "bench/bench_meshes.h"

namespace {

using rastrace::bench::cgal_mesh;
const auto& kMeshes = rastrace::bench::kComparisonMeshes;

template <typename Build>
void run_on(benchmark::State& state, Build build) {
  const rastrace::Mesh& mesh = cgal_mesh(kMeshes[state.range(0)]);
  const rastrace::MeshletLimits limits{64, static_cast<std::uint32_t>(state.range(1))};
  state.SetLabel(std::string(kMeshes[state.range(0)]) + " 64/" + std::to_string(limits.max_triangles));
  rastrace::MeshletSet last;
  for (auto _ : state) {
    last = build(mesh, limits);
    benchmark::DoNotOptimize(last.vertices.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * mesh.face_count()));
  state.counters["vertices_per_triangle"] = double(last.vertices.size()) / double(mesh.face_count());
  state.counters["meshlets"] = double(last.meshlets.size());
}

void BM_greedy(benchmark::State& state) {
  run_on(state, [](const rastrace::Mesh& mesh, const rastrace::MeshletLimits& limits) {
    return rastrace::build_meshlets_greedy(mesh.indices, mesh.positions, limits);
  });
}
void BM_meshopt(benchmark::State& state) {
  run_on(state, [](const rastrace::Mesh& mesh, const rastrace::MeshletLimits& limits) {
    return rastrace::meshopt_build_meshlets(mesh.indices, mesh.positions, limits);
  });
}
void BM_spatial(benchmark::State& state) {
  run_on(state, [](const rastrace::Mesh& mesh, const rastrace::MeshletLimits& limits) {
    return rastrace::build_meshlets_spatial(mesh.indices, mesh.positions, limits);
  });
}
void BM_scan(benchmark::State& state) {
  run_on(state, [](const rastrace::Mesh& mesh, const rastrace::MeshletLimits& limits) {
    return rastrace::build_meshlets_scan(mesh.indices, mesh.vertex_count(), limits);
  });
}
void BM_meshopt_scan(benchmark::State& state) {
  run_on(state, [](const rastrace::Mesh& mesh, const rastrace::MeshletLimits& limits) {
    return rastrace::meshopt_build_meshlets_scan(mesh.indices, mesh.vertex_count(), limits);
  });
}

void limits(benchmark::internal::Benchmark* b) {
  for (int mesh = 0; mesh < 3; ++mesh)
    for (int triangles : {124, 64}) b->Args({mesh, triangles});
  b->Unit(benchmark::kMillisecond);
}

BENCHMARK(BM_greedy)->Apply(limits);
BENCHMARK(BM_meshopt)->Apply(limits);
BENCHMARK(BM_spatial)->Apply(limits);
BENCHMARK(BM_scan)->Apply(limits);
BENCHMARK(BM_meshopt_scan)->Apply(limits);

}  // namespace
