#!/usr/bin/python3
"""World.ray_cast_batch against World.ray_cast in a Python loop (issue 57), thread CPU time (the
machine is shared): query_bench's scene, 10,000 random static boxes and balls at one body per
8 m^3, and 100,000 rays of 10 m from random points in it.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_query_bench.py
"""
import time

import numpy as np
import rbsim

BODIES = 10000
RAYS = 100000
LOOPED = 20000       # rays cast one call each
RAY_LENGTH = 10.0    # [m]
VOLUME_PER_BODY = 8.0  # [m^3]


def main():
    rng = np.random.default_rng(57)
    side = (VOLUME_PER_BODY * BODIES) ** (1 / 3)
    world = rbsim.World(gravity=[0, 0, 0])
    for i in range(BODIES):
        shape = ({"type": "sphere", "radius": float(rng.uniform(0.25, 0.5))} if i % 2 == 0 else
                 {"type": "box", "extents": list(2 * rng.uniform(0.25, 0.5, 3))})
        world.add_body(shape=shape, mass=1, position=rng.uniform(0, side, 3), static=True)
    origins = rng.uniform(0, side, (RAYS, 3))
    directions = rng.normal(size=(RAYS, 3))
    world.ray_cast_batch(origins[:10], directions[:10], RAY_LENGTH)  # builds the tree
    start = time.thread_time()
    hits = world.ray_cast_batch(origins, directions, RAY_LENGTH)
    batch = time.thread_time() - start
    start = time.thread_time()
    for i in range(LOOPED):
        world.ray_cast(origins[i], directions[i], RAY_LENGTH)
    looped = time.thread_time() - start
    print(f"{BODIES} bodies: ray_cast_batch {1e9 * batch / RAYS:.0f} ns a ray ({RAYS / batch / 1e6:.2f} M rays/s, "
          f"{hits['hit'].sum()} of {RAYS} hit); ray_cast in a loop {1e9 * looped / LOOPED:.0f} ns a ray")


if __name__ == "__main__":
    main()
