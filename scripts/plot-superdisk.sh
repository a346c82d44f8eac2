#!/bin/sh
# Plot of the certified optimal superdisk density and the Lambda0 / Lambda1 lattices against p
# (like the PRL's figure). Usage: scripts/plot-superdisk.sh [superpack-binary] [out.png] [a:b:h]
# Writes the CSV next to the PNG (out.csv) and plots interval midpoints (the enclosures are far
# narrower than a pixel; the CSV holds the certified lo/hi).
set -eu
binary=${1:-build/superpack}
png=${2:-superdisk.png}
range=${3:-0.5:4:0.025}
csv=${png%.png}.csv
# Exit 4 (some p undecided, e.g. 0.5 < p < 0.55) still leaves a complete CSV: those rows
# carry no optimum and the plot skips them.
status=0
"$binary" superdisk --scan "$range" --csv > "$csv" || status=$?
[ "$status" -eq 0 ] || [ "$status" -eq 4 ] || exit "$status"
gnuplot <<GNUPLOT
set datafile separator ','
set terminal pngcairo size 900,600
set output '$png'
set xlabel 'p'
set ylabel 'packing density phi'
set key bottom right
set grid
plot '$csv' using 1:((\$6+\$7)/2) every ::1 with lines lw 3 lc rgb '#999999' title 'certified optimum (Fejes Toth)', \
     '$csv' using 1:((\$2+\$3)/2) every ::1 with lines lw 1.5 lc rgb '#d62728' title 'Lambda0 (contact along the diagonal)', \
     '$csv' using 1:((\$4+\$5)/2) every ::1 with lines lw 1.5 lc rgb '#1f77b4' title 'Lambda1 (contact along an axis)'
GNUPLOT
echo "wrote $png and $csv"
