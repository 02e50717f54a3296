#!/usr/bin/env bash
# mypy finds the installed package's types (PEP 561: rbsim/__init__.pyi with py.typed, issue 57):
# a script using rbsim rightly type-checks (--strict), and one assigning World.time, a float, to a
# str is refused for that. Without the stubs mypy refuses both, with "missing library stubs or py.typed
# marker" and nothing about the types. Sourced by tests/app/install_test.sh and pip_install_test.sh.
# usage: check_types WORK_DIR PYTHON_COMMAND...   (the interpreter as the user runs it; Debian's python3-mypy)
check_types() {
  local work=$1 out
  shift
  mkdir -p "$work/typed"
  cat > "$work/typed/good.py" <<'PY'
import rbsim

world: rbsim.World = rbsim.World(dt=1 / 60)
ball: rbsim.BodyId = world.add_body(shape={"type": "sphere", "radius": 0.5}, mass=1.0, position=(0, 2, 0))
world.step(10)
seconds: float = world.time
version: str = rbsim.__version__
PY
  cat > "$work/typed/bad.py" <<'PY'
import rbsim

wrong: str = rbsim.World().time
PY
  (cd "$work/typed" && "$@" -m mypy --cache-dir "$work/typed/cache" --strict good.py) > "$work/typed/good.log" 2>&1 ||
    { cat "$work/typed/good.log" >&2; echo "check_types: mypy refused good.py: it did not find rbsim's types" >&2; return 1; }
  if (cd "$work/typed" && "$@" -m mypy --cache-dir "$work/typed/cache" bad.py) > "$work/typed/bad.log" 2>&1; then
    echo "check_types: mypy passed bad.py (a float assigned to a str)" >&2
    return 1
  fi
  grep -q 'Incompatible types in assignment (expression has type "float", variable has type "str")' "$work/typed/bad.log" ||
    { cat "$work/typed/bad.log" >&2; echo "check_types: mypy refused bad.py for another reason" >&2; return 1; }
}
