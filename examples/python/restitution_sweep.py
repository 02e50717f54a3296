#!/usr/bin/python3
"""A ball dropped onto the ground for restitution 0 to 1, with both contact solvers at 60 Hz and
240 Hz: the height of the first rebound against Newton's law of restitution, h1 = e^2 h0 (the
approach speed sqrt(2 g h0) comes back times e). Below Settings::restitutionThreshold (0.5 m/s)
an approach does not bounce. The rebound comes out a few millimetres high, (1 - e^2) d: the
collision pass reverses an approach at the start of the step that will close its gap, d above
the ground (d < |v| dt). One World per solver and step: each drop goes back to the state saved
before it (World.get_state, set_state) and changes the ball's restitution (World.set_body), rather
than building the World again. Writes restitution_sweep.png.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/restitution_sweep.py [--out DIR]
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import rbsim

RADIUS = 0.1  # [m]
DROP = 1.0    # h0: height of the ball's bottom above the ground [m]


def dropped_ball(solver, dt):
    """A World with the ball held 1 m above the ground, its state saved there, and the ball's id."""
    world = rbsim.World(dt=dt, solver=solver, integrator="dlm")
    world.add_plane()  # restitution 0: the pair's restitution is the larger of the two, the ball's
    ball = world.add_body(shape={"type": "sphere", "radius": RADIUS}, mass=1.0, position=[0, RADIUS + DROP, 0])
    return world, world.get_state(), ball


def first_rebound(world, start, ball, restitution):
    """The highest the ball's bottom rises after its first contact with the ground [m], dropped from
    the saved state `start` with its restitution changed (World.set_body): one World for the sweep."""
    world.set_state(start)
    world.set_body(ball, restitution=restitution)
    bounced, top = False, 0.0
    for _ in range(int(2.5 / world.dt)):
        world.step()
        height, vy = world.x[0, 1] - RADIUS, world.v[0, 1]
        if not bounced and vy > 0:
            bounced = True
        if bounced:
            top = max(top, height)
            if vy < 0:
                break
    return top


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=".", help="folder for restitution_sweep.png")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    e = np.linspace(0, 1, 21)
    fig, (ax, err) = plt.subplots(1, 2, figsize=(12, 5))
    ax.plot(e, e**2 * DROP, "k-", lw=3, alpha=0.3, label="e^2 h0 (Newton)")
    for solver in rbsim.solvers():
        for dt, style in ((1 / 60, "o--"), (1 / 240, "x-")):
            label = f"{solver}, dt = 1/{round(1 / dt)} s"
            world, start, ball = dropped_ball(solver, dt)
            h = np.array([first_rebound(world, start, ball, c) for c in e])
            miss = (h - e**2 * DROP) * 1000  # [mm]
            ax.plot(e, h, style, label=label)
            err.plot(e, miss, style, label=label)
            print(f"{solver:9s} dt 1/{round(1 / dt):3d}: rebound {h[10]:.4f} m at e = 0.5 (e^2 h0 = 0.25), "
                  f"{h[-1]:.4f} m at e = 1; off by {miss[e > 0].min():+.1f} to {miss[e > 0].max():+.1f} mm for e > 0")
    ax.set(title=f"first rebound of a ball dropped {DROP} m", xlabel="restitution e", ylabel="rebound height [m]")
    ax.legend()
    err.axhline(0, color="k", lw=0.5)
    err.set(title="rebound - e^2 h0", xlabel="restitution e",
            ylabel="[mm]")
    err.legend()
    fig.tight_layout()
    fig.savefig(out / "restitution_sweep.png", dpi=110)
    print("wrote", out / "restitution_sweep.png")


if __name__ == "__main__":
    main()
