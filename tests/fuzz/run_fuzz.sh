#!/usr/bin/env bash
# Fuzzes the scene loader, the OBJ loader and the --set override parser with libFuzzer for a
# bounded time each, then minimises what was found into the corpus kept in the repository.
#
#   bash tests/fuzz/run_fuzz.sh [SECONDS_PER_TARGET [TARGET...]]   (default 60; scene obj set record)
#
# Builds build-fuzz/ with clang, -fsanitize=fuzzer plus AddressSanitizer and UBSan (RBSIM_FUZZ,
# RBSIM_SANITIZE), then runs each <target>_fuzzer on its corpus tests/fuzz/corpus/<target>/ plus
# the seeds (the demo scenes and meshes and tests/data/bad/). New inputs go to
# build-fuzz/corpus/<target>/; after the run they are merged (libFuzzer -merge=1: only inputs that
# add coverage, smallest first) with the kept corpus into a fresh tests/fuzz/corpus/<target>/, so
# the repository keeps a minimal corpus that ctest replays in every build. Inputs are at most
# MAX_LEN bytes, so the kept corpus stays small (a few hundred KB per target).
#
# A crash, a timeout (an input running over $timeout, 30 s) or an out-of-memory is written to
# build-fuzz/crashes/ (never into the repository) and makes the script fail; with
# RBSIM_FUZZ_KEEP_GOING=1 the fuzzer runs in fork mode and carries on past them for the whole time
# (a campaign), collecting every artifact. A crash becomes a regression case: copy it into
# tests/data/bad/ (a case in cases.json if rbsim can show it, or tests/fuzz/corpus/ otherwise),
# then fix it. Prints each target's executions and artifacts at the end.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-60}
shift || true
targets=("$@")
[ ${#targets[@]} -gt 0 ] || targets=(scene obj set record)
build=build-fuzz
max_len=4096          # [bytes] longest generated input: keeps the kept corpus files small
# [s] an input running longer is reported as a hang. This build runs 15-20 times slower than the
# release one (-O1, ASan, coverage on every comparison): the demo scenes' meshes, 0.7 s to load in
# release, took 10-15 s here, so 30 s flags inputs over ~2 s of release time.
timeout=30
kept=tests/fuzz/corpus

if ! command -v clang++ > /dev/null; then
  echo "run_fuzz.sh: installing clang (libFuzzer ships with it)" >&2
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends clang > /dev/null
fi
bash .ci/setup

mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link -DFUZZING_BUILD_MODE_UNSAFE_FOR_PRODUCTION" \
  -DRBSIM_SANITIZE=ON -DRBSIM_FUZZ=ON -DRBSIM_BUILD_BENCH=OFF > "$build/configure.log"
cmake --build "$build" -j2 --target "${targets[@]/%/_fuzzer}"

export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
mkdir -p "$build/crashes"
keep_going=()
if [ "${RBSIM_FUZZ_KEEP_GOING:-0}" = 1 ]; then
  keep_going=(-fork=1 -ignore_crashes=1 -ignore_timeouts=1 -ignore_ooms=1)
fi
summary=()
status=0

seeds() {  # the read-only seed folders of a target
  case $1 in
    scene) echo assets/scenes tests/data/bad ;;
    obj) echo assets/meshes tests/data/bad ;;
    set) echo ;;  # the assignments need the base-scene byte: only tests/fuzz/corpus/set
    record) echo ;;  # recordings of the target's own scene: only tests/fuzz/corpus/record
  esac
}

run() {  # target
  local target=$1 fuzzer="$build/tests/fuzz/$1_fuzzer"
  local log="$build/$target.log" work="$build/corpus/$target"
  mkdir -p "$work" "$kept/$target"
  # Findings are crash-, timeout-, oom- and leak- files; libFuzzer also writes a slow-unit- file
  # for an input over 10 s but under the timeout, counted apart: slow, not hung.
  local findings="^$target-(crash|timeout|oom|leak)-" slow="^$target-slow-unit-" before slow_before
  before=$(ls "$build/crashes" | grep -cE "$findings" || true)
  slow_before=$(ls "$build/crashes" | grep -cE "$slow" || true)
  echo "+ $target for ${seconds} s (log: $log)"
  # shellcheck disable=SC2046
  if ! nice -n 19 "$fuzzer" -max_total_time="$seconds" -timeout=$timeout -rss_limit_mb=2048 -max_len=$max_len \
      $( [ -f "tests/fuzz/$target.dict" ] && echo "-dict=tests/fuzz/$target.dict" ) -artifact_prefix="$build/crashes/$target-" -print_final_stats=1 \
      "${keep_going[@]}" "$work" "$kept/$target" $(seeds "$target") > "$log" 2>&1; then
    status=1
    grep -m5 -E "ERROR|runtime error|==ABORTING|terminate called" "$log" || true
  fi
  local artifacts=$(( $(ls "$build/crashes" | grep -cE "$findings" || true) - before ))
  local slow_units=$(( $(ls "$build/crashes" | grep -cE "$slow" || true) - slow_before ))
  [ "$artifacts" -eq 0 ] || status=1
  local runs
  runs=$(grep -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' | tail -1 || true)
  # Fork mode prints no final stats: its last progress line "#N ..." counts the executions.
  [ -n "$runs" ] || runs=$(grep -oE '^#[0-9]+' "$log" | tail -1 | tr -d '#' || true)

  # Minimise: a fresh folder takes the inputs of the kept and the new corpus that add coverage.
  local merged="$build/merged/$target"
  rm -rf "$merged" && mkdir -p "$merged"
  nice -n 19 "$fuzzer" -merge=1 -max_len=$max_len -timeout=$timeout -rss_limit_mb=2048 \
    -artifact_prefix="$build/crashes/merge-$target-" "$merged" "$kept/$target" "$work" > "$build/$target.merge.log" 2>&1 || {
    echo "run_fuzz.sh: merging the $target corpus failed (see $build/$target.merge.log); kept corpus unchanged" >&2
    status=1
    summary+=("$target: ${runs:-?} executions in ${seconds} s, $artifacts artifacts ($slow_units slow units), merge failed")
    return
  }
  find "$merged" -type f -size +${max_len}c -delete
  rm -rf "$kept/$target" && mv "$merged" "$kept/$target"
  local files size
  files=$(find "$kept/$target" -type f | wc -l)
  size=$(( $(du -sb "$kept/$target" | cut -f1) / 1024 ))
  summary+=("$target: ${runs:-?} executions in ${seconds} s, $artifacts artifacts ($slow_units slow units); kept corpus $files files, ${size} KB")
}

for target in "${targets[@]}"; do run "$target"; done
printf '%s\n' "${summary[@]}"
exit $status
