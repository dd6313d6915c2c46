#!/usr/bin/env bash
# Installs the build into a temporary prefix, builds tests/package/consumer against it (an
# out-of-tree find_package(rastrace) linking rastrace::cache_sim and rastrace::traces), runs it
# on a din trace whose misses are known, and checks that the consumer links none of the optional
# libraries (assimp, OSMesa, OpenImageIO) and no module it does not use.
# Usage: install_test.sh BUILD_DIR SOURCE_DIR [EXTRA_LINKER_FLAGS]
set -euo pipefail
build=$1 source=$2 linker_flags=${3:-}
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

cmake --install "$build" --prefix "$tmp/prefix" >"$tmp/install.log"
for f in lib/librastrace_cache_sim.a lib/cmake/rastrace/rastraceConfig.cmake include/rastrace/cache_sim.h \
         include/rastrace/cache_sim/byte_cache.h include/rastrace/traces.h; do
  [ -e "$tmp/prefix/$f" ] || { echo "not installed: $f"; exit 1; }
done

cmake -S "$source/tests/package/consumer" -B "$tmp/consumer" -DCMAKE_PREFIX_PATH="$tmp/prefix" \
      -DCMAKE_BUILD_TYPE=Release ${linker_flags:+"-DCMAKE_EXE_LINKER_FLAGS=$linker_flags"} >"$tmp/configure.log" 2>&1 ||
  { cat "$tmp/configure.log"; exit 1; }
cmake --build "$tmp/consumer" >"$tmp/build.log" 2>&1 || { cat "$tmp/build.log"; exit 1; }

# 10 lines (64 B apart) read twice: a fully associative LRU cache of 8 lines misses all 20
# (the second round finds each line evicted), one of 16 lines only the first 10.
for round in 1 2; do for i in 0 1 2 3 4 5 6 7 8 9; do printf '0 %x\n' $((i * 64)); done; done >"$tmp/loop.din"
small=$("$tmp/consumer/consumer" "$tmp/loop.din" size=512B,line=64B,assoc=full,policy=lru)
large=$("$tmp/consumer/consumer" "$tmp/loop.din" size=1KiB,line=64B,assoc=full,policy=lru)
[ "$small" = "accesses 20 misses 20 compulsory 10" ] || { echo "8 lines: got '$small'"; exit 1; }
[ "$large" = "accesses 20 misses 10 compulsory 10" ] || { echo "16 lines: got '$large'"; exit 1; }

# What the consumer linked: the command line and the shared libraries it needs.
link=$(cat "$tmp/consumer/CMakeFiles/consumer.dir/link.txt")
needed=$(readelf -d "$tmp/consumer/consumer" | grep NEEDED || true)
for unwanted in assimp OSMesa OpenImageIO rastrace_scenes rastrace_pipeline rastrace_reference rastrace_experiments; do
  if grep -qi "$unwanted" <<<"$link$needed"; then
    echo "the consumer links $unwanted:"; echo "$link"; echo "$needed"; exit 1
  fi
done
grep -q librastrace_cache_sim.a <<<"$link" || { echo "cache_sim not linked: $link"; exit 1; }
echo "consumer built against the installed package: $small / $large"
