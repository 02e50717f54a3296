#!/bin/sh
# The frame pipeline end to end (issue 11): assets/scenes/bench_1000_bodies.json (1000 boxes,
# 10 s at 60 fps, 1280x720) simulated, rendered, written as PNG frames and an MP4, in several
# configurations, each run ROUNDS times in turn. Builds nothing: needs BUILD_DIR/rbsim.
# Usage, from the repository root: bench/frame_pipeline.sh [BUILD_DIR] [ROUNDS]
# Writes bench/results/frame_pipeline.csv: one row per run; the stage columns are ms per frame as
# rbsim prints them (png and video run on writer threads, in parallel with the others), wall_s
# and cpu_s (user + system, every thread and ffmpeg) from /usr/bin/time, load1 the 1-minute load
# average when the run started (the machine is shared).
set -eu
build=${1:-build}
rounds=${2:-2}
root=$(cd "$(dirname "$0")/.." && pwd)
scene="$root/assets/scenes/bench_1000_bodies.json"
csv="$root/bench/results/frame_pipeline.csv"
out="$build/frames_bench"
mkdir -p "$root/bench/results" "$out"
[ -x "$build/rbsim" ] || { echo "$0: $build/rbsim not found (build the rbsim target first)" >&2; exit 2; }

echo "config,round,frames,wall_s,cpu_s,load1,simulate_ms,build_ms,render_ms,readback_ms,handoff_ms,png_ms,video_ms,png_mb" > "$csv"

# run CONFIG ROUND [env assignments...] -- rbsim arguments...
run() {
  config=$1 round=$2
  shift 2
  envs=""
  while [ "$1" != "--" ]; do envs="$envs $1"; shift; done
  shift
  rm -rf "$out/png"
  load=$(cut -d' ' -f1 /proc/loadavg)
  log="$out/$config.log"
  env $envs /usr/bin/time -f "TIME %e %U %S" "$build/rbsim" run "$scene" "$@" > "$log" 2>&1
  pngmb=$(du -sm "$out/png" 2>/dev/null | cut -f1 || true)
  awk -v config="$config" -v round="$round" -v load="$load" -v pngmb="${pngmb:-0}" '
    /^steps/ { frames = $4; sub(",", "", frames) }
    /^ms per frame/ {
      line = $0; gsub(/[;,]/, " ", line); n = split(line, w, " ")
      for (i = 1; i < n; ++i) if (w[i] ~ /^(simulate|build|render|readback|hand-off|png|video)$/) v[w[i]] = w[i + 1]
    }
    /^TIME/ { wall = $2; cpu = $3 + $4 }
    END {
      printf "%s,%s,%s,%s,%.2f,%s,%s,%s,%s,%s,%s,%s,%s,%s\n", config, round, frames + 0, wall, cpu, load,
             v["simulate"], v["build"], v["render"], v["readback"], v["hand-off"], v["png"], v["video"], pngmb
    }' "$log" | tee -a "$csv"
}

for round in $(seq 1 "$rounds"); do
  # The issue's goal: PNG frames kept (default level 1) and the MP4, default llvmpipe threads.
  run png1_video "$round" -- --frames "$out/png" --video "$out/bench.mp4"
  run png0_video "$round" -- --frames "$out/png" --video "$out/bench.mp4" --png-level 0
  run png6_video "$round" -- --frames "$out/png" --video "$out/bench.mp4" --png-level 6
  run video_only "$round" -- --video "$out/bench.mp4"
  run png1_video_lp1 "$round" LP_NUM_THREADS=1 -- --frames "$out/png" --video "$out/bench.mp4"
  run simulate_only "$round" -- --no-render
done
echo "Wrote $csv"
