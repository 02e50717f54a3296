#!/usr/bin/env python3
"""Scenes that remove a large burst at once (issue 56, item 3): 100,000 resting boxes, and 3,000
ragdolls, each spawned in one burst and removed by its lifetime at step REMOVAL_STEP.

    python3 bench/removal_scenes.py DIR
    time rbsim run DIR/boxes_burst.json --no-render --steps 31   # the removal is step 30's
    time rbsim run DIR/boxes_burst.json --no-render --steps 30   # the same without it

The difference of the two times is the removal (and one step of nothing). World::destroyBody one
body at a time walked every contact and warm start for each: about 150 s for the boxes.
"""
import json
import os
import sys

DT = 1.0 / 60.0  # [s] the default time step
REMOVAL_STEP = 30  # the burst's lifetime in steps: long enough for the boxes to rest in contact
BOX = 0.5  # [m] box side
# [m] between box centres: 5 mm apart, within the default contact margin (10 mm), so every box
# has speculative contacts with its neighbours besides the ground's.
BOX_PITCH = 0.505
BOX_ROWS, BOX_COLUMNS = 250, 400  # 100,000 boxes, the most one burst adds (kMaxSpawnCount)
RAGDOLL_PITCH = 1.5  # [m] between figures, apart: each falls alone onto the ground
RAGDOLL_ROWS, RAGDOLL_COLUMNS = 50, 60  # 3,000 figures, 33,000 bodies


def grid(rows, columns, pitch):
    return [[(c - 0.5 * (columns - 1)) * pitch, 0.0, (r - 0.5 * (rows - 1)) * pitch]
            for r in range(rows) for c in range(columns)]


def scene(title, block):
    lifetime = REMOVAL_STEP * DT
    block.update({"name": "burst", "count": 1, "random_orientation": False, "start": 0,
                  "period": 1000, "lifetime": lifetime})
    return {"title": title, "world": {"dt": DT, "steps": REMOVAL_STEP + 1, "gravity": [0, -9.81, 0]},
            "planes": [{"normal": [0, 1, 0], "point": [0, 0, 0]}], "spawn": [block]}


def main():
    out = sys.argv[1] if len(sys.argv) > 1 else "."
    os.makedirs(out, exist_ok=True)
    boxes = scene("100,000 resting boxes removed in one burst", {
        "body": {"shape": {"type": "box", "extents": [BOX, BOX, BOX]}, "mass": 1},
        "region": {"min": [0, 0.5 * BOX, 0], "max": [0, 0.5 * BOX, 0]},
        "offsets": grid(BOX_ROWS, BOX_COLUMNS, BOX_PITCH)})
    ragdolls = scene("3,000 ragdolls removed in one burst", {
        "ragdoll": {"mass": 70},
        "region": {"min": [0, 0, 0], "max": [0, 0, 0]},
        "offsets": grid(RAGDOLL_ROWS, RAGDOLL_COLUMNS, RAGDOLL_PITCH)})
    for name, doc in (("boxes_burst.json", boxes), ("ragdolls_burst.json", ragdolls)):
        with open(os.path.join(out, name), "w") as f:
            json.dump(doc, f)


if __name__ == "__main__":
    main()
