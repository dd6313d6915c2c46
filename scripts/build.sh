#!/usr/bin/env bash
# Configures and builds rastrace. Usage: scripts/build.sh [--sanitize]
# Release build in build/, or AddressSanitizer + UBSan build in build-asan/. Warnings are errors.
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
cmake -S "$here" -B "$dir" -DRASTRACE_WERROR=ON "${flags[@]}" >"$dir.configure.log" 2>&1 ||
  { cat "$dir.configure.log" >&2; exit 1; }
cmake --build "$dir" -j"$(nproc)" 2>&1 | grep -v -E '^\[ *[0-9]+%\]|^gmake|Built target|Scanning dependencies' >&2 || true
cmake --build "$dir" -j"$(nproc)" >/dev/null  # fails here (with the errors above) if the build failed
echo "$dir"
