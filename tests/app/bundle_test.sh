#!/usr/bin/env bash
# bench/make_bundle.sh (issue 36): the zip unpacks into rbsim-source/ and rbsim/, and the program
# in rbsim/ runs demo 2 from another folder with the shaders and assets beside it, not the source
# tree's. usage: bundle_test.sh SOURCE_DIR BUILD_DIR
set -euo pipefail
source_dir=$1
build_dir=$2
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
bash "$source_dir/bench/make_bundle.sh" --build "$build_dir" --out "$work/rbsim.zip"
mkdir "$work/unpacked" "$work/elsewhere"
unzip -q "$work/rbsim.zip" -d "$work/unpacked"
fail() { echo "bundle_test: $*" >&2; exit 1; }
[ -f "$work/unpacked/rbsim-source/README.md" ] || fail "rbsim-source/README.md missing"
[ -f "$work/unpacked/rbsim-source/.ci/run" ] || fail "rbsim-source/.ci/run missing"
[ -x "$work/unpacked/rbsim/rbsim" ] || fail "rbsim/rbsim missing or not executable"
cd "$work/elsewhere"
listing=$(env -u RBSIM_ASSET_DIR -u RBSIM_SHADER_DIR "$work/unpacked/rbsim/rbsim" list)
grep -qx "  assets   $work/unpacked/rbsim/assets" <<< "$listing" || fail "assets not found beside the program: $listing"
grep -qx "  shaders  $work/unpacked/rbsim/shaders" <<< "$listing" || fail "shaders not found beside the program: $listing"
env -u RBSIM_ASSET_DIR -u RBSIM_SHADER_DIR "$work/unpacked/rbsim/rbsim" demo 2 --phase 1 --set world.duration=0.2 \
  --frames "$work/elsewhere/frames" > "$work/run.log" 2>&1 || { cat "$work/run.log" >&2; fail "demo 2 failed"; }
[ -f "$work/elsewhere/frames/frame_000000.png" ] || fail "no frame written"
[ -s "$work/elsewhere/videos/assignment2_1.mp4" ] || { ls -R "$work/elsewhere" >&2; fail "no video written"; }
echo "bundle_test: the unpacked program ran demo 2 from $work/elsewhere"
