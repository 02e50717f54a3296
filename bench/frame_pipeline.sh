#!/bin/sh
# The frame pipeline end to end (issues 11 and 22), optionally side by side with another build
# (e.g. the commit before a change, built elsewhere) in the same run on the same machine:
#   demo2       `rbsim demo 2` at 1280x720 with its overlay, MP4 only: frames per second
#   bench1000   assets/scenes/bench_1000_bodies.json (1000 boxes, 10 s at 60 fps, 1280x720) with
#               PNG frames and an MP4 (the goal: at most 20 s of wall time)
#   reel        `rbsim demo all` (every demo, PNG frames, MP4s and the reel; the goal: less wall
#               time than the reel plays)
# and, for BUILD_DIR only, bench1000 with LP_NUM_THREADS=1, 2 and 4 (llvmpipe's rasteriser
# threads; unset means one per core). Builds nothing: needs BUILD_DIR/rbsim (and BASELINE/rbsim).
# Usage, from the repository root: bench/frame_pipeline.sh [BUILD_DIR] [ROUNDS] [BASELINE_DIR]
# Writes bench/results/frame_pipeline.csv: one row per run. wall_s and cpu_s (user + system of
# every thread and of ffmpeg) come from /usr/bin/time; render_ms, png_ms and video_ms are the ms
# per frame rbsim prints (png and video on writer threads, in parallel); fps is frames / wall_s;
# video_s is how long the run's video plays; load1 the 1-minute load average at the start.
set -eu
build=${1:-build}
rounds=${2:-1}
baseline=${3:-}
root=$(cd "$(dirname "$0")/.." && pwd)
scene="$root/assets/scenes/bench_1000_bodies.json"
csv="$root/bench/results/frame_pipeline.csv"
out=$(mktemp -d "${TMPDIR:-/tmp}/rbsim_frame_pipeline.XXXXXX")
trap 'rm -rf "$out"' EXIT
mkdir -p "$root/bench/results"
for dir in "$build" $baseline; do
  [ -x "$dir/rbsim" ] || { echo "$0: $dir/rbsim not found (build the rbsim target first)" >&2; exit 2; }
done
build=$(cd "$build" && pwd)
[ -z "$baseline" ] || baseline=$(cd "$baseline" && pwd)

echo "bench,build,round,frames,wall_s,cpu_s,fps,video_s,load1,render_ms,png_ms,video_ms" > "$csv"

# run BENCH LABEL BINARY ROUND [env assignments...] -- rbsim arguments...   (in a fresh folder)
run() {
  bench=$1 label=$2 binary=$3 round=$4
  shift 4
  envs=""
  while [ "$1" != "--" ]; do envs="$envs $1"; shift; done
  shift
  work="$out/$bench-$label-$round"
  mkdir -p "$work"
  load=$(cut -d' ' -f1 /proc/loadavg)
  log="$work/log"
  (cd "$work" && env $envs /usr/bin/time -f "TIME %e %U %S" "$binary" "$@" > "$log" 2>&1)
  video=$(ls "$work"/videos/rbsim-demos.mp4 "$work"/*.mp4 2>/dev/null | head -n 1)
  seconds=$(ffprobe -v error -select_streams v:0 -show_entries stream=duration -of csv=p=0 "$video" 2>/dev/null || echo 0)
  awk -v bench="$bench" -v label="$label" -v round="$round" -v load="$load" -v seconds="$seconds" '
    /^steps/ { frames = $4; sub(",", "", frames) }
    /rbsim-demos.mp4/ { frames = $4 }
    /^ms per frame/ {
      line = $0; gsub(/[;,]/, " ", line); n = split(line, w, " ")
      for (i = 1; i < n; ++i) if (w[i] ~ /^(render|png|video)$/) v[w[i]] = w[i + 1]
    }
    /^TIME/ { wall = $2; cpu = $3 + $4 }
    END {
      printf "%s,%s,%s,%s,%s,%.2f,%.1f,%s,%s,%s,%s,%s\n", bench, label, round, frames + 0, wall, cpu,
             (wall > 0 ? frames / wall : 0), seconds, load, v["render"], v["png"], v["video"]
    }' "$log" | tee -a "$csv"
}

for round in $(seq 1 "$rounds"); do
  for pair in "new:$build" ${baseline:+"baseline:$baseline"}; do
    label=${pair%%:*} dir=${pair#*:}
    run demo2 "$label" "$dir/rbsim" "$round" -- demo 2 --video demo2.mp4
    run bench1000 "$label" "$dir/rbsim" "$round" -- run "$scene" --frames png --video bench.mp4
    run reel "$label" "$dir/rbsim" "$round" -- demo all
  done
  for threads in 1 2 4; do
    run bench1000_lp$threads new "$build/rbsim" "$round" LP_NUM_THREADS=$threads -- run "$scene" --frames png --video bench.mp4
  done
done
echo "Wrote $csv"
