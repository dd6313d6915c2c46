// The Python module's goal (docs/PERFORMANCE.md, "Python: a sweep result into pandas"): a 10^6-row
// sweep result reaches pandas in under 50 ms beyond the sweep itself.
//
// The benchmark embeds the interpreter the module was built for and imports the built module
// (<build>/python/rastrace). A real sweep over a rendered trace (builtin:bunny at 128x128, 672
// byte-cache configurations) is repeated to 1,000,608 rows in C++; each iteration
// then pays what a user pays after the sweep:
//   - SweepToPandas: `rows.columns().to_pandas()` (numpy columns, then a DataFrame that keeps them)
//   - SweepToPandasDefault, the comparison row: `pandas.DataFrame(rows.columns())`, pandas'
//     default, which copies the columns into one 2-D block per dtype
//   - Columns: `rows.columns()` alone (the C++ side)
// The result is dropped outside the timed region: a notebook keeps it.
//
// Argument 0 ("fresh"): every array is a new mapping whose pages the kernel zeroes at first touch
// (glibc's mmap threshold fixed at 1 MiB), as the first large result of a process. Argument 1
// ("reused"): freed memory stays in the heap (mmap threshold at glibc's maximum, 32 MiB, above the
// 8 MB columns; no trimming), as in a notebook after its first large result.
#include <malloc.h>

#include <cstdio>
#include <exception>
#include <optional>

#include <benchmark/benchmark.h>
#include <pybind11/embed.h>

namespace py = pybind11;

namespace {

constexpr std::size_t kRows = 1'000'000;
constexpr const char* kSpec =
    "size=1KiB..64KiB,line=16B/32B/64B/128B,assoc=1/2/4/full,policy=fifo/lru/random,layout=linear/morton";

struct Fixture {
  py::object rows;  // rastrace._rastrace._SweepRows, not yet converted
  py::object pandas;
};
std::optional<Fixture> fixture;  // reset in main() before the interpreter ends

const Fixture& sweep_rows() {
  if (fixture) return *fixture;
  py::module_::import("sys").attr("path").attr("insert")(0, RASTRACE_PYTHON_DIR);
  const py::module_ rastrace = py::module_::import("rastrace");
  const py::module_ native = py::module_::import("rastrace._rastrace");
  const py::object folder = py::module_::import("tempfile").attr("TemporaryDirectory")();
  const std::string trace = folder.attr("name").cast<std::string>() + "/bunny.rtrace";
  rastrace.attr("render")("builtin:bunny", py::arg("trace") = trace, py::arg("size") = "128x128");
  const std::size_t swept = py::len(native.attr("_sweep_rows")(trace, kSpec, 1));
  const std::size_t repeat = (kRows + swept - 1) / swept;
  fixture = Fixture{native.attr("_sweep_rows")(trace, kSpec, repeat), py::module_::import("pandas")};
  folder.attr("cleanup")();
  return *fixture;
}

void set_memory_reuse(benchmark::State& state) {
  const bool reuse = state.range(0) == 1;
  // Fixed values also switch off glibc's dynamic threshold, which otherwise moves with the frees.
  mallopt(M_MMAP_THRESHOLD, reuse ? 32 * 1024 * 1024 : 1024 * 1024);
  mallopt(M_TRIM_THRESHOLD, reuse ? 1 << 30 : 128 * 1024);
  state.SetLabel(reuse ? "reused memory" : "fresh pages");
}

template <typename Convert>
void run(benchmark::State& state, Convert convert) {
  const Fixture& f = sweep_rows();
  set_memory_reuse(state);
  for (auto _ : state) {
    py::object result = convert(f);
    state.PauseTiming();
    result = py::none();  // freeing is not part of reaching pandas
    state.ResumeTiming();
  }
  state.counters["rows"] = static_cast<double>(py::len(f.rows));
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * py::len(f.rows)));
}

void BM_SweepToPandas(benchmark::State& state) {
  run(state, [](const Fixture& f) { return f.rows.attr("columns")().attr("to_pandas")(); });
}
BENCHMARK(BM_SweepToPandas)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_SweepToPandasDefault(benchmark::State& state) {
  run(state, [](const Fixture& f) { return f.pandas.attr("DataFrame")(f.rows.attr("columns")()); });
}
BENCHMARK(BM_SweepToPandasDefault)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

void BM_Columns(benchmark::State& state) {
  run(state, [](const Fixture& f) { return f.rows.attr("columns")(); });
}
BENCHMARK(BM_Columns)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);

}  // namespace

int main(int argc, char** argv) {
  py::scoped_interpreter python;
  benchmark::Initialize(&argc, argv);
  if (benchmark::ReportUnrecognizedArguments(argc, argv)) return 1;
  int status = 0;
  try {
    benchmark::RunSpecifiedBenchmarks();
  } catch (const std::exception& e) {  // the module or pandas failed to import, or the sweep failed
    std::fprintf(stderr, "bench_python_columns: %s\n", e.what());
    status = 1;
  }
  benchmark::Shutdown();
  fixture.reset();
  return status;
}
