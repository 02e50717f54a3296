#!/usr/bin/env python3
"""Writes contact_solvers.json, demo 5's last phase: the stacking scenes of issue 18
(bench/stack_layout.h: a column of 20 unit boxes and a 20-row pyramid wall of 210, 1 kg,
friction 0.6, stacked touching, dt = 1/60 s, sleep off) run with the PGS and the soft-step
contact solver side by side in one video, through the scene's "compare" block (app/run/phase.h).

    python3 assets/scenes/make_contact_solvers.py
"""
import json
import os

HERE = os.path.dirname(os.path.abspath(__file__))

TIME_STEP = 1.0 / 60.0  # [s], bench/stack_layout.h kStackTimeStep
DURATION = 10.0         # [s] simulated, kStackSeconds
BOX_EDGE = 1.0          # [m], kStackBoxSize
BOX_MASS = 1.0          # [kg], kStackBoxMass
FRICTION = 0.6          # [1] static and kinetic, kStackFriction (bench: Material{0, 0.6, 0.6})
COLUMN_BOXES = 20
PYRAMID_ROWS = 20       # 20 * 21 / 2 = 210 boxes
# The column stands this far right of the pyramid's centre: 2 m clear of its bottom row [m].
COLUMN_X = 0.5 * PYRAMID_ROWS * BOX_EDGE + 2.0 + 0.5 * BOX_EDGE

COLUMN_COLOR = [0.30, 0.55, 0.90]
TOP_COLOR = [0.95, 0.85, 0.30]   # the column's top box, whose variables the panel shows
PYRAMID_BOTTOM = [0.85, 0.45, 0.20]
PYRAMID_TOP = [0.95, 0.75, 0.45]


def box(name, x, y, color):
    return {"name": name, "shape": {"type": "box", "extents": [BOX_EDGE] * 3}, "mass": BOX_MASS,
            "position": [x, y, 0], "friction_static": FRICTION, "friction_kinetic": FRICTION,
            "color": [round(c, 3) for c in color]}


def bodies():
    out = []
    for i in range(COLUMN_BOXES):  # centres at y = 0.5 + i: touching, none overlapping
        top = i == COLUMN_BOXES - 1
        out.append(box(f"stack_{i}", COLUMN_X, (0.5 + i) * BOX_EDGE, TOP_COLOR if top else COLUMN_COLOR))
    k = 0
    for r in range(PYRAMID_ROWS):  # row r holds PYRAMID_ROWS - r boxes, centred (Box3D's large_pyramid)
        count = PYRAMID_ROWS - r
        f = r / (PYRAMID_ROWS - 1)
        color = [a + f * (b - a) for a, b in zip(PYRAMID_BOTTOM, PYRAMID_TOP)]
        for i in range(count):
            out.append(box(f"pyramid_{k}", (i - 0.5 * (count - 1)) * BOX_EDGE, (0.5 + r) * BOX_EDGE, color))
            k += 1
    return out


def main():
    scene = {
        "title": "Demo 5 (c): PGS against soft step at dt = 1/60 s",
        "compare": {"key": "world.solver", "values": ["pgs", "soft-step"], "labels": ["PGS", "soft step"]},
        # Each solver's settings written out (engine/include/rbsim/settings/settings.h's defaults today), so that
        # the caption stays true if the defaults move.
        "world": {"dt": TIME_STEP, "duration": DURATION, "sleep": False, "velocity_iterations": 10,
                  "position_iterations": 4, "substeps": 8, "contact_hertz": 120},
        "view": {
            "camera": {"eye": [1.5, 11.0, 29.0], "target": [1.5, 9.5, 0.0], "fov_deg": 45},
            "size": [1280, 720], "fps": 30, "axes": False, "selected": f"stack_{COLUMN_BOXES - 1}",
            "caption": "a column of 20 and a pyramid of 210 unit boxes, sleep off. PGS: 10 sweeps, split "
                       "impulses; soft step: 8 substeps of 120 Hz soft contacts (Box2D v3)",
        },
        "planes": [{"normal": [0, 1, 0], "friction_static": FRICTION, "friction_kinetic": FRICTION}],
        "bodies": bodies(),
    }
    lines = ["{"]
    keys = [k for k in scene if k != "bodies"]
    for key in keys:
        lines.append(f" {json.dumps(key)}: {json.dumps(scene[key])},")
    lines.append(' "bodies": [')
    lines.append(",\n".join("  " + json.dumps(b) for b in scene["bodies"]))
    lines.append(" ]")
    lines.append("}")
    with open(os.path.join(HERE, "contact_solvers.json"), "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
