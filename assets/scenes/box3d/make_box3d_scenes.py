#!/usr/bin/env python3
# Writes Box3D's eleven benchmark scenes (benchmark/main.c) as rbsim scene files, next to this script:
#
#   large_pyramid.json    CreateLargePyramid: a 2D pyramid of 100 rows, 5050 unit cubes
#   many_pyramids.json    CreateManyPyramids + CreateSmallPyramid: 14 x 14 pyramids of 10 rows, 10780 cubes
#   joint_grid.json       CreateJointGrid: 100 x 100 spheres joined by ball joints, top row static
#   convex_pile.json      CreateConvexPile: 8 x 8 x 80 copies of one 32-point hull (+ convex_pile_hull.obj)
#   washer.json           CreateWasher: a kinematic drum of 40 hulls turning, 20 x 20 x 20 cubes inside
#   rain.json             CreateRain + StepRain: 10 x 10 cells of a grid mesh and a torus mesh (+ rain_cell.obj),
#                         a column of 10 groups of 3 ragdolls dropped at the benchmark's steps, the
#                         oldest column cleared and dropped again once all ten have fallen
#   junkyard.json         CreateJunkyard + StepJunkyard: 10584 rock hulls (+ junkyard_rock.obj) dropped into a
#                         walled yard, a kinematic prism (+ junkyard_pusher.obj) going round it on keyframes
#   large_world.json      CreateLargeWorld + StepLargeWorld: a 10 km floor of static boxes (coarser than Box3D's,
#                         see there), 100 spheres dropped one every 5 steps by spawners
#   trees100.json, trees50.json, trees25.json
#                         CreateTrees(1, 2, 4): 50 trees of 22 hexagonal prisms toppling onto a wave mesh of
#                         1, 0.5, 0.25 m cells (+ trees<N>_ground.obj: the mesh, or a strip of it)
#
# Layouts follow Box3D (github.com/erincatto/box3d) at commit
# 30c67b5e6d0a3a66f0f506c69ce9e9e0587e3b7c, shared/benchmarks.c: CreateLargePyramid,
# CreateSmallPyramid, CreateManyPyramids, CreateJointGrid, CreateConvexPile (its point generator
# NextConvexPileRandom, ConvexPileRandomFloat, UnitRandomPoint, emulated here in float32), with the
# release sizes (BENCHMARK_DEBUG == 0). dt = 1/60 s, gravity -10 m/s^2 and friction 0.6 are
# Box3D's (benchmark/main.c, src/types.c); the solver runs with rbsim's own defaults (Box3D's are
# 4 substeps and 30 Hz contacts: --set world.substeps=4 --set world.contact_hertz=30), density
# 1000 unless the benchmark sets its own, and each file runs the benchmark's step count.
#
# What rbsim's format cannot say the same way (see also the "caption" of each file, and the notes
# above junkyard(), large_world() and trees() for those scenes):
#  - Box3D's ground is a static box whose top face is y = 0; here it is the plane y = 0 (infinite).
#  - A body's "position" in rbsim is its centre of mass: the hull's bodies are placed at Box3D's
#    body origin plus the hull's centre of mass (the OBJ keeps Box3D's points as they are).
#  - Joint grid: Box3D's filter (category 2, mask ~2) keeps every sphere from touching every
#    other, and there is nothing else in that world, so collisions are off ("collisions": false).
#    Box3D also joins the static top row's neighbours to each other (99 joints between two static
#    bodies, which do nothing); rbsim wants a dynamic body_a, so those are left out.
#  - Rain: Box3D's human (shared/human.c) has 14 bones (three spine pieces and a neck); rbsim's
#    ragdoll preset (world/ragdoll.h) has 11, so the scene has 3300 bodies where Box3D has 4200.
#    Box3D's per-bone joint friction (5 N m x 1, 0.8 at the neck, 0.4 at the head), its rolling
#    resistance 0.2 and the negative filter group that keeps a group's torsos and thighs apart are
#    not in the preset: every joint has 5 N m.
#  - Box3D's sleep test is |v| + |omega| * extent < 0.05 m/s for 0.5 s; rbsim tests |v| and |omega|
#    apart, so the convex pile asks for 0.05 m/s and 0.05 / 2 rad/s (the hull's radius is 2 m).
#
# Standard library only. Run: python3 make_box3d_scenes.py
import itertools
import json
import math
import os
import struct

HERE = os.path.dirname(os.path.abspath(__file__))
BOX3D_COMMIT = "30c67b5e6d0a3a66f0f506c69ce9e9e0587e3b7c"
FRICTION = 0.6  # b3DefaultSurfaceMaterial: one Coulomb coefficient, so mu_s = mu_k


def f32(x):
    """x rounded to the nearest float32 (every Box3D value is a float)."""
    return struct.unpack("<f", struct.pack("<f", x))[0]


def num(x, digits=6):
    """A short JSON number: an int when whole, else rounded to `digits` decimals."""
    x = round(float(x), digits)
    if x == 0.0:
        return 0
    return int(x) if x == int(x) else x


def vec(v, digits=6):
    return [num(c, digits) for c in v]


def world_block(steps, sleep, **extra):
    w = {"gravity": [0, -10, 0], "dt": 1.0 / 60.0, "steps": steps,
         "sleep": sleep}
    w.update(extra)
    return w


# rbsim's renderer clips at a fixed far plane 200 m deep (app/render/frame_data.h, Camera::farPlane;
# no scene key sets it): every camera below keeps the scene within 190 m of depth, widening fov_deg
# where 45 degrees would need a farther eye. The convex pile's 320 m column cannot fit (see there).
def view_block(eye, target, caption, fov=45, **extra):
    v = {"camera": {"eye": eye, "target": target, "fov_deg": fov}, "size": [1280, 720], "fps": 60,
         "axes": False, "overlay": False, "caption": caption}
    v.update(extra)
    return v


def ground_plane():
    return {"normal": [0, 1, 0], "point": [0, 0, 0], "friction_static": FRICTION, "friction_kinetic": FRICTION}


def write_scene(name, head, bodies, joints=None):
    """One key per line for the head, one body (and one joint) per line."""
    dump = lambda o: json.dumps(o, separators=(", ", ": "))
    lines = ["{"]
    for key, value in head.items():
        lines.append('  "%s": %s,' % (key, dump(value)))
    lines.append('  "bodies": [')
    lines.append(",\n".join("    " + dump(b) for b in bodies))
    if joints:
        lines.append("  ],")
        lines.append('  "joints": [')
        lines.append(",\n".join("    " + dump(j) for j in joints))
    lines.append("  ]")
    lines.append("}")
    path = os.path.join(HERE, name)
    with open(path, "w") as out:
        out.write("\n".join(lines) + "\n")
    print("wrote %s: %d bodies, %d joints, %d bytes" % (name, len(bodies), len(joints or []), os.path.getsize(path)))


def cube(position, color=None):
    b = {"shape": {"type": "box", "extents": [1, 1, 1]}, "density": 100,
         "friction_static": FRICTION, "friction_kinetic": FRICTION, "position": vec(position)}
    if color:
        b["color"] = color
    return b


ROW_COLORS = [[0.85, 0.45, 0.25], [0.3, 0.55, 0.9]]


# ---------------------------------------------------------------------------------------------
# CreateLargePyramid: baseCount = 100, h = 0.5, shift = h; density 100; sleep off.
def large_pyramid():
    base_count, h = 100, 0.5
    shift = 1.0 * h
    bodies = []
    for i in range(base_count):
        y = (2.0 * i + 1.0) * shift
        for j in range(i, base_count):
            x = (i + 1.0) * shift + 2.0 * (j - i) * shift - h * base_count
            bodies.append(cube((x, y, 0.0), ROW_COLORS[i % 2]))
    assert len(bodies) == 5050
    head = {
        "title": "Box3D benchmark large_pyramid: a pyramid of 100 rows, 5050 unit cubes",
        "world": world_block(200, False),
        "view": view_block([30, 55, 150], [0, 48, 0],
                           "Box3D %s shared/benchmarks.c CreateLargePyramid (baseCount 100): 5050 cubes of half "
                           "extent 0.5, density 100, friction 0.6, dt 1/60 s, sleep off, 200 steps; "
                           "ground: the plane y = 0 (Box3D: a static box 800 x 2 x 800 m, top at y = 0)" % BOX3D_COMMIT[:7]),
        "planes": [ground_plane()],
    }
    write_scene("large_pyramid.json", head, bodies)


# ---------------------------------------------------------------------------------------------
# CreateManyPyramids: baseCount 10, extent 0.5, 14 x 14; each CreateSmallPyramid; density 100;
# bodyDef.enableSleep = false on every cube (sleep off).
def many_pyramids():
    base_count, extent, row_count, column_count = 10, f32(0.5), 14, 14
    ground_extent = f32(extent * column_count * (base_count + 1.0))  # 77
    base_width = f32(2.0 * extent * base_count)                      # 10
    base_z = f32(-ground_extent + 2.0 * extent)                      # -76
    delta_z = f32(f32(2.0 * f32(ground_extent - 2.0 * extent)) / f32(row_count - 1.0))  # 152 / 13 in float32
    bodies = []
    for i in range(row_count):
        for j in range(column_count):
            center_x = f32(-ground_extent + j * (base_width + 2.0 * extent) + 2.0 * extent)
            # CreateSmallPyramid( worldId, baseCount, extent, centerX, baseZ )
            for r in range(base_count):
                y = (2.0 * r + 1.0) * extent
                for c in range(r, base_count):
                    x = (r + 1.0) * extent + 2.0 * (c - r) * extent + center_x - 0.5
                    bodies.append(cube((x, y, base_z), ROW_COLORS[(i + j) % 2]))
        base_z = f32(base_z + delta_z)  # Box3D accumulates baseZ += deltaZ in float
    assert len(bodies) == 10780
    head = {
        "title": "Box3D benchmark many_pyramids: 14 x 14 pyramids of 10 rows, 10780 unit cubes",
        "world": world_block(100, False),
        "view": view_block([0, 120, 85], [0, 0, 20],
                           "Box3D %s shared/benchmarks.c CreateManyPyramids (14 x 14 CreateSmallPyramid, baseCount 10): "
                           "10780 cubes of half extent 0.5, density 100, friction 0.6, dt 1/60 s, "
                           "sleep off, 100 steps; ground: the plane y = 0 (Box3D: a static box 154 x 2 x 154 m, "
                           "top at y = 0)" % BOX3D_COMMIT[:7], fov=60),
        "planes": [ground_plane()],
    }
    write_scene("many_pyramids.json", head, bodies)


# ---------------------------------------------------------------------------------------------
# CreateJointGrid: n = 100; spheres of radius 0.4, density 1000 (b3DefaultShapeDef); body (k, i)
# at (k, -i, 0), static when i == 0; a spherical joint to the body above (local anchors
# (0, -0.5, 0) on it, (0, 0.5, 0) on this one) and to the body on the left ((0.5, 0, 0) on it,
# (-0.5, 0, 0) on this one). Both local anchors meet at one world point, rbsim's "anchor".
def joint_grid():
    n = 100
    name = lambda k, i: "s%d_%d" % (k, i)
    bodies, joints = [], []
    skipped = 0
    for k in range(n):
        for i in range(n):
            b = {"name": name(k, i), "shape": {"type": "sphere", "radius": 0.4}, "density": 1000,
                 "friction_static": FRICTION, "friction_kinetic": FRICTION, "position": vec((k, -i, 0))}
            if i == 0:
                b["static"] = True
                b["color"] = [0.45, 0.45, 0.5]
            bodies.append(b)
            if i > 0:
                # body A = (k, i - 1), body B = (k, i): A's (0,-0.5,0) and B's (0,0.5,0) meet here.
                anchor_a = (k + 0.0, -(i - 1) - 0.5, 0.0)
                anchor_b = (k + 0.0, -i + 0.5, 0.0)
                assert anchor_a == anchor_b
                # rbsim's body_a must be dynamic: this body (i > 0) is; Box3D's A (the one above) may be static.
                joints.append({"type": "ball", "body_a": name(k, i), "body_b": name(k, i - 1), "anchor": vec(anchor_b)})
            if k > 0:
                anchor_a = (k - 1 + 0.5, -i + 0.0, 0.0)
                anchor_b = (k - 0.5, -i + 0.0, 0.0)
                assert anchor_a == anchor_b
                if i == 0:
                    skipped += 1  # between two static bodies: does nothing in Box3D, refused by rbsim
                else:
                    joints.append({"type": "ball", "body_a": name(k, i), "body_b": name(k - 1, i), "anchor": vec(anchor_b)})
    assert len(bodies) == n * n and len(joints) + skipped == 2 * n * (n - 1) and skipped == n - 1
    head = {
        "title": "Box3D benchmark joint_grid: 100 x 100 spheres joined by 19701 ball joints",
        # Box3D's filter (category 2, mask ~2) stops every sphere-sphere contact, and the world has
        # nothing else: no contact can occur, so collision detection is off.
        "world": world_block(100, False, collisions=False),
        "view": view_block([49.5, -45, 135], [49.5, -50, 0],
                           "Box3D %s shared/benchmarks.c CreateJointGrid (n = 100): spheres r = 0.4 at (k, -i, 0), "
                           "density 1000, row i = 0 static, ball joints up and left (the 99 joints between two static "
                           "bodies left out), no contacts (Box3D filters them all), dt 1/60 s, sleep off, "
                           "100 steps" % BOX3D_COMMIT[:7], grid=False),
    }
    write_scene("joint_grid.json", head, bodies, joints)


# ---------------------------------------------------------------------------------------------
# CreateConvexPile: the hull of 32 points of PEEL's BasicRandom (seed 42) on a sphere of radius 2,
# 8 x 8 x 80 bodies, default shape (density 1000, friction 0.6), sleep on.
def convex_pile_points(point_count=32, amplitude=2.0, seed=42):
    state = [seed]

    def next_random():  # NextConvexPileRandom: unsigned 32-bit LCG
        state[0] = (state[0] * 2147001325 + 715136305) & 0xFFFFFFFF
        return state[0]

    def random_float():  # ConvexPileRandomFloat: in [-0.5, 0.5]
        return f32(f32((next_random() & 0xFFFF) / 65535.0) - 0.5)

    def unit_random_point():  # UnitRandomPoint: rejection sampled, then b3Normalize
        while True:
            p = [random_float(), random_float(), random_float()]
            length_sq = f32(f32(f32(p[0] * p[0]) + f32(p[1] * p[1])) + f32(p[2] * p[2]))  # b3Dot
            if not length_sq > 0.25:
                break
        s = f32(1.0 / f32(math.sqrt(length_sq)))
        return [f32(s * c) for c in p]

    return [[f32(amplitude * c) for c in unit_random_point()] for _ in range(point_count)]


def sub(a, b):
    return [a[0] - b[0], a[1] - b[1], a[2] - b[2]]


def cross(a, b):
    return [a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]]


def dot(a, b):
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]


def convex_hull(points):
    """Triangles (i, j, k), wound counter-clockwise seen from outside, of the convex hull of
    points in general position (no four on a plane): a triple is a face when every other point
    lies strictly on one side of its plane. O(n^4), instant for 32 points."""
    n = len(points)
    size = max(max(abs(c) for c in p) for p in points)
    eps = 1e-9 * size
    faces = []
    for i, j, k in itertools.combinations(range(n), 3):
        normal = cross(sub(points[j], points[i]), sub(points[k], points[i]))
        length = math.sqrt(dot(normal, normal))
        sides = [dot(normal, sub(points[m], points[i])) / length for m in range(n) if m not in (i, j, k)]
        if all(s < -eps for s in sides):
            faces.append((i, j, k))
        elif all(s > eps for s in sides):
            faces.append((i, k, j))
        else:
            assert not (all(s <= eps for s in sides) or all(s >= -eps for s in sides)), \
                "four points on one face plane: this hull needs a general hull builder"
    return faces


def volume_and_centroid(points, faces):
    volume, moment = 0.0, [0.0, 0.0, 0.0]
    for i, j, k in faces:
        a, b, c = points[i], points[j], points[k]
        v = dot(a, cross(b, c)) / 6.0  # tetrahedron (origin, a, b, c)
        volume += v
        for axis in range(3):
            moment[axis] += v * (a[axis] + b[axis] + c[axis]) / 4.0
    return volume, [m / volume for m in moment]


def convex_pile():
    points = convex_pile_points()
    faces = convex_hull(points)
    used = sorted({v for f in faces for v in f})
    assert used == list(range(32)) and len(faces) == 2 * 32 - 4, (len(used), len(faces))
    volume, centroid = volume_and_centroid(points, faces)
    assert volume > 0.0

    obj = os.path.join(HERE, "convex_pile_hull.obj")
    with open(obj, "w") as out:
        out.write("# Box3D %s shared/benchmarks.c CreateConvexPile: the convex hull of 32 points on a\n"
                  "# sphere of radius 2 (PEEL's BasicRandom, seed 42), as Box3D computes them in float32\n"
                  "# (printed with 9 digits: exact). %d triangles, wound outward; volume %.6f m^3, centre of\n"
                  "# mass (%.6f, %.6f, %.6f). Written by make_box3d_scenes.py.\n"
                  % (BOX3D_COMMIT[:7], len(faces), volume, *centroid))
        for p in points:
            out.write("v %.9g %.9g %.9g\n" % tuple(p))
        for f in faces:
            out.write("f %d %d %d\n" % (f[0] + 1, f[1] + 1, f[2] + 1))
    print("wrote convex_pile_hull.obj: %d vertices, %d triangles, volume %.6f, centre of mass %s"
          % (len(points), len(faces), volume, vec(centroid)))

    count_x, count_z, layers, amplitude = 8, 8, 80, 2.0
    scatter = 2.0 * amplitude
    bodies = []
    colors = [[0.85, 0.55, 0.25], [0.35, 0.6, 0.85], [0.5, 0.75, 0.4]]
    for layer in range(layers):
        for z in range(count_z):
            for x in range(count_x):
                origin = ((x - 0.5 * count_x) * scatter, amplitude + 2.0 * amplitude * layer, (z - 0.5 * count_z) * scatter)
                # rbsim places the centre of mass: Box3D's body origin plus the hull's centroid.
                com = [origin[a] + centroid[a] for a in range(3)]
                bodies.append({"shape": {"type": "mesh", "file": "convex_pile_hull.obj"}, "density": 1000,
                               "friction_static": FRICTION, "friction_kinetic": FRICTION, "position": vec(com),
                               "color": colors[layer % 3]})
    assert len(bodies) == 5120
    head = {
        "title": "Box3D benchmark convex_pile: 5120 copies of a 32-point hull falling into a pile",
        "world": world_block(500, True, sleep_linear_speed=0.05, sleep_angular_speed=0.025, time_to_sleep=0.5),
        "view": view_block([120, 70, 120], [-2, 72, -2],
                           "Box3D %s shared/benchmarks.c CreateConvexPile: 8 x 8 x 80 hulls of 32 points on a sphere "
                           "of radius 2 (convex_pile_hull.obj), spaced 4 m, density 1000, friction 0.6, dt 1/60 s, "
                           "sleep on, 500 steps; ground: the plane y = 0 (Box3D: a static box "
                           "500 x 2 x 500 m, top at y = 0); the camera frames the column's lowest 150 m, where the pile "
                           "forms (the renderer's 200 m far plane cannot hold the whole 320 m column)" % BOX3D_COMMIT[:7],
                           fov=60),
        "planes": [ground_plane()],
    }
    write_scene("convex_pile.json", head, bodies)
    return points, faces, centroid


# ---------------------------------------------------------------------------------------------
# CreateWasher: a kinematic drum at (0, 21, 0) turning at 25 degrees/s about z, made of 36 staves
# (hexahedra between radii 16 and 18 m, z from -10 to 10, each a tenth of its 10 degrees short at
# both ends) and 4 paddles (radii 14 to 16, at staves 0, 9, 18, 27): one compound body of 40
# hulls. Inside, 20 x 20 x 20 cubes of half extent 0.2 spaced 0.8 m. Box3D also gives the drum a
# drift of (0.001, -0.002, 0) m/s; here it turns about its axis through (0, 21, 0) and nothing
# else ("motion": "pivot").
def hexahedron_triangles(points):
    """Outward-wound triangles of a hexahedron whose points are Box3D's p1..p8 order: (near, r_in,
    a1), (near, r_out, a1), (near, r_in, a2), (near, r_out, a2), then the same on the far side."""
    quads = [(0, 1, 3, 2), (4, 5, 7, 6), (0, 2, 6, 4), (1, 3, 7, 5), (0, 1, 5, 4), (2, 3, 7, 6)]
    centre = [sum(p[a] for p in points) / 8.0 for a in range(3)]
    triangles = []
    for q in quads:
        for tri in ((q[0], q[1], q[2]), (q[0], q[2], q[3])):
            a, b, c = (points[i] for i in tri)
            outward = dot(cross(sub(b, a), sub(c, a)), sub(a, centre)) > 0.0
            triangles.append(list(tri) if outward else [tri[0], tri[2], tri[1]])
    return triangles


def washer_drum_shapes(r0, r1, r2, near, far, **material):
    """The drum's 40 hulls: 36 staves between r1 and r2, each a tenth of its 10 degrees short at
    both ends, and a paddle between r0 and r1 at every ninth, from z = near to far."""
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
            points = [at(near, inner, a1), at(near, outer, a1), at(near, inner, a2), at(near, outer, a2),
                      at(far, inner, a1), at(far, outer, a1), at(far, inner, a2), at(far, outer, a2)]
            shape = {"type": "hull", "vertices": [vec(p) for p in points], "triangles": hexahedron_triangles(points)}
            shape.update(material)
            shapes.append(shape)
        u1 = u2
    assert len(shapes) == 40
    return shapes


def washer():
    speed = math.radians(25.0)
    shapes = washer_drum_shapes(14.0, 16.0, 18.0, -10.0, 10.0, friction_static=FRICTION, friction_kinetic=FRICTION)
    drum = {"name": "drum", "shapes": shapes, "kinematic": True, "position": [0, 21, 0], "color": [0.6, 0.6, 0.65],
            "motion": {"pivot": [0, 21, 0], "angular_velocity": [0, 0, num(speed, 9)]}}
    grid, a = 20, 0.2
    bodies = [drum]
    x = -2.0 * a * grid
    for i in range(grid):
        y = -2.0 * a * grid + 21.0
        for j in range(grid):
            z = -2.0 * a * grid
            for k in range(grid):
                bodies.append({"shape": {"type": "box", "extents": [2 * a, 2 * a, 2 * a]}, "density": 1000,
                               "friction_static": FRICTION, "friction_kinetic": FRICTION, "position": vec((x, y, z)),
                               "color": ROW_COLORS[(i + j + k) % 2]})
                z += 4.0 * a
            y += 4.0 * a
        x += 4.0 * a
    assert len(bodies) == 8001
    head = {
        "title": "Box3D benchmark washer: a drum of 40 hulls turning, tumbling 8000 cubes",
        "world": world_block(1000, True),
        "view": view_block([0, 24, 75], [0, 19, 0],
                           "Box3D %s shared/benchmarks.c CreateWasher: a kinematic drum of 36 staves and 4 paddles "
                           "(40 hulls, one compound body) turning at 25 degrees/s about its axis; 20 x 20 x 20 cubes "
                           "of half extent 0.2, density 1000, friction 0.6, dt 1/60 s, sleep on, 1000 steps; ground: "
                           "the plane y = 0 (Box3D: a static box 120 x 2 x 120 m, top at y = 0)" % BOX3D_COMMIT[:7]),
        "planes": [ground_plane()],
    }
    write_scene("washer.json", head, bodies)


# ---------------------------------------------------------------------------------------------
# CreateRain, StepRain (release: RAIN_GRID_COUNT 10, RAIN_GROUP_SIZE 3, RAIN_GRID_SIZE 15): a
# static body per cell holding b3CreateGridMesh(8, 8, 1.875) and b3CreateTorusMesh(16, 16, 3.75, 1)
# (the torus stands in the x-y plane, half of it under the grid); StepRain runs before the step
# whose index has (index & 0x2F) == 0, that is at steps 0, 16, 64, 80, 128, ... (two in every 64),
# and each time creates the next column's ten groups of three humans, 20 m up, 0.75 m apart in x;
# from the eleventh time on it destroys the oldest column and creates it again. So column c falls
# at step 64 (c // 2) + 16 (c % 2) and again every 320 steps: a spawner per column with that start,
# a period of 320 steps and a lifetime of 320 steps.
RAIN_GRID_SIZE = 15.0
RAIN_GRID_COUNT = 10
RAIN_GROUP_SIZE = 3
RAIN_STEPS = 400


def rain_cell_mesh():
    """Box3D's grid mesh and torus mesh of one cell, as vertices and outward-wound triangles."""
    vertices, triangles = [], []
    rows, width = 8, RAIN_GRID_SIZE / 8.0
    for ix in range(rows + 1):
        for iz in range(rows + 1):
            vertices.append((-0.5 * RAIN_GRID_SIZE + width * ix, 0.0, -0.5 * RAIN_GRID_SIZE + width * iz))
    for ix in range(rows):
        for iz in range(rows):
            a, b = ix * (rows + 1) + iz, (ix + 1) * (rows + 1) + iz
            triangles += [(a, a + 1, b), (b, a + 1, b + 1)]  # facing +y
    base = len(vertices)
    radial, tubular, radius, thickness = 16, 16, 0.25 * RAIN_GRID_SIZE, 1.0
    for r in range(radial):
        for t in range(tubular):
            u, v = 2.0 * math.pi * t / tubular, 2.0 * math.pi * r / radial
            vertices.append(((radius + thickness * math.cos(v)) * math.cos(u),
                             (radius + thickness * math.cos(v)) * math.sin(u), thickness * math.sin(v)))
    for r1 in range(radial):
        r2 = (r1 + 1) % radial
        for t1 in range(tubular):
            t2 = (t1 + 1) % tubular
            i1, i2, i3, i4 = (base + r1 * tubular + t1, base + r1 * tubular + t2, base + r2 * tubular + t2,
                              base + r2 * tubular + t1)
            triangles += [(i1, i2, i3), (i3, i4, i1)]
    # Box3D's torus winding, checked outward here: each triangle's normal points away from the tube's
    # centre line (the point of the ring nearest the triangle's centroid).
    def outward(tri):
        p = [vertices[i] for i in tri]
        n = cross(sub(p[1], p[0]), sub(p[2], p[0]))
        c = [sum(q[k] for q in p) / 3.0 for k in range(3)]
        ring = math.hypot(c[0], c[1])
        centre = (radius * c[0] / ring, radius * c[1] / ring, 0.0)
        return dot(n, sub(c, centre)) > 0.0
    torus = triangles[2 * rows * rows:]
    if not all(outward(t) for t in torus):
        assert not any(outward(t) for t in torus)
        triangles[2 * rows * rows:] = [(a, c, b) for a, b, c in torus]
    return vertices, triangles


def rain():
    vertices, triangles = rain_cell_mesh()
    with open(os.path.join(HERE, "rain_cell.obj"), "w") as out:
        out.write("# Box3D %s CreateRain's cell: b3CreateGridMesh(8, 8, 1.875) and b3CreateTorusMesh(16, 16, 3.75, 1)"
                  " (make_box3d_scenes.py)\n" % BOX3D_COMMIT[:7])
        out.writelines("v %s %s %s\n" % tuple(repr(num(c, 9)) for c in v) for v in vertices)
        out.writelines("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in triangles)
    span = RAIN_GRID_SIZE * RAIN_GRID_COUNT
    bodies = []
    for i in range(RAIN_GRID_COUNT):
        for j in range(RAIN_GRID_COUNT):
            centre = (-0.5 * span + RAIN_GRID_SIZE * (i + 0.5), 0.0, -0.5 * span + RAIN_GRID_SIZE * (j + 0.5))
            bodies.append({"name": "cell_%d_%d" % (i, j), "shape": {"type": "mesh", "file": "rain_cell.obj"},
                           "collide_as": "triangles", "static": True, "mass": 1, "inertia": "cube",
                           "position": vec(centre), "friction_static": FRICTION, "friction_kinetic": FRICTION,
                           "color": [0.55, 0.6, 0.55]})
    dt = 1.0 / 60.0
    cycle = 10 * 32  # steps between two drops of one column
    spawn = []
    for column in range(RAIN_GRID_COUNT):
        first = 64 * (column // 2) + 16 * (column % 2)
        assert first & 0x2F == 0
        x = -0.5 * span + RAIN_GRID_SIZE * (column + 0.5)
        offsets = [[num(0.75 * k), 0, num(-0.5 * span + RAIN_GRID_SIZE * (row + 0.5))]
                   for row in range(RAIN_GRID_COUNT) for k in range(RAIN_GROUP_SIZE)]
        spawn.append({"name": "column%d" % column, "ragdoll": {"mass": 70, "joint_friction": 5, "joint_hertz": 1,
                                                               "joint_damping_ratio": 0.7},
                      "region": {"min": [num(x), 20, 0], "max": [num(x), 20, 0]}, "random_orientation": False,
                      "offsets": offsets, "start": num(first * dt, 12), "period": num(cycle * dt, 12),
                      "lifetime": num(cycle * dt, 12)})
    head = {
        "title": "Box3D benchmark rain: columns of ragdoll groups falling on 100 cells of grid and torus meshes",
        "world": world_block(RAIN_STEPS, True),
        "view": view_block([0, 45, 100], [0, 0, -10],
                           "Box3D %s shared/benchmarks.c CreateRain, StepRain: 10 x 10 static cells of a grid mesh "
                           "and a torus mesh (collided triangle by triangle); at steps 0, 16, 64, 80, ... a column of "
                           "10 groups of 3 ragdolls (rbsim's 11-capsule preset, 70 kg, joint friction 5 N m, springs "
                           "1 Hz, damping ratio 0.7) drops from 20 m; once all ten columns are down the oldest is "
                           "cleared and dropped again; dt 1/60 s, sleep on, 400 steps" % BOX3D_COMMIT[:7], fov=60,
                           grid=False),
        "spawn": spawn,
    }
    write_scene("rain.json", head, bodies)


# ---------------------------------------------------------------------------------------------
# Box3D's float32 trigonometry, for the points its creators compute: b3ComputeCosSin (a rational
# approximation of cos and sin after b3UnwindAngle, normalised; src/math_functions.c), which
# b3Sin, b3Cos, b3CreateCylinder, b3CreateRock and b3CreateWaveMesh all use.
B3_PI = f32(3.14159265359)


def b3_cos_sin(radians):
    x = f32(math.remainder(f32(radians), f32(2.0 * B3_PI)))  # b3UnwindAngle: remainderf, exact
    pi2 = f32(B3_PI * B3_PI)
    if x < f32(0.5 * B3_PI) * -1.0 or x > f32(0.5 * B3_PI):
        y = f32(x + B3_PI) if x < 0.0 else f32(x - B3_PI)
        y2 = f32(y * y)
        c = -f32(f32(pi2 - f32(4.0 * y2)) / f32(pi2 + y2))
    else:
        y2 = f32(x * x)
        c = f32(f32(pi2 - f32(4.0 * y2)) / f32(pi2 + y2))
    y = f32(x + B3_PI) if x < 0.0 else x
    sign = -1.0 if x < 0.0 else 1.0
    num_ = f32(f32(16.0 * y) * f32(B3_PI - y))
    s = sign * f32(num_ / f32(f32(5.0 * pi2) - f32(f32(4.0 * y) * f32(B3_PI - y))))
    mag = f32(math.sqrt(f32(f32(s * s) + f32(c * c))))
    inv = f32(1.0 / mag) if mag > 0.0 else 0.0
    return f32(c * inv), f32(s * inv)


def b3_cylinder_points(height, radius, y_offset, sides):
    """b3CreateCylinder's points: bottom and top of each side in turn, alpha accumulated in float."""
    points, alpha = [], 0.0
    delta = f32(f32(2.0 * B3_PI) / sides)
    for _ in range(sides):
        c, s = b3_cos_sin(alpha)
        points.append([f32(radius * c), f32(y_offset), f32(radius * s)])
        points.append([f32(radius * c), f32(y_offset + height), f32(radius * s)])
        alpha = f32(alpha + delta)
    return points


def outward(points, triangles):
    """Each triangle wound counter-clockwise seen from outside a convex solid's centre."""
    centre = [sum(p[a] for p in points) / len(points) for a in range(3)]
    fixed = []
    for tri in triangles:
        a, b, c = (points[i] for i in tri)
        if dot(cross(sub(b, a), sub(c, a)), sub(a, centre)) > 0.0:
            fixed.append(list(tri))
        else:
            fixed.append([tri[0], tri[2], tri[1]])
    return fixed


def prism_triangles(sides):
    """A prism of b3_cylinder_points' order (2i bottom, 2i + 1 top): sides as two triangles each,
    caps as fans (b3CreateHull keeps them as quads and polygons: the same solid)."""
    tris = []
    for i in range(sides):
        j = (i + 1) % sides
        tris += [(2 * i, 2 * j, 2 * j + 1), (2 * i, 2 * j + 1, 2 * i + 1)]
    for i in range(1, sides - 1):
        tris += [(0, 2 * i, 2 * i + 2), (1, 2 * i + 1, 2 * i + 3)]
    return tris


def write_obj(name, header, points, triangles, digits=9):
    with open(os.path.join(HERE, name), "w") as out:
        out.writelines("# %s\n" % line for line in header)
        out.writelines("v %s %s %s\n" % tuple("%.*g" % (digits, c) for c in p) for p in points)
        out.writelines("f %d %d %d\n" % (a + 1, b + 1, c + 1) for a, b, c in triangles)
    print("wrote %s: %d vertices, %d triangles, %d bytes" % (name, len(points), len(triangles),
                                                             os.path.getsize(os.path.join(HERE, name))))


def sleep_keys(linear, extent):
    """Box3D sleeps a body when |v| + |omega x maxExtent| < sleepThreshold for 0.5 s (b3_timeToSleep);
    rbsim tests |v| and |omega| apart: the threshold, and the threshold over the body's reach."""
    return {"sleep_linear_speed": linear, "sleep_angular_speed": num(linear / extent, 6), "time_to_sleep": 0.5}


# ---------------------------------------------------------------------------------------------
# CreateJunkyard + StepJunkyard (release: 24 layers): a static ground (box 240 x 2 x 240 m, top
# at y = 0) with four walls (half extents 1 x 8 x 50 m centred at x = +-50, y = 7, and 50 x 8 x 1 at
# z = +-50); 24 x 21 x 21 = 10584 rocks (b3CreateRock(1.5): the hull of 10 points of a Fibonacci
# lattice on a sphere of radius 1.5, density 1000, friction 0.6) at (-40 + 4X, 25 + 4Y, -40 + 4Z);
# a kinematic pusher (b3CreateCylinder(24, 4, 0, 16): a 16-sided prism of radius 4 m from y = 0 to
# 24) at (35, 0, 0) that StepJunkyard moves, before every step, to the point at -6 degrees/s along
# the circle of radius 35 m about the y axis with b3Body_SetTargetTransform, without turning it.
# rbsim's keyframes do the same: each step ends on the next key, the pusher keeps its orientation;
# the keys are one a step, Box3D's float32 path (its angle accumulated as degrees += -0.1f, its
# b3ComputeCosSin, which is up to 0.1 degree off the exact circle), round the whole circle (3600
# steps, 60 s), and loop: the wrap jumps by the gap printed when the script runs (8 mm; a step
# moves it 6 cm). Here the ground box is the plane y = 0 (as in the other scenes) and the walls
# one static compound body of four boxes; the rocks' sleep test is split as sleep_keys says. Box3D's
# own layout starts the lowest rocks over the pusher up to 0.38 m into its top (a rock reaches
# 1.38 m below its origin, the pusher's top is at 24 m): so does this one.
JUNKYARD_STEPS = 500


def junkyard():
    rock = []  # b3CreateRock( 1.5f )
    phi = f32(f32(1.0 + f32(math.sqrt(5.0))) / 2.0)
    dc, ds = b3_cos_sin(f32(f32(2.0 * B3_PI) / phi))
    c, s = 1.0, 0.0
    for i in range(10):
        z = f32(1.0 - f32(f32(2.0 * i + 1.0) / 10.0))
        rxy = f32(math.sqrt(f32(1.0 - f32(z * z))))
        rock.append([f32(f32(1.5 * rxy) * c), f32(f32(1.5 * rxy) * s), f32(1.5 * z)])
        c, s = f32(f32(dc * c) - f32(ds * s)), f32(f32(ds * c) + f32(dc * s))
    rock_faces = convex_hull(rock)
    assert sorted({v for f in rock_faces for v in f}) == list(range(10)) and len(rock_faces) == 16
    rock_volume, rock_centroid = volume_and_centroid(rock, rock_faces)
    write_obj("junkyard_rock.obj", ["Box3D %s shared/benchmarks.c CreateJunkyard's rock: b3CreateRock(1.5), the hull of 10"
                                    % BOX3D_COMMIT[:7],
                                    "points of a Fibonacci lattice on a sphere of radius 1.5 m, computed as Box3D does in float32.",
                                    "Volume %.6f m^3, centre of mass (%.6f, %.6f, %.6f). Written by make_box3d_scenes.py."
                                    % (rock_volume, *rock_centroid)], rock, rock_faces)

    pusher = b3_cylinder_points(24.0, 4.0, 0.0, 16)
    pusher_faces = outward(pusher, prism_triangles(16))
    pusher_volume, pusher_centroid = volume_and_centroid(pusher, pusher_faces)
    write_obj("junkyard_pusher.obj", ["Box3D %s shared/benchmarks.c CreateJunkyard's pusher: b3CreateCylinder(24, 4, 0, 16), a"
                                      % BOX3D_COMMIT[:7],
                                      "16-sided prism of radius 4 m from y = 0 to 24 m (float32 as Box3D computes it). Volume %.4f"
                                      " m^3." % pusher_volume, "Written by make_box3d_scenes.py."], pusher, pusher_faces)

    colors = [[0.55, 0.5, 0.45], [0.65, 0.55, 0.4], [0.5, 0.55, 0.6]]
    bodies = [{"name": "walls", "static": True, "position": [0, 7, 0], "color": [0.5, 0.5, 0.55],
               "shapes": [{"type": "box", "extents": vec(e), "position": vec(p), "friction_static": FRICTION,
                           "friction_kinetic": FRICTION}
                          for e, p in (((2, 16, 100), (-50, 0, 0)), ((2, 16, 100), (50, 0, 0)),
                                       ((100, 16, 2), (0, 0, -50)), ((100, 16, 2), (0, 0, 50)))]}]
    # The pusher's path: key k is where its centre of mass is after k steps, as Box3D computes it.
    dt = 1.0 / 60.0
    radius = 35.0
    keys, degrees = [], f32(0.0)
    for k in range(3601):
        c, s = b3_cos_sin(f32(f32(degrees * B3_PI) / 180.0))
        p = [f32(radius * c) + pusher_centroid[0], pusher_centroid[1], f32(radius * s) + pusher_centroid[2]]
        keys.append({"time": num(k * dt, 12), "position": vec(p, 9)})
        degrees = f32(degrees + f32(-6.0 * f32(dt)))  # StepJunkyard: degrees += omega * timeStep
    gap = math.dist(keys[0]["position"], keys[-1]["position"])
    assert gap < 0.01, gap
    print("junkyard: after 3600 steps the pusher is %.2g m from its start (where the keys loop)" % gap)
    bodies.append({"name": "pusher", "shape": {"type": "mesh", "file": "junkyard_pusher.obj"}, "density": 1000,
                   "kinematic": True, "friction_static": FRICTION, "friction_kinetic": FRICTION,
                   "position": keys[0]["position"], "color": [0.8, 0.3, 0.25],
                   "motion": {"keyframes": keys, "loop": True}})
    for Y in range(24):
        for X in range(21):
            for Z in range(21):
                origin = (-40.0 + 4.0 * X, 4.0 * Y + 24.0 + 1.0, -40.0 + 4.0 * Z)
                bodies.append({"shape": {"type": "mesh", "file": "junkyard_rock.obj"}, "density": 1000,
                               "friction_static": FRICTION, "friction_kinetic": FRICTION,
                               "position": vec([origin[a] + rock_centroid[a] for a in range(3)]),
                               "color": colors[Y % 3]})
    assert len(bodies) == 2 + 24 * 21 * 21
    reach = max(math.sqrt(dot(sub(p, rock_centroid), sub(p, rock_centroid))) for p in rock)
    head = {
        "title": "Box3D benchmark junkyard: 10584 rock hulls in a walled yard, a kinematic pusher going round",
        "world": world_block(JUNKYARD_STEPS, True, **sleep_keys(0.05, reach)),
        "view": view_block([65, 70, 80], [0, 30, 0],
                           "Box3D %s shared/benchmarks.c CreateJunkyard, StepJunkyard: 24 x 21 x 21 rocks (b3CreateRock(1.5), "
                           "10-point hulls, density 1000, friction 0.6) dropped from 25 to 117 m into a yard walled at "
                           "+-50 m (walls 16 m high); a kinematic 16-sided prism of radius 4 m and height 24 m goes round "
                           "the circle of radius 35 m at -6 degrees/s without turning (keyframes, one a step); "
                           "dt 1/60 s, sleep on, 500 steps; ground: the plane y = 0 (Box3D: a static box 240 x 2 x 240 m, "
                           "top at y = 0, that also holds the walls)" % BOX3D_COMMIT[:7], fov=60),
        "planes": [ground_plane()],
    }
    write_scene("junkyard.json", head, bodies)


# ---------------------------------------------------------------------------------------------
# CreateLargeWorld + StepLargeWorld (release: STATIC_FLOOR_GRID 1000, STATIC_FLOOR_CELL_SIZE 10,
# STATIC_FLOOR_SPHERES 100, STATIC_FLOOR_DROP_INTERVAL 5): a floor of 1000 x 1000 static boxes of
# 10 x 0.5 x 10 m (centres at y = 0, tops at y = 0.25) spanning 10 km, and spheres of radius 0.5
# (density 1000, friction 0.6) created at y = 1.5 one every 5 steps from step 5 on (StepLargeWorld
# runs before step i, i = 5, 10, ...: 99 spheres within the 500 steps), sphere n over the inner
# 80 % of the floor on a 10 x 10 grid: x = -4000 + 800 (n % 10 + 0.5), z = -4000 + 800 (n / 10 + 0.5).
# Each sphere is a spawner of one body at its step ("start", and an "end" half a step later).
#
# The floor is coarser here: LARGE_WORLD_CELL m boxes, (10000 / LARGE_WORLD_CELL)^2 of them. A
# million static bodies would take ~150 MB of scene file (rbsim reads at most 64 MiB); spawners make
# dynamic bodies only and a compound holds at most 128 shapes, so the format has no compact form of
# a grid of static bodies. The floor's top, extent and material are Box3D's; every cell size that
# divides 200 m keeps the drop points on cell corners, as Box3D's are (each sphere lands where four
# boxes meet). What Box3D measures here, its broad phase holding a million static proxies, is not
# reproduced: rbsim's broad phase holds 10^4 floor boxes.
LARGE_WORLD_CELL = 100.0
LARGE_WORLD_STEPS = 500


def large_world():
    span, cell = 10000.0, LARGE_WORLD_CELL
    grid = int(round(span / cell))
    assert grid * cell == span and 200.0 % cell == 0.0
    bodies = []
    for i in range(grid):
        for j in range(grid):
            bodies.append({"shape": {"type": "box", "extents": vec((cell, 0.5, cell))}, "static": True, "mass": 1,
                           "position": vec((-0.5 * span + (i + 0.5) * cell, 0, -0.5 * span + (j + 0.5) * cell)),
                           "friction_static": FRICTION, "friction_kinetic": FRICTION,
                           "color": [0.55, 0.6, 0.55] if (i + j) % 2 else [0.45, 0.5, 0.5]})
    dt = 1.0 / 60.0
    side, half = 10, f32(0.5 * 10.0 * 1000)
    inset = f32(f32(f32(0.1) * 2.0) * half)
    usable = f32(f32(2.0 * half) - f32(2.0 * inset))
    spawn = []
    for n in range(100):  # the 100th would fall at step 500, after the run
        x = f32(f32(-half + inset) + f32((n % side + 0.5) * f32(usable / side)))
        z = f32(f32(-half + inset) + f32((n // side + 0.5) * f32(usable / side)))
        assert x % cell == 0.0 and z % cell == 0.0
        step = 5 * (n + 1)
        spawn.append({"name": "sphere%d" % n,
                      "body": {"shape": {"type": "sphere", "radius": 0.5}, "density": 1000,
                               "friction_static": FRICTION, "friction_kinetic": FRICTION, "color": [0.85, 0.45, 0.25]},
                      "region": {"min": vec((x, 1.5, z)), "max": vec((x, 1.5, z))}, "random_orientation": False,
                      "start": num(step * dt, 12), "period": num(dt, 12), "end": num((step + 0.5) * dt, 12)})
    head = {
        "title": "Box3D benchmark large_world: a 10 km floor of static boxes, spheres dropped on it one every 5 steps",
        "world": world_block(LARGE_WORLD_STEPS, True, **sleep_keys(0.05, 0.5)),
        "view": view_block([-3585, 5, -3580], [-3600, 0.5, -3600],
                           "Box3D %s shared/benchmarks.c CreateLargeWorld, StepLargeWorld: a floor of static boxes "
                           "%g x 0.5 x %g m (Box3D: 1000 x 1000 boxes of 10 x 0.5 x 10 m) spanning 10 km, tops at "
                           "y = 0.25; spheres of radius 0.5 (density 1000, friction 0.6) created at y = 1.5 one every 5 "
                           "steps on a 10 x 10 grid 800 m apart; dt 1/60 s, sleep on, 500 steps; the camera watches "
                           "the first sphere's corner" % (BOX3D_COMMIT[:7], cell, cell), grid=False),
        "spawn": spawn,
    }
    write_scene("large_world.json", head, bodies)


# ---------------------------------------------------------------------------------------------
# CreateTrees( scale ) for trees25 (scale 4), trees50 (2) and trees100 (1), release sizes: a static
# b3CreateWaveMesh(150 scale, 200 scale, 1 / scale, 0.4, 0.05, 0.1): a grid of 150 x 200 m in cells
# of 1 / scale m, y = 0.4 sin(2 pi 0.1 (x + 75)) sin(2 pi 0.05 (z + 100)) at the grid points, default
# material (friction 0.6); 50 trees, each one body of 22 hulls b3CreateCylinder(l + 2 r, r, y - r, 6)
# (l = 1.5, r from 0.75 shrinking by 0.95 a hull, y from 1 by l + 2 r): hexagonal prisms stacked 53 m
# high, density 1, friction 0.9, sleep threshold 0.2 m/s; tree i at (0, 1, -70 + 3 i), turning
# about z at 0.5 (0.5 + 0.5 i / 50) rad/s, the sign alternating, about its body origin (its
# centre of mass moving at omega x (c - origin)), so the trees topple over and land on the waves.
#
# The wave mesh is one OBJ file, <scene>_ground.obj, when it stays under MAX_GROUND_TRIANGLES
# (~5 MB of OBJ): trees100's 60,000 triangles are Box3D's mesh as it is, one static mesh ground.
# trees50's 240,000 and trees25's 960,000 (~7.5 and ~30 MB) are cut into strips along x: the
# heights repeat every 10 m in x from the mesh's corner, so a strip a whole number of periods wide
# is one mesh file laid side by side (trees50: 3 strips 50 m wide, trees25: 15 strips 10 m wide;
# the fewest that keep the file under the limit). The same triangles, 3 or 15 static bodies where
# Box3D has one mesh shape; the strips' boundary edges (trees50: x = -25, 25; trees25: x = -65, -55,
# ..., 65, across the fallen trees) are felt, where Box3D's one mesh has inner edges, though the
# surface joins smoothly there. Box3D computes each height from its own angle in float32; the
# strips repeat the first's: they differ by the figure printed when the script runs (~1e-6 m).
# Box3D's rolling resistance 0.05 has no rbsim counterpart and is left out.
MAX_GROUND_TRIANGLES = 160000
TREE_STEPS = 500


def wave_heights(count, cell, frequency):
    """b3CreateWaveMesh's sin(omega i) along one axis, omega = 2 pi frequency cell in float32."""
    omega = f32(f32(f32(2.0 * B3_PI) * f32(frequency)) * cell)
    return [b3_cos_sin(f32(omega * i))[1] for i in range(count + 1)]


def trees(scale):
    name = "trees%d" % (100 // scale)
    cell = 1.0 / scale
    x_count, z_count = 150 * scale, 200 * scale
    amplitude = f32(0.4)
    rows = wave_heights(x_count, cell, 0.1)     # rowHeight, by ix (columnFrequency 0.1 along x)
    columns = wave_heights(z_count, cell, 0.05)  # columnHeight, by iz (rowFrequency 0.05 along z)
    strips = min(n for n in (1, 3, 5, 15) if 2 * x_count * z_count // n <= MAX_GROUND_TRIANGLES)
    period = x_count // strips  # cells of one strip, a whole number of 10 m periods
    width = period * cell
    assert strips * period == x_count and width % 10.0 == 0.0
    height = lambda ix, iz: f32(f32(amplitude * rows[ix]) * columns[iz])
    worst = max(abs(height(k * period + j, iz) - height(j, iz))
                for k in range(strips) for j in range(period + 1) for iz in range(z_count + 1))
    print("%s: %d strip(s), whose heights are within %.2g m of Box3D's mesh" % (name, strips, worst))
    vertices, triangles = [], []
    for j in range(period + 1):
        for iz in range(z_count + 1):
            vertices.append([j * cell - 0.5 * width, height(j, iz), -100.0 + iz * cell])
    for j in range(period):
        for iz in range(z_count):
            i1 = iz + (z_count + 1) * j
            i2, i4 = i1 + 1, i1 + z_count + 1
            triangles += [(i1, i2, i4 + 1), (i4 + 1, i4, i1)]  # Box3D's two triangles a cell, facing +y
    obj = name + "_ground.obj"
    what = ("the whole mesh" if strips == 1 else
            "a strip %g m wide (x from %g to %g) of it, %d x periods of its 15; %s.json lays %d side by side"
            % (width, -0.5 * width, 0.5 * width, width // 10, name, strips))
    write_obj(obj, ["Box3D %s shared/benchmarks.c CreateTrees(%d): b3CreateWaveMesh(%d, %d, %g, 0.4, 0.05, 0.1),"
                    % (BOX3D_COMMIT[:7], scale, x_count, z_count, cell),
                    what + ".", "Written by make_box3d_scenes.py."], vertices, triangles)
    lo = [min(v[a] for v in vertices) for a in range(3)]
    hi = [max(v[a] for v in vertices) for a in range(3)]
    centre = [0.5 * (lo[a] + hi[a]) for a in range(3)]  # "inertia": "cube": the mesh's box centre
    bodies = []
    for k in range(strips):
        bodies.append({"name": "ground%d" % k, "shape": {"type": "mesh", "file": obj}, "collide_as": "triangles",
                       "static": True, "mass": 1, "inertia": "cube",
                       "position": vec((-75.0 + width * (k + 0.5) + centre[0], centre[1], centre[2]), 9),
                       "friction_static": FRICTION, "friction_kinetic": FRICTION,
                       "color": [0.5, 0.6, 0.45] if k % 2 else [0.45, 0.55, 0.42]})

    hulls = []  # in the tree's body frame (Box3D's body origin)
    y, r, l = f32(1.0), f32(0.75), f32(1.5)
    for _ in range(22):
        points = b3_cylinder_points(f32(l + f32(2.0 * r)), r, f32(y - r), 6)
        hulls.append((points, outward(points, prism_triangles(6))))
        y = f32(y + f32(l + f32(2.0 * r)))
        r = f32(0.95 * r)
    volume, moment = 0.0, [0.0, 0.0, 0.0]
    for points, faces in hulls:
        v, c = volume_and_centroid(points, faces)
        volume += v
        moment = [moment[a] + v * c[a] for a in range(3)]
    com = [m / volume for m in moment]
    reach = max(math.sqrt(dot(sub(p, com), sub(p, com))) for points, _ in hulls for p in points)
    shapes = [{"type": "hull", "vertices": [vec(p) for p in points], "triangles": faces, "density": 1,
               "friction_static": 0.9, "friction_kinetic": 0.9} for points, faces in hulls]
    omega_sign, z = -0.5, -70.0
    for i in range(50):
        scale_v = f32(0.5 + f32(f32(0.5 * i) / 50))
        wz = f32(scale_v * omega_sign)
        # v = omega x (centre - origin) = (-wz cy, wz cx, 0), the centre (nearly) straight above the origin.
        bodies.append({"name": "tree%d" % i, "shapes": shapes, "position": vec((com[0], 1.0 + com[1], z + com[2])),
                       "angular_velocity": [0, 0, num(wz, 9)], "velocity": [num(-wz * com[1], 9), num(wz * com[0], 9), 0],
                       "color": [0.55, 0.4, 0.25] if i % 2 else [0.45, 0.33, 0.2]})
        z += 3.0
        omega_sign = -omega_sign
    head = {
        "title": "Box3D benchmark %s: 50 trees of 22 hulls toppling onto a wave mesh of %g m cells" % (name, cell),
        "world": world_block(TREE_STEPS, True, **sleep_keys(0.2, reach)),
        "view": view_block([70, 40, 75], [0, 3, 5],
                           "Box3D %s shared/benchmarks.c CreateTrees(%d): 50 trees, each one body of 22 hexagonal prisms "
                           "53 m high (density 1, friction 0.9), set turning about z at 0.25 to 0.5 rad/s, sides "
                           "alternating, topple onto b3CreateWaveMesh(%d, %d, %g, 0.4, 0.05, 0.1) (%d triangles%s); no "
                           "rolling resistance (Box3D: 0.05); dt 1/60 s, sleep on (0.2 m/s), 500 steps"
                           % (BOX3D_COMMIT[:7], scale, x_count, z_count, cell, strips * len(triangles),
                              "" if strips == 1 else ", here %d strips %g m wide of one mesh file" % (strips, width)),
                           fov=60, grid=False),
    }
    write_scene(name + ".json", head, bodies)


if __name__ == "__main__":
    rain()
    washer()
    large_pyramid()
    many_pyramids()
    joint_grid()
    convex_pile()
    junkyard()
    large_world()
    trees(4)
    trees(2)
    trees(1)
