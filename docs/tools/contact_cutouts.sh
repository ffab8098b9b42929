#!/usr/bin/env bash
# Redraws docs/contact-cutouts.png: a box standing on a floor, solved with its footprint cut out
# of the floor (left), the same box 2 mm above the floor, not cut (middle), and a reference with
# patches of 0.2 m instead of 0.5 m (right). The scene is the one of
# tests/app/contact_cutout_test.cpp. Needs a built tree (./run.sh or ./test.sh) and ImageMagick's
# montage (Debian: imagemagick); the figure is committed, so only this script needs them.
set -euo pipefail
cd "$(dirname "$0")/../.."
walkrad=${WALKRAD:-build/walkrad}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
scene() {  # lift patch
  cat <<JSON
{ "format": "walkrad-scene/1", "settings": { "patch_size": $2 },
  "materials": { "white": { "reflectance": [0.6, 0.6, 0.6] },
                 "lamp": { "reflectance": [0.5, 0.5, 0.5], "emission": [8, 8, 8] } },
  "objects": [
    { "name": "room", "movable": false,
      "solids": [ { "profile": [[0, 0], [4, 0], [4, 3], [0, 3]], "from": 0, "to": 2.5, "inward": true, "material": "white",
                    "faces": { "top": { "holes": [ { "polygon": [[1.5, 1], [2.5, 1], [2.5, 2], [1.5, 2]], "fill": "lamp" } ] } } } ] },
    { "name": "box",
      "solids": [ { "profile": [[1.2, 1.3], [2.1, 1.3], [2.1, 2.2], [1.2, 2.2]], "from": $1, "to": 0.8, "material": "white" } ] } ],
  "cameras": { "default": { "position": [2.6, 1.2, 0.2], "look_at": [1.65, 0.1, 1.6], "fov_y": 55 } } }
JSON
}
for case in "cut 0 0.5" "uncut 0.002 0.5" "reference 0 0.2"; do
  set -- $case
  scene "$2" "$3" > "$work/$1.json"
  for wire in "" --wireframe; do
    "$walkrad" render "$work/$1.json" --out "$work/$1$wire.png" --exposure 1.5 --width 360 --height 270 --threads 2 --quiet $wire
  done
done
montage -label 'footprint cut out' "$work/cut.png" -label 'box 2 mm above, not cut' "$work/uncut.png" \
        -label 'reference (0.2 m patches)' "$work/reference.png" \
        -label '' "$work/cut--wireframe.png" -label '' "$work/uncut--wireframe.png" -label '' "$work/reference--wireframe.png" \
        -tile 3x2 -geometry +3+3 -font DejaVu-Sans -pointsize 14 docs/contact-cutouts.png
echo "wrote docs/contact-cutouts.png"
