#!/bin/bash
# Regenerates every figure of REPORT.md (issue 11): builds the benchmarks, runs each one writing a
# CSV into bench/results/, draws the plots (PNG) with gnuplot from those CSVs (REPORT.md's five,
# sized for print, are bench/results/report_*.png: bench/report/plots.gp), extracts one still
# per demo video into videos/stills/ (rendering the demo first when its MP4 is missing), and
# rewrites the generated blocks (<!-- fig:NAME --> ... <!-- /fig:NAME -->) of REPORT.md and of the
# docs/*.md pages the long tables moved to (issue 26) from the CSVs, points the line
# `Video: [rbsim-demos](...)` at the URL in bench/video_url.txt, then renders REPORT.pdf
# (bench/make_pdf.sh).
#
# usage: bash bench/make_report.sh [--all] [--quick] [--no-bench] [--no-stills] [--build DIR]
#   --all        the whole submission in one command (issue 26): also renders every demo and the
#                reel with its chapters (`rbsim demo all`), and ends with a list of where each file is
#   --quick      fewer repetitions and sizes: a check in minutes (the report says it was quick)
#   --no-bench   keep the CSVs in bench/results/, only redraw the plots, refill REPORT.md and docs/
#                and render REPORT.pdf
#   --no-stills  keep videos/stills/ as it is
#   --build DIR  the Release build folder (default build/)
# RBSIM_BASELINE_BUILD=DIR also times that build's rbsim in bench/frame_pipeline.sh, side by side.
# Needs: cmake, a C++ compiler, gnuplot, ffmpeg, python3 (standard library only), and for the PDF
# pandoc and pdflatex (.ci/setup installs them).
set -euo pipefail

root=$(cd "$(dirname "$0")/.." && pwd)
cd "$root"
mode=full
run_bench=1
make_stills=1
all=0
build=build
while [ $# -gt 0 ]; do
  case $1 in
    --all) all=1 ;;
    --quick) mode=quick ;;
    --no-bench) run_bench=0 ;;
    --no-stills) make_stills=0 ;;
    --build) build=$2; shift ;;
    *) echo "usage: bash bench/make_report.sh [--all] [--quick] [--no-bench] [--no-stills] [--build DIR]" >&2; exit 2 ;;
  esac
  shift
done

results=bench/results
logs=$results/logs
mkdir -p "$results" "$logs" videos/stills
started=$(date +%s)
say() { printf '[make_report %4ds] %s\n' $(( $(date +%s) - started )) "$*"; }
# Heavy work runs at the lowest priority: the machine is shared with other builds.
low() { nice -n 19 "$@"; }

targets=(rbsim step_bench throughput_bench stage_skip_bench broadphase_bench narrowphase_bench contact_pile
         contact_scenes bullet_pile bullet_pile_double particle_bench soft_bench accuracy_sweep sdf_bench
         sdf_contact_bench)

if [ $run_bench = 1 ] || [ $make_stills = 1 ] || [ $all = 1 ]; then
  say "configuring $build (Release, benchmarks on)"
  cmake -S . -B "$build" -G Ninja -DCMAKE_BUILD_TYPE=Release -DRBSIM_BUILD_BENCH=ON > "$logs/cmake.log" 2>&1 \
    || { tail -20 "$logs/cmake.log"; exit 1; }
  # bench/CMakeLists.txt makes the Bullet piles only where pkg-config found Bullet (both builds);
  # naming a target that does not exist would stop the build, so leave them out (the run below
  # says the pile has no Bullet rows).
  if ! grep -q '^BULLET_FOUND:INTERNAL=1$' "$build/CMakeCache.txt" ||
     ! grep -q '^BULLET_DOUBLE_FOUND:INTERNAL=1$' "$build/CMakeCache.txt"; then
    kept=()
    for target in "${targets[@]}"; do [[ $target == bullet_pile* ]] || kept+=("$target"); done
    targets=("${kept[@]}")
  fi
  say "building ${targets[*]} (log: $logs/build.log)"
  low cmake --build "$build" -j2 --target "${targets[@]}" > "$logs/build.log" 2>&1 \
    || { tail -30 "$logs/build.log"; exit 1; }
fi

if [ $all = 1 ]; then
  # Every demo's video, the reel and its chapters (videos/chapters.txt, also muxed into the reel),
  # rendered now so the stills below and the report come from this commit's videos.
  say "rendering every demo and the reel: $build/rbsim demo all (log: $logs/demo_all.log)"
  low /usr/bin/time -f "wall %e s" "$build/rbsim" demo all < /dev/null > "$logs/demo_all.log" 2>&1 \
    || { tail -20 "$logs/demo_all.log"; exit 1; }
  say "demo all: $(tail -1 "$logs/demo_all.log")"
fi

if [ $run_bench = 1 ]; then
  load_before=$(cut -d' ' -f1-3 /proc/loadavg)
  if [ $mode = quick ]; then
    gb_reps=(--benchmark_repetitions=1 --benchmark_min_time=0.1)
    piles=(100 1000)
    soft_moduli=(1e5)
    accuracy_timing=(--timing-seconds 0.02)
    broadphase_filter=(--benchmark_filter='/(1000|10000)/')
  else
    gb_reps=(--benchmark_repetitions=3 --benchmark_min_time=1 --benchmark_report_aggregates_only=true)
    piles=(100 1000 4000)
    soft_moduli=(1e5 1e7)
    accuracy_timing=()
    broadphase_filter=()
  fi
  # Google Benchmark programs: JSON, turned into CSV (one row per run, or per aggregate with
  # repetitions) by bench/report/json_to_csv.py, since their CSV reporter cannot mix counters.
  gbench() {  # gbench NAME PROGRAM [ARGS...]
    local name=$1 program=$2; shift 2
    say "running $program -> $results/$name.csv"
    low "$build/bench/$program" "$@" --benchmark_out="$logs/$name.json" --benchmark_out_format=json \
      > "$logs/$name.log" 2>&1 || { tail -20 "$logs/$name.log"; exit 1; }
    python3 bench/report/json_to_csv.py "$logs/$name.json" "$results/$name.csv"
  }
  gbench step step_bench "${gb_reps[@]}"
  gbench throughput throughput_bench "${gb_reps[@]}"
  gbench stage_skip stage_skip_bench "${gb_reps[@]}"
  gbench broadphase broadphase_bench "${broadphase_filter[@]}"
  gbench particles particle_bench "${gb_reps[@]}"
  gbench narrowphase narrowphase_bench "${gb_reps[@]}"
  # Programs that time whole runs themselves: their printed lines become CSV (bench/report/logs_to_csv.py).
  say "running contact_pile ${piles[*]}"
  low "$build/bench/contact_pile" "${piles[@]}" > "$logs/contact_pile.log"
  for variant in bullet_pile bullet_pile_double; do
    if [ -x "$build/bench/$variant" ]; then
      say "running $variant ${piles[*]}"
      low "$build/bench/$variant" "${piles[@]}" > "$logs/$variant.log"
    else
      say "WARNING: $variant not built (apt-get install libbullet-dev); the pile has no Bullet rows"
      rm -f "$logs/$variant.log"
    fi
  done
  # REPORT section 5's plot: the stacks after 10 s with each solver (about 2 minutes).
  say "running contact_scenes -> $results/contact_scenes.csv"
  low "$build/bench/contact_scenes" --scenes stack10,stack20,stack40,pyramid20 --solvers soft-step,pgs \
    --integrators expmap,dlm --csv "$results/contact_scenes.csv" > "$logs/contact_scenes.log" 2>&1 \
    || { tail -20 "$logs/contact_scenes.log"; exit 1; }
  say "running soft_bench ${soft_moduli[*]}"
  low "$build/bench/soft_bench" "${soft_moduli[@]}" > "$logs/soft.log"
  python3 bench/report/logs_to_csv.py "$logs" "$results"
  say "running sdf_bench -> $results/sdf.csv"
  low "$build/bench/sdf_bench" --csv "$results/sdf.csv" > "$logs/sdf.log" 2>&1
  say "running sdf_contact_bench -> $results/sdf_contact.csv"
  low "$build/bench/sdf_contact_bench" "$results/sdf_contact.csv" > "$logs/sdf_contact.log" 2>&1
  # Not niced: the frame pipeline's wall time is the figure, and it needs both cores.
  say "running bench/frame_pipeline.sh -> $results/frame_pipeline.csv"
  bash bench/frame_pipeline.sh "$build" 1 ${RBSIM_BASELINE_BUILD:-} > "$logs/frame_pipeline.log" 2>&1 \
    || { tail -20 "$logs/frame_pipeline.log"; exit 1; }
  say "running accuracy_sweep -> $results/accuracy.csv"
  low "$build/bench/accuracy_sweep" "$results/accuracy.csv" "${accuracy_timing[@]}" > "$logs/accuracy.log" 2>&1
  load_after=$(cut -d' ' -f1-3 /proc/loadavg)
  # The machine the figures come from.
  {
    echo "key,value"
    echo "mode,$mode"
    echo "date,$(date -u +%Y-%m-%dT%H:%MZ)"
    echo "commit,$(git rev-parse --short HEAD)"
    echo "nproc,$(nproc)"
    echo "cpu,\"$(grep -m1 'model name' /proc/cpuinfo | cut -d: -f2 | sed 's/^ *//')\""
    echo "memory_gib,$(awk '/MemTotal/ { printf "%.1f", $2 / 1048576 }' /proc/meminfo)"
    echo "os,\"$(. /etc/os-release && echo "$PRETTY_NAME")\""
    echo "compiler,\"$(c++ --version | head -1)\""
    echo "load_before,\"$load_before\""
    echo "load_after,\"$load_after\""
    echo "bench_seconds,$(( $(date +%s) - started ))"
  } > "$results/machine.csv"
fi

say "drawing plots with gnuplot"
gnuplot -e "csv='$results/accuracy.csv'; outdir='$results'" bench/plot_accuracy.gp
plot_data=$(mktemp -d)
trap 'rm -rf "$plot_data"' EXIT
python3 bench/report/plot_data.py "$results" "$plot_data"
gnuplot -e "data='$plot_data'; outdir='$results'" bench/report/plots.gp

if [ $make_stills = 1 ]; then
  # demo number, video name, time of the still [s] (a moment that shows what the section is about),
  # and optionally the still's name when a demo gives several (default: the video's name)
  while read -r number name at still; do
    still=${still:-$name}
    if [ ! -f "videos/$name.mp4" ]; then
      say "rendering demo $number (videos/$name.mp4 is missing)"
      low "$build/rbsim" demo "$number" < /dev/null > "$logs/demo$number.log" 2>&1 || { tail -20 "$logs/demo$number.log"; exit 1; }
    fi
    say "still of videos/$name.mp4 at $at s -> videos/stills/$still.png"
    ffmpeg -nostdin -v error -y -ss "$at" -i "videos/$name.mp4" -frames:v 1 -vf scale=640:-1 "videos/stills/$still.png"
  done < bench/report/stills.txt
fi

say "filling the generated blocks of REPORT.md and docs/*.md"
python3 bench/report/fill_report.py "$results" REPORT.md docs/*.md
# The video line, in REPORT.md and in any docs page that has it (a page links the local reel
# relative to itself while bench/video_url.txt holds no URL).
pages=(REPORT.md)
for page in docs/*.md; do [ -f "$page" ] && pages+=("$page"); done
python3 bench/report/video_link.py bench/video_url.txt "${pages[@]}"
say "rendering REPORT.pdf: bash bench/make_pdf.sh (log: $logs/make_pdf.log)"
bash bench/make_pdf.sh > "$logs/make_pdf.log" 2>&1 || { tail -20 "$logs/make_pdf.log"; exit 1; }

if [ $all = 1 ]; then
  say "the submission's zip: bash bench/make_bundle.sh --build $build"
  bash bench/make_bundle.sh --build "$build" --out videos/rbsim-submission.zip
  say "done in $(( $(date +%s) - started )) s ($mode, --all); the submission's files:"
  where() {  # where FILE WHAT: the file, its size, what it is; a missing file is said to be missing
    if [ -e "$1" ]; then
      printf '  %-34s %8s  %s\n' "$1" "$(du -sh --apparent-size "$1" | cut -f1)" "$2"
    else
      printf '  %-34s %8s  %s\n' "$1" "MISSING" "$2"
    fi
  }
  for video in videos/*.mp4; do
    [ "$video" = videos/rbsim-demos.mp4 ] || where "$video" "one demo's video"
  done
  where videos/rbsim-demos.mp4 "the reel: every demo behind title cards, with chapters"
  where videos/chapters.txt "the reel's chapters, for the YouTube description"
  where videos/stills "the demos' stills (docs/ pages)"
  where REPORT.md "the report (video line: bench/video_url.txt)"
  for page in docs/*.md; do [ -f "$page" ] && where "$page" "a docs page"; done
  where REPORT.pdf "the report as a PDF (bench/make_pdf.sh)"
  where videos/rbsim-submission.zip "the source (git HEAD) and the program with its shaders and assets (bench/make_bundle.sh)"
  where "$results" "benchmark CSVs and plots (logs in $logs)"
else
  say "done in $(( $(date +%s) - started )) s ($mode)"
fi
