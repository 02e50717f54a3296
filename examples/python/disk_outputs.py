#!/usr/bin/python3
"""A World built in Python, written to disk: its scene file (World.save_scene), which loads back
into the same World (equal state hashes after 240 steps); then a run through the program's runner
(World.run) writing the CSV trace, the recording and a glTF animation, the same bytes as `rbsim run
<scene> --trace --record --gltf`; the recording read back as arrays (rbsim.read_recording) and
plotted against the trace. Writes disk_outputs.png and, beside it, disk_outputs.json, .csv,
.rbrec and .glb.

    PYTHONPATH=build/python /usr/bin/python3 examples/python/disk_outputs.py [--out DIR]
"""
import argparse
import csv
import pathlib

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np
import rbsim

STEPS = 240        # 4 s at 1/60 s
TRACE_EVERY = 6    # a trace row every 0.1 s


def build():
    world = rbsim.World(dt=1 / 60)
    world.add_plane(restitution=0.4)
    world.add_body(name="ball", shape={"type": "sphere", "radius": 0.2}, mass=1.0, position=(-1, 2, 0),
                   velocity=(0.5, 0, 0), restitution=0.4)
    world.add_body(name="rod", shape={"type": "box", "extents": (1.0, 0.08, 0.08)}, mass=1.0, position=(1.5, 2, 0))
    world.add_joint(type="hinge", body_a="rod", anchor=(1.0, 2, 0), axis=(0, 0, 1))  # a pendulum from level
    return world


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("--out", default="videos/plots", help="folder for the PNG and the files")
    out = pathlib.Path(parser.parse_args().out)
    out.mkdir(parents=True, exist_ok=True)
    files = {k: out / f"disk_outputs.{k}" for k in ("json", "csv", "rbrec", "glb")}

    world = build()
    world.save_scene(files["json"])  # before the first step: the file is this World, bit for bit
    twin = rbsim.load_scene(str(files["json"])).world()
    summary = world.run(STEPS, trace=files["csv"], trace_every=TRACE_EVERY, record=files["rbrec"], gltf=files["glb"])
    twin.step(STEPS)
    print(f"scene reloaded and stepped {STEPS} steps: hashes equal = {twin.state_hash() == world.state_hash()}")
    print(f"recording: {summary['record_bytes']} bytes; glTF: {summary['gltf_bodies']} bodies, "
          f"{summary['gltf_frames']} frames")

    rec = rbsim.read_recording(files["rbrec"])
    with open(files["csv"], newline="") as f:
        rows = [r for r in csv.DictReader(f)]
    fig, ax = plt.subplots(figsize=(9, 4.5), dpi=100)
    for i, name in enumerate(rec["names"]):
        ax.plot(rec["time"], rec["x"][:, i, 1], label=f"{name}: recording, every step")
        mine = [r for r in rows if r["body"] == name]
        ax.plot([float(r["t"]) for r in mine], [float(r["y"]) for r in mine], "o", ms=3,
                label=f"{name}: trace, every {TRACE_EVERY} steps")
    last = rec["x"][-1, rec["names"].index("ball"), 1]
    print(f"recorded steps {rec['step'][0]}..{rec['step'][-1]}; ball at y = {last:.4f} m "
          f"(World.x: {world.x[world.index_of(world.id_at(0)), 1]:.4f} m)")
    assert np.array_equal(rec["x"][-1], world.x)
    ax.set_xlabel("t [s]")
    ax.set_ylabel("height of the centre of mass [m]")
    ax.set_title("A World saved as a scene, traced and recorded from Python")
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(out / "disk_outputs.png")


if __name__ == "__main__":
    main()
