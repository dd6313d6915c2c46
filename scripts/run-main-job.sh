#!/usr/bin/env bash
# Installs what is missing, builds, and runs rastrace's main job on the built-in scene.
set -euo pipefail
here=$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)
bash "$here/scripts/setup.sh"
dir=$(bash "$here/scripts/build.sh")
cd "$here"
"$dir/apps/rastrace" info builtin:bunny
