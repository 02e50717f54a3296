#!/usr/bin/env python3
"""Where a build's time went (issue 53): the slowest compile and link steps, from Ninja's own log
(BUILD/.ninja_log: start and end of every step, in ms), and the slowest tests, from CTest's own
cost data (BUILD/Testing/Temporary/CTestCostData.txt: a test's average seconds over its runs).
Prints Markdown tables for docs/ci.md; .ci/run prints them for every build it makes.

    python3 .ci/timings.py BUILD_DIR [--top N]
"""
import argparse
import os
import sys


def ninja_steps(build):
    """(seconds, output) of each step of the last build in BUILD/.ninja_log, slowest first."""
    path = os.path.join(build, ".ninja_log")
    if not os.path.exists(path):
        return None
    last = {}
    with open(path) as log:
        for line in log:
            if line.startswith("#"):
                continue
            fields = line.rstrip("\n").split("\t")
            if len(fields) < 4:
                continue
            start, end, output = int(fields[0]), int(fields[1]), fields[3]
            last[output] = (end - start) / 1000.0
    return sorted(((s, o) for o, s in last.items()), reverse=True)


def test_costs(build):
    """(seconds, name) of each test in CTest's cost data, slowest first."""
    path = os.path.join(build, "Testing", "Temporary", "CTestCostData.txt")
    if not os.path.exists(path):
        return None
    costs = []
    with open(path) as data:
        for line in data:
            if line.startswith("---"):
                break  # the failed tests' list follows
            fields = line.rsplit(None, 2)  # a name may hold spaces ("... # GetParam() = 3")
            if len(fields) == 3:
                costs.append((float(fields[2]), fields[0].split("  #")[0]))
    return sorted(costs, reverse=True)


def table(rows, top, what):
    total = sum(s for s, _ in rows)
    print(f"| {what} | s | share |")
    print("|---|---|---|")
    for seconds, name in rows[:top]:
        print(f"| `{name}` | {seconds:.1f} | {100.0 * seconds / total:.0f} % |")
    print(f"| all {len(rows)} | {total:.0f} | 100 % |")
    print()


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("build")
    parser.add_argument("--top", type=int, default=15)
    args = parser.parse_args()
    steps = ninja_steps(args.build)
    tests = test_costs(args.build)
    if steps is None and tests is None:
        print(f"{args.build}: neither .ninja_log nor CTest cost data (build with -G Ninja, run ctest)", file=sys.stderr)
        return 2
    print(f"### {os.path.basename(os.path.normpath(args.build))}\n")
    if steps:
        print("Compile and link steps (wall seconds each; the build ran two at a time):\n")
        table(steps, args.top, "step")
    if tests:
        print("Tests (CTest's cost data: seconds each; ctest ran two at a time):\n")
        table(tests, args.top, "test")
    return 0


if __name__ == "__main__":
    sys.exit(main())
