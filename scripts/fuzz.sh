#!/usr/bin/env bash
# Builds the libFuzzer targets (fuzz/, clang 14 with ASan + UBSan, in build-fuzz/) and runs each
# for SECONDS (default 60) on its corpus: the committed seeds (fuzz/corpus/<target>/) plus the
# generated ones (scripts/fuzz_seeds.py, build-fuzz/seeds/<target>/). New coverage goes to
# build-fuzz/corpus/<target>/ (kept between runs), failing inputs to build-fuzz/artifacts/.
# Fails on any crash, sanitizer report, uncaught exception, input slower than 5 s or allocation
# over 1 GiB (libFuzzer's -timeout, -rss_limit_mb and -malloc_limit_mb).
# Usage: scripts/fuzz.sh [SECONDS] [TARGET...]     FUZZ_JOBS=N runs N targets at once (default 1)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
seconds="${1:-60}"
shift || true
dir="$here/build-fuzz"
all_targets=(off ply obj scene assimp trace_reader trace_chunk csv_trace din cache_spec size_list)
targets=("$@")
((${#targets[@]})) || targets=("${all_targets[@]}")

flags=(-DCMAKE_BUILD_TYPE=RelWithDebInfo -DCMAKE_C_COMPILER=clang -DCMAKE_CXX_COMPILER=clang++
       -DRASTRACE_FUZZ=ON -DRASTRACE_WERROR=ON -DRASTRACE_BENCHMARKS=OFF -DRASTRACE_PYTHON=OFF)
if command -v ccache >/dev/null; then
  flags+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$here}"
fi
mkdir -p "$dir"
start=$(date +%s)
cmake -S "$here" -B "$dir" "${flags[@]}" >"$dir/configure.log" 2>&1 || { cat "$dir/configure.log" >&2; exit 1; }
build_targets=()
for t in "${targets[@]}"; do build_targets+=("fuzz_$t"); done
nice cmake --build "$dir" -j"$(nproc)" --target "${build_targets[@]}" >"$dir/build.log" 2>&1 ||
  { grep -v -E '^\[ *[0-9]+%\]|^gmake|Built target|Scanning dependencies' "$dir/build.log" >&2; exit 1; }
echo "fuzz: built ${#targets[@]} targets in $(($(date +%s) - start)) s" >&2
python3 "$here/scripts/fuzz_seeds.py" "$dir/seeds" >&2

# Longest input per target: a few KiB of text for the grammars, more for files.
max_len() {
  case "$1" in
    cache_spec | size_list) echo 256 ;;
    off | obj | scene | csv_trace | din) echo 16384 ;;
    *) echo 65536 ;;
  esac
}

run_one() {
  local t=$1
  local corpus="$dir/corpus/$t" artifacts="$dir/artifacts/$t"
  mkdir -p "$corpus" "$artifacts"
  local seeds=("$here/fuzz/corpus/$t") dict=()
  # A dictionary (keywords, header counts such as 4294967295) lets mutations reach the loops over
  # declared counts, which random bytes rarely spell.
  [ -f "$here/fuzz/dict/$t.dict" ] && dict=("-dict=$here/fuzz/dict/$t.dict")
  [ -d "$dir/seeds/$t" ] && seeds+=("$dir/seeds/$t")
  # -malloc_limit_mb: one allocation over 1 GiB is a failure even when RSS stays low.
  "$dir/fuzz/fuzz_$t" "$corpus" "${seeds[@]}" -max_total_time="$seconds" -timeout=5 -rss_limit_mb=1024 \
    -malloc_limit_mb=1024 -max_len="$(max_len "$t")" -artifact_prefix="$artifacts/" -print_final_stats=1 \
    "${dict[@]}" >"$dir/$t.log" 2>&1
}

jobs="${FUZZ_JOBS:-1}"
failed=()
pids=()
names=()
wait_one() {
  local pid=${pids[0]} name=${names[0]}
  pids=("${pids[@]:1}")
  names=("${names[@]:1}")
  if wait "$pid"; then
    local stats
    stats=$(grep -E '^#[0-9]+.*(DONE|pulse)' "$dir/$name.log" | tail -1 || true)
    echo "fuzz: $name ok: ${stats:-no stats}" >&2
  else
    echo "fuzz: $name FAILED (log: $dir/$name.log, inputs: $dir/artifacts/$name/)" >&2
    grep -E 'ERROR|SUMMARY|runtime error|terminate|Test unit written' "$dir/$name.log" | head -8 >&2 || true
    failed+=("$name")
  fi
}
for t in "${targets[@]}"; do
  run_one "$t" &
  pids+=($!)
  names+=("$t")
  if ((${#pids[@]} >= jobs)); then wait_one; fi
done
while ((${#pids[@]})); do wait_one; done
echo "fuzz: total $(($(date +%s) - start)) s" >&2
if ((${#failed[@]})); then
  echo "fuzz: failures in ${failed[*]}" >&2
  exit 1
fi
