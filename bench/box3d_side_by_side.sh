#!/usr/bin/env bash
# Box3D's eleven benchmark scenes (benchmark/main.c at 30c67b5), rbsim against Box3D, one thread
# each (issue 54): rbsim's copies (assets/scenes/box3d/, bench/box3d_scenes) for Box3D's step
# counts, and Box3D's own `benchmark` program (-t=1 -w=1 -r=1) from the scalar and SSE2 builds
# of bench/box3d_reference/build.sh. Prints a Markdown table of milliseconds per step.
#   usage: bench/box3d_side_by_side.sh BUILD_DIR BOX3D_OUT_DIR
#   env:   SCENES (default: all eleven), RBSIM_STEPS_<scene> (e.g. RBSIM_STEPS_trees25=100 runs rbsim's
#          copy for fewer steps than Box3D's benchmark, which cannot be told; the table says so)
set -euo pipefail
build=${1:?usage: bench/box3d_side_by_side.sh BUILD_DIR BOX3D_OUT_DIR}
box3d=${2:?usage: bench/box3d_side_by_side.sh BUILD_DIR BOX3D_OUT_DIR}
scenes=${SCENES:-large_pyramid many_pyramids joint_grid convex_pile washer rain junkyard large_world trees100 trees50 trees25}
rbsim=$build/bench/box3d_scenes
[[ -x $rbsim ]] || { echo "box3d_side_by_side.sh: $rbsim not built" >&2; exit 2; }
work=$(mktemp -d)  # Box3D's benchmark writes its csv files into the working directory
trap 'rm -rf "$work"' EXIT

# Box3D's benchmark prints "benchmark: NAME, steps = N" then "run 0 : T (ms)" for the whole run.
box3dMs() {  # variant scene
  local exe=$box3d/$1/bin/benchmark
  [[ -x $exe ]] || { echo "-"; return; }
  (cd "$work" && "$exe" -t=1 -w=1 -r=1 -b="$2") |
    awk '/^benchmark:/ { steps = $NF } /^run / { ms = $(NF - 1) } END { if (steps > 0) printf "%.2f", ms / steps; else print "-" }'
}

echo "| scene | steps (rbsim) | Box3D scalar | Box3D SSE2 | rbsim | rbsim / Box3D scalar |"
echo "|---|---|---|---|---|---|"
for scene in $scenes; do
  var=RBSIM_STEPS_$scene
  steps=${!var:-}
  line=$("$rbsim" --scenes "$scene" --threads 1 ${steps:+--steps "$steps"} | awk '/ wall / { for (i = 1; i <= NF; ++i) { if ($i == "wall") ms = $(i + 1); if ($i == "steps") n = $(i - 1) } } END { print ms, n }')
  read -r ms n <<<"$line"
  scalar=$(box3dMs scalar "$scene")
  sse2=$(box3dMs sse2 "$scene")
  ratio=$(awk -v a="$ms" -v b="$scalar" 'BEGIN { if (b + 0 > 0) printf "%.2fx", a / b; else print "-" }')
  echo "| $scene | $n | $scalar | $sse2 | $ms | $ratio |"
done
