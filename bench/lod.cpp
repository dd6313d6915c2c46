// Progressive-mesh build time against meshoptimizer 0.18's meshopt_simplify, same binary, same
// meshes: our builder makes the whole collapse sequence down to its default floor (2% of the
// faces); meshopt_simplify is asked for the same final triangle count once. Items processed =
// input triangles. The build of bunny00 is about 1 s.
//   build/bench/bench_lod --benchmark_min_time=1
#include <algorithm>
#include <map>
#include <string>

#include <benchmark/benchmark.h>

#include "lod/progressive_mesh.h"
#include "lod/progressive_mesh_peer.h"
#include "scenes/mesh_io.h"

namespace {

const char* const kMeshes[] = {"fandisk", "triceratops", "bunny00"};

const rastrace::Mesh& bench_mesh(int which) {
  static std::map<int, rastrace::Mesh> meshes;
  auto found = meshes.find(which);
  if (found == meshes.end())
    found =
        meshes
            .emplace(which, rastrace::load_mesh(std::string(RASTRACE_DATA_DIR) + "/meshes/" + kMeshes[which] + ".off"))
            .first;
  return found->second;
}

void BM_build_progressive_mesh(benchmark::State& state) {
  const rastrace::Mesh& mesh = bench_mesh(int(state.range(0)));
  state.SetLabel(kMeshes[state.range(0)]);
  std::size_t collapses = 0;
  for (auto _ : state) {
    const rastrace::ProgressiveMesh pm = rastrace::build_progressive_mesh(mesh, {});
    collapses = pm.collapses.size();
    benchmark::DoNotOptimize(pm.collapses.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * mesh.face_count()));
  state.counters["collapses"] = double(collapses);
}

void BM_meshopt_simplify(benchmark::State& state) {
  const rastrace::Mesh& mesh = bench_mesh(int(state.range(0)));
  state.SetLabel(kMeshes[state.range(0)]);
  const auto target = std::max<std::uint32_t>(16, std::uint32_t(mesh.face_count() / 50));
  std::size_t triangles = 0;
  for (auto _ : state) {
    const auto out = rastrace::meshopt_simplified_triangles(mesh, target);
    triangles = out.size();
    benchmark::DoNotOptimize(out.data());
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * mesh.face_count()));
  state.counters["triangles"] = double(triangles);
}

}  // namespace

BENCHMARK(BM_build_progressive_mesh)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_meshopt_simplify)->DenseRange(0, 2)->Unit(benchmark::kMillisecond);
