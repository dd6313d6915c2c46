#!/usr/bin/env bash
# Installs what is missing, builds, and runs the whole test suite with ctest.
# Usage: scripts/run-tests.sh [--sanitize]   (--sanitize: the ASan + UBSan build)
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/scripts/setup.sh"
dir=$(bash "$here/scripts/build.sh" "$@")
export ASAN_OPTIONS=detect_leaks=1:abort_on_error=1
export UBSAN_OPTIONS=print_stacktrace=1:halt_on_error=1
if [ "${1:-}" = "--sanitize" ]; then
  # python/CMakeLists.txt leaves the module out of this build: an ASan-instrumented extension
  # loads only into an interpreter started with the ASan runtime preloaded.
  echo "run-tests: the Python tests (python/tests) are skipped under --sanitize; the Release run has them" >&2
fi
cd "$dir" && ctest --output-on-failure -j"$(nproc)"
