#!/usr/bin/python3
"""A robot's camera view of a table top: colour, depth and segmentation from one call of
rbsim.Renderer.render (PyBullet's getCameraImage, MuJoCo's Renderer with depth and segmentation
on). Three balls, a box and a capsule settle on the ground for 1 s; then each body's pixels are
found by its row in the segmentation image, and the depth under its nearest pixel is compared with
the distance along the camera axis to the body's nearest point (exact for the balls: the centre's
distance minus the radius, up to the 0.8 mm the drawn polyhedron lies inside the sphere). Writes camera_images.png (the
three images side by side) and camera_images.npz (the arrays).

    PYTHONPATH=build/python /usr/bin/python3 examples/python/camera_images.py [--out DIR]
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import rbsim

WIDTH, HEIGHT = 480, 320
EYE = np.array([0.0, 2.2, 3.2])
TARGET = np.array([0.0, 0.2, 0.0])
BALL_RADIUS = 0.18  # [m]


def build():
    world = rbsim.World(dt=1 / 60)
    world.add_plane()
    for k, x in enumerate([-0.7, 0.0, 0.7]):
        world.add_body(name=f"ball{k}", shape={"type": "sphere", "radius": BALL_RADIUS}, mass=1,
                       position=[x, BALL_RADIUS + 0.3, 0.5], color=[0.9, 0.25 + 0.3 * k, 0.2])
    world.add_body(name="box", shape={"type": "box", "extents": [0.5, 0.3, 0.4]}, mass=2, position=[-0.4, 0.4, -0.4],
                   orientation={"axis_angle_deg": [0, 1, 0, 25]}, color=[0.25, 0.45, 0.9])
    world.add_body(name="capsule", shape={"type": "capsule", "radius": 0.1, "length": 0.5}, mass=1,
                   position=[0.5, 0.3, -0.3], orientation={"axis_angle_deg": [0, 0, 1, 90]}, color=[0.3, 0.8, 0.4])
    return world


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default=".", help="folder for camera_images.png and .npz")
    args = parser.parse_args()
    out = pathlib.Path(args.out)
    out.mkdir(parents=True, exist_ok=True)

    world = build()
    world.step(60)
    renderer = rbsim.Renderer(WIDTH, HEIGHT)
    images = renderer.render(world, depth=True, segmentation=True, axes=False,
                             camera={"eye": EYE.tolist(), "target": TARGET.tolist(), "fov_deg": 45})
    rgba, depth, seg, bodies = images["rgba"], images["depth"], images["segmentation"], images["bodies"]
    forward = (TARGET - EYE) / np.linalg.norm(TARGET - EYE)
    names = world.names
    print(f"{'row':>3} {'body':8} {'pixels':>6} {'nearest depth [m]':>18} {'expected [m]':>13}")
    for row, body in enumerate(bodies):
        mask = seg == row
        nearest = depth[mask].min() if mask.any() else np.inf
        # A ball's nearest point along the camera axis: its centre's depth minus the radius. The drawn
        # ball is a 48 x 24 polyhedron inscribed in the sphere, whose faces lie up to r (1 - cos 5.3 deg)
        # = 0.8 mm inside it, and the colour pass's polygon offset adds 3 steps of the depth buffer.
        centre = world.x[world.index_of(body)]
        expected = f"{(centre - EYE) @ forward - BALL_RADIUS:13.4f}" if names[row].startswith("ball") else ""
        print(f"{row:3d} {names[row]:8} {mask.sum():6d} {nearest:18.4f} {expected}")
    print(f"ground {np.sum(seg == -2)} pixels, sky {np.sum(seg == -1)} pixels (depth inf: {np.isinf(depth).sum()})")

    fig, axes = plt.subplots(1, 3, figsize=(18, 4.6))
    axes[0].imshow(rgba)
    axes[0].set_title("rgba")
    shown = axes[1].imshow(np.where(np.isfinite(depth), depth, np.nan), cmap="viridis", vmax=8.0)
    fig.colorbar(shown, ax=axes[1], label="depth along the camera axis [m] (sky: inf, blank)")
    axes[1].set_title("depth")
    palette = plt.get_cmap("tab10")
    colours = np.zeros((*seg.shape, 3))
    colours[seg == -1] = (1, 1, 1)
    colours[seg == -2] = (0.75, 0.75, 0.75)
    for row in range(len(bodies)):
        colours[seg == row] = palette(row)[:3]
    axes[2].imshow(colours)
    axes[2].legend(handles=[plt.Rectangle((0, 0), 1, 1, color=palette(r)) for r in range(len(bodies))],
                   labels=[f"{r}: {names[r]}" for r in range(len(bodies))], loc="upper right", fontsize=8)
    axes[2].set_title("segmentation: body row (-2 ground grey, -1 sky white)")
    for ax in axes:
        ax.axis("off")
    fig.tight_layout()
    fig.savefig(out / "camera_images.png", dpi=90)
    np.savez_compressed(out / "camera_images.npz", rgba=rgba, depth=depth, segmentation=seg)
    print("wrote", out / "camera_images.png")


if __name__ == "__main__":
    main()
