// Every ordering and the adjacency builder on the generated pathological meshes
// (tests/support/pathological_meshes.h: degenerate faces, duplicates, few vertices, edge and
// vertex fans) against a well-formed grid of the same face count. The counter x_grid is the
// time over the same algorithm's time on the grid (goal: at most 10). grid-untagged is the grid
// without its layout tag, scanline's general path on well-formed faces.
//   build/bench/bench_pathological --benchmark_min_time=0.05
#include <chrono>
#include <map>
#include <string>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

#include <benchmark/benchmark.h>

#include "core/error.h"
#include "reorder/adjacency/build.h"
#include "reorder/ordering.h"
#include "tests/support/pathological_meshes.h"

namespace rastrace {
namespace {

constexpr std::uint32_t kFaces = 3000;

std::map<std::string, double>& grid_seconds() {
  static std::map<std::string, double> seconds;
  return seconds;
}

template <typename Run>
void measure(benchmark::State& state, const std::string& algorithm, const std::string& mesh, Run run) {
  double total = 0;
  for (auto _ : state) {
    const auto start = std::chrono::steady_clock::now();
    run();
    total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
  const double mean = total / static_cast<double>(state.iterations());
  if (mesh == "grid") grid_seconds()[algorithm] = mean;
  const auto grid = grid_seconds().find(algorithm);
  if (grid != grid_seconds().end() && grid->second > 0) state.counters["x_grid"] = mean / grid->second;
}

// The corpus, plus the grid without its make_grid layout tag: scanline takes a shortcut on a
// tagged grid (its rows are the quads' order, no sort), so the untagged copy shows what the
// general path costs on the same faces.
std::vector<std::pair<std::string, Mesh>> corpus() {
  auto meshes = testing::pathological_meshes(kFaces);
  Mesh untagged = meshes.front().second;
  untagged.grid.reset();
  meshes.emplace_back("grid-untagged", std::move(untagged));
  return meshes;
}

const bool registered = [] {
#if defined(__GLIBC__)
  // glibc serves a block over 128 KiB with a fresh mmap (whose page faults are slow on a shared
  // virtual machine) until a large block has been freed, then raises that threshold. Each
  // algorithm runs the grid first, so its denominator paid those faults or not depending on
  // what ran before it (forsyth's grid 3x slower than the same faces measured later). A fixed
  // threshold keeps every block on the heap, so the ratios compare the algorithms' work.
  mallopt(M_MMAP_THRESHOLD, 64 << 20);
  mallopt(M_TRIM_THRESHOLD, 128 << 20);
#endif
  static const auto meshes = corpus();
  for (const ReorderAlgorithm& algorithm : reorder_algorithms()) {
    for (const auto& [name, mesh] : meshes) {
      benchmark::RegisterBenchmark((algorithm.name + "/" + name).c_str(), [&algorithm, &name = name,
                                                                           &mesh = mesh](benchmark::State& state) {
        ReorderParams params;
        // local runs to convergence where it converges in seconds (the grid, the fans): its time
        // then compares work, not budgets. 10 s caps few-vertices, which does not (PERFORMANCE.md).
        params.time_budget_seconds = algorithm.name == "local" ? 10.0 : 0.5;
        measure(state, algorithm.name, name, [&] {
          try {
            benchmark::DoNotOptimize(algorithm.run(mesh, params));
          } catch (const InputError&) {
            state.SkipWithError("refused (grid meshes only)");
          }
        });
      })->Unit(benchmark::kMillisecond);
    }
  }
  for (const auto& [name, mesh] : meshes)
    benchmark::RegisterBenchmark(("adjacency-build/" + name).c_str(), [&name = name,
                                                                       &mesh = mesh](benchmark::State& state) {
      CoverParams params;
      params.time_budget_seconds = 0.5;
      measure(state, "adjacency-build", name,
              [&] { benchmark::DoNotOptimize(build_adjacency_primitives(mesh, params)); });
    })->Unit(benchmark::kMillisecond);
  return true;
}();

}  // namespace
}  // namespace rastrace
