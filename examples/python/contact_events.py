#!/usr/bin/python3
"""Contact events: a ball with restitution 0.7 dropped 1 m onto a box bounces; after
each world.step(n) the ball's begin, hit and end events say when it landed and left, and how fast
it hit (hit_speed: the approach speed along the normal, which the n-th bounce brings back times
e^n; Box3D's b3World_GetContactEvents). Plots the ball's height with the events on it and prints
one line per hit. Writes contact_events.png.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/contact_events.py [--out DIR]
"""
import argparse
import math
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import rbsim

DT = 1 / 240        # [s]
DROP = 1.0          # the ball's bottom above the box's top [m]
RADIUS = 0.1        # [m]
RESTITUTION = 0.7   # [1]
CHUNK = 12          # steps per step(n) call: the events of all 12 come back together


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", default="videos/plots", help="folder for contact_events.png")
    out = pathlib.Path(parser.parse_args().out)
    out.mkdir(parents=True, exist_ok=True)

    world = rbsim.World(dt=DT, hit_event_speed=0.5)  # [m/s]: quieter landings are no hit
    world.add_body(shape={"type": "box", "extents": [2, 1, 2]}, mass=1.0, static=True, name="box")
    ball = world.add_body(shape={"type": "sphere", "radius": RADIUS}, mass=1.0, restitution=RESTITUTION,
                          position=(0, 0.5 + RADIUS + DROP, 0), name="ball")
    times, heights, marks = [], [], {"begin": [], "hit": [], "end": []}
    while world.time < 3.0:
        world.step(CHUNK)
        times.append(world.time)
        heights.append(world.x[world.index_of(ball), 1] - RADIUS - 0.5)
        events = world.contact_events()
        for kind in marks:
            for step in events[f"{kind}_step"]:
                marks[kind].append((step + 1) * DT)
        for speed, step in zip(events["hit_speed"], events["hit_step"]):
            print(f"hit at t = {(step + 1) * DT:.3f} s, approach {speed:.3f} m/s")

    first = math.sqrt(2 * 9.81 * DROP)
    print(f"first impact, free fall: {first:.3f} m/s")
    fig, ax = plt.subplots(figsize=(9, 4.5), dpi=100)
    ax.plot(times, heights, color="0.3", label="ball's bottom above the box [m]")
    for kind, style in (("begin", "g|"), ("hit", "rx"), ("end", "b|")):
        ax.plot(marks[kind], [0.0] * len(marks[kind]), style, markersize=14, label=kind)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("height [m]")
    ax.set_title(f"contact events of a ball bouncing on a box (e = {RESTITUTION}, dt = 1/240 s)")
    ax.legend()
    fig.tight_layout()
    fig.savefig(out / "contact_events.png")


if __name__ == "__main__":
    main()
