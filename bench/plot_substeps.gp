# Run time against error on Box3D's large pyramid, from bench/substep_sweep.sh's CSV (issue 54):
# left, the top box's sink; right, the fastest box after the run; each against milliseconds per
# step on one thread, one point per substep count (labelled), one curve per engine. Lower and to
# the left is better: a curve below another is more accurate at every price.
#   usage: gnuplot -e "csv='bench/results/substeps.csv'; png='bench/results/substeps.png'" bench/plot_substeps.gp
if (!exists("csv")) csv = 'bench/results/substeps.csv'
if (!exists("png")) png = 'bench/results/substeps.png'
set datafile separator comma
set terminal pngcairo size 1400, 560 font 'DejaVu Sans,11'
set output png
set multiplot layout 1, 2 title "Box3D's large pyramid (5050 boxes, 600 steps at 1/60 s, sleep off, one thread): run time against error over the substep count"
set logscale y
set grid
set key top right
set xlabel 'ms per step'
engines = system(sprintf("awk -F, 'NR > 1 && !seen[$1]++ { printf \"%%s \", $1 }' '%s'", csv))
# Rows of one engine on the pyramid, as "ms value substeps", sorted by substeps.
rows(engine, col) = sprintf("< awk -F, -v OFS=, -v e=%s -v c=%d 'NR > 1 && $1 == e && $2 == \"large_pyramid\" { print $5, ($c > 1e-4 ? $c : 1e-4), $3 }' '%s' | sort -t, -n -k3", engine, col, csv)
set ylabel 'top box sink [m] (log)'
plot for [e in engines] rows(e, 8) using 1:2 with linespoints lw 2 pt 7 title e, \
     for [e in engines] rows(e, 8) using 1:2:3 with labels offset 0.8, 0.6 notitle
set ylabel 'fastest box at the end [m/s] (log)'
plot for [e in engines] rows(e, 6) using 1:2 with linespoints lw 2 pt 7 title e, \
     for [e in engines] rows(e, 6) using 1:2:3 with labels offset 0.8, 0.6 notitle
unset multiplot
