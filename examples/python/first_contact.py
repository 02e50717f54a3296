#!/usr/bin/python3
"""When does a falling box first touch the ground? A ray cast measures the gap below it, free fall
predicts the time, t* = sqrt(2 gap / g); the simulation finds it by stepping at 60 Hz until the
contact solver first pushes (World.contacts(): a positive normal impulse), then rewinding to the
state saved one step before (World.get_state, set_state) and stepping again with a time step 8
times smaller, three times over: each pass narrows the step in which contact begins. Then, from one
saved state, a tumbling box is replayed with three integrators to compare how well each keeps its
kinetic energy. Writes first_contact.png.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/first_contact.py [--out DIR]
"""
import argparse
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import rbsim

G = 9.81            # [m/s^2]
HALF = 0.25         # half the box's edge [m]
DROP = 1.0          # height of the box's bottom face above the ground [m]
COARSE_DT = 1 / 60  # [s]
REFINE = 8          # each pass divides the time step by this
PASSES = 3


def falling_box():
    world = rbsim.World(dt=COARSE_DT, gravity=(0, -G, 0), sleep=False)
    world.add_plane()
    world.add_body(name="box", shape={"type": "box", "extents": [2 * HALF] * 3}, mass=1.0,
                   position=(0, DROP + HALF, 0))
    return world


def pushed(world):
    """The solver pushed the box this step: a contact point with a positive normal impulse."""
    contacts = world.contacts()
    return bool(len(contacts)) and bool((contacts["normal_impulse"] > 0).any())


def step_until_contact(world, limit_steps):
    """Steps until the first push; returns the state saved one step before it. The solver sees the
    ground coming (speculative contacts) and may push a step before the faces meet, so the contact
    time t* lies in [start, end + dt] of the step it returns."""
    for _ in range(limit_steps):
        before = world.get_state()
        world.step()
        if pushed(world):
            return before
    raise RuntimeError("the box never touched the ground")


def find_first_contact():
    world = falling_box()
    # The ray starts just under the box (a ray starting inside a body hits it at distance 0).
    hit = world.ray_cast(origin=(0, DROP - 1e-9, 0), direction=(0, -1, 0))
    gap = hit["distance"] + 1e-9
    predicted = math.sqrt(2 * gap / G)
    passes = []
    dt = COARSE_DT
    for k in range(PASSES + 1):
        before = step_until_contact(world, limit_steps=10 * REFINE ** PASSES)
        passes.append({"dt": dt, "start": before.time, "end": world.time})
        if k < PASSES:
            world.set_state(before)  # back to the last step without contact...
            dt /= REFINE
            world.dt = dt            # ...and on with a finer step
    return gap, predicted, passes


def integrator_drift(names, seconds=4.0):
    """A box tumbling about its middle axis in free fall, from one saved state, with each integrator:
    its kinetic energy in the centre-of-mass frame, (L . omega) / 2, over time."""
    world = rbsim.World(dt=1 / 60, gravity=(0, 0, 0), sleep=False)
    world.add_body(name="brick", shape={"type": "box", "extents": [1.0, 0.4, 0.2]}, mass=1.0,
                   angular_velocity=(0.05, 3.0, 0.05))
    start = world.get_state()
    curves = {}
    for name in names:
        world.set_state(start)
        world.integrator = name
        times, energy = [], []
        for _ in range(int(seconds / world.dt)):
            world.step()
            times.append(world.time)
            energy.append(0.5 * float(world.L[0] @ world.omega[0]))
        curves[name] = (np.array(times), np.array(energy))
    return curves


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=".", help="folder for first_contact.png")
    out = pathlib.Path(parser.parse_args().out)

    gap, predicted, passes = find_first_contact()
    print(f"ray cast: {gap:.6f} m below the box; free fall reaches the ground at t* = {predicted:.6f} s")
    for p in passes:
        print(f"dt = 1/{1 / p['dt']:.0f} s: the solver first pushes in the step [{p['start']:.6f}, {p['end']:.6f}] s "
              f"(t* - start = {predicted - p['start']:+.2e} s)")
    curves = integrator_drift(["euler-quat", "rk4", "exact"])
    for name, (_, e) in curves.items():
        print(f"{name:>10}: kinetic energy {e[0]:.6f} J -> {e[-1]:.6f} J ({(e[-1] - e[0]) / e[0]:+.2e})")

    fig, (left, right) = plt.subplots(1, 2, figsize=(12, 4.5))
    dts = np.array([p["dt"] for p in passes])
    left.loglog(dts, [predicted - p["start"] for p in passes], "o-", label="t* - start of the step with contact")
    left.loglog(dts, [p["end"] - p["start"] for p in passes], "s--", label="the step, dt")
    left.set(xlabel="dt [s]", ylabel="[s]", title="First contact: rewind, finer step, again")
    left.invert_xaxis()
    left.legend(fontsize=8)
    for name, (t, e) in curves.items():
        right.plot(t, e, label=name)
    right.set(xlabel="t [s]", ylabel="kinetic energy [J]", title="One saved state, three integrators (dt = 1/60 s)")
    right.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "first_contact.png", dpi=100)


if __name__ == "__main__":
    main()
