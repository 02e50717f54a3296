#!/usr/bin/env python3
"""Scenes that load a CSG tree at the edge of the implicit-shape budget (shapes/implicit_shape.h,
issue 37): a balanced union of N small primitives of one kind, scattered and turned at random in
a 1 m cube, at a given resolution. Timing their loads measures what a primitive evaluation and a
mesh triangle cost, which kMaxImplicitEvaluations is set from:

    python3 bench/csg_stress.py KIND N RESOLUTION > /tmp/csg.json
    /usr/bin/time -f "%e s" build/rbsim run /tmp/csg.json --no-render --quiet

KIND: spheres, tori, ellipsoids, boxes (small, many surface cells) or big (overlapping 0.4 m
spheres: few primitives, a large smooth surface). Measured (2026-11-29): 4096 ellipsoids at
resolution 16 are refused at the budget after 7.5 s, 64 tori at 100 load in 3.7 s, one big sphere
at 150 in 4.7 s; at 170 it is refused after 1.1 s (its 808,452-triangle mesh's checks)."""
import json
import random
import sys

kind, n, res = sys.argv[1], int(sys.argv[2]), int(sys.argv[3])
rng = random.Random(1)


def primitive():
    p = [rng.uniform(-0.5, 0.5) for _ in range(3)]
    turn = {"axis_angle_deg": [rng.uniform(-1, 1), rng.uniform(-1, 1), 1.0, rng.uniform(0, 180)]}
    if kind == "spheres":
        return {"type": "implicit", "function": "sphere", "radius": 0.02, "position": p}
    if kind == "tori":
        return {"type": "implicit", "function": "torus", "major_radius": 0.04, "minor_radius": 0.012,
                "position": p, "orientation": turn}
    if kind == "ellipsoids":
        return {"type": "implicit", "function": "ellipsoid", "radii": [0.05, 0.02, 0.01], "position": p,
                "orientation": turn}
    if kind == "boxes":
        return {"type": "implicit", "function": "box", "extents": [0.06, 0.02, 0.01], "position": p,
                "orientation": turn}
    if kind == "big":
        return {"type": "implicit", "function": "sphere", "radius": 0.4, "position": [x * 0.2 for x in p]}
    raise SystemExit("KIND is one of spheres, tori, ellipsoids, boxes, big")


def tree(lo, hi):
    if hi - lo == 1:
        return primitive()
    mid = (lo + hi) // 2
    return {"type": "csg", "op": "union", "a": tree(lo, mid), "b": tree(mid, hi),
            "orientation": {"axis_angle_deg": [0, 1, 0, 0.1]}}


shape = tree(0, n)
shape["resolution"] = res
print(json.dumps({"title": f"CSG stress: {n} {kind} at resolution {res}",
                  "world": {"dt": 1 / 60, "duration": 1 / 60},
                  "bodies": [{"name": "stress", "static": True, "density": 1000, "position": [0, 1, 0],
                              "shape": shape}]}))
