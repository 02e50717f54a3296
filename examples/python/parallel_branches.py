#!/usr/bin/python3
"""What-if branches in worker processes from one saved state (issue 57). A stack of boxes settles
for 1 s; its state is saved (State.save) and pickled to a pool of spawned worker processes. Each
worker builds the World from the state's scene (World.from_state) and goes on for 1.5 s after
giving the top box a sideways push of a different speed; worker 0 pushes nothing and must match,
bit for bit at every step, the run this process makes (World.state_hash). Writes
parallel_branches.png: the top box's height and sideways position over time in each branch.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/parallel_branches.py [--out DIR]
"""
import argparse
import multiprocessing
import pathlib
import pickle

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import rbsim

SCENE = "contact_stacking"
SETTLE = 1.0                      # [s] before the state is saved
AFTER = 1.5                       # [s] each branch runs after it
PUSHES = [0.0, 0.5, 1.0, 2.0]     # the top box's sideways speed at the branch [m/s]


def top_box(world):
    """Index of the highest body (the scene's bodies are all dynamic, on a ground plane)."""
    return int(np.argmax(world.x[:, 1]))


def branch(pickled, push):
    """A worker: the World from the state, the push, then the top box's path and the hashes."""
    world = rbsim.World.from_state(pickle.loads(pickled))
    top = top_box(world)
    if push:
        world.set_pose(world.id_at(top), velocity=(push, 0.0, 0.0))
    path, hashes = [], []
    for _ in range(round(AFTER / world.dt)):
        world.step()
        path.append(world.x[top].copy())
        hashes.append(world.state_hash())
    return np.array(path), hashes


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."))
    out = parser.parse_args().out
    out.mkdir(parents=True, exist_ok=True)

    world = rbsim.load_scene(SCENE).world()
    world.step(round(SETTLE / world.dt))
    state = world.get_state()
    state.save(out / "stack.state")            # the same bytes pickle gives
    pickled = pickle.dumps(rbsim.load_state(out / "stack.state"))
    print(f"state at t = {state.time:.3f} s: {len(pickled)} bytes pickled, {world.contact_count} contacts")

    here = []
    for _ in range(round(AFTER / world.dt)):
        world.step()
        here.append(world.state_hash())

    with multiprocessing.get_context("spawn").Pool(len(PUSHES)) as pool:
        results = pool.starmap(branch, [(pickled, push) for push in PUSHES])
    assert results[0][1] == here, "the unpushed branch left the run made here"
    print("branch without a push: equal state hash at every one of", len(here), "steps")

    fig, (height, side) = plt.subplots(1, 2, figsize=(11, 4.2))
    t = SETTLE + world.dt * np.arange(1, len(here) + 1)
    for push, (path, _) in zip(PUSHES, results):
        height.plot(t, path[:, 1], label=f"push {push:g} m/s")
        side.plot(t, path[:, 0], label=f"push {push:g} m/s")
        print(f"push {push:3.1f} m/s: top box ends at x = {path[-1, 0]:+.3f} m, y = {path[-1, 1]:.3f} m")
    height.set(xlabel="t [s]", ylabel="top box height y [m]", title="branches from one pickled state")
    side.set(xlabel="t [s]", ylabel="top box x [m]", title="worker 0 (no push) = this process, bit for bit")
    height.legend()
    fig.tight_layout()
    fig.savefig(out / "parallel_branches.png", dpi=100)


if __name__ == "__main__":
    main()
