#!/usr/bin/env bash
# Redraws docs/adaptive-shadow.png: the shadow of a box on a floor (assets/box-on-floor.json)
# solved on the mesh at its patch size (left) and with adaptive refinement during the solve
# (right, default threshold 0.25 and minimum element a quarter of the 0.5 m patch size), shaded
# above and with the mesh drawn below. Needs a built tree (./run.sh or ./test.sh) and ImageMagick
# (Debian: imagemagick); the figure is committed, so only this script needs them.
set -euo pipefail
cd "$(dirname "$0")/../.."
walkrad=${WALKRAD:-build/walkrad}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
for case in "fixed --no-adapt" "adaptive --adapt-threshold 0.25"; do
  set -- $case
  name=$1
  shift
  for wire in "" --wireframe; do
    "$walkrad" render assets/box-on-floor.json "$@" --out "$work/$name$wire.png" --exposure 1.5 --width 400 \
      --height 300 --threads 2 --quiet $wire
  done
done
montage -label 'mesh at the patch size' "$work/fixed.png" -label 'adaptive refinement while solving' "$work/adaptive.png" \
        -label '' "$work/fixed--wireframe.png" -label '' "$work/adaptive--wireframe.png" \
        -tile 2x2 -geometry +3+3 -font DejaVu-Sans -pointsize 14 docs/adaptive-shadow.png
echo "wrote docs/adaptive-shadow.png"
