#!/usr/bin/env bash
# Redraws docs/figure-6-1.png: meshing the kitchen at the patch sizes of the thesis' figure 6.1
# (24, 20, 16, 12 and 8 inches): elements and time. Needs a built tree (./run.sh or ./test.sh)
# and gnuplot (Debian: gnuplot-nox); the figure is committed, so only this script needs it.
set -euo pipefail
cd "$(dirname "$0")/../.."
data=$(mktemp)
trap 'rm -f "$data" "$data.json"' EXIT
for size in 24 20 16 12 8; do
  build/walkrad mesh assets/kitchen.json --patch-size "$size" --repeat 20 --stats "$data.json" >/dev/null
  elements=$(grep '"elements"' "$data.json" | tr -dc '0-9')
  ms=$(grep '"mesh_ms"' "$data.json" | sed 's/.*: *//; s/,//')
  echo "$size $elements $ms" >> "$data"
done
cat "$data"
gnuplot <<PLOT
set terminal pngcairo size 900,520 font ",11"
set output "docs/figure-6-1.png"
set title "Meshing the kitchen (assets/kitchen.json) at the patch sizes of thesis figure 6.1"
set xlabel "patch size (inches)"
set ylabel "elements"
set y2label "mesh time (ms, best of 20, one core)"
set xrange [26:6]
set yrange [0:*]
set y2range [0:*]
set ytics nomirror
set y2tics
set key top left
set grid
plot "$data" using 1:2 with linespoints lw 2 pt 7 title "elements", \
     "$data" using 1:3 axes x1y2 with linespoints lw 2 pt 5 title "time (ms)"
PLOT
echo "wrote docs/figure-6-1.png"
