#!/usr/bin/env bash
# `pip install .` (issue 39), as README's Install section gives it: into a venv made with
# --system-site-packages (Debian's NumPy), offline (--no-build-isolation), from a copy of the
# files the package is made of. The module is this build's (RBSIM_CMAKE_BUILD_DIR, setup.py): the
# test checks the packaging, not a second compile. Then, from another folder, the venv's python
# imports it, finds its shaders and assets in <venv>/share/rbsim, simulates and renders, and mypy
# finds its types (the package rbsim/ with __init__.pyi and py.typed, issue 57).
# usage: pip_install_test.sh SOURCE_DIR BUILD_DIR PYTHON
set -euo pipefail
source_dir=$1
build_dir=$2
python=$3
work=$(mktemp -d)
trap 'rm -rf "$work"' EXIT
fail() { echo "pip_install_test: $*" >&2; exit 1; }
mkdir -p "$work/src/python" "$work/src/docs"
cp "$source_dir"/{setup.py,pyproject.toml,CMakeLists.txt,LICENSE} "$work/src/"
cp -r "$source_dir/shaders" "$source_dir/assets" "$work/src/"
cp -r "$source_dir/python/rbsim" "$work/src/python/"
cp "$source_dir/docs/python.md" "$work/src/docs/"
"$python" -m venv --system-site-packages "$work/venv" || fail "$python -m venv failed (python3-venv)"
RBSIM_CMAKE_BUILD_DIR=$build_dir "$work/venv/bin/python" -m pip install --no-build-isolation --no-input \
  "$work/src" > "$work/pip.log" 2>&1 || { cat "$work/pip.log" >&2; fail "pip install failed"; }
mkdir "$work/elsewhere"
cd "$work/elsewhere"
env -u RBSIM_ASSET_DIR -u RBSIM_SHADER_DIR -u PYTHONPATH "$work/venv/bin/python" - "$work/venv" <<'PY' || fail "the pip-installed module failed"
import pathlib
import subprocess
import sys
import rbsim
venv = pathlib.Path(sys.argv[1]).resolve()
module = pathlib.Path(rbsim.__file__).resolve()
assert venv in module.parents, module
assert module.name == "__init__.py" and module.parent.name == "rbsim", module
assert {p.name for p in module.parent.iterdir()} >= {"__init__.pyi", "py.typed"}, "no stubs or py.typed in the package"
assert rbsim.World.__module__ == "rbsim", rbsim.World.__module__
dirs = rbsim.data_dirs()
assert dirs == {"assets": str(venv / "share/rbsim/assets"), "shaders": str(venv / "share/rbsim/shaders")}, dirs
version = subprocess.run([sys.executable, "-m", "pip", "show", "rbsim"], capture_output=True, text=True).stdout
assert f"Version: {rbsim.__version__}" in version, version
assert "License: MIT" in version, version
world = rbsim.load_scene("contact_stacking").world()
world.step(30)
assert len(world.contacts()) > 0
frame = rbsim.Renderer(64, 36).render(world)
assert frame.shape == (36, 64, 4) and frame[..., :3].std() > 0, frame.shape
PY
source "$source_dir/tests/package/check_types.sh"
check_types "$work" env -u PYTHONPATH "$work/venv/bin/python" || fail "mypy did not find the pip-installed package's types"
echo "pip_install_test: pip installed the module into $work/venv and it ran from another folder"
