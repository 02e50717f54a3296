#!/usr/bin/python3
"""Ten boxes dropped as a loose column onto the ground, with both contact solvers at 60 Hz: the
kinetic, potential and total energy of the stack over time, and the picture at the end (rendered
by rbsim.Renderer, the program's renderer). Contacts only remove energy: the total may fall (the
boxes land without restitution, friction slides) but should never rise. It prints the largest
rise of the total over any stretch of the run, max over t of E(t) - min E(s <= t). Writes
falling_stack.png.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/falling_stack.py [--out DIR]
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import rbsim

BOXES = 10
SIZE = 0.4     # edge [m]
GAP = 0.15     # between neighbours at the start [m]
SECONDS = 6.0  # simulated [s]


def build(solver):
    world = rbsim.World(dt=1 / 60, solver=solver)
    world.add_plane(friction_static=0.6, friction_kinetic=0.5)
    rng = np.random.default_rng(7)
    for k in range(BOXES):
        # A slight offset and twist per box, so the column is not a perfect one.
        world.add_body(name=f"box{k}", shape={"type": "box", "extents": [SIZE] * 3}, density=500,
                       position=[*rng.uniform(-0.03, 0.03, 1), SIZE / 2 + GAP + k * (SIZE + GAP), 0],
                       orientation={"axis_angle_deg": [0, 1, 0, float(rng.uniform(-10, 10))]},
                       friction_static=0.6, friction_kinetic=0.5, color=[0.2 + 0.07 * k, 0.4, 0.9 - 0.06 * k])
    return world


def run(solver):
    world = build(solver)
    t, ke, pe = [], [], []
    for _ in range(int(SECONDS / world.dt) + 1):
        t.append(world.time)
        ke.append(world.ke.sum())
        pe.append(world.pe.sum())
        world.step()
    return world, np.array(t), np.array(ke), np.array(pe)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=".", help="folder for falling_stack.png")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    fig, axes = plt.subplots(1, 3, figsize=(18, 6), gridspec_kw={"width_ratios": [1, 1, 0.6]})
    renderer = rbsim.Renderer(480, 640)
    camera = {"eye": [5.0, 3.0, 7.5], "target": [0, 2.0, 0], "fov_deg": 45}
    for ax, solver in zip(axes[:2], rbsim.solvers()):
        world, t, ke, pe = run(solver)
        total = ke + pe
        ax.plot(t, ke, label="kinetic")
        ax.plot(t, pe, label="potential (m g y)")
        ax.plot(t, total, "k", label="total")
        rise = (total - np.minimum.accumulate(total)).max()
        top = world.x[:, 1].max()
        ax.set(title=f"{solver}, dt = 1/60 s: largest rise of the total {rise:.3g} J, top box at {top:.2f} m",
               xlabel="t [s]", ylabel="energy [J]")
        ax.legend()
        print(f"{solver:9s}: energy {total[0]:.2f} J -> {total[-1]:.2f} J, largest rise {rise:.3g} J, "
              f"{world.awake.sum()} of {len(world)} boxes awake, top box centre at {top:.3f} m "
              f"(a standing column: {SIZE / 2 + (BOXES - 1) * SIZE:.3f} m)")
        if solver == "soft-step":
            axes[2].imshow(renderer.render(world, camera=camera, overlay=False))
            axes[2].set(title=f"soft step at t = {world.time:.1f} s (rbsim.Renderer)")
            axes[2].axis("off")
    fig.tight_layout()
    fig.savefig(out / "falling_stack.png", dpi=100)
    print("wrote", out / "falling_stack.png")


if __name__ == "__main__":
    main()
