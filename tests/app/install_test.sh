#!/usr/bin/env bash
# `cmake --install` (issue 39): into a temporary prefix, then, from another folder and with the
# source tree out of reach of the data lookup, the installed program finds its shaders and assets
# in <prefix>/share/rbsim and runs demo 2; the installed Python module finds them there too and
# simulates. usage: install_test.sh BUILD_DIR [PYTHON]
set -euo pipefail
build_dir=$1
python=${2:-}
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "install_test: $*" >&2; exit 1; }
cmake --install "$build_dir" --prefix "$work/prefix" > "$work/install.log" 2>&1 || { cat "$work/install.log" >&2; fail "cmake --install failed"; }
prefix=$work/prefix
[ -x "$prefix/bin/rbsim" ] || fail "bin/rbsim missing"
[ -f "$prefix/share/rbsim/shaders/lighting.glsl" ] || fail "share/rbsim/shaders missing"
[ -d "$prefix/share/rbsim/assets/scenes" ] || fail "share/rbsim/assets/scenes missing"
mkdir "$work/elsewhere"
cd "$work/elsewhere"
listing=$(env -u RBSIM_ASSET_DIR -u RBSIM_SHADER_DIR "$prefix/bin/rbsim" list)
grep -qx "  assets   $prefix/share/rbsim/assets" <<< "$listing" || fail "assets not found in share/rbsim: $listing"
grep -qx "  shaders  $prefix/share/rbsim/shaders" <<< "$listing" || fail "shaders not found in share/rbsim: $listing"
env -u RBSIM_ASSET_DIR -u RBSIM_SHADER_DIR "$prefix/bin/rbsim" demo 2 --phase 1 --set world.duration=0.2 > "$work/run.log" 2>&1 ||
  { cat "$work/run.log" >&2; fail "the installed rbsim demo 2 failed"; }
[ -s "$work/elsewhere/videos/assignment2_1.mp4" ] || { ls -R "$work/elsewhere" >&2; fail "no video written"; }
if [ -n "$python" ]; then
  module_dir=$prefix/lib/python3/dist-packages
  ls "$module_dir"/rbsim*.so > /dev/null 2>&1 || fail "the Python module is not in lib/python3/dist-packages"
  [ -f "$module_dir/rbsim.pyi" ] || fail "the type stubs are not beside the module"
  env -u RBSIM_ASSET_DIR -u RBSIM_SHADER_DIR PYTHONPATH="$module_dir" "$python" - "$prefix" <<'PY' || fail "the installed Python module failed"
import sys
import rbsim
prefix = sys.argv[1]
dirs = rbsim.data_dirs()
assert dirs == {"assets": prefix + "/share/rbsim/assets", "shaders": prefix + "/share/rbsim/shaders"}, dirs
assert rbsim.__file__.startswith(prefix), rbsim.__file__
world = rbsim.load_scene("assignment2_b_velocity").world()
world.step(10)
frame = rbsim.Renderer(64, 36).render(world)
assert frame.shape == (36, 64, 4), frame.shape
PY
fi
echo "install_test: the installed program and module ran from $work/elsewhere"
