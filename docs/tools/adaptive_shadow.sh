#!/usr/bin/env bash
# Redraws docs/adaptive-shadow.png: the shadow of a box on a floor (assets/box-on-floor.json)
# solved on the mesh at its patch size (left) and with adaptive refinement during the solve
# (right, default threshold 0.25 and minimum element a quarter of the 0.5 m patch size), shaded
# above and with the mesh drawn below. Needs a built tree (./run.sh or ./test.sh) and ImageMagick
# (Debian: imagemagick); the figure is committed, so only this script needs them.
set -euo pipefail
cd "$(dirname "$0")/../.."
source docs/tools/box_on_floor.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
render_box_on_floor "$work" 400 300 "fixed --no-adapt" "adaptive --adapt-threshold 0.25"
montage -label 'mesh at the patch size' "$work/fixed.png" -label 'adaptive refinement while solving' "$work/adaptive.png" \
        -label '' "$work/fixed--wireframe.png" -label '' "$work/adaptive--wireframe.png" \
        -tile 2x2 -geometry +3+3 -font DejaVu-Sans -pointsize 14 docs/adaptive-shadow.png
echo "wrote docs/adaptive-shadow.png"
