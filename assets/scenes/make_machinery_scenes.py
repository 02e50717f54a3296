#!/usr/bin/env python3
# Writes the scenes of demo 8 (issue 40: compound bodies, filters, kinematic motion), next to
# this script:
#
#   machinery_table.json   a table of five boxes, a hammer and a dumbbell (compound bodies), a
#                          turntable and a lift (kinematic motion), two balls of one group
#   machinery_washer.json  a drum of 36 staves and 4 paddles (one kinematic compound of 40 hulls)
#                          turning about its axis, tumbling 216 boxes: Box3D's washer, smaller
#
# Standard library only. Run: python3 make_machinery_scenes.py
import json
import math
import os

HERE = os.path.dirname(os.path.abspath(__file__))


def num(x, digits=6):
    x = round(float(x), digits)
    if x == 0.0:
        return 0
    return int(x) if x == int(x) else x


def vec(v, digits=6):
    return [num(c, digits) for c in v]


def write(name, scene):
    path = os.path.join(HERE, name)
    dump = lambda o: json.dumps(o, separators=(", ", ": "))
    lines = ["{"]
    items = [(k, v) for k, v in scene.items() if k != "bodies"]
    for key, value in items:
        lines.append('  "%s": %s,' % (key, dump(value)))
    lines.append('  "bodies": [')
    lines.append(",\n".join("    " + dump(b) for b in scene["bodies"]))
    lines.append("  ]")
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
        "view": {"camera": {"eye": [1.0, 4.2, 8.5], "target": [0.2, 0.6, 0], "fov_deg": 50}, "size": [1280, 720],
                 "fps": 30, "axes": False, "contacts": True,
                 "caption": "one body, many shapes: the table stands on four legs, the hammer lands on its head, "
                            "the dumbbell rolls on its balls; the turntable and the lift carry boxes by friction; "
                            "the two violet balls share a negative group and pass through each other"},
        "planes": [{"normal": [0, 1, 0], "point": [0, 0, 0]}],
        "bodies": [table, hammer, dumbbell] + cubes + [turntable, rider, lift, passenger] + ghosts,
    }


def hexahedron_triangles(points):
    quads = [(0, 1, 3, 2), (4, 5, 7, 6), (0, 2, 6, 4), (1, 3, 7, 5), (0, 1, 5, 4), (2, 3, 7, 6)]
    centre = [sum(p[a] for p in points) / 8.0 for a in range(3)]
    sub = lambda a, b: [a[i] - b[i] for i in range(3)]
    cross = lambda a, b: [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]
    dot = lambda a, b: sum(a[i] * b[i] for i in range(3))
    triangles = []
    for q in quads:
        for tri in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
            a, b, c = (points[i] for i in tri)
            outward = dot(cross(sub(b, a), sub(c, a)), sub(a, centre)) > 0.0
            triangles.append(list(tri) if outward else [tri[0], tri[2], tri[1]])
    return triangles


def washer_scene():
    # Box3D's CreateWasher at a quarter of its size: radii 3.5, 4, 4.5 m, 5 m deep, 36 staves of 10
    # degrees (each a tenth short at both ends) and a paddle at every ninth.
    r0, r1, r2, half_depth = 3.5, 4.0, 4.5, 2.5
    centre_y = 5.0
    angle = math.pi / 18.0
    rot = lambda v, t: [v[0] * math.cos(t) - v[1] * math.sin(t), v[0] * math.sin(t) + v[1] * math.cos(t), 0.0]
    at = lambda z, r, u: [r * u[0], r * u[1], z]
    shapes = []
    u1 = [1.0, 0.0, 0.0]
    for i in range(36):
        u2 = [1.0, 0.0, 0.0] if i == 35 else rot(u1, angle)
        for inner, outer, a1, a2, take in ((r1, r2, rot(u1, -0.1 * angle), rot(u2, 0.1 * angle), True),
                                           (r0, r1, u1, u2, i % 9 == 0)):
            if not take:
                continue
            points = [at(-half_depth, inner, a1), at(-half_depth, outer, a1), at(-half_depth, inner, a2),
                      at(-half_depth, outer, a2), at(half_depth, inner, a1), at(half_depth, outer, a1),
                      at(half_depth, inner, a2), at(half_depth, outer, a2)]
            shapes.append({"type": "hull", "vertices": [vec(p) for p in points],
                           "triangles": hexahedron_triangles(points)})
        u1 = u2
    assert len(shapes) == 40
    drum = {"name": "drum", "shapes": shapes, "kinematic": True, "position": [0, centre_y, 0],
            "color": [0.6, 0.62, 0.68],
            "motion": {"pivot": [0, centre_y, 0], "angular_velocity": [0, 0, num(math.radians(45.0), 9)]}}
    bodies = [drum]
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
        "view": {"camera": {"eye": [0, 6.0, 16.0], "target": [0, 5.0, 0], "fov_deg": 50}, "size": [1280, 720],
                 "fps": 30, "axes": False,
                 "caption": "Box3D's washer, a quarter of its size: one kinematic body of 36 staves and 4 paddles "
                            "turning at 45 degrees/s about its axis lifts the boxes and lets them fall"},
        "planes": [{"normal": [0, 1, 0], "point": [0, 0, 0]}],
        "bodies": bodies,
    }


if __name__ == "__main__":
    write("machinery_table.json", table_scene())
    write("machinery_washer.json", washer_scene())
