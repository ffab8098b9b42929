#!/usr/bin/env bash
# ./run.sh [SCENE]: sets up and builds walkrad, then opens the walkthrough window when a display
# is present, or renders SCENE headless (OSMesa) and prints the image's path.
set -euo pipefail
cd "$(dirname "$0")"
scripts/setup.sh
scene=${1:-assets/cornell.json}
if [[ -n "${DISPLAY:-}${WAYLAND_DISPLAY:-}" ]]; then
  exec build/walkrad view "$scene"
fi
mkdir -p out
image="out/$(basename "${scene%.*}").png"
build/walkrad render "$scene" --out "$image" --stats "out/$(basename "${scene%.*}").stats.json"
echo "$(pwd)/$image"
