// LoD-change speed of each VIPM representation (Forsyth, "Comparison of VIPM Methods", 2001): one
// iteration sweeps one instance from full detail to the last LoD a collapse at a time and back.
// time_per_change = seconds per collapse or split ("54.9n" = 54.9 ns; a level switch's copy included).
//   build/bench/bench_vipm --benchmark_min_time=0.2
#include <memory>
#include <string>

#include <benchmark/benchmark.h>

#include "lod/progressive_mesh.h"
#include "lod/vipm_measure_methods.h"
#include "scenes/mesh_io.h"

namespace {

struct Bunny {
  rastrace::ProgressiveMesh pm;
  rastrace::VipmMethods methods;
};

Bunny& bunny() {
  static Bunny b = [] {
    Bunny out;
    const rastrace::Mesh mesh = rastrace::load_mesh(std::string(RASTRACE_DATA_DIR) + "/meshes/bunny00.off");
    out.pm = rastrace::build_progressive_mesh(mesh);
    out.methods = rastrace::build_vipm_methods(out.pm, rastrace::reordered_mesh(mesh, out.pm));
    return out;
  }();
  return b;
}

void BM_VipmSweep(benchmark::State& state) {
  rastrace::VipmRepresentation& r = *bunny().methods.representations[state.range(0)];
  state.SetLabel(r.method());
  const std::uint32_t last = r.lod_count() - 1;
  r.set_lod(0);
  for (auto _ : state) {
    for (std::uint32_t n = 1; n <= last; ++n) benchmark::DoNotOptimize(r.set_lod(n));
    for (std::uint32_t n = last; n-- > 0;) benchmark::DoNotOptimize(r.set_lod(n));
  }
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations()) * 2 * last);
  state.counters["time_per_change"] =
      benchmark::Counter(2.0 * last, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}
BENCHMARK(BM_VipmSweep)->DenseRange(0, 5)->Unit(benchmark::kMillisecond);

}  // namespace
