# The report's benchmark plots (issue 11), drawn from the tables bench/report/plot_data.py lays
# out from the CSVs of bench/results/. bench/make_report.sh runs this; by hand:
#   python3 bench/report/plot_data.py bench/results /tmp/plot && \
#   gnuplot -e "data='/tmp/plot'; outdir='bench/results'" bench/report/plots.gp
# Writes broadphase.png, pile.png, particles.png, throughput.png, soft.png into outdir.

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
