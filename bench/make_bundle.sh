#!/usr/bin/env bash
# The submission's zip (seed 004: "a zip file of the source and the executable"):
#   rbsim-source/  the repository at HEAD (git archive);
#   rbsim/         the built program with the shaders and assets it reads, runnable from wherever
#                  the zip is unpacked (`rbsim/rbsim demo 2`): it finds shaders/ and assets/ beside
#                  itself (app/render/data_dir.h). It links Debian's shared libraries, which
#                  `bash rbsim-source/.ci/setup` installs.
# usage: bash bench/make_bundle.sh [--build DIR] [--out FILE]   (default build, videos/rbsim-submission.zip)
set -euo pipefail
build=build
out=videos/rbsim-submission.zip
while [ $# -gt 0 ]; do
  case $1 in
    --build) build=$2; shift ;;
    --out) out=$2; shift ;;
    *) echo "usage: bash bench/make_bundle.sh [--build DIR] [--out FILE]" >&2; exit 2 ;;
  esac
  shift
done
root=$(cd "$(dirname "$0")/.." && pwd)
if [ ! -x "$build/rbsim" ]; then
  echo "make_bundle: $build/rbsim: no such program; build it first (cmake --build $build --target rbsim)" >&2
  exit 2
fi
if ! git -C "$root" rev-parse --verify -q HEAD > /dev/null; then
  echo "make_bundle: $root: not a git checkout; the source part is git archive's" >&2
  exit 2
fi
stage=$(mktemp -d)
trap 'rm -rf "$stage"' EXIT
mkdir -p "$stage/rbsim"
cp "$build/rbsim" "$stage/rbsim/"
cp -r "$root/shaders" "$root/assets" "$stage/rbsim/"
git -C "$root" archive --format=tar --prefix=rbsim-source/ HEAD | tar -x -C "$stage"
mkdir -p "$(dirname "$out")"
out=$(realpath "$(dirname "$out")")/$(basename "$out")
rm -f "$out"
(cd "$stage" && zip -qr "$out" rbsim rbsim-source)
echo "make_bundle: $out ($(du -h "$out" | cut -f1)): rbsim-source/ (git HEAD) and rbsim/ (run rbsim/rbsim demo 2)"
