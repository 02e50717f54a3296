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
