#!/usr/bin/env bash
# The physics-only Python module (RBSIM_PYTHON_RENDER=OFF, issue 57) links no GL, LLVM, image,
# video or X11 library, directly (readelf -d) or through another (ldd), and still simulates, while
# rbsim.Renderer says why it is missing. Run on a module that renders (MODE render), the same
# check must find those libraries: the check sees what it looks for.
# usage: physics_only_test.sh PACKAGE_PARENT_DIR PYTHON MODE   (MODE: physics-only | render)
set -euo pipefail
parent=$1
python=$2
mode=$3
fail() { echo "physics_only_test: $*" >&2; exit 1; }
module=$(ls "$parent"/rbsim/_rbsim*.so 2> /dev/null | head -1)
[ -n "$module" ] || fail "no module in $parent/rbsim"
# What a renderer brings: Mesa (OSMesa, GL, EGL, glapi, gallium), LLVM (llvmpipe), PNG, FFmpeg, X11.
render_libs='lib(OSMesa|GL|GLX|OpenGL|EGL|glapi|gallium|LLVM|png|av(codec|format|util)|sw(scale|resample)|X11)[-.]'
direct=$(readelf -d "$module" | grep NEEDED || true)
all=$(ldd "$module")
if [ "$mode" = physics-only ]; then
  if grep -Eq "$render_libs" <<< "$direct"; then fail "$module needs: $(grep -E "$render_libs" <<< "$direct")"; fi
  if grep -Eq "$render_libs" <<< "$all"; then fail "$module loads, through another library: $(grep -E "$render_libs" <<< "$all")"; fi
  echo "physics_only_test: $module needs $(wc -l <<< "$direct") libraries directly, $(wc -l <<< "$all") in all, none of them GL, LLVM, image, video or X11"
  env PYTHONPATH="$parent" "$python" - <<'PY' || fail "the physics-only module failed"
import rbsim
world = rbsim.load_scene("contact_stacking").world()
world.step(30)
assert len(world.contacts()) > 0 and world.step_count == 30
assert rbsim.World.__module__ == "rbsim"
for name in ("Renderer", "VideoWriter"):
    try:
        getattr(rbsim, name)
    except AttributeError as e:
        assert "RBSIM_PYTHON_RENDER=OFF" in str(e), e
    else:
        raise AssertionError(f"a physics-only module has rbsim.{name}")
PY
else
  grep -Eq "$render_libs" <<< "$all" || fail "the check found no GL library in a module that renders: $all"
  echo "physics_only_test: the rendering module loads $(grep -Ec "$render_libs" <<< "$all") of them, as it should"
fi
