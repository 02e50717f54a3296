#!/usr/bin/env bash
# Fuzzes the scene loader and the OBJ loader with libFuzzer for a bounded time each.
#
#   bash tests/fuzz/run_fuzz.sh [SECONDS_PER_TARGET]     (default 60)
#
# Builds build-fuzz/ with clang, -fsanitize=fuzzer plus AddressSanitizer and UBSan (RBSIM_FUZZ,
# RBSIM_SANITIZE), then runs scene_fuzzer and obj_fuzzer on the seed corpus (tests/fuzz/corpus/,
# plus the demo scenes and meshes and tests/data/bad/). New interesting inputs go to
# build-fuzz/corpus/, never into the repository; a crash is written to build-fuzz/crashes/ and ends
# the script with a failure. A crash becomes a regression case: copy it into tests/data/bad/
# (a case in cases.json if rbsim can show it, or tests/fuzz/corpus/ otherwise, which ctest
# replays in every build), then fix it. Prints each target's executions and crashes at the end.
set -euo pipefail
cd "$(dirname "$0")/../.."
seconds=${1:-60}
build=build-fuzz

if ! command -v clang++ > /dev/null; then
  echo "run_fuzz.sh: installing clang (libFuzzer ships with it)" >&2
  sudo_cmd=()
  if [ "$(id -u)" -ne 0 ]; then sudo_cmd=(sudo); fi
  "${sudo_cmd[@]}" apt-get install -y -qq --no-install-recommends clang > /dev/null
fi
bash .ci/setup

mkdir -p "$build"
cmake -S . -B "$build" -DCMAKE_CXX_COMPILER=clang++ -DCMAKE_BUILD_TYPE=RelWithDebInfo \
  -DCMAKE_CXX_FLAGS_RELWITHDEBINFO="-O1 -g1" -DCMAKE_CXX_FLAGS="-fsanitize=fuzzer-no-link" \
  -DRBSIM_SANITIZE=ON -DRBSIM_FUZZ=ON -DRBSIM_BUILD_BENCH=OFF > "$build/configure.log"
cmake --build "$build" -j2 --target scene_fuzzer obj_fuzzer

export ASAN_OPTIONS="halt_on_error=1:detect_leaks=1"
export UBSAN_OPTIONS="halt_on_error=1:print_stacktrace=1"
mkdir -p "$build/crashes"
summary=()
status=0
run() {  # target, dictionary, seed folders...
  local target=$1 dict=$2
  shift 2
  mkdir -p "$build/corpus/$target"
  local log="$build/$target.log"
  echo "+ $target for ${seconds} s (log: $log)"
  if "$build/tests/fuzz/$target" -max_total_time="$seconds" -timeout=10 -rss_limit_mb=2048 \
      -dict="$dict" -artifact_prefix="$build/crashes/$target-" -print_final_stats=1 \
      "$build/corpus/$target" "$@" > "$log" 2>&1; then
    crashes=0
  else
    crashes=$(ls "$build/crashes" | grep -c "^$target-" || true)
    status=1
    grep -m5 -E "ERROR|runtime error|==ABORTING|terminate called" "$log" || true
  fi
  local runs
  runs=$(grep -m1 -oE 'stat::number_of_executed_units: *[0-9]+' "$log" | grep -oE '[0-9]+$' || echo "?")
  summary+=("$target: $runs executions in ${seconds} s, $crashes crashes")
}
run scene_fuzzer tests/fuzz/scene.dict tests/fuzz/corpus/scene assets/scenes tests/data/bad
run obj_fuzzer tests/fuzz/obj.dict tests/fuzz/corpus/obj assets/meshes tests/data/bad
printf '%s\n' "${summary[@]}"
exit $status
