#!/usr/bin/python3
"""The Dzhanibekov effect (the tennis-racket theorem): a box spun about its intermediate axis
flips over and back. Every integrator at dt = 1/60 s and 1/240 s against the exact torque-free
motion (World.exact_rotation: Jacobi elliptic functions), the orientation error in degrees over
time (errors below 1e-15 degrees are drawn at 1e-15). The exact and exact4 integrators step the
same closed form, so theirs is rounding alone: stepping adds nothing to the flow. Writes
dzhanibekov.png.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/dzhanibekov.py [--out DIR] [--seconds S]
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import rbsim


def angle_between(q, r):
    """Rotation angle [rad] from orientation r to q, both (k, 4) unit quaternions (w, x, y, z)."""
    w = np.abs(np.einsum("ij,ij->i", q, r))  # |<q, r>| = cos(angle / 2); q and -q are one rotation
    # The sine half from the vector part of r^-1 q keeps the digits near zero that arccos loses.
    rw, rv = r[:, 0], -r[:, 1:]
    qw, qv = q[:, 0], q[:, 1:]
    v = rw[:, None] * qv + qw[:, None] * rv + np.cross(rv, qv)
    return 2 * np.arctan2(np.linalg.norm(v, axis=1), w)


def run(integrator, dt, seconds):
    world = rbsim.World(dt=dt, integrator=integrator, gravity=[0, 0, 0], collisions=False)
    # 3 x 1 x 0.2 m: moments I1 < I2 < I3 about x, z, y; the spin is about z, the middle one,
    # with a small push off it so the flip comes within a few seconds.
    body = world.add_body(name="racket", shape={"type": "box", "extents": [0.3, 0.02, 0.1]}, mass=1.0,
                          angular_velocity=[0.01, 0.0, 2 * np.pi])
    steps = int(round(seconds / dt))
    times = np.arange(1, steps + 1) * dt
    exact = world.exact_rotation(body, times)
    q = np.empty((steps, 4))
    energy = world.ke[0]
    for k in range(steps):
        world.step()
        q[k] = world.q[0]
    drift = world.ke[0] / energy - 1
    return times, np.degrees(angle_between(q, exact)), exact, drift


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=".", help="folder for dzhanibekov.png")
    parser.add_argument("--seconds", type=float, default=12.0, help="simulated time [s]")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    fig, axes = plt.subplots(1, 3, figsize=(16, 5), gridspec_kw={"width_ratios": [1, 1.4, 1.4]})
    times, _, exact, _ = run("exact", 1 / 240, args.seconds)
    # The body's z axis (the spin axis) in world frame: R e_z from the exact orientation.
    w, x, y, z = exact.T
    axes[0].plot(times, 2 * (x * z + w * y), label="x")
    axes[0].plot(times, 2 * (y * z - w * x), label="y")
    axes[0].plot(times, 1 - 2 * (x * x + y * y), label="z")
    axes[0].set(title="exact motion: the spin axis in world frame", xlabel="t [s]")
    axes[0].legend()
    for ax, dt, label in ((axes[1], 1 / 60, "1/60"), (axes[2], 1 / 240, "1/240")):
        for integrator in rbsim.integrators():
            t, error, _, drift = run(integrator, dt, args.seconds)
            ax.semilogy(t, np.maximum(error, 1e-15), label=f"{integrator} (energy {drift:+.1e})")
            print(f"dt {label:6s} {integrator:17s} error at {t[-1]:.0f} s: {error[-1]:9.3g} deg, "
                  f"largest {error.max():9.3g} deg, energy drift {drift:+.2e}")
        ax.set(title=f"orientation error against the exact motion, dt = {label} s", xlabel="t [s]",
               ylabel="angle [deg]", ylim=(1e-16, 400))
        ax.legend(fontsize=7, loc="lower right")
    fig.tight_layout()
    fig.savefig(out / "dzhanibekov.png", dpi=110)
    print("wrote", out / "dzhanibekov.png")


if __name__ == "__main__":
    main()
