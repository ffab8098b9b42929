# shellcheck shell=bash
# Sourced by the scripts that draw figures of assets/box-on-floor.json.

# render_box_on_floor DIR WIDTH HEIGHT CASE...: renders the scene once for each CASE, "NAME
# [OPTION...]" with the options of `walkrad render`, shaded into DIR/NAME.png and with the mesh
# drawn into DIR/NAME--wireframe.png, at WIDTH x HEIGHT, exposure 1.5, on two threads. The
# program is $WALKRAD (default build/walkrad, from the top of the tree).
render_box_on_floor() {
  local dir=$1 width=$2 height=$3 case wire
  local -a options
  shift 3
  for case in "$@"; do
    read -ra options <<< "$case"
    for wire in "" --wireframe; do
      "${WALKRAD:-build/walkrad}" render assets/box-on-floor.json "${options[@]:1}" --out "$dir/${options[0]}$wire.png" \
        --exposure 1.5 --width "$width" --height "$height" --threads 2 --quiet $wire
    done
  done
}
