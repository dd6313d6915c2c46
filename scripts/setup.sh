#!/usr/bin/env bash
# Installs every Debian package rastrace needs (only those missing) and unpacks the real data
# (CGAL's meshes, assimp's test models) into data/, which git ignores.
# Idempotent and quiet when everything is already there. Run as root on Debian 12, or with sudo.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
data="${RASTRACE_DATA:-$here/data}"

packages=(
  cmake g++ make pkg-config
  clang libclang-rt-14-dev  # the fuzz targets (scripts/fuzz.sh): clang 14 and libFuzzer
  libglm-dev              # math
  libopenimageio-dev      # image I/O and diffs
  openimageio-tools       # OpenImageIO's CMake package refers to its tools (iconvert)
  libosmesa6-dev          # Mesa OSMesa: reference renderer (softpipe, llvmpipe), BC7 encoder
  libsquish-dev           # BC1-BC5 texture encoder (texcodec/)
  libastcenc-dev          # ASTC texture encoder and decoder (texcodec/)
  libgtest-dev libgmock-dev
  libbenchmark-dev
  libassimp-dev           # mesh and scene import
  libzstd-dev             # trace compression
  libcli11-dev            # command line
  nlohmann-json3-dev      # scene files, JSON output
  liblemon-dev            # graph matching
  libmeshoptimizer-dev    # peer for tests and benchmarks
  gnuplot-nox             # plots
  libcgal-demo            # real meshes (data.tar.gz)
  assimp-testmodels       # textured models
  slurm-wlm munge         # the sharded-sweep test runs a real single-node Slurm
  # The Python module (python/), for Debian's /usr/bin/python3:
  pybind11-dev python3-dev  # building the extension (pybind11's CMake package, Python.h)
  python3-numpy           # its arrays (every result)
  python3-pytest          # the Python tests (ctest runs them)
  python3-pandas python3-matplotlib  # the tests and examples/: sweeps as DataFrames, plots
  python3-pip python3-venv  # `pip install .` into a venv (README, "Python")
)

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if ((${#missing[@]})); then
  echo "setup: installing ${missing[*]}" >&2
  sudo=""
  if [ "$(id -u)" -ne 0 ]; then sudo="sudo"; fi
  export DEBIAN_FRONTEND=noninteractive
  $sudo apt-get update -qq
  $sudo apt-get install -y -qq --no-install-recommends "${missing[@]}" >/dev/null
fi

# CGAL's meshes: data/meshes/*.off inside the documentation tarball.
if [ ! -f "$data/meshes/fandisk.off" ]; then
  mkdir -p "$data"
  tar -xzf /usr/share/doc/libcgal-dev/data.tar.gz -C "$data" --strip-components=1 data/meshes
fi
# assimp's models stay where Debian puts them; a link makes the data folder self-describing.
if [ ! -e "$data/assimp" ]; then
  ln -s /usr/share/assimp/models "$data/assimp"
fi
