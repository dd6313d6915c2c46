// The Python module's goal (docs/PERFORMANCE.md, "Python: a sweep result into pandas"): a 10^6-row
// sweep result reaches pandas in under 50 ms beyond the sweep itself.
//
// The benchmark embeds the interpreter the module was built for and imports the built module
// (<build>/python/rastrace). A real sweep over a rendered trace (builtin:bunny at 128x128, 672
// byte-cache configurations) runs once; before each iteration, untimed, its rows are repeated to
// 1,000,608 in C++ and written into fresh columns exactly as the sweep's workers write them
// (python/src/sweep_columns.h): the state a sweep of 10^6 configurations ends in. Each iteration
// then times everything between the sweep's end and a DataFrame:
//   - SweepToPandas: `sweep.columns().to_pandas()` (the columns handed to numpy, a DataFrame
//     that keeps them)
//   - SweepToPandasDefault, the comparison row: `pandas.DataFrame(sweep.columns())`, pandas'
//     default, which copies the columns into one 2-D block per dtype
// and, to show what the sweep pays, the untimed step above, `sweep.repeated(k)`:
//   - SweepRowCopies: the 10^6 rows copied and freed (write_columns=False)
//   - SweepRowCopiesAndColumnWrites: each repetition of the rows copied, then written into the
//     columns as a worker writes its job's rows; the rows freed
//   - SweepRowsFree: the sweep's last step alone, freeing its 10^6 rows (190 MB); the old
//     conversion freed them after it, and the old benchmark did not time that either
// The difference of the first two is what the column writes add to a sweep of 10^6
// configurations, whose simulation takes minutes (0.3 ms of CPU per configuration in this one).
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
  py::object sweep;  // rastrace._rastrace._SweepRows of the 672-configuration sweep
  std::size_t repeat = 0;
  py::object pandas;
};
std::optional<Fixture> fixture;  // reset in main() before the interpreter ends

const Fixture& swept() {
  if (fixture) return *fixture;
  py::module_::import("sys").attr("path").attr("insert")(0, RASTRACE_PYTHON_DIR);
  const py::module_ rastrace = py::module_::import("rastrace");
  const py::module_ native = py::module_::import("rastrace._rastrace");
  const py::object folder = py::module_::import("tempfile").attr("TemporaryDirectory")();
  const std::string trace = folder.attr("name").cast<std::string>() + "/bunny.rtrace";
  rastrace.attr("render")("builtin:bunny", py::arg("trace") = trace, py::arg("size") = "128x128");
  py::object sweep = native.attr("_sweep_rows")(trace, kSpec);
  const std::size_t repeat = (kRows + py::len(sweep) - 1) / py::len(sweep);
  fixture = Fixture{sweep, repeat, py::module_::import("pandas")};
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

void count_rows(benchmark::State& state, std::size_t rows) {
  state.counters["rows"] = static_cast<double>(rows);
  state.SetItemsProcessed(static_cast<std::int64_t>(state.iterations() * rows));
}

// Every iteration starts from a fresh 10^6-row sweep state (untimed) and times `convert`.
template <typename Convert>
void run(benchmark::State& state, Convert convert) {
  const Fixture& f = swept();
  set_memory_reuse(state);
  std::size_t rows = 0;
  for (auto _ : state) {
    state.PauseTiming();
    py::object sweep = f.sweep.attr("repeated")(f.repeat);
    rows = py::len(sweep);
    state.ResumeTiming();
    py::object result = convert(f, sweep);
    state.PauseTiming();
    result = py::none();  // freeing is not part of reaching pandas
    sweep = py::none();
    state.ResumeTiming();
  }
  count_rows(state, rows);
}

// The untimed state costs about a second per iteration: a fixed count keeps a run short.
constexpr int kIterations = 10;

void BM_SweepToPandas(benchmark::State& state) {
  run(state, [](const Fixture&, const py::object& sweep) { return sweep.attr("columns")().attr("to_pandas")(); });
}
BENCHMARK(BM_SweepToPandas)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(kIterations);

void BM_SweepToPandasDefault(benchmark::State& state) {
  run(state, [](const Fixture& f, const py::object& sweep) { return f.pandas.attr("DataFrame")(sweep.attr("columns")()); });
}
BENCHMARK(BM_SweepToPandasDefault)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond)->Iterations(kIterations);

// What moved into the sweep: `repeated` with and without the columns written.
void time_repeated(benchmark::State& state, bool write_columns) {
  const Fixture& f = swept();
  set_memory_reuse(state);
  for (auto _ : state) {
    py::object sweep = f.sweep.attr("repeated")(f.repeat, write_columns);
    state.PauseTiming();
    sweep = py::none();
    state.ResumeTiming();
  }
  count_rows(state, py::len(f.sweep) * f.repeat);
}

void BM_SweepRowsFree(benchmark::State& state) {
  const Fixture& f = swept();
  set_memory_reuse(state);
  for (auto _ : state) {
    state.PauseTiming();
    py::object sweep = f.sweep.attr("repeated")(f.repeat, true, true);
    state.ResumeTiming();
    sweep.attr("free_rows")();
    state.PauseTiming();
    sweep = py::none();
    state.ResumeTiming();
  }
  count_rows(state, py::len(f.sweep) * f.repeat);
}

void BM_SweepRowCopies(benchmark::State& state) { time_repeated(state, false); }
BENCHMARK(BM_SweepRowCopies)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(kIterations);

void BM_SweepRowCopiesAndColumnWrites(benchmark::State& state) { time_repeated(state, true); }
BENCHMARK(BM_SweepRowCopiesAndColumnWrites)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(kIterations);
BENCHMARK(BM_SweepRowsFree)->Arg(0)->Unit(benchmark::kMillisecond)->Iterations(kIterations);

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
