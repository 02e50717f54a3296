#!/usr/bin/python3
"""What the Python module's state arrays cost next to a step: per body, a World.x snapshot (one
pass filling a new (n, 3) array), World.state() (every array), and a step of free flight, for
worlds of 10 to 100,000 spheres with collisions off. Writes bench/results/python_state.csv.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_state_bench.py [CSV]
"""
import csv
import pathlib
import sys
import timeit

import rbsim

OUT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent / "results" / "python_state.csv")


def best_seconds(fn, budget=0.3):
    """The fastest of five rounds, each repeating fn for about `budget` seconds in all."""
    calls = max(1, int(budget / 5 / max(timeit.timeit(fn, number=1), 1e-7)))
    return min(timeit.repeat(fn, number=calls, repeat=5)) / calls


def main():
    rows = []
    for n in (10, 1000, 100000):
        world = rbsim.World(dt=1 / 60, collisions=False, integrator="symplectic-euler", sleep=False)
        for k in range(n):
            world.add_body(shape={"type": "sphere", "radius": 0.1}, mass=1.0, position=[k % 100, 10 + k // 10000, k // 100 % 100],
                           velocity=[1, 0, 0])
        for name, fn in (("step", world.step), ("x", lambda: world.x), ("q", lambda: world.q), ("R", lambda: world.R),
                         ("state", world.state)):
            seconds = best_seconds(fn)
            rows.append({"bodies": n, "call": name, "us_per_call": seconds * 1e6, "ns_per_body": seconds / n * 1e9})
            print(f"{n:7d} bodies  {name:6s} {seconds * 1e6:10.1f} us a call  {seconds / n * 1e9:8.1f} ns a body")
    OUT.parent.mkdir(parents=True, exist_ok=True)
    with open(OUT, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print("wrote", OUT)


if __name__ == "__main__":
    main()
