#!/usr/bin/python3
"""What the depth and segmentation images (issue 57) add to a frame of rbsim.Renderer.render: the
best time of 40 frames with colour only, with depth, with segmentation and with both, at 640 x 360
and 1280 x 720, for 10 and 1000 boxes on the ground (the default view, no panel). OSMesa on
llvmpipe: the machine's cores rasterise, so the figures depend on what else runs (the best of 40
frames is the one least disturbed), and the CPU time of all the process's threads, which a shared
machine disturbs less (llvmpipe's rasteriser threads included). Body axes off, and the first two again with them on: then the
depth copy is made before the axes are drawn and waits for the frame so far (gl_renderer.cpp).
Writes bench/results/python_render.csv.

    PYTHONPATH=build/python /usr/bin/python3 bench/python_render_bench.py [CSV]
"""
import csv
import pathlib
import sys
import time

import rbsim

OUT = pathlib.Path(sys.argv[1] if len(sys.argv) > 1 else pathlib.Path(__file__).parent / "results" / "python_render.csv")
FRAMES = 40  # timed per case, after WARMUP
WARMUP = 3   # the first frames compile shaders and make the extra targets
CASES = {"colour": {"axes": False}, "depth": {"axes": False, "depth": True},
         "segmentation": {"axes": False, "segmentation": True}, "both": {"axes": False, "depth": True, "segmentation": True},
         "colour_axes": {"axes": True}, "depth_axes": {"axes": True, "depth": True}}


def boxes(n):
    world = rbsim.World(dt=1 / 60, gravity=[0, 0, 0])
    world.add_plane()
    side = int(round(n ** 0.5))
    for k in range(n):
        world.add_body(shape={"type": "box", "extents": [0.2, 0.2, 0.2]}, mass=1, static=True,
                       position=[0.3 * (k % side) - 0.15 * side, 0.1, 0.3 * (k // side) - 0.15 * side])
    return world


def best_ms(renderer, world):
    """Per case, the fastest of FRAMES frames; the cases take turns, so each sees the same load."""
    for keywords in CASES.values():
        for _ in range(WARMUP):
            renderer.render(world, **keywords)
    best = {f"{name}_{kind}": float("inf") for name in CASES for kind in ("ms", "cpu_ms")}
    for _ in range(FRAMES):
        for name, keywords in CASES.items():
            start, cpu = time.perf_counter(), time.process_time()
            renderer.render(world, **keywords)
            best[f"{name}_ms"] = min(best[f"{name}_ms"], 1000 * (time.perf_counter() - start))
            best[f"{name}_cpu_ms"] = min(best[f"{name}_cpu_ms"], 1000 * (time.process_time() - cpu))
    return best


def main():
    rows = []
    for width, height in ((640, 360), (1280, 720)):
        renderer = rbsim.Renderer(width, height)
        for n in (10, 1000):
            world = boxes(n)
            row = {"size": f"{width}x{height}", "bodies": n}
            row.update({name: round(ms, 2) for name, ms in best_ms(renderer, world).items()})
            rows.append(row)
            print(row, flush=True)
    OUT.parent.mkdir(parents=True, exist_ok=True)
    with open(OUT, "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0]))
        writer.writeheader()
        writer.writerows(rows)
    print("wrote", OUT)


if __name__ == "__main__":
    main()
