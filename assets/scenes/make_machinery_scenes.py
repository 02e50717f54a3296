#!/usr/bin/env python3
# Writes the scenes of demo 8 (issue 40: compound bodies, filters, kinematic motion), next to
# this script:
#
#   machinery_table.json   a table of five boxes, a hammer and a dumbbell (compound bodies), a
#                          turntable and a lift (kinematic motion), two balls of one group
#   machinery_washer.json  a drum of 36 staves and 4 paddles (one kinematic compound of 40 hulls)
#                          turning about its axis, tumbling 216 boxes: Box3D's washer, smaller
#   machinery_rain.json    ragdolls (the preset of eleven capsules) raining in rows onto a mesh
#                          ground (assets/meshes/terrain.obj, collided triangle by triangle), a
#                          spawner dropping a row every second and clearing it 3 s later
#
# Standard library only. Run: python3 make_machinery_scenes.py
import json
import math
import os
import sys

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "box3d"))
sys.dont_write_bytecode = True  # no __pycache__ beside the scenes
from make_box3d_scenes import num, vec, washer_drum_shapes  # noqa: E402  (the washer's drum, smaller)


def write(name, scene):
    path = os.path.join(HERE, name)
    dump = lambda o: json.dumps(o, separators=(", ", ": "))
    lists = [k for k in ("bodies", "ragdolls") if k in scene]
    lines = ["{"]
    for key, value in scene.items():
        if key not in lists:
            lines.append('  "%s": %s,' % (key, dump(value)))
    for n, key in enumerate(lists):
        lines.append('  "%s": [' % key)
        lines.append(",\n".join("    " + dump(b) for b in scene[key]))
        lines.append("  ]" + ("," if n + 1 < len(lists) else ""))
    lines.append("}")
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")
    print("wrote %s: %d bodies, %d bytes" % (name, len(scene["bodies"]), os.path.getsize(path)))


def box(extents, position, **extra):
    part = {"type": "box", "extents": vec(extents), "position": vec(position)}
    part.update(extra)
    return part


def table_scene():
    legs = [box((0.08, 0.72, 0.08), (x, 0.36, z)) for x in (-0.7, 0.7) for z in (-0.4, 0.4)]
    table = {"name": "table", "shapes": [box((1.6, 0.06, 1.0), (0, 0.75, 0))] + legs, "mass": 15,
             "position": [0, 0.62, 0], "color": [0.62, 0.42, 0.25]}
    hammer = {"name": "hammer", "mass": 1.2, "position": [0.2, 2.2, 0.1],
              "orientation": {"axis_angle_deg": [1, 0, 1, 30]}, "angular_velocity": [0, 2, 1],
              "shapes": [{"type": "capsule", "radius": 0.025, "length": 0.45, "position": [0, 0, 0],
                          "density": 700},
                         box((0.22, 0.07, 0.07), (0, 0.26, 0), density=7800)],
              "color": [0.5, 0.5, 0.55]}
    dumbbell = {"name": "dumbbell", "position": [-3.0, 0.2, 1.2], "velocity": [2.0, 0, 0],
                "angular_velocity": [0, 0, -10.0], "color": [0.3, 0.3, 0.35],
                "shapes": [{"type": "sphere", "radius": 0.2, "position": [0, 0, -0.35], "density": 7800},
                           {"type": "sphere", "radius": 0.2, "position": [0, 0, 0.35], "density": 7800},
                           {"type": "capsule", "radius": 0.04, "length": 0.5,
                            "orientation": {"axis_angle_deg": [1, 0, 0, 90]}, "density": 7800}]}
    cubes = [{"name": "cube%d" % i, "shape": {"type": "box", "extents": [0.2, 0.2, 0.2]}, "mass": 0.5,
              "position": vec((-0.45 + 0.3 * i, 1.3 + 0.25 * i, -0.2)), "color": [0.3, 0.55, 0.9]} for i in range(3)]
    turntable = {"name": "turntable", "shape": {"type": "box", "extents": [1.6, 0.1, 1.6]}, "mass": 10,
                 "kinematic": True, "position": [3.2, 0.05, 0], "color": [0.45, 0.6, 0.4],
                 "motion": {"pivot": [3.2, 0, 0], "angular_velocity": [0, 1.2, 0]}}
    rider = {"name": "rider", "shape": {"type": "box", "extents": [0.3, 0.3, 0.3]}, "mass": 1,
             "position": [3.8, 0.25, 0], "color": [0.9, 0.75, 0.3]}
    lift = {"name": "lift", "shape": {"type": "box", "extents": [1.0, 0.1, 1.0]}, "mass": 10, "kinematic": True,
            "position": [-3.0, 0.05, -1.8], "color": [0.45, 0.6, 0.4],
            "motion": {"loop": True, "keyframes": [
                {"time": 0, "position": [-3.0, 0.05, -1.8]},
                {"time": 2, "position": [-3.0, 1.5, -1.8]},
                {"time": 3, "position": [-3.0, 1.5, -1.8], "orientation": {"axis_angle_deg": [0, 1, 0, 90]}},
                {"time": 5, "position": [-3.0, 0.05, -1.8], "orientation": {"axis_angle_deg": [0, 1, 0, 90]}},
                {"time": 6, "position": [-3.0, 0.05, -1.8]}]}}
    passenger = {"name": "passenger", "shape": {"type": "box", "extents": [0.3, 0.3, 0.3]}, "mass": 1,
                 "position": [-3.0, 0.25, -1.8], "color": [0.9, 0.75, 0.3]}
    ghosts = [{"name": "ghost%d" % i, "shape": {"type": "sphere", "radius": 0.25}, "mass": 1,
               "position": [1.8, 0.3 + 1.2 * i, 1.6], "filter": {"group": -1}, "color": [0.75, 0.35, 0.75]}
              for i in range(2)]
    return {
        "title": "Compound bodies and machinery: a table of five boxes, a hammer, a dumbbell, a turntable, a lift",
        "world": {"dt": 1 / 60, "duration": 8.0},
        "view": {"camera": {"eye": [-0.3, 2.3, 4.6], "target": [-0.5, 0.5, 0], "fov_deg": 55}, "size": [1280, 720],
                 "fps": 30, "axes": False, "contacts": False,
                 "caption": "one body, many shapes: the table stands on four legs, the hammer lands on its head, "
                            "the dumbbell rolls on its balls; the turntable and the lift carry boxes by friction; "
                            "the two violet balls share a negative group and pass through each other"},
        "planes": [{"normal": [0, 1, 0], "point": [0, 0, 0]}],
        "bodies": [table, hammer, dumbbell] + cubes + [turntable, rider, lift, passenger] + ghosts,
    }


def washer_scene():
    # Box3D's CreateWasher at a quarter of its size: radii 3.5, 4, 4.5 m, 8 m deep, 36 staves of 10
    # degrees (each a tenth short at both ends) and a paddle at every ninth; a static wall closes
    # the back (Box3D's drum is open at both ends, 20 m deep for 16 m of boxes).
    r0, r1, r2, half_depth = 3.5, 4.0, 4.5, 4.0
    centre_y = 5.0
    shapes = washer_drum_shapes(r0, r1, r2, -half_depth, half_depth)
    drum = {"name": "drum", "shapes": shapes, "kinematic": True, "position": [0, centre_y, 0],
            "color": [0.6, 0.62, 0.68],
            "motion": {"pivot": [0, centre_y, 0], "angular_velocity": [0, 0, num(math.radians(45.0), 9)]}}
    wall = {"name": "back_wall", "shape": {"type": "box", "extents": [10, 10, 0.4]}, "mass": 1, "static": True,
            "position": [0, centre_y, -half_depth - 0.2], "color": [0.45, 0.47, 0.52]}
    bodies = [drum, wall]
    colors = [[0.85, 0.45, 0.25], [0.3, 0.55, 0.9], [0.5, 0.75, 0.4]]
    n, spacing = 6, 0.8
    for i in range(n):
        for j in range(n):
            for k in range(n):
                p = (-0.5 * (n - 1) * spacing + i * spacing, centre_y - 0.5 * (n - 1) * spacing + j * spacing,
                     -0.5 * (n - 1) * spacing + k * spacing)
                bodies.append({"name": "box%d" % len(bodies), "shape": {"type": "box", "extents": [0.5, 0.5, 0.5]},
                               "density": 1000, "position": vec(p), "color": colors[(i + j + k) % 3]})
    return {
        "title": "A washer: a drum of 40 hulls turning about its axis, tumbling 216 boxes",
        "world": {"dt": 1 / 60, "duration": 10.0},
        "view": {"camera": {"eye": [0, 6.0, 19.0], "target": [0, 5.0, 0], "fov_deg": 50}, "size": [1280, 720],
                 "fps": 30, "axes": False, "selected": "box100",
                 "caption": "Box3D's washer, a quarter of its size: one kinematic body of 36 staves and 4 paddles "
                            "turning at 45 degrees/s about its axis lifts the boxes and lets them fall"},
        "planes": [{"normal": [0, 1, 0], "point": [0, 0, 0]}],
        "bodies": bodies,
    }


def rain_scene():
    # Box3D's rain in miniature: a spawner drops a row of five ragdolls every second from 6 m, at a
    # depth and a turn its seeded generator draws (the row's figures turned alike, 2 m apart, more
    # than a 1.8 m figure spans however it is turned), and clears each row 3 s after it came, so
    # three rows lie on the terrain at a time.
    return {
        "title": "A ragdoll rain on a mesh ground: rows of figures of eleven capsules and ten limited joints",
        "world": {"dt": 1 / 60, "duration": 6.0},
        "view": {"camera": {"eye": [-1.0, 3.2, 6.5], "target": [-0.6, 0.4, 0], "fov_deg": 55}, "size": [1280, 720],
                 "fps": 30, "axes": False,
                 "caption": "a spawner drops a row of five figures every second and clears each row 3 s later; each "
                            "figure: capsules joined by cones and twists at the waist, neck, shoulders and hips, "
                            "hinges at the elbows and knees, with joint friction and soft springs (Box3D's "
                            "shared/human.c layout); the ground is a triangle mesh from an OBJ"},
        "kill_volume": {"min": [-20, -5, -20], "max": [20, 40, 20]},
        "bodies": [{"name": "terrain", "shape": {"type": "mesh", "file": "../meshes/terrain.obj"},
                    "collide_as": "triangles", "static": True, "mass": 100, "inertia": "cube",
                    "color": [0.45, 0.6, 0.4]}],
        "spawn": [{"name": "doll", "period": 1.0, "lifetime": 3.0, "seed": 40,
                   "ragdoll": {"joint_friction": 1.0, "joint_hertz": 1.0, "joint_damping_ratio": 0.7},
                   "region": {"min": [-0.3, 6.0, -2.5], "max": [0.3, 6.0, 2.5]},
                   "offsets": [[-4.0 + 2.0 * k, 0, 0] for k in range(5)]}],
    }


if __name__ == "__main__":
    write("machinery_table.json", table_scene())
    write("machinery_washer.json", washer_scene())
    write("machinery_rain.json", rain_scene())
