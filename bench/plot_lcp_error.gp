# PGS's normal impulses against the exact LCP reference (issue 55), from bench/lcp_reference's CSV:
# left, the error in the Delassus norm (what the impulses do to the bodies, unique) against PGS's
# sweeps 1..50; right, the same error against microseconds per solve, with the longer runs
# (100 to 1000 sweeps) and the LCP's own time per solve as a vertical line per scene.
#   usage: gnuplot -e "csv='bench/results/lcp_error.csv'; png='bench/results/lcp_error.png'" bench/plot_lcp_error.gp
if (!exists("csv")) csv = 'bench/results/lcp_error.csv'
if (!exists("png")) png = 'bench/results/lcp_error.png'
set datafile separator comma
set terminal pngcairo size 1400, 560 font 'DejaVu Sans,11'
set output png
set multiplot layout 1, 2 title "PGS (cold start) against the exact LCP reference (world.solver = lcp): frictionless resting scenes at dt = 1/60 s, one thread"
scenes = system(sprintf("awk -F, 'NR > 1 && !seen[$1]++ { printf \"%%s \", $1 }' '%s'", csv))
# PGS rows of one scene as "sweeps us error", the error floored at 1e-16 for the log scale.
pgs(scene, most) = sprintf("< awk -F, -v s=%s -v m=%d 'NR > 1 && $1 == s && $2 == \"pgs\" && $3 <= m { print $3 \",\" $4 \",\" ($5 > 1e-16 ? $5 : 1e-16) }' '%s'", scene, most, csv)
lcpTime(scene) = real(system(sprintf("awk -F, -v s=%s 'NR > 1 && $1 == s && $2 == \"lcp\" { print $4 }' '%s'", scene, csv)))
set logscale y
set format y '10^{%L}'
set grid
set key top right
set xlabel 'PGS sweeps (Settings::velocityIterations)'
set ylabel 'normal impulse error ||J^T(f_{pgs} - f_{lcp})||_{M^{-1}} / ||J^T f_{lcp}||'
set xrange [0:50]
plot for [s in scenes] pgs(s, 50) using 1:3 with linespoints lw 2 pt 7 ps 0.6 title s
set logscale x
set xrange [*:*]
set xlabel 'microseconds per solve (log)'
unset arrow
i = 0
do for [s in scenes] {
  i = i + 1
  set arrow i from lcpTime(s), graph 0 to lcpTime(s), graph 1 nohead dt 2 lw 1.5 lc i
  set label i sprintf("LCP %s", s) at lcpTime(s), graph 0.05 rotate by 90 left offset -0.6, 0 tc lt i
}
plot for [s in scenes] pgs(s, 1000) using 2:3 with linespoints lw 2 pt 7 ps 0.6 title sprintf("%s (1 to 1000 sweeps)", s)
unset multiplot
