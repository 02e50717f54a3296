#!/bin/sh
# Regenerates bench/results/accuracy.csv and the figures accuracy.png, accuracy_energy.png
# (issue 3). Usage, from anywhere: bench/run_accuracy_sweep.sh BUILD_DIR [--timing-seconds S]
# BUILD_DIR is a Release build with RBSIM_BUILD_BENCH=ON and the accuracy_sweep target built.
set -eu
if [ $# -lt 1 ]; then
  echo "usage: $0 BUILD_DIR [--timing-seconds S]" >&2
  exit 2
fi
build=$1
shift
bench=$(cd "$(dirname "$0")" && pwd)
mkdir -p "$bench/results"
"$build/bench/accuracy_sweep" "$bench/results/accuracy.csv" "$@"
gnuplot -e "csv='$bench/results/accuracy.csv'; outdir='$bench/results'" "$bench/plot_accuracy.gp"
echo "Wrote $bench/results/accuracy.png and $bench/results/accuracy_energy.png"
