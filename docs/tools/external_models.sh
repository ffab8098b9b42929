#!/usr/bin/env bash
# Redraws docs/external-models.png: the real glTF models of ../shared/scenes-external/ (made by
# others), each with the sidecar that gives it light (tests/app/sidecars/), after 40 shots of
# the solver (the first bounces of the lamps' and sky's light; the rest is still the ambient
# estimate). A full solve of these models takes minutes; CI renders only their first, ambient,
# picture (tests/app/gltf_render_test.cpp). Needs a built tree and ImageMagick (Debian:
# imagemagick); the figure is committed, so only this script needs them.
set -euo pipefail
cd "$(dirname "$0")/../.."
external=../shared/scenes-external
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
models=(modern-hall-staircase/modern_hall grey-white-room-fireplace/grey_white_room
        sponza-crytek/sponza white-room-living/white_room)
args=()
for model in "${models[@]}"; do
  name=$(basename "$model")
  build/walkrad render "$external/$model.gltf" --sidecar "tests/app/sidecars/$name.walkrad.json" \
    --max-shots 40 --width 480 --height 360 --out "$work/$name.png" --stats "$work/$name.json" --quiet
  label=$(python3 -c "import json,sys;d=json.load(open(sys.argv[1]));print(f\"{sys.argv[2]}: {d['elements']:,} elements, {d['patches']:,} patches\")" \
          "$work/$name.json" "$name")
  args+=(-label "$label" "$work/$name.png")
done
montage "${args[@]}" -tile 2x2 -geometry +3+3 -font DejaVu-Sans -pointsize 14 docs/external-models.png
echo "wrote docs/external-models.png"
