#!/usr/bin/env python3
"""The engine's modules depend downward only (issue 20): each include of a module's header in an
engine file ("rbsim/MODULE/..." for a public header in engine/include, "MODULE/..." for a private
one in engine/src) must name its own module or one of a lower layer, and no header may reach
itself through its includes. The app's folders are layered the same way (issue 35: run/ and
record/ included each other). Prints every offending include (file, line, what it includes) and
exits 1.

    python3 tests/layers/check_layers.py [REPO_DIR]
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
# The app's folders, lowest first: the renderer knows no physics, a recording is a file format,
# the glTF export writes the renderer's body meshes and the bodies' poses, a run builds frames
# from all of them, the window drives runs and replays, the command line's flags and messages sit
# above them, and main.cpp everything. The engine's public headers lie below all of them.
APP_LAYERS = [
    ["render", "record", "demos"],
    ["export"],
    ["run"],
    ["window"],
    ["cli"],
    ["."],
]
# Systems beside the rigid bodies, stepped through the step hook (dynamics/step_listener.h), and
# fracture: world/world.h must reach none of their headers, however indirectly (issue 35).
WORLD_HEADER = "world/world.h"
NOT_IN_WORLD_HEADER = ["particles", "soft", "planar", "fracture"]
APP_LAYER_OF = {folder: level for level, folders in enumerate(APP_LAYERS) for folder in folders}
INCLUDE = re.compile(r'^\s*#\s*include\s+"(rbsim/)?([^"]+)"')


def walk(root):
    for folder, _, names in os.walk(root):
        for name in sorted(names):
            if name.endswith((".h", ".cpp")):
                path = os.path.join(folder, name)
                yield os.path.relpath(path, root).replace(os.sep, "/"), path


def engine_files(repo):
    """(module-relative name, path) of every engine file: public headers and private files share
    one name space, the module's folder, as their includes do."""
    yield from walk(os.path.join(repo, "engine", "include", "rbsim"))
    yield from walk(os.path.join(repo, "engine", "src"))


def self_test():
    """A made-up engine with one upward include and one cycle must give exactly those two problems."""
    import tempfile
    with tempfile.TemporaryDirectory() as engine:
        files = {
            "engine/include/rbsim/math/types.h": '#include "rbsim/world/world.h"\n',  # upward
            "engine/include/rbsim/world/world.h": '#include "rbsim/math/types.h"\n#include "world/a.h"\n'
                                                  '#include "rbsim/particles/p.h"\n',  # a sibling system
            "engine/include/rbsim/particles/p.h": "",
            "engine/src/world/a.h": '#include "rbsim/world/world.h"\n',  # a cycle within world
            "app/run/runner.cpp": '#include "record/recording.h"\n',
            "app/record/recording.h": '#include "run/runner.h"\n',  # upward in the app
            "app/run/runner.h": '#include "rbsim/world/world.h"\n',
        }
        for rel, text in files.items():
            os.makedirs(os.path.join(engine, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(engine, rel), "w", encoding="utf-8") as f:
                f.write(text)
        problems = check(engine)
    upward = [p for p in problems if p.startswith("math/types.h:1: includes world/world.h")]
    app = [p for p in problems if p.startswith("app/record/recording.h:1: includes run/runner.h")]
    cycles = [p for p in problems if p.startswith("include cycle:")]
    sibling = [p for p in problems if p.startswith("world/world.h reaches particles/p.h")]
    ok = (len(upward) == 1 and len(app) == 1 and len(cycles) >= 1 and len(sibling) == 1 and
          len(upward) + len(app) + len(cycles) + len(sibling) == len(problems))
    print("self-test", "passed" if ok else "FAILED", problems)
    return 0 if ok else 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    repo = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    problems = check(repo)
    for p in problems:
        print(p)
    print(f"check_layers: {len(problems)} problems", file=sys.stderr)
    return 1 if problems else 0


def check(repo):
    problems = []
    graph = {}  # file -> files it includes (module-relative for the engine, "app/..." for the app)
    for rel, path in engine_files(repo):
        module = rel.split("/")[0]
        if module not in LAYER_OF:
            problems.append(f"{rel}: module '{module}' has no layer in tests/layers/check_layers.py")
            continue
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m or m.group(2).split("/")[0] not in LAYER_OF:
                    continue
                target = m.group(2)
                graph.setdefault(rel, []).append(target)
                other = target.split("/")[0]
                if other != module and LAYER_OF[other] >= LAYER_OF[module]:
                    problems.append(f"{rel}:{number}: includes {target}: {other} (layer {LAYER_OF[other]}) "
                                    f"is not below {module} (layer {LAYER_OF[module]})")
    for rel, path in walk(os.path.join(repo, "app")):
        folder = rel.split("/")[0] if "/" in rel else "."
        if folder not in APP_LAYER_OF:
            problems.append(f"app/{rel}: folder '{folder}' has no layer in tests/layers/check_layers.py")
            continue
        with open(path, encoding="utf-8") as f:
            for number, line in enumerate(f, 1):
                m = INCLUDE.match(line)
                if not m or m.group(1):
                    continue  # the engine's public headers lie below the app
                target = m.group(2)
                if os.path.isfile(os.path.join(os.path.dirname(path), target)):  # beside the includer
                    target = os.path.normpath(os.path.join(os.path.dirname(rel), target)).replace(os.sep, "/")
                other = target.split("/")[0] if "/" in target else "."
                if other not in APP_LAYER_OF:
                    continue
                graph.setdefault("app/" + rel, []).append("app/" + target)
                if other != folder and APP_LAYER_OF[other] >= APP_LAYER_OF[folder]:
                    problems.append(f"app/{rel}:{number}: includes {target}: {other} (layer {APP_LAYER_OF[other]}) "
                                    f"is not below {folder} (layer {APP_LAYER_OF[folder]})")
    reached, todo = set(), [WORLD_HEADER]
    while todo:
        node = todo.pop()
        if node not in reached:
            reached.add(node)
            todo += graph.get(node, [])
    for node in sorted(reached):
        if node.split("/")[0] in NOT_IN_WORLD_HEADER:
            problems.append(f"{WORLD_HEADER} reaches {node}: {node.split('/')[0]} is a system of its own "
                            "(world/systems.h), not part of the World's header")
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
