#!/usr/bin/env bash
# Installs what is missing, builds, and runs the main job: `rastrace report` on the built-in bunny
# (vertex cache orderings, texture cache sweeps, plots, frames) into out/report.md, then every
# published figure beside ours into out/reproduce.md.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/scripts/setup.sh"
dir=$(bash "$here/scripts/build.sh")
cd "$here"
"$dir/apps/rastrace" report builtin:bunny -o out
"$dir/apps/rastrace" reproduce -o out/reproduce.md
echo "wrote out/report.md and out/reproduce.md"
