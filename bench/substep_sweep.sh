#!/usr/bin/env bash
# Run time against error over the soft step's substep count (issue 54): Box3D's large pyramid
# (600 steps at 1/60 s, sleep off) and joint grid (100 steps), each swept over world.substeps with
# every other setting at its default, on one thread; beside them the same sweep of Box3D when
# bench/box3d_reference/build.sh has built it. Error is read from positions alone, the same way
# for both engines (box3d_scenes.cpp, pyramid_sweep.c): the fastest body at the end, the top
# body's sink and its sideways drift.
#   usage: bench/substep_sweep.sh BUILD_DIR [BOX3D_OUT_DIR]
#   env:   SUBSTEPS (rbsim's counts, default "2 4 6 8 10 12"), BOX3D_SUBSTEPS ("2 4 8"),
#          STEPS (600), GRID_STEPS (100), OUT (bench/results/substeps.csv)
# Writes OUT and, with gnuplot, its plot beside it (plot_substeps.gp). Run it on an idle machine:
# the times of one run are comparable with each other only.
set -euo pipefail
build=${1:?usage: bench/substep_sweep.sh BUILD_DIR [BOX3D_OUT_DIR]}
box3d=${2:-}
here=$(cd "$(dirname "$0")" && pwd)
substeps=${SUBSTEPS:-2 4 6 8 10 12}
box3dSubsteps=${BOX3D_SUBSTEPS:-2 4 8}
steps=${STEPS:-600}
gridSteps=${GRID_STEPS:-100}
out=${OUT:-$here/results/substeps.csv}
rbsim=$build/bench/box3d_scenes
[[ -x $rbsim ]] || { echo "substep_sweep.sh: $rbsim not built (cmake --build $build --target box3d_scenes)" >&2; exit 2; }

tmp=$(mktemp "$out.XXXXXX")
trap 'rm -f "$tmp"' EXIT
echo "engine,scene,substeps,steps,ms_per_step,fastest_mps,top_drift_m,top_sink_m" >"$tmp"

# box3d_scenes prints "... wall X ms/step ..." and "... end: fastest F m/s  top drift D m  top sink S m ...".
rbsimRow() {  # scene steps substeps
  "$rbsim" --scenes "$1" --steps "$2" --threads 1 --set "world.substeps=$3" |
    awk -v scene="$1" -v steps="$2" -v count="$3" '
      / wall / { for (i = 1; i <= NF; ++i) if ($i == "wall") ms = $(i + 1) }
      / end: / { for (i = 1; i <= NF; ++i) { if ($i == "fastest") f = $(i + 1); if ($i == "drift") d = $(i + 1); if ($i == "sink") s = $(i + 1) } }
      END { printf "rbsim,%s,%s,%s,%s,%s,%s,%s\n", scene, count, steps, ms, f, d, s }'
}
box3dRow() {  # variant scene steps substeps
  "$box3d/$1/pyramid_sweep" --scene "$2" --steps "$3" --substeps "$4" |
    awk -v engine="box3d-$1" '
      { for (i = 1; i < NF; i += 2) v[$i] = $(i + 1) }
      END { printf "%s,%s,%s,%s,%s,%s,%s,%s\n", engine, v["scene"], v["substeps"], v["steps"], v["ms_per_step"], v["fastest_mps"], v["top_drift_m"], v["top_sink_m"] }'
}

for n in $substeps; do
  rbsimRow large_pyramid "$steps" "$n" | tee -a "$tmp"
  rbsimRow joint_grid "$gridSteps" "$n" | tee -a "$tmp"
done
if [[ -n $box3d ]]; then
  for variant in scalar sse2; do
    [[ -x $box3d/$variant/pyramid_sweep ]] || continue
    for n in $box3dSubsteps; do
      box3dRow "$variant" large_pyramid "$steps" "$n" | tee -a "$tmp"
      box3dRow "$variant" joint_grid "$gridSteps" "$n" | tee -a "$tmp"
    done
  done
fi
mv "$tmp" "$out"
trap - EXIT
if command -v gnuplot >/dev/null; then
  gnuplot -e "csv='$out'; png='${out%.csv}.png'" "$here/plot_substeps.gp"
  echo "wrote $out and ${out%.csv}.png"
else
  echo "wrote $out (no gnuplot: no plot)"
fi
