"""Joints built from Python: World.add_joint(**joint) takes the keys of an entry of "joints"."""
import math

import numpy as np
import pytest
import rbsim


def pendulum(**joint):
    world = rbsim.World(dt=1 / 240, gravity=[0, -9.81, 0], sleep=False)
    world.add_body(name="rod", shape={"type": "box", "extents": [0.1, 1.0, 0.1]}, mass=1.0,
                   position=[0.5, 0.0, 0.0], orientation={"axis_angle_deg": [0, 0, 1, 90]})
    world.add_joint(body_a="rod", anchor=[0, 0, 0], **joint)
    return world


@pytest.mark.parametrize("joint", [{"type": "ball"}, {"type": "hinge", "axis": [0, 0, 1]}])
def test_rod_released_level_swings_through_the_bottom_on_its_pivot(joint):
    world = pendulum(**joint)
    # Down from level, I_pivot = m (w^2 + l^2) / 12 + m (l / 2)^2: at the bottom, m g l / 2 = I w^2 / 2.
    inertia = (0.01 + 1.0) / 12 + 0.25
    speed = math.sqrt(9.81 * 0.5 * 2 / inertia)
    fastest = 0.0
    for _ in range(240):
        world.step(1)
        fastest = max(fastest, abs(world.omega[0][2]))
        assert np.linalg.norm(world.x[0]) == pytest.approx(0.5, abs=1e-3)
    assert fastest == pytest.approx(speed, rel=5e-3)


def test_bad_joint_names_the_call_and_the_key():
    world = rbsim.World()
    world.add_body(name="rod", shape={"type": "box", "extents": [0.1, 1.0, 0.1]}, mass=1.0)
    with pytest.raises(rbsim.InputError, match=r"World.add_joint\(\): body_a: no body is named \"door\""):
        world.add_joint(type="ball", body_a="door", anchor=[0, 0, 0])
    with pytest.raises(rbsim.InputError, match=r"World.add_joint\(\): limits"):
        world.add_joint(type="hinge", body_a="rod", anchor=[0, 0, 0], axis=[0, 1, 0], limits=[1, -1])


def test_a_hinge_reads_its_speed_angle_and_the_pull_at_the_bottom_of_the_swing():
    world = pendulum(type="hinge", axis=[0, 0, 1])
    readings = []
    for _ in range(240):
        world.step(1)
        readings.append((abs(world.omega[0][2]), world.joints()[0], world.omega[0][2]))
    fastest, joint, omega = max(readings, key=lambda r: r[0])
    assert joint["speed"] == pytest.approx(omega, abs=1e-12)
    assert joint["body_a"] == 0 and joint["body_b"] == -1 and joint["hinge"]
    assert abs(joint["angle"]) == pytest.approx(math.pi / 2, abs=0.02)  # level -> straight down
    # At the bottom the joint holds the weight and turns the centre on its circle: m (g + w^2 r).
    assert joint["force"][1] == pytest.approx(1.0 * (9.81 + fastest ** 2 * 0.5), rel=1e-2)
    assert joint["anchor_b"] == pytest.approx((0, 0, 0), abs=1e-15)
    assert np.linalg.norm(joint["anchor_a"] - joint["anchor_b"]) < 1e-3


def test_a_ball_joint_has_no_angle_and_holds_a_hanging_body_by_its_weight():
    world = rbsim.World(dt=1 / 60, gravity=[0, -9.81, 0], sleep=False)
    world.add_body(name="bob", shape={"type": "sphere", "radius": 0.1}, mass=2.0, position=[0, -1, 0])
    world.add_joint(type="ball", body_a="bob", anchor=[0, 0, 0])
    world.step(120)
    joint = world.joints()[0]
    assert math.isnan(joint["angle"]) and math.isnan(joint["speed"]) and not joint["hinge"]
    assert joint["force"] == pytest.approx((0, 2.0 * 9.81, 0), abs=1e-6)
    assert rbsim.World().joints().shape == (0,)


def test_a_slider_on_an_incline_reads_its_translation_and_accelerates_at_g_sin_a():
    world = rbsim.World(dt=1 / 60, gravity=[0, -9.81, 0], sleep=False)
    world.add_body(name="cart", shape={"type": "box", "extents": [0.4, 0.2, 0.3]}, mass=1.0)
    slope = math.radians(30)
    world.add_joint(type="prismatic", body_a="cart", anchor=[0, 0, 0], axis=[math.cos(slope), -math.sin(slope), 0])
    world.step(60)
    joint = world.joints()[0]
    assert joint["type"] == b"prismatic" and not joint["hinge"] and math.isnan(joint["angle"])
    assert joint["translation_speed"] == pytest.approx(9.81 * math.sin(slope) * 1.0, rel=1e-9)
    assert joint["translation"] == pytest.approx(np.linalg.norm(world.x[0]), rel=1e-6)


def test_the_joint_family_takes_its_keys_and_refuses_the_others():
    world = rbsim.World(dt=1 / 60, gravity=[0, -9.81, 0], sleep=False)
    world.add_body(name="arm", shape={"type": "box", "extents": [1.0, 0.1, 0.1]}, mass=1.0, position=[0.5, 0, 0])
    world.add_body(name="beam", shape={"type": "box", "extents": [1.0, 0.1, 0.1]}, mass=1.0, position=[0.5, 2, 0])
    world.add_joint(type="ball", body_a="arm", anchor=[0, 0, 0], axis=[1, 0, 0], cone=math.radians(30),
                    twist=[-0.2, 0.2], friction=0.01)
    world.add_joint(type="weld", body_a="beam", anchor=[0, 2, 0], linear_hertz=8, angular_hertz=8,
                    linear_damping_ratio=1, angular_damping_ratio=1)
    world.step(180)
    arm, beam = world.joints()
    assert arm["type"] == b"ball" and arm["swing"] == pytest.approx(math.radians(30), abs=1e-3)
    assert abs(arm["twist"]) < 1e-6
    assert beam["type"] == b"weld" and math.isnan(beam["swing"])
    assert -world.x[1][1] + 2 > 0  # the soft weld droops, and holds
    assert np.linalg.norm(world.v[1]) < 1e-3
    with pytest.raises(rbsim.InputError, match=r"World.add_joint\(\): friction"):
        world.add_joint(type="weld", body_a="arm", anchor=[0, 0, 0], friction=1.0)
    with pytest.raises(rbsim.InputError, match=r"World.add_joint\(\): cone"):
        world.add_joint(type="hinge", body_a="arm", anchor=[0, 0, 0], axis=[0, 0, 1], cone=0.5)
