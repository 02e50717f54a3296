# Figures of the accuracy sweep (issue 3) from the CSV of bench/accuracy/accuracy_sweep.cpp.
# Usage: gnuplot -e "csv='bench/results/accuracy.csv'; outdir='bench/results'" bench/plot_accuracy.gp
# (bench/run_accuracy_sweep.sh runs the sweep and then this).
#   accuracy.png        max orientation error of the torque-free box against wall time per run,
#                       over the whole run and over the first seconds
#   accuracy_energy.png its max energy drift, and its flip-period error (no-flip runs marked)
#   accuracy_torque.png max orientation error of the box under a body-fixed torque
# Columns are read by name, so the sweep may add columns; one curve per integrator listed in
# the CSV, so a new integrator appears without editing this script.

if (!exists("csv")) csv = 'bench/results/accuracy.csv'
if (!exists("outdir")) outdir = 'bench/results'
box = 'torque-free-box'
pi_rad = pi  # the largest possible orientation error [rad]

# gnuplot's default colours repeat after eight: the ninth and tenth integrators get their own.
set linetype 9 lc rgb '#8b4513' lw 1 pt 10
set linetype 10 lc rgb '#e7298a' lw 1 pt 12
set datafile separator comma
set datafile columnheaders  # 'nan' cells read as NaN: not drawn
set encoding utf8

# The value in column `col` (by header name) of the first row of the box case, for labels.
boxValue(col) = system(sprintf("awk -F, -v col=%s -v box=%s 'NR == 1 { for (i = 1; i <= NF; ++i) if ($i == col) c = i; next } $1 == box { printf \"%%g\", $c; exit }' '%s'", col, box, csv))
# Integrators and step rates in CSV order (case and integrator are columns 1 and 2, steps_per_s 3).
names = system(sprintf("awk -F, 'NR > 1 && !seen[$2]++ { printf \"%%s \", $2 }' '%s'", csv))
rates = system(sprintf("awk -F, 'NR > 1 && !seen[$3]++ { printf \"1/%%s \", $3 }' '%s'", csv))
simtime = boxValue('sim_time_s')             # [s]
early = boxValue('early_horizon_s')          # [s]
halfperiod = boxValue('flip_half_period_exact_s')  # [s]
if (words(names) == 0) { print "plot_accuracy.gp: no rows in ".csv; exit status 1 }

# x and y of a row of integrator `name` in the box case; NaN (not drawn) for every other row.
onBox(name, value) = (strcol("case") eq box && strcol("integrator") eq name) ? value : NaN
noFlip(name, value) = (strcol("flip_status") eq 'no-flip') ? onBox(name, value) : NaN

set logscale xy
set format y '10^{%L}'
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
set key outside right top spacing 1.2 box opaque
set xlabel sprintf('wall time per %s s simulated run [ms], fastest of repeats  (points per curve: dt = %s s, left to right)', simtime, rates)
set pointsize 1.3

# --- Orientation error: the whole run, and the first seconds before the first flip ---------------
set output outdir.'/accuracy.png'
set terminal pngcairo size 1280,1150 enhanced font 'Sans,11' linewidth 1.5
set multiplot layout 2,1 title "Torque-free box 1.0 x 0.3 x 0.1 m near its intermediate axis (Dzhanibekov flips): max orientation error\nerror = angle of R_{exact}^T R [rad] against the exact solution (Landau and Lifshitz §37); it cannot exceed π\nexpmap and symplectic-euler coincide here: without torque their steps are the same"
set ylabel 'max orientation error [rad]'
set yrange [1e-13:20]  # exact and exact4 sit at rounding (an error of exactly 0 is not drawn)
set arrow 1 from graph 0, first pi_rad to graph 1, first pi_rad nohead dt 2 lc rgb '#888888'
set label 1 'π rad: orientation lost' at graph 0.01, first pi_rad * 1.5 tc rgb '#666666'
set title sprintf('over the whole %s s run (4 flips); circled: the body stopped flipping (flip-period error nan)', simtime)
plot for [i=1:words(names)] csv using (onBox(word(names, i), column("wall_ms_per_run"))):(column("orient_err_max_rad")) \
       with linespoints lc i pt (4 + 2 * ((i - 1) % 5)) title word(names, i), \
     for [i=1:words(names)] csv using (noFlip(word(names, i), column("wall_ms_per_run"))):(column("orient_err_max_rad")) \
       with points lc rgb 'black' pt 6 ps 2.6 title (i == 1 ? 'stopped flipping' : '')
set title sprintf('over the first %s s only (before the first flip): the first-order methods have not yet lost the orientation', early)
plot for [i=1:words(names)] csv using (onBox(word(names, i), column("wall_ms_per_run"))):(column("orient_err_max_early_rad")) \
       with linespoints lc i pt (4 + 2 * ((i - 1) % 5)) title word(names, i)
unset multiplot
unset arrow 1
unset label 1

# --- Energy drift and flip-period error -----------------------------------------------------------
set output outdir.'/accuracy_energy.png'
set multiplot layout 2,1 title sprintf("Torque-free box near its intermediate axis, %s s simulated", simtime)
set title 'max relative energy drift max_t |E(t)/E_0 - 1|'
set ylabel 'max |E/E_0 - 1|  [1]'
set yrange [*:100]
plot for [i=1:words(names)] csv using (onBox(word(names, i), column("wall_ms_per_run"))):(column("energy_drift_max_rel")) \
       with linespoints lc i pt (4 + 2 * ((i - 1) % 5)) title word(names, i)

# Runs without a measurable flip period are drawn on the dashed line at the top (never dropped).
noflip_y = 3.0  # plotted value for "no flip" [1]: above any real error, which is < 1 here
set title sprintf("flip half-period error |T_{sim}/2 - T/2| / (T/2), T/2 = %s s; on the dashed line: NO FLIP (the body stopped flipping)", halfperiod)
set ylabel 'flip half-period error [1]'
set yrange [*:10]
set arrow 2 from graph 0, first noflip_y to graph 1, first noflip_y nohead dt 2 lc rgb '#888888'
set label 2 'no flip' at graph 0.01, first noflip_y * 1.5 tc rgb '#666666'
plot for [i=1:words(names)] csv using (onBox(word(names, i), column("wall_ms_per_run"))):(column("flip_period_err_rel")) \
       with linespoints lc i pt (4 + 2 * ((i - 1) % 5)) title word(names, i), \
     for [i=1:words(names)] csv using (noFlip(word(names, i), column("wall_ms_per_run"))):(noflip_y) \
       with points lc i pt 2 ps 2 notitle
unset multiplot
unset output

# --- The box under a torque fixed in the body: the splitting methods' orders show ----------------
torqued = 'torqued-box'
onTorqued(name, value) = (strcol("case") eq torqued && strcol("integrator") eq name) ? value : NaN
set output outdir.'/accuracy_torque.png'
set terminal pngcairo size 1280,700 enhanced font 'Sans,11' linewidth 1.5
set title "Box 1.0 x 0.3 x 0.1 m under a torque fixed in the body, omega_0 = (0.3, 4, -0.5) rad/s: max orientation error over the run\nagainst world-frame RK4 at 1/30000 s (its own error about 1e-10 rad: the floor of the most accurate curves)"
set ylabel 'max orientation error [rad]'
set yrange [1e-12:20]
unset arrow 2
unset label 2
plot for [i=1:words(names)] csv using (onTorqued(word(names, i), column("wall_ms_per_run"))):(column("orient_err_max_rad")) \
       with linespoints lc i pt (4 + 2 * ((i - 1) % 5)) title word(names, i)
