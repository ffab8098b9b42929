#!/usr/bin/env bash
# Redraws docs/contact-cutouts.png: a box standing on a floor, solved with its footprint cut out
# of the floor (left), the same box 2 mm above the floor, not cut (middle), and a reference with
# patches of 0.2 m instead of 0.5 m (right): assets/box-on-floor.json, the scene of
# tests/app/contact_cutout_test.cpp. Needs a built tree (./run.sh or ./test.sh) and ImageMagick
# (Debian: imagemagick); the figure is committed, so only this script needs them.
set -euo pipefail
cd "$(dirname "$0")/../.."
source docs/tools/box_on_floor.sh
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
# Cut out: as the file stands. Not cut: the box moved 2 mm up after converging (the edit path
# takes the footprint away and corrects the light). Reference: patches of 0.2 m.
render_box_on_floor "$work" 360 270 "cut" "uncut --move box:0,0.002,0" "reference --patch-size 0.2"
montage -label 'footprint cut out' "$work/cut.png" -label 'box 2 mm above, not cut' "$work/uncut.png" \
        -label 'reference (0.2 m patches)' "$work/reference.png" \
        -label '' "$work/cut--wireframe.png" -label '' "$work/uncut--wireframe.png" -label '' "$work/reference--wireframe.png" \
        -tile 3x2 -geometry +3+3 -font DejaVu-Sans -pointsize 14 docs/contact-cutouts.png
echo "wrote docs/contact-cutouts.png"
