#!/usr/bin/env bash
# Builds Box3D (erincatto/box3d at commit 30c67b5, the one rbsim's assets/scenes/box3d/ were made
# from) twice, scalar and SSE2, plus pyramid_sweep.c and Box3D's own `benchmark` against each.
#   usage: build.sh BOX3D_GIT_DIR OUT_DIR
#   BOX3D_GIT_DIR: any git repository holding that commit (a clone or a bare mirror).
#   OUT_DIR/src                   Box3D's source, checked out at 30c67b5 (fetched, not vendored)
#   OUT_DIR/{scalar,sse2}/pyramid_sweep
#   OUT_DIR/{scalar,sse2}/bin/benchmark
# Compiler: CMake's default C compiler (cc), or $CC if set.
set -euo pipefail

if [[ $# -ne 2 ]]; then
  echo "usage: $0 BOX3D_GIT_DIR OUT_DIR" >&2
  exit 2
fi
BOX3D_GIT_DIR=$1
OUT_DIR=$(mkdir -p "$2" && cd "$2" && pwd)
BOX3D_COMMIT=30c67b5
HERE=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
SRC=$OUT_DIR/src

if [[ ! -d $SRC/.git ]]; then
  git clone --quiet --no-checkout "$BOX3D_GIT_DIR" "$SRC"
fi
git -C "$SRC" -c advice.detachedHead=false checkout --quiet --force "$BOX3D_COMMIT"

# variant name -> value of Box3D's option BOX3D_DISABLE_SIMD (its CMakeLists.txt; src/core.h then
# defines B3_SIMD_NONE instead of B3_SIMD_SSE2 on x86-64).
declare -A DISABLE_SIMD=([scalar]=ON [sse2]=OFF)

for variant in scalar sse2; do
  build=$OUT_DIR/$variant
  # Samples and unit tests are off: the samples fetch GLFW etc. from the network at configure time.
  # BOX3D_VALIDATE stays at its default; it only acts when NDEBUG is undefined (include/box3d/base.h),
  # and Release defines NDEBUG.
  cmake -S "$SRC" -B "$build" -G Ninja \
    -DCMAKE_BUILD_TYPE=Release \
    -DBOX3D_DISABLE_SIMD="${DISABLE_SIMD[$variant]}" \
    -DBOX3D_SAMPLES=OFF -DBOX3D_UNIT_TESTS=OFF -DBOX3D_BENCHMARKS=ON \
    -DCMAKE_VERBOSE_MAKEFILE=OFF >"$build.configure.log"
  cmake --build "$build" --target box3d shared benchmark >"$build.build.log"

  # The driver with the same compiler and Release flags CMake used for Box3D (-O3 -DNDEBUG, and
  # -ffp-contract=off from Box3D's CMakeLists.txt), linked statically to this variant's libraries.
  cc=$(sed -n 's/^CMAKE_C_COMPILER:[A-Z]*=//p' "$build/CMakeCache.txt")
  "$cc" -std=gnu17 -O3 -DNDEBUG -ffp-contract=off -Wall -Wextra \
    -I"$SRC/include" -I"$SRC/shared" \
    "$HERE/pyramid_sweep.c" "$build/shared/libshared.a" "$build/src/libbox3d.a" -lm -pthread \
    -o "$build/pyramid_sweep"
  echo "$variant: $build/pyramid_sweep  $build/bin/benchmark  ($("$cc" --version | head -1))"
done
