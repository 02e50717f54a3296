#!/usr/bin/env bash
# `cmake --install` (issue 39): into a temporary prefix, then, from another folder and with the
# source tree out of reach of the data lookup, the installed program finds its shaders and assets
# in <prefix>/share/rbsim and runs demo 2; the installed Python package imports with PYTHONPATH
# unset, finds them there too, simulates and renders, and mypy finds its types.
# usage: install_test.sh BUILD_DIR [PYTHON]
set -euo pipefail
here=$(cd "$(dirname "$0")" && pwd)
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
  # The package where the interpreter looks for this prefix (python/site_dir.py): for a prefix of
  # its own, <prefix>/lib/python3.X/site-packages, the user site when PYTHONUSERBASE names the
  # prefix; so it imports with PYTHONPATH unset, as from ~/.local with nothing set (issue 57).
  site=$(PYTHONUSERBASE=$prefix "$python" -c 'import site; print(site.getusersitepackages())')
  ls "$site"/rbsim/_rbsim*.so > /dev/null 2>&1 || { find "$prefix" -name '_rbsim*' >&2; fail "the Python module is not in $site/rbsim"; }
  [ -f "$site/rbsim/__init__.py" ] || fail "rbsim/__init__.py is not installed"
  [ -f "$site/rbsim/__init__.pyi" ] && [ -f "$site/rbsim/py.typed" ] || fail "the type stubs and py.typed are not in the package"
  env -u RBSIM_ASSET_DIR -u RBSIM_SHADER_DIR -u PYTHONPATH PYTHONUSERBASE="$prefix" "$python" - "$prefix" "$site" <<'PY' || fail "the installed Python module failed"
import sys
import rbsim
prefix, site = sys.argv[1], sys.argv[2]
assert rbsim.__file__ == site + "/rbsim/__init__.py", rbsim.__file__
assert rbsim.World.__module__ == "rbsim" and rbsim.load_scene.__module__ == "rbsim", rbsim.World.__module__
dirs = rbsim.data_dirs()
assert dirs == {"assets": prefix + "/share/rbsim/assets", "shaders": prefix + "/share/rbsim/shaders"}, dirs
world = rbsim.load_scene("assignment2_b_velocity").world()
world.step(10)
frame = rbsim.Renderer(64, 36).render(world)
assert frame.shape == (36, 64, 4), frame.shape
PY
  source "$here/../package/check_types.sh"
  check_types "$work" env -u PYTHONPATH PYTHONUSERBASE="$prefix" "$python" || fail "mypy did not find the installed package's types"
fi
echo "install_test: the installed program and module ran from $work/elsewhere"
