#!/usr/bin/python3
"""The parameter sweep of issue 57: a multiprocessing.Pool(2) steps 4 Worlds of 300 falling boxes
120 steps each, with World.threads left at its default and with threads=1, one after the other,
ROUNDS times; then one step(120) of such a World in the parent while the pool's two workers step
others (a World under load). Prints the seconds of each, and the median of the rounds.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_pool_sweep.py [ROUNDS]

With OpenMP's spinning threads (before issue 54) the sweep took 45.8 s with the default and 2.7 s
with threads=1 on this 2-core machine, and the step under load 5.08 s against 0.59 s.
"""
import multiprocessing
import statistics
import sys
import time

import rbsim

BOXES = 300
STEPS = 120
WORLDS = 4
WORKERS = 2


def build(threads):
    """300 unit boxes in a 10 x 3 x 10 block above the ground, a little apart so they fall and pile."""
    world = rbsim.World(dt=1 / 60) if threads is None else rbsim.World(dt=1 / 60, threads=threads)
    world.add_plane(normal=[0, 1, 0], point=[0, 0, 0])
    for k in range(BOXES):
        i, j, layer = k % 10, k // 10 % 10, k // 100
        world.add_body(shape={"type": "box", "extents": [1.0, 1.0, 1.0]}, mass=1.0,
                       position=[1.1 * i, 1.0 + 1.3 * layer, 1.1 * j + 0.05 * layer])
    return world


def run(threads):
    world = build(threads)
    world.step(STEPS)
    return world.state_hash()


def sweep(threads):
    start = time.perf_counter()
    with multiprocessing.get_context("fork").Pool(WORKERS) as pool:
        hashes = pool.map(run, [threads] * WORLDS)
    return time.perf_counter() - start, hashes


def under_load(threads):
    """One step(STEPS) here while two workers step Worlds of the same size with the same threads."""
    world = build(threads)
    with multiprocessing.get_context("fork").Pool(WORKERS) as pool:
        busy = pool.map_async(run, [threads] * WORLDS)
        start = time.perf_counter()
        world.step(STEPS)
        seconds = time.perf_counter() - start
        busy.get()
    return seconds


def main():
    rounds = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    results = {"default": [], "threads=1": [], "load default": [], "load threads=1": []}
    for _ in range(rounds):
        for name, threads in (("default", None), ("threads=1", 1)):
            seconds, hashes = sweep(threads)
            results[name].append(seconds)
            results["load " + name].append(under_load(threads))
        if len(set(hashes)) != 1:
            sys.exit("the four Worlds differ: " + str(hashes))
    for name, values in results.items():
        print(f"{name:16s} median {statistics.median(values):6.2f} s  "
              f"(min {min(values):.2f}, max {max(values):.2f}, {rounds} rounds)")


if __name__ == "__main__":
    main()
