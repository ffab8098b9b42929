#!/bin/bash
# A file dropped onto the window opens in it: the window starts on SCENE, a file manager's drop
# (tests/app/xdnd_drop.py, the XDND protocol) brings DROPPED, and the window says it opened it.
# usage: window_drop_test.sh WALKRAD SCENE DROPPED SCREENSHOT (under an X server)
set -u
walkrad=$1 scene=$2 dropped=$3 screenshot=$4
/usr/bin/python3 "$(dirname "$0")/xdnd_drop.py" "$dropped" 60 &
drop=$!
output=$("$walkrad" view "$scene" --width 640 --height 480 --frames 600 --screenshot "$screenshot")
status=$?
wait $drop || { echo "the drop failed"; exit 1; }
echo "$output"
[[ $status -eq 0 ]] || { echo "walkrad view exited $status"; exit 1; }
grep -q "walkrad view: opened $(realpath "$dropped")" <<<"$output" || { echo "the dropped file was not opened"; exit 1; }
