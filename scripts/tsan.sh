#!/usr/bin/env bash
# ThreadSanitizer over the code that runs threads: the trace reader's read-ahead thread
# (traces/trace_reader.cpp; the ReadAhead tests), the trace writer's compression threads and
# ordered stage (traces/trace_writer.cpp; TraceWriterThreads), the parallel sweep's workers, each of which replays with its own
# read-ahead (cache_sim/sweep.cpp; ParallelSweep), and the multi-threaded renderer's tile workers
# (raster/worker_pool.cpp; the RenderIdentity tests at 2 and 4 threads, which also write traces
# through the writer's thread, and RasterWorkspaceReuse, whose frames reuse the cached workers and
# buffers after an interrupted frame; InPlaceTrace, whose workers copy tiles' events into a
# MemorySink's lent storage). Own build in build-tsan/.
# Only the three test executables and the libraries they link are built: their `/fast` make
# targets skip the dependency on the rastrace tool, which these tests do not run. `/fast` also
# skips the step that merges the compiler's header dependencies, so that step (`depend`) runs
# first: without it a test object compiled before a header changed is not rebuilt, and the tests
# fail on stale struct layouts (ReadAhead failed so, 3 December 2026, with no race behind it).
# Fails on any data race, lock-order inversion or test failure.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
dir="$here/build-tsan"
flags=(-G "Unix Makefiles" -DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1 -g"
       "-DCMAKE_CXX_FLAGS=-fsanitize=thread" "-DCMAKE_EXE_LINKER_FLAGS=-fsanitize=thread"
       -DRASTRACE_WERROR=ON -DRASTRACE_BENCHMARKS=OFF -DRASTRACE_PYTHON=OFF
       -DCMAKE_GTEST_DISCOVER_TESTS_DISCOVERY_MODE=PRE_TEST)  # no run at build time: ctest is not used
if command -v ccache >/dev/null; then
  flags+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$here}"
fi
start=$(date +%s)
mkdir -p "$dir"
cmake -S "$here" -B "$dir" "${flags[@]}" >"$dir/configure.log" 2>&1 || { cat "$dir/configure.log" >&2; exit 1; }
{
  nice cmake --build "$dir" -j"$(nproc)" --target core traces scenes cache_sim raster pipeline reorder &&
  (
    for t in test_traces test_cache_sim test_pipeline; do
      nice make -C "$dir" -f "tests/CMakeFiles/$t.dir/build.make" "tests/CMakeFiles/$t.dir/depend" &&
        nice make -C "$dir" -j"$(nproc)" "$t/fast" || exit 1
    done  # in a subshell: `exit 1` fails the build step, reported below
  )
} >"$dir/build.log" 2>&1 || { grep -E 'error|Error' "$dir/build.log" | head -30 >&2; exit 1; }
echo "tsan: built in $(($(date +%s) - start)) s" >&2
# halt_on_error: the first report fails the run; second_deadlock_stack: both stacks of an inversion.
export TSAN_OPTIONS="halt_on_error=1 second_deadlock_stack=1 ${TSAN_OPTIONS:-}"
export RASTRACE_READ_AHEAD=1
"$dir/tests/test_traces" --gtest_filter='ReadAhead.*:TraceFile*:TraceWriterThreads.TheFile*:TraceWriterThreads.WhatFour*' \
  --gtest_brief=1
"$dir/tests/test_cache_sim" --gtest_filter='ParallelSweep.*:SweepRowSink.*:LiveBank*' --gtest_brief=1
"$dir/tests/test_pipeline" --gtest_filter='RenderIdentity.TwoThreads*:RenderIdentity.FourThreads*:RasterWorkspaceReuse*:InPlaceTrace.*' --gtest_brief=1
echo "tsan: no report, total $(($(date +%s) - start)) s" >&2
