#!/usr/bin/python3
"""What a pickled State (issue 57) costs on Box3D's large pyramid (assets/scenes/box3d/
large_pyramid.json) after it has settled for 60 steps: its size, the time to pickle it (World
snapshot + CBOR), to unpickle it, and to set it into a World built from the scene, next to one
step. Each time is the fastest of five.

    PYTHONPATH=build/python /usr/bin/python3 bench/snapshot_bench.py
"""
import pathlib
import pickle
import time

import rbsim

SCENE = pathlib.Path(__file__).resolve().parent.parent / "assets" / "scenes" / "box3d" / "large_pyramid.json"


def best(fn, repeat=5):
    times = []
    for _ in range(repeat):
        start = time.perf_counter()
        fn()
        times.append(time.perf_counter() - start)
    return min(times)


def main():
    world = rbsim.load_scene(str(SCENE)).world()
    world.step(60)
    state = world.get_state()
    pickled = pickle.dumps(state)
    loaded = pickle.loads(pickled)
    target = rbsim.load_scene(str(SCENE)).world()
    print(f"{len(world)} bodies, {world.contact_count} contacts at step {world.step_count}")
    print(f"pickled state: {len(pickled)} bytes ({len(pickled) / len(world):.0f} bytes a body)")
    print(f"pickle.dumps:  {best(lambda: pickle.dumps(state)) * 1e3:8.1f} ms")
    print(f"pickle.loads:  {best(lambda: pickle.loads(pickled)) * 1e3:8.1f} ms")
    print(f"set_state:     {best(lambda: target.set_state(loaded)) * 1e3:8.1f} ms")
    print(f"one step:      {best(world.step) * 1e3:8.1f} ms")


if __name__ == "__main__":
    main()
