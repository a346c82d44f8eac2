#!/bin/sh
# The densest certified lattice packing of superballs against p, with every family (the
# paper's Fig. 4, and beyond): `superpack best --scan a:b:h --csv`, then gnuplot.
# Usage: scripts/plot-best.sh [superpack-binary] [out.png] [a:b:h]
# Writes the CSV next to the PNG (out.csv) and plots interval midpoints (the enclosures are far
# narrower than a pixel; the CSV holds the certified lo/hi). A family is drawn solid where it
# is a certified packing and dotted where it is not one (O1 on most of its range).
set -eu
binary=${1:-build/superpack}
png=${2:-best.png}
range=${3:-0.5:3:0.05}
csv=${png%.png}.csv
status=0
"$binary" best --scan "$range" --csv --starts 4 > "$csv" || status=$?
[ "$status" -eq 0 ] || [ "$status" -eq 4 ] || exit "$status"
# One solid and one dotted curve per family: the family columns are NAME_lo, NAME_hi,
# NAME_packing from column 6 on.
plots=$(head -1 "$csv" | tr ',' '\n' | awk -v q="'" -v f="$csv" '
  /_lo$/ { name = substr($0, 1, length($0) - 3); lo = NR; hi = NR + 1; pk = NR + 2;
           if (name == "phi") next;
           printf ", %s%s%s using 1:(strcol(%d) eq \"yes\" ? ($%d+$%d)/2 : 1/0) with lines lw 1.5 title \"%s\"", q, f, q, pk, lo, hi, name;
           printf ", %s%s%s using 1:(strcol(%d) eq \"yes\" ? 1/0 : ($%d+$%d)/2) with points pt 7 ps 0.3 title \"%s, not a packing\"", q, f, q, pk, lo, hi, name }')
gnuplot <<GNUPLOT
set datafile separator ','
set terminal pngcairo size 1000,650
set output '$png'
set xlabel 'p'
set ylabel 'lattice packing density phi'
set key bottom right
set grid
set yrange [0.7:1]
plot '$csv' using 1:((\$3+\$4)/2) every ::1 with lines lw 4 lc rgb '#999999' title 'densest certified lattice (superpack best)'$plots
GNUPLOT
echo "wrote $png and $csv"
