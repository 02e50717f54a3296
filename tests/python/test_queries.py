"""Queries a researcher reaches for (issue 39): ray casts against closed forms, the version, the
GIL released while a World steps, and the import without NumPy."""
import math
import os
import re
import subprocess
import sys
import threading

import numpy as np
import pytest
import rbsim

from conftest import SOURCE


def test_a_ray_finds_the_sphere_the_box_and_the_ground_where_their_equations_say():
    w = rbsim.World(gravity=[0, 0, 0])
    w.add_plane(normal=(0, 1, 0), point=(0, 0, 0))
    ball = w.add_body(shape={"type": "sphere", "radius": 0.5}, mass=1, position=(0, 1, 0))
    box = w.add_body(shape={"type": "box", "extents": [1.0, 1.0, 1.0]}, mass=1, position=(3, 1, 0))
    # Off-centre by 0.3 along x: the sphere is entered at z = -sqrt(0.5^2 - 0.3^2) = -0.4.
    hit = w.ray_cast((0.3, 1, -5), (0, 0, 2))
    assert hit["body"] == ball and hit["plane"] is None
    assert hit["distance"] == pytest.approx(4.6, abs=1e-12)
    assert hit["point"] == pytest.approx((0.3, 1.0, -0.4), abs=1e-12)
    assert hit["normal"] == pytest.approx((0.6, 0.0, -0.8), abs=1e-12)
    down = w.ray_cast((3.2, 4, 0.1), (0, -1, 0))
    assert down["body"] == box and down["distance"] == pytest.approx(4 - 1.5, abs=1e-12)
    ground = w.ray_cast((10, 2, 0), (1, -1, 0))
    assert ground["body"] is None and ground["plane"] == 0
    assert ground["distance"] == pytest.approx(2 * math.sqrt(2), abs=1e-12)
    assert ground["point"] == pytest.approx((12, 0, 0), abs=1e-12)
    assert w.ray_cast((0, 5, 0), (0, 1, 0)) is None  # up, into nothing
    assert w.ray_cast((3.2, 4, 0.1), (0, -1, 0), max_distance=2.4) is None  # the box is 2.5 away
    assert w.ray_cast((0, 1, 0), (1, 0, 0))["distance"] == 0.0  # from inside the sphere


def test_a_ray_direction_of_any_finite_length_is_a_direction():
    # Issue 56: (1e-200, 0, 0) was refused as zero and (1e200, 0, 0) as not finite, their squared
    # norms having under- and overflowed; each is the unit direction (1, 0, 0).
    w = rbsim.World(gravity=[0, 0, 0])
    w.add_body(shape={"type": "box", "extents": [1.0, 1.0, 1.0]}, mass=1, position=(3, 1, 0))
    for scale in (1e-200, 1e-160, 1.0, 1e160, 1e200, 5e-324):
        hit = w.ray_cast((0, 1, 0), (scale, 0, 0))
        assert hit is not None, scale
        assert hit["distance"] == pytest.approx(2.5, abs=1e-12)
        assert hit["normal"] == pytest.approx((-1.0, 0.0, 0.0), abs=1e-12)


def test_a_bad_ray_is_refused_naming_the_parameter():
    w = rbsim.World()
    for args, field in [(((0, 0), (1, 0, 0)), "origin"), (((0, 0, 0), (0, 0, 0)), "direction"),
                        (((0, 0, 0), (1, float("nan"), 0)), "direction")]:
        with pytest.raises(rbsim.InputError) as e:
            w.ray_cast(*args)
        assert e.value.field == field
    with pytest.raises(rbsim.InputError) as e:
        w.ray_cast((0, 0, 0), (1, 0, 0), max_distance=-1)
    assert e.value.field == "max_distance"


def test_the_version_is_the_projects():
    project = re.search(r"project\(rbsim VERSION ([0-9.]+)", (SOURCE / "CMakeLists.txt").read_text()).group(1)
    assert rbsim.__version__ == project


def test_other_threads_run_while_a_world_steps():
    w = rbsim.World(dt=1 / 240)
    w.add_plane()
    for i in range(200):
        w.add_body(shape={"type": "box", "extents": [0.2, 0.2, 0.2]}, mass=1,
                   position=(0.25 * (i % 10), 0.15 + 0.25 * (i // 10), 0))
    started, done = threading.Event(), threading.Event()

    def run():
        started.set()
        w.step(480)
        done.set()

    worker = threading.Thread(target=run)
    worker.start()
    started.wait()
    # Holding the GIL for the whole call, step() would let this loop run only before and after it.
    spins = 0
    while not done.is_set():
        spins += 1
    worker.join()
    assert w.step_count == 480
    assert spins > 10000


def test_without_numpy_the_import_fails_saying_so():
    code = "import sys; sys.modules['numpy'] = None; import rbsim"
    done = subprocess.run([sys.executable, "-c", code], capture_output=True, text=True, env=os.environ, timeout=60)
    assert done.returncode != 0
    assert "ImportError: rbsim needs NumPy" in done.stderr


def test_contacts_hold_every_point_sleeping_pairs_included():
    # Ten unit boxes dropped side by side on the ground: each rests on four corners (manifold of 4).
    w = rbsim.World(dt=1 / 60)
    w.add_plane()
    for i in range(10):
        w.add_body(shape={"type": "box", "extents": [1, 1, 1]}, mass=1, position=(1.5 * i, 0.6, 0))
    w.step(30)
    c = w.contacts()
    assert len(c) == w.contact_count == 40
    assert set(c.dtype.names) >= {"body_a", "body_b", "plane", "point", "normal", "depth", "normal_impulse",
                                  "friction_impulse", "awake"}
    assert (c["body_a"] == -1).all() and (c["plane"] == 0).all()
    assert sorted(set(c["body_b"])) == list(range(10))
    np.testing.assert_allclose(c["normal"], np.tile([0.0, 1.0, 0.0], (40, 1)), atol=1e-12)
    # Awake and resting: the four points of a box carry its weight m g dt between them.
    assert c["awake"].all()
    for b in range(10):
        assert c["normal_impulse"][c["body_b"] == b].sum() == pytest.approx(9.81 / 60, rel=1e-2)
    # Once asleep, the same 40 points stay, unsolved (NaN impulses), and the count does not drop.
    for _ in range(600):
        w.step()
        if not w.awake.any():
            break
    assert not w.awake.any()
    asleep = w.contacts()
    assert len(asleep) == w.contact_count == 40
    assert not asleep["awake"].any() and np.isnan(asleep["normal_impulse"]).all()
    np.testing.assert_allclose(asleep["point"][:, 1], 0.0, atol=0.01)  # on the ground


# Scene queries through the tree (issue 57), against brute force in NumPy over random spheres,
# whose every answer has a closed form: a ray enters |o + s d - c| = r, a sphere of radius q swept
# along d is the ray against r + q, the nearest surface point is |p - c| - r away.
SPHERES = 300  # bodies in the random scene
HALF_WIDTH = 20.0  # [m] centres within +-HALF_WIDTH


def sphere_scene(seed):
    rng = np.random.default_rng(seed)
    w = rbsim.World(gravity=[0, 0, 0])
    w.add_plane(normal=(0, 1, 0), point=(0, -HALF_WIDTH, 0))
    centres = rng.uniform(-HALF_WIDTH, HALF_WIDTH, (SPHERES, 3))
    radii = rng.uniform(0.2, 1.5, SPHERES)
    categories = rng.integers(1, 4, SPHERES)
    for i in range(SPHERES):
        w.add_body(shape={"type": "sphere", "radius": float(radii[i])}, mass=1, position=centres[i],
                   static=bool(i % 4 == 0), filter={"category": int(categories[i])})
    return w, rng, centres, radii, categories


def brute_rays(origins, directions, centres, radii, reach, seen, with_ground=True):
    """Nearest entry of each ray into the spheres `seen` (a bool per sphere) and the plane y = -HALF_WIDTH."""
    d = directions / np.linalg.norm(directions, axis=1)[:, None]
    oc = origins[:, None, :] - centres[None, :, :]
    b = np.einsum("nk,nmk->nm", d, oc)
    c = np.einsum("nmk,nmk->nm", oc, oc) - radii[None, :] ** 2
    disc = b * b - c
    s = np.where(c <= 0, 0.0, -b - np.sqrt(np.maximum(disc, 0)))
    s = np.where((disc >= 0) & (s >= 0) & seen[None, :], s, np.inf)
    s = np.where(s <= reach, s, np.inf)
    body = np.argmin(s, axis=1)
    best = s[np.arange(len(s)), body]
    height = origins[:, 1] + HALF_WIDTH  # above the ground; below it, inside its half-space: a hit at 0
    ground = np.where(height < 0, 0.0, np.where(d[:, 1] < 0, height / -d[:, 1], np.inf))
    ground = np.where(with_ground, ground, np.inf)
    ground = np.where(ground <= reach, ground, np.inf)
    plane = ground < best
    return np.minimum(best, ground), np.where(plane | np.isinf(best), -1, body), plane


def test_a_batch_of_rays_is_brute_force_over_every_sphere_and_the_ground():
    w, rng, centres, radii, categories = sphere_scene(1)
    n = 2000
    origins = rng.uniform(-1.2 * HALF_WIDTH, 1.2 * HALF_WIDTH, (n, 3))
    directions = rng.normal(size=(n, 3))
    for mask, reach in ((None, None), (0b10, 15.0)):
        seen = np.ones(SPHERES, bool) if mask is None else (categories & mask) != 0
        got = w.ray_cast_batch(origins, directions, max_distance=reach, mask=mask)
        # The ground counts as category 1, which mask 0b10 leaves out.
        want, body, plane = brute_rays(origins, directions, centres, radii, np.inf if reach is None else reach, seen,
                                       with_ground=mask is None)
        assert np.array_equal(got["hit"], np.isfinite(want))
        assert np.allclose(got["distance"][got["hit"]], want[got["hit"]], atol=1e-9)
        assert np.array_equal(got["body"], body)
        assert np.array_equal(got["plane"] == 0, plane)
        hit = got["hit"]
        unit = directions / np.linalg.norm(directions, axis=1)[:, None]
        assert np.allclose(got["point"][hit], origins[hit] + want[hit, None] * unit[hit], atol=1e-9)
        assert np.isnan(got["point"][~hit]).all() and np.isinf(got["distance"][~hit]).all()
        assert hit.sum() > n / 20  # the comparison compares hits


def test_a_batch_answers_as_ray_cast_row_by_row_with_the_compound_s_child():
    w = rbsim.World(gravity=[0, 0, 0])
    table = w.add_body(mass=1, position=(0, 0, 5), shapes=[
        {"type": "box", "extents": [1, 1, 1], "position": [-1, 0, 0]},
        {"type": "box", "extents": [1, 1, 1], "position": [1, 0, 0], "filter": {"category": 2}}])
    origins = np.array([[-1.0, 0, 0], [1.0, 0, 0], [5.0, 0, 0]])
    directions = np.array([[0, 0, 1.0]] * 3)
    batch = w.ray_cast_batch(origins, directions)
    assert list(batch["child"]) == [0, 1, -1] and list(batch["body"]) == [0, 0, -1]
    for i in range(3):
        one = w.ray_cast(origins[i], directions[i])
        assert (one is None) == (not batch["hit"][i])
        if one is not None:
            assert one["body"] == table and one["child"] == batch["child"][i]
            assert one["distance"] == pytest.approx(batch["distance"][i], abs=0) == 4.5
    assert w.ray_cast((1, 0, 0), (0, 0, 1), mask=1) is None  # the right box is in category 2 only


def test_overlap_closest_point_and_boxes_are_brute_force_over_every_sphere():
    w, rng, centres, radii, _ = sphere_scene(2)
    ids = [w.id_at(i) for i in range(SPHERES)]
    for _ in range(100):
        p = rng.uniform(-HALF_WIDTH, HALF_WIDTH, 3)
        q = float(rng.uniform(0.1, 3.0))
        gaps = np.linalg.norm(centres - p, axis=1) - radii
        touched = [ids[i] for i in np.flatnonzero(gaps <= q)]
        found = w.overlap({"type": "sphere", "radius": q}, p, planes=False)
        assert [f["body"] for f in found] == touched
        near = w.closest_point(p, planes=False)
        assert near["body"] == ids[int(np.argmin(gaps))]
        assert near["distance"] == pytest.approx(gaps.min(), abs=1e-9)
        lower, upper = p - q, p + q
        inside = (centres + radii[:, None] >= lower).all(axis=1) & (centres - radii[:, None] <= upper).all(axis=1)
        assert w.query_aabb(lower, upper) == [ids[i] for i in np.flatnonzero(inside)]


def test_a_swept_sphere_is_the_ray_against_spheres_grown_by_its_radius():
    w, rng, centres, radii, _ = sphere_scene(3)
    hits = 0
    for _ in range(100):
        p = rng.uniform(-HALF_WIDTH, HALF_WIDTH, 3)
        d = rng.normal(size=3)
        q = float(rng.uniform(0.05, 1.0))
        if (np.linalg.norm(centres - p, axis=1) <= radii + q).any():
            continue  # starts touching: distance 0 by definition, nothing to compare
        want, body, _ = brute_rays(p[None], d[None], centres, radii + q, 30.0, np.ones(SPHERES, bool),
                                  with_ground=False)
        got = w.shape_cast({"type": "sphere", "radius": q}, p, d, 30.0, planes=False)
        if np.isinf(want[0]) or body[0] < 0:
            assert got is None
            continue
        hits += 1
        assert got["body"] == w.id_at(int(body[0]))
        assert got["distance"] == pytest.approx(want[0], abs=2e-6)
        assert got["distance"] <= want[0] + 1e-12  # never past the contact
    assert hits > 10


def test_queries_see_a_body_moved_added_or_removed_at_once():
    w = rbsim.World(gravity=[0, 0, 0])
    a = w.add_body(shape={"type": "sphere", "radius": 0.5}, mass=1, position=(5, 0, 0))
    assert w.ray_cast((0, 0, 0), (1, 0, 0))["distance"] == pytest.approx(4.5, abs=1e-12)
    w.set_pose(a, position=(3, 0, 0))
    assert w.ray_cast((0, 0, 0), (1, 0, 0))["distance"] == pytest.approx(2.5, abs=1e-12)
    b = w.add_body(shape={"type": "box", "extents": [1, 1, 1]}, mass=1, position=(2, 0, 0))
    assert w.ray_cast((0, 0, 0), (1, 0, 0))["body"] == b
    w.remove_body(b)
    assert w.closest_point((0, 0, 0))["body"] == a
    assert w.query_aabb((-1, -1, -1), (1, 1, 1)) == []


def test_bad_queries_name_the_call_and_the_field():
    w = rbsim.World()
    w.add_body(shape={"type": "sphere", "radius": 0.5}, mass=1)
    cases = [
        (lambda: w.ray_cast_batch(np.zeros((3, 3)), np.zeros((2, 3))), "World.ray_cast_batch()", "directions"),
        (lambda: w.ray_cast_batch(np.zeros((3, 2)), np.zeros((3, 2))), "World.ray_cast_batch()", "origins"),
        (lambda: w.ray_cast((0, 0, 0), (1, 0, 0), mask=-1), "World.ray_cast()", "mask"),
        (lambda: w.shape_cast({"type": "cone"}, (0, 0, 0), (1, 0, 0)), "World.shape_cast()", "shape.type"),
        (lambda: w.overlap({"type": "sphere"}, (0, 0, 0)), "World.overlap()", "shape.radius"),
        (lambda: w.closest_point((0, 0, math.nan)), "World.closest_point()", "point"),
        (lambda: w.query_aabb((0, 0), (1, 1, 1)), "World.query_aabb()", "lower"),
    ]
    for call, name, field in cases:
        with pytest.raises(rbsim.InputError) as e:
            call()
        assert e.value.file == name and e.value.field == field
    with pytest.raises(rbsim.InputError):
        w.ray_cast_batch(np.zeros((1, 3)), np.zeros((1, 3)))  # a zero direction, refused by the engine
    with pytest.raises(TypeError):
        w.ray_cast((0, 0, 0), (1, 0, 0), category="1")
