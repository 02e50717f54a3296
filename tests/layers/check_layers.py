#!/usr/bin/env python3
"""The engine's modules depend downward only (issue 20): each #include "rbsim/MODULE/..." in an
engine file must name its own module or one of a lower layer, and no header may reach itself
through its includes. Prints every offending include (file, line, what it includes) and exits 1.

    python3 tests/layers/check_layers.py [ENGINE_DIR]
    python3 tests/layers/check_layers.py --self-test   # shows that an upward include and a cycle fail
"""
import os
import re
import sys

# Lowest first. A module may include its own headers and those of any lower layer, never of its
# own layer or above: so modules of one layer are independent of each other.
LAYERS = [
    ["math"],
    ["geometry", "integrate"],
    ["shapes", "io"],
    ["mass"],
    ["settings", "body"],
    ["collision", "fracture"],
    ["dynamics"],
    ["particles", "soft", "planar"],
    ["world"],
    ["scene"],
]
LAYER_OF = {module: level for level, modules in enumerate(LAYERS) for module in modules}
INCLUDE = re.compile(r'^\s*#\s*include\s+"rbsim/([^"]+)"')


def engine_files(engine):
    for folder, _, names in os.walk(engine):
        for name in sorted(names):
            if name.endswith((".h", ".cpp")):
                path = os.path.join(folder, name)
                yield os.path.relpath(path, engine).replace(os.sep, "/"), path


def self_test():
    """A made-up engine with one upward include and one cycle must give exactly those two problems."""
    import tempfile
    with tempfile.TemporaryDirectory() as engine:
        files = {
            "math/types.h": '#include "rbsim/world/world.h"\n',  # upward
            "world/world.h": '#include "rbsim/math/types.h"\n#include "rbsim/world/a.h"\n',
            "world/a.h": '#include "rbsim/world/world.h"\n',  # a cycle within world
        }
        for rel, text in files.items():
            os.makedirs(os.path.join(engine, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(engine, rel), "w", encoding="utf-8") as f:
                f.write(text)
        problems = check(engine)
    upward = [p for p in problems if p.startswith("math/types.h:1: includes rbsim/world/world.h")]
    cycles = [p for p in problems if p.startswith("include cycle:")]
    ok = len(upward) == 1 and len(cycles) >= 1
    print("self-test", "passed" if ok else "FAILED", problems)
    return 0 if ok else 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    engine = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..", "engine")
    problems = check(engine)
    for p in problems:
        print(p)
    print(f"check_layers: {len(problems)} problems", file=sys.stderr)
    return 1 if problems else 0


def check(engine):
    problems = []
    graph = {}  # header -> headers it includes (engine-relative)
    for rel, path in engine_files(engine):
        module = rel.split("/")[0]
        if module not in LAYER_OF:
            problems.append(f"{rel}: module '{module}' has no layer in tests/layers/check_layers.py")
            continue
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m:
                    continue
                target = m.group(1)
                graph.setdefault(rel, []).append(target)
                other = target.split("/")[0]
                if other == module:
                    continue
                if other not in LAYER_OF:
                    problems.append(f"{rel}:{number}: includes rbsim/{target}, of no known module")
                elif LAYER_OF[other] >= LAYER_OF[module]:
                    problems.append(f"{rel}:{number}: includes rbsim/{target}: {other} (layer {LAYER_OF[other]}) "
                                    f"is not below {module} (layer {LAYER_OF[module]})")
    # Cycles among files (within a module too): depth-first search over the include graph.
    state = {}
    def visit(node, stack):
        state[node] = 1
        for nxt in graph.get(node, []):
            if state.get(nxt) == 1:
                cycle = stack[stack.index(nxt):] + [nxt] if nxt in stack else [node, nxt]
                problems.append("include cycle: " + " -> ".join(cycle))
            elif nxt not in state:
                visit(nxt, stack + [nxt])
        state[node] = 2
    for node in sorted(graph):
        if node not in state:
            visit(node, [node])
    return problems


if __name__ == "__main__":
    sys.exit(main())
