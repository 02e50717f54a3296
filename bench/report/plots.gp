# The report's benchmark plots (issue 11), drawn from the tables bench/report/plot_data.py lays
# out from the CSVs of bench/results/. bench/make_report.sh runs this; by hand:
#   python3 bench/report/plot_data.py bench/results /tmp/plot && \
#   gnuplot -e "data='/tmp/plot'; outdir='bench/results'" bench/report/plots.gp
# Writes broadphase.png, pile.png, particles.png, throughput.png, soft.png into outdir (for docs/),
# and REPORT.md's plots, sized for print: report_particles.png, report_accuracy.png,
# report_broadphase.png, report_narrowphase.png, report_stacks.png.

if (!exists("data")) data = '/tmp/plot'
if (!exists("outdir")) outdir = 'bench/results'
set terminal pngcairo size 900,560 enhanced font 'Sans,11' linewidth 1.5
set encoding utf8
set grid xtics ytics mxtics mytics lc rgb '#dddddd'
set key top left box opaque
set pointsize 1.3

# --- Broad phase: time per update against N ------------------------------------------------------
set output outdir.'/broadphase.png'
set title "Broad phase: one update of N boxes (seed 004 \"sweep and prune\" against all pairs)"
set logscale xy
set format x '10^{%L}'
set format y '10^{%L}'
set xlabel 'boxes N'
set ylabel 'CPU time per update [ms]'
f = data.'/broadphase.dat'
plot f using 1:2 with linespoints pt 7 title 'sweep and prune, coherent motion', \
     f using 1:3 with linespoints pt 5 title 'sweep and prune, fixed swaps per box', \
     f using 1:4 with linespoints pt 9 title 'sweep and prune, every box teleports', \
     f using 1:5 with linespoints pt 4 dt 2 title 'brute force, coherent', \
     f using 1:6 with linespoints pt 6 dt 2 title 'brute force, teleporting'

# --- Box pile: rbsim (soft step, PGS) against Bullet ----------------------------------------------------------------
set output outdir.'/pile.png'
set title "Box pile on a plane, dt = 1/60 s, 10 solver sweeps: median time per step of steps 300-600"
set xlabel 'boxes N'
set ylabel 'wall time per step [ms]'
f = data.'/pile.dat'
plot f using 1:2 with linespoints pt 7 lc 1 title 'rbsim soft step, sleep off', \
     f using 1:3 with linespoints pt 7 lc 4 title 'rbsim PGS, sleep off', \
     f using 1:4 with linespoints pt 5 lc 2 title 'Bullet 3.24 float, sleep off', \
     f using 1:5 with linespoints pt 9 lc 3 title 'Bullet 3.24 double, sleep off', \
     f using 1:6 with linespoints pt 6 lc 1 dt 2 title 'rbsim soft step, sleep on', \
     f using 1:7 with linespoints pt 6 lc 4 dt 2 title 'rbsim PGS, sleep on', \
     f using 1:8 with linespoints pt 4 lc 2 dt 2 title 'Bullet float, sleep on', \
     f using 1:9 with linespoints pt 8 lc 3 dt 2 title 'Bullet double, sleep on'

# --- Particles: steps per second against the memory bound ----------------------------------------
set output outdir.'/particles.png'
set title "Particle step (gravity, drag, a ground plane): rate against the memory-bandwidth bound"
set xlabel 'particles'
set ylabel 'particle-steps per CPU second'
set key bottom left
f = data.'/particles.dat'
plot f using 1:2 with linespoints pt 7 title 'measured', \
     f using 1:3 with lines dt 2 lc rgb '#444444' title 'bound: memcpy bandwidth / bytes per particle-step'
unset logscale
set format x '%g'
set format y '%g'

# --- Throughput per integrator ---------------------------------------------------------------------
set output outdir.'/throughput.png'
set title "Rigid bodies without collisions: body-steps per CPU second by integrator and body count"
set style data histograms
set style histogram clustered gap 1.5
set style fill solid 0.8 border -1
set key top right
set xlabel 'integrator'
set ylabel 'million body-steps per second'
set logscale y
set yrange [1:*]
set xtics nomirror
f = data.'/throughput.dat'
plot f using 2:xtic(1) title '1 body', \
     '' using 3 title '10^3 bodies', \
     '' using 4 title '10^5 bodies', \
     '' using 5 fs pattern 4 lc rgb '#555555' title 'memory bound at 10^5 bodies'

# --- Soft bodies: cost per simulated second ------------------------------------------------------
set output outdir.'/soft.png'
set terminal pngcairo size 900,600 enhanced font 'Sans,11' linewidth 1.5
set title "FEM soft block (corotated, ν = 0.3) dropped on the ground: CPU cost per simulated second"
set xlabel ''
set ylabel 'wall time per simulated second [ms]'
set key top left
set bmargin 5
tets = system('cat '.data.'/soft_tets.txt')
f = data.'/soft.dat'
plot for [i=1:words(tets)] f using (column(i + 1)):xtic(1) title word(tets, i).' tetrahedra'
unset output

# === The report's plots (issue 36): one per section of REPORT.md, sized for print ================
# bench/report/pdf_layout.lua places every PNG of REPORT.md at 200 pixels per inch, so the size
# given here (px(cm)) is the plot's size on paper, at most 16.9 cm (the text is 17 cm wide: A4 less
# 2 cm margins; a wider plot runs off the margin and fails tests/report/check_report_pdf.sh), and
# pngcairo's font of 21 pt (4/3 px per pt: 28 px) prints at 28/200 inch = 10 pt. Tick labels avoid
# superscripts (which print smaller): 1e-6, 10k. No titles: REPORT.md's caption below each plot says
# what was measured and the command.
dpi = 200.0
px(cm) = int(cm / 2.54 * dpi + 0.5)
printfont = 'Sans,21'
reset
set encoding utf8
set grid xtics ytics lc rgb '#d8d8d8'
set border lw 1.5
set pointsize 1.8

# --- Section 1: particle-steps per second against the memory bound ------------------------------
w = px(12.0); h = px(4.4)
set terminal pngcairo size w,h enhanced font printfont linewidth 3
set output outdir.'/report_particles.png'
set logscale x
set format x '%.0s%c'
set xrange [700:1.4e6]
set yrange [0:200]
set xlabel 'particles in the system' offset 0,0.3
set ylabel 'M particle-steps / s' offset 1,0
set key bottom left horizontal Left reverse box opaque samplen 2
f = data.'/particles.dat'
plot f using 1:($2 / 1e6) with linespoints pt 7 lc rgb '#1f5fbf' title 'measured', \
     f using 1:($3 / 1e6) with lines dt 2 lc rgb '#444444' title 'memory bound'
unset logscale
set xrange [*:*]
set yrange [*:*]

# --- Section 2: orientation error of the torque-free box against the cost of a run --------------
names = system('cat '.data.'/accuracy_names.txt')
early = word(system('cat '.data.'/accuracy_horizons.txt'), 1) + 0
whole = word(system('cat '.data.'/accuracy_horizons.txt'), 2) + 0
w = px(16.9); h = px(6.0)
set terminal pngcairo size w,h enhanced font printfont linewidth 3
set output outdir.'/report_accuracy.png'
set linetype 9 lc rgb '#8b4513' pt 10
set linetype 10 lc rgb '#e7298a' pt 12
set logscale xy
set format x '%g'
set format y '1e%T'
set xrange [0.05:15]
set yrange [1e-13:30]
set ytics 100
set xlabel ''
set ylabel 'max orientation error [rad]' offset 1,0
set arrow 1 from graph 0, first pi to graph 1, first pi nohead dt 2 lc rgb '#888888' lw 1
set multiplot layout 1,2
set bmargin at screen 0.2; set tmargin at screen 0.97
steps = system('cat '.data.'/accuracy_steps.txt')
set label 2 sprintf('wall time per %g s run [ms]; the points of a curve: dt = %s s', whole, steps) at screen 0.5, screen 0.04 center
set lmargin at screen 0.1; set rmargin at screen 0.39
set label 1 sprintf('error in the first %g s', early) at graph 0.06, graph 0.2
unset key
plot for [i=1:words(names)] data.'/accuracy.dat' index (i - 1) using 1:2 with linespoints lc i pt (4 + 2 * ((i - 1) % 5)) title word(names, i)
unset label 2
set lmargin at screen 0.43; set rmargin at screen 0.72
set label 1 sprintf('in the whole %g s', whole)
set key at screen 0.74, graph 1 top left vertical Left reverse samplen 1.2 spacing 1 width 0 nobox
set ytics format ''
set ylabel ''
plot for [i=1:words(names)] data.'/accuracy.dat' index (i - 1) using 1:3 with linespoints lc i pt (4 + 2 * ((i - 1) % 5)) title word(names, i)
unset multiplot
unset arrow 1
unset label 1
unset logscale
set ytics autofreq format '%g'
set lmargin; set rmargin; set bmargin; set tmargin

# --- Section 3: broad phase, time per update against N ------------------------------------------
w = px(16.9); h = px(7.0)
set terminal pngcairo size w,h enhanced font printfont linewidth 3
set output outdir.'/report_broadphase.png'
set logscale xy
set format x '%.0s%c'
set format y '%g'
set xrange [800:60000]
set xtics add ('50k' 50000)
set yrange [0.05:1e4]
set ytics 10
set lmargin 10
set xlabel 'boxes N (fixed density, each moving 2 % of its size per step)' offset 0,0.3
set ylabel 'CPU time per update [ms]' offset 0.5,0
set key outside right center vertical Left reverse samplen 1.5 spacing 1.05 width -1
f = data.'/broadphase.dat'
plot f using 1:2 with linespoints pt 7 lc 1 title 'SAP, coherent', \
     f using 1:3 with linespoints pt 5 lc 2 title 'SAP, fixed swaps per box', \
     f using 1:4 with linespoints pt 9 lc 3 title 'SAP, every box teleports', \
     f using 1:5 with linespoints pt 4 lc 4 dt 2 title 'all pairs, coherent', \
     f using 1:6 with linespoints pt 6 lc 7 dt 2 title 'all pairs, teleporting'
unset logscale
set xtics autofreq
set ytics autofreq
set lmargin

# --- Section 4: narrow phase, time per query by pair type ---------------------------------------
w = px(13.0); h = px(6.4)
set terminal pngcairo size w,h enhanced font printfont linewidth 3
set output outdir.'/report_narrowphase.png'
unset key
set logscale x
set format x '%.0s%c'
f = data.'/narrowphase.dat'
pairs = int(system("grep -vc '^#' ".f))
set xrange [5:1e6]
set yrange [-0.7:pairs - 0.3]
set ytics scale 0
set grid noytics xtics
set xlabel 'CPU time per query [ns] (posed 1 cm deep)' offset 0,0.3
set ylabel ''
plot f using (sqrt(5 * $2)):0:(5):2:($0 - 0.32):($0 + 0.32):ytic(1) with boxxyerror fs solid 0.6 lc rgb '#1f5fbf', \
     f using ($2 * 1.15):0:(sprintf('%.0f', $2)) with labels left
unset logscale
set ytics scale default
set grid ytics
set yrange [*:*]
set xrange [*:*]

# --- Section 5: stacks after 10 s, per solver -----------------------------------------------------
w = px(15.0); h = px(5.6)
set terminal pngcairo size w,h enhanced font printfont linewidth 3
set output outdir.'/report_stacks.png'
set style data histograms
set style histogram clustered gap 1.2
set style fill solid 0.75 border -1
set logscale y
set format y '%g'
set yrange [5e-4:*]
set xrange [-0.6:3.6]
set bmargin 3.6
set xtics nomirror scale 0
set format x '%g'
set xlabel ''
set ylabel 'largest displacement [m]' offset 1,0
set key outside right center vertical Left reverse samplen 1.5 spacing 1.1 nobox
set arrow 1 from graph 0, first 0.5 to graph 1, first 0.5 nohead dt 2 lc rgb '#444444' lw 1
f = data.'/stacks.dat'
plot f using 2:xtic(word(strcol(1), 1)."\n".word(strcol(1), 2)) lc rgb '#1f5fbf' title 'soft step (default)', \
     '' using 3 lc rgb '#d95f02' title 'PGS, expmap', \
     '' using 4 lc rgb '#fdb863' title 'PGS, dlm', \
     NaN with lines dt 2 lc rgb '#444444' lw 1 title '0.5 m: half a box'
set bmargin
unset output
