#!/usr/bin/env bash
# Configures and builds rastrace. Usage: scripts/build.sh [--sanitize]
# Release build in build/, or AddressSanitizer + UBSan build in build-asan/. Warnings are errors.
# Prints the build folder on stdout; compiler messages (without progress lines) go to stderr.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
if [ "${1:-}" = "--sanitize" ]; then
  dir="$here/build-asan"
  # -O1 without -g, as the AddressSanitizer documentation advises: reports still name functions,
  # and the build is much faster than RelWithDebInfo (CI runs both builds in under 30 minutes).
  flags=(-DCMAKE_BUILD_TYPE=Release "-DCMAKE_CXX_FLAGS_RELEASE=-O1" -DRASTRACE_SANITIZE=ON -DRASTRACE_BENCHMARKS=OFF)
else
  dir="$here/build"
  flags=(-DCMAKE_BUILD_TYPE=Release)
fi
# ccache, when the machine has it, only speeds rebuilds; the build does not need it.
if command -v ccache >/dev/null; then
  flags+=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache)
  export CCACHE_BASEDIR="${CCACHE_BASEDIR:-$here}"
fi
cmake -S "$here" -B "$dir" -DRASTRACE_WERROR=ON "${flags[@]}" >"$dir.configure.log" 2>&1 ||
  { cat "$dir.configure.log" >&2; exit 1; }
status=0
cmake --build "$dir" -j"$(nproc)" >"$dir.log" 2>&1 || status=$?
grep -v -E '^\[ *[0-9]+%\]|^gmake|Built target|Scanning dependencies' "$dir.log" >&2 || true
if [ "$status" -ne 0 ]; then
  echo "build failed (full log: $dir.log)" >&2
  exit "$status"
fi
echo "$dir"
