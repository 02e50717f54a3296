#!/usr/bin/env python3
"""Every quoted #include resolves in a fresh checkout, before any build (issue 35), and the public
headers stand alone. Each tree of the repository may include from the folders its CMake targets
put on the include path, and from its own folder; nothing is generated or linked at build time.
  - engine/include/rbsim/ (the public API, installed) includes only public headers;
  - engine/src/ (sources and private headers) includes public and private ones;
  - app/, python/ and examples/ see the public headers only; tests/ and bench/ may reach the
    private ones (rbsim::internals).
Prints every include that does not resolve (file, line, what and where it looked) and exits 1.

    python3 tests/layers/check_includes.py [REPO_DIR]
    python3 tests/layers/check_includes.py --self-test   # a private include in a public header fails
"""
import os
import re
import sys

INCLUDE = re.compile(r'^\s*#\s*include\s+"([^"]+)"')
SOURCES = (".h", ".cpp")
# Per tree (the longest prefix wins): the include roots its targets use (engine/CMakeLists.txt,
# app/CMakeLists.txt, python/CMakeLists.txt, bench/CMakeLists.txt, tests/*/CMakeLists.txt).
ROOTS = {
    "engine/include": ["engine/include"],
    "engine/src": ["engine/include", "engine/src"],
    "app": ["engine/include", "app"],
    "python": ["engine/include", "app", "python/src"],
    "examples": ["engine/include"],
    "bench": ["engine/include", "engine/src", "app", "bench"],
    "tests": ["engine/include", "engine/src", "app", "bench", "tests/engine", "tests"],
}


def roots_of(rel):
    best = max((p for p in ROOTS if rel == p or rel.startswith(p + "/")), key=len, default=None)
    return ROOTS[best] if best else None


def check(repo):
    problems = []
    for top in sorted({p.split("/")[0] for p in ROOTS}):
        for folder, dirs, names in os.walk(os.path.join(repo, top)):
            dirs[:] = sorted(d for d in dirs if d not in ("build", "__pycache__"))
            for name in sorted(names):
                if not name.endswith(SOURCES):
                    continue
                path = os.path.join(folder, name)
                rel = os.path.relpath(path, repo).replace(os.sep, "/")
                roots = roots_of(rel)
                if roots is None:
                    continue
                with open(path, encoding="utf-8", errors="replace") as f:
                    for number, line in enumerate(f, 1):
                        m = INCLUDE.match(line)
                        if not m:
                            continue
                        target = m.group(1)
                        if os.path.isfile(os.path.join(folder, target)) and not rel.startswith("engine/include/"):
                            continue
                        if any(os.path.isfile(os.path.join(repo, r, target)) for r in roots):
                            continue
                        problems.append(f"{rel}:{number}: \"{target}\" is in none of {', '.join(roots)}")
    return problems


def self_test():
    """A made-up repository: a public header including a private one, and an app file including a
    private header, must give exactly those two problems; the correct includes none."""
    import tempfile
    with tempfile.TemporaryDirectory() as repo:
        files = {
            "engine/include/rbsim/world/world.h": '#include "rbsim/math/types.h"\n#include "world/islands.h"\n',
            "engine/include/rbsim/math/types.h": "",
            "engine/src/world/islands.h": '#include "rbsim/math/types.h"\n',
            "engine/src/world/world.cpp": '#include "rbsim/world/world.h"\n#include "world/islands.h"\n',
            "app/run/view.cpp": '#include "rbsim/world/world.h"\n#include "world/islands.h"\n',
        }
        for rel, text in files.items():
            os.makedirs(os.path.join(repo, os.path.dirname(rel)), exist_ok=True)
            with open(os.path.join(repo, rel), "w", encoding="utf-8") as f:
                f.write(text)
        problems = check(repo)
    expected = ["engine/include/rbsim/world/world.h:2:", "app/run/view.cpp:2:"]
    ok = len(problems) == 2 and all(any(p.startswith(e) for p in problems) for e in expected)
    print("self-test", "passed" if ok else "FAILED", problems)
    return 0 if ok else 1


def main():
    if sys.argv[1:] == ["--self-test"]:
        return self_test()
    repo = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..")
    problems = check(repo)
    for p in problems:
        print(p)
    print(f"check_includes: {len(problems)} problems", file=sys.stderr)
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
