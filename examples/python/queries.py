#!/usr/bin/python3
"""Scene queries (issue 57): 400 boxes and balls dropped onto the ground, then a depth camera of
160 x 90 rays cast in one World.ray_cast_batch call (the GIL released), a sphere swept down onto
the pile, the bodies a box overlaps, the surface nearest a point and the bodies in a box. Writes
queries.png: the depth image, and the pile from above with what each query found.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/queries.py [--out DIR]
"""
import argparse
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import rbsim

BODIES = 400
WIDTH, HEIGHT = 160, 90  # depth image [rays]
FOV = np.radians(70.0)   # horizontal field of view [rad]


def build_pile():
    rng = np.random.default_rng(57)
    world = rbsim.World(dt=1 / 60)
    world.add_plane()
    for i in range(BODIES):
        position = (rng.uniform(-4, 4), rng.uniform(0.5, 8), rng.uniform(-4, 4))
        shape = ({"type": "sphere", "radius": 0.3} if i % 2 else {"type": "box", "extents": [0.6, 0.4, 0.5]})
        # Balls in category 2, boxes in category 1: a query's mask picks either.
        world.add_body(shape=shape, mass=1.0, position=position, filter={"category": 2 if i % 2 else 1})
    world.step(240)  # 4 s: the pile settles, much of it asleep
    return world


def depth_image(world):
    """One ray per pixel from a camera at (0, 4, 10) looking at the pile's centre."""
    eye = np.array([0.0, 4.0, 10.0])
    forward = -np.array([0.0, 3.0, 10.0]) / np.linalg.norm([0.0, 3.0, 10.0])
    right = np.cross(forward, [0.0, 1.0, 0.0])
    right /= np.linalg.norm(right)
    up = np.cross(right, forward)
    half = np.tan(FOV / 2)
    u, v = np.meshgrid(np.linspace(-half, half, WIDTH), np.linspace(half, -half, HEIGHT) * HEIGHT / WIDTH)
    directions = forward + u[..., None] * right + v[..., None] * up
    origins = np.broadcast_to(eye, directions.shape)
    hits = world.ray_cast_batch(origins.reshape(-1, 3), directions.reshape(-1, 3), max_distance=30.0)
    return hits["distance"].reshape(HEIGHT, WIDTH), hits


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=pathlib.Path, default=pathlib.Path("."))
    out = parser.parse_args().out
    out.mkdir(parents=True, exist_ok=True)
    world = build_pile()
    depth, hits = depth_image(world)
    print(f"depth image: {hits['hit'].sum()} of {hits['hit'].size} rays hit, "
          f"{(hits['body'] >= 0).sum()} on bodies, {(hits['plane'] >= 0).sum()} on the ground")

    drop = world.shape_cast({"type": "sphere", "radius": 0.5}, (0, 12, 0), (0, -1, 0))
    print(f"a ball of radius 0.5 dropped from y = 12 lands after {drop['distance']:.3f} m, on "
          f"{'the ground' if drop['body'] is None else 'body ' + str(world.index_of(drop['body']))}")
    balls = world.overlap({"type": "box", "extents": [3, 2, 3]}, (0, 1, 0), mask=2)
    print(f"a 3 x 2 x 3 m box at the centre overlaps {len(balls)} balls")
    near = world.closest_point((5, 1, 5), planes=False)
    print(f"the body surface nearest (5, 1, 5) is {near['distance']:.3f} m away at "
          f"({near['point'][0]:.2f}, {near['point'][1]:.2f}, {near['point'][2]:.2f})")
    in_box = world.query_aabb((-1, 0, -1), (1, 10, 1))
    print(f"{len(in_box)} bodies' boxes reach into the column |x|, |z| < 1")

    x = world.state()["x"]
    fig, (left, right) = plt.subplots(1, 2, figsize=(13, 5))
    shown = left.imshow(np.where(np.isfinite(depth), depth, np.nan), cmap="viridis")
    fig.colorbar(shown, ax=left, label="distance [m]")
    left.set_title(f"depth image: {WIDTH} x {HEIGHT} rays, one ray_cast_batch call")
    left.axis("off")
    right.scatter(x[:, 0], x[:, 2], s=6, c="0.7", label="bodies")
    overlapped = [world.index_of(b["body"]) for b in balls]
    right.scatter(x[overlapped, 0], x[overlapped, 2], s=12, c="tab:orange", label="balls the box overlaps")
    column = [world.index_of(b) for b in in_box]
    right.scatter(x[column, 0], x[column, 2], s=12, c="tab:blue", marker="s", label="boxes reaching the column")
    right.plot([near["point"][0], 5], [near["point"][2], 5], "k-", label="nearest surface to (5, 1, 5)")
    right.set_aspect("equal")
    right.set_xlabel("x [m]")
    right.set_ylabel("z [m]")
    right.set_title("the pile from above")
    right.legend(loc="upper left", fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "queries.png", dpi=100)


if __name__ == "__main__":
    main()
