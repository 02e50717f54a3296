"""Changes while running (issue 57): World.set_body, body_properties, set_joint and remove_joint.
Each change acts from the next step on that body or joint alone; a refused one raises what a
scene file would say and leaves the World as it was. Every case at dt = 1/60 and 1/240 s."""
import math

import numpy as np
import pytest
import rbsim

G = 9.81       # [m/s^2]
RADIUS = 0.1   # the balls' [m]
DTS = pytest.mark.parametrize("dt", [1 / 60, 1 / 240], ids=["dt_1_60", "dt_1_240"])


def bouncing(dt, restitution):
    # dlm, as restitution_sweep.py: its free flight peaks where the closed form does.
    world = rbsim.World(dt=dt, gravity=[0, -G, 0], sleep=False, integrator="dlm")
    world.add_plane()  # restitution 0: the pair takes the ball's, the larger
    a = world.add_body(name="a", shape={"type": "sphere", "radius": RADIUS}, mass=1.0,
                       position=[0, RADIUS + 1.0, 0], restitution=restitution)
    world.add_body(name="control", shape={"type": "sphere", "radius": RADIUS}, mass=1.0,
                   position=[3, RADIUS + 1.0, 0], restitution=restitution)
    return world, a


def rebounds(world, change=None, count=2):
    """The heights of the ball's first `count` rebound tops [m], calling change() at the first top,
    with the control ball's state at every step."""
    tops, top, went_up, last_vy, control = [], 0.0, False, 0.0, []
    while len(tops) < count:
        world.step()
        control.append(np.concatenate([world.x[1], world.q[1], world.P[1], world.L[1]]))
        vy, height = world.v[0, 1], world.x[0, 1] - RADIUS
        went_up = went_up or (last_vy <= 0 < vy)
        if went_up:
            top = max(top, height)
        if went_up and last_vy > 0 >= vy:
            tops.append(top)
            top, went_up = 0.0, False
            if change and len(tops) == 1:
                change()
        last_vy = vy
    return tops, np.array(control)


@DTS
def test_restitution_changed_between_bounces_gives_the_new_rebound_and_nothing_else(dt):
    world, ball = bouncing(dt, 0.5)
    changed, changed_control = rebounds(world, lambda: world.set_body(ball, restitution=0.8))
    plain, plain_control = rebounds(bouncing(dt, 0.5)[0])
    assert changed[0] == plain[0]
    for tops, e in ((changed, 0.8), (plain, 0.5)):
        # Newton's law from the height it fell: e^2 h, up to (1 - e^2) |v| dt high (the collision
        # pass reverses an approach up to |v| dt above the ground; restitution_sweep.py).
        speed = math.sqrt(2 * G * tops[0])
        assert e**2 * tops[0] - 1e-3 < tops[1] < e**2 * tops[0] + (1 - e**2) * speed * dt + 1e-3
    n = min(len(changed_control), len(plain_control))
    assert np.array_equal(changed_control[:n], plain_control[:n])  # the control ball, bit for bit


@DTS
def test_mass_change_on_a_spring_gives_the_new_equilibrium(dt):
    world = rbsim.World(dt=dt, gravity=[0, -G, 0], sleep=False)
    box = world.add_body(shape={"type": "box", "extents": [0.2, 0.2, 0.2]}, mass=1.0,
                         springs=[{"anchor": [0, 0, 0], "stiffness": 200, "damping": 20}])
    world.step(round(6 / dt))
    assert world.x[0, 1] == pytest.approx(-1.0 * G / 200, abs=1e-6)  # x = -m g / k
    inertia = np.array(world.body_properties(box)["inertia"])
    world.set_body(box, mass=2.0)  # alone, the mass scales the inertia with it
    assert np.allclose(world.body_properties(box)["inertia"], 2 * inertia, rtol=1e-15, atol=0)
    world.step(round(6 / dt))
    assert world.x[0, 1] == pytest.approx(-2.0 * G / 200, abs=1e-6)


@DTS
def test_friction_change_starts_and_stops_sliding_at_the_friction_angle(dt):
    theta = math.pi / 6  # tan(theta) = 0.577: mu 0.7 holds, 0.3 slides, 0.9 stops it
    world = rbsim.World(dt=dt, gravity=[G * math.sin(theta), -G * math.cos(theta), 0], sleep=False)
    world.add_plane(friction_static=10, friction_kinetic=10)  # the pair's mu: sqrt(10 mu_box)

    def mu(m):
        return {"friction_static": m * m / 10, "friction_kinetic": m * m / 10}
    box = world.add_body(shape={"type": "box", "extents": [0.2, 0.2, 0.2]}, mass=1.0, position=[0, 0.1, 0], **mu(0.7))
    world.step(round(1 / dt))
    assert abs(world.v[0, 0]) < 1e-3
    world.set_body(box, **mu(0.3))
    world.step(round(0.5 / dt))
    down = G * (math.sin(theta) - 0.3 * math.cos(theta))  # 2.357 m/s^2
    assert world.v[0, 0] == pytest.approx(down * 0.5, rel=0.02)
    world.set_body(box, **mu(0.9))
    stop = G * (0.9 * math.cos(theta) - math.sin(theta))  # 2.746 m/s^2
    world.step(round((world.v[0, 0] / stop + 0.5) / dt))
    assert abs(world.v[0, 0]) < 1e-3


@DTS
def test_filter_change_lets_a_body_fall_through_the_ground_from_the_next_step(dt):
    world = rbsim.World(dt=dt, gravity=[0, -G, 0], sleep=False)
    world.add_plane()  # category 1
    box = world.add_body(shape={"type": "box", "extents": [0.2, 0.2, 0.2]}, mass=1.0, position=[0, 0.1, 0])
    world.step(round(1 / dt))
    assert world.contact_count > 0
    vy = world.v[0, 1]
    world.set_body(box, filter={"mask": 0xFFFF_FFFF_FFFF_FFFE})  # every category but the ground's
    assert world.body_properties(box)["filter"] == {"category": 1, "mask": 0xFFFF_FFFF_FFFF_FFFE, "group": 0}
    steps = round(0.5 / dt)
    for _ in range(steps):
        world.step()
        assert world.contact_count == 0
    assert world.v[0, 1] == pytest.approx(vy - G * steps * dt, abs=1e-9)


def hinge_wheel(dt):
    world = rbsim.World(dt=dt, gravity=[0, 0, 0], sleep=False)
    world.add_body(name="wheel", shape={"type": "box", "extents": [0.5, 0.5, 0.1]}, mass=1.0)
    world.add_joint(type="hinge", body_a="wheel", anchor=[0, 0, 0], axis=[0, 0, 1],
                    motor={"speed": 1.0, "max_torque": 100.0})
    return world


@DTS
def test_motor_reaches_the_new_target_speed(dt):
    world = hinge_wheel(dt)
    world.step(round(0.5 / dt))
    assert world.joints()["speed"][0] == pytest.approx(1.0, abs=1e-6)
    world.set_joint(0, motor={"speed": -2.0})  # the torque is kept
    world.step(round(0.1 / dt))
    assert world.joints()["speed"][0] == pytest.approx(-2.0, abs=1e-6)
    world.set_joint(0, motor=False)
    world.step(round(0.2 / dt))
    assert world.joints()["speed"][0] == pytest.approx(-2.0, abs=1e-6)  # free: it spins on


@DTS
def test_removed_joint_lets_the_body_fall_freely(dt):
    world = rbsim.World(dt=dt, gravity=[0, -G, 0], sleep=False)
    for name, x in (("box", 0.0), ("other", 3.0)):
        world.add_body(name=name, shape={"type": "box", "extents": [0.2, 0.2, 0.2]}, mass=1.0, position=[x, -0.5, 0])
        world.add_joint(type="ball", body_a=name, anchor=[x, 0, 0])
    world.step(round(1 / dt))
    world.remove_joint(0)
    assert len(world.joints()) == 1 and world.joints()["body_a"][0] == 1  # the second moved down
    y0, v0 = world.x[0, 1], world.v[0, 1]
    steps = round(0.5 / dt)
    world.step(steps)
    t = steps * dt
    assert world.v[0, 1] == pytest.approx(v0 - G * t, abs=1e-9)
    assert world.x[0, 1] == pytest.approx(y0 + v0 * t - G * t * t / 2, abs=G * t * dt / 2 + 1e-9)
    assert world.x[1, 1] == pytest.approx(-0.5, abs=1e-3)  # still hanging


@DTS
def test_a_sweep_without_rebuilding_goes_back_to_the_saved_properties(dt):
    world, ball = bouncing(dt, 0.5)
    saved = world.get_state()
    world.set_body(ball, restitution=0.9, mass=3.0)
    world.step(10)
    world.set_state(saved)
    assert world.body_properties(ball)["restitution"] == 0.5 and world.body_properties(ball)["mass"] == 1.0


@pytest.mark.parametrize("keys, field, words", [
    ({"mass": -1.0}, "mass", "expected a positive number, got -1"),
    ({"mass": float("nan")}, "mass", "expected a finite number"),
    ({"inertia": [[1, 0, 0], [0, -1, 0], [0, 0, 1]]}, "inertia", "expected a symmetric positive definite"),
    ({"inertia": [1, 2]}, "inertia", "expected a 3 x 3 tensor"),
    ({"mass": 1e200}, "mass", "a mass of 1e+200 kg"),
    ({"restitution": 1.5}, "restitution", "expected a coefficient in [0, 1]"),
    ({"friction_static": -0.1}, "friction_static", "expected a finite value >= 0 (mu_s)"),
    ({"friction_kinetic": 0.9}, "friction_kinetic", "expected mu_k <= friction_static (mu_s)"),
    ({"filter": {"group": 2**40}}, "filter.group", "expected an integer from -2147483648 to 2147483647"),
    ({"filter": {"mask": -1}}, "filter.mask", "expected an unsigned integer"),
    ({"density": 5}, "density", ""),
])
def test_bad_body_values_are_refused_and_change_nothing(keys, field, words):
    world, ball = bouncing(1 / 60, 0.5)
    world.set_body(ball, mass=2.0, friction_static=0.6)  # restitution 0.5 stays: keys left out are kept
    world.step(5)
    before, properties = world.state_hash(), world.body_properties(ball)
    with pytest.raises(rbsim.InputError) as error:
        world.set_body(ball, **{"restitution": 0.2, **keys})  # a good key goes with the bad one
    assert error.value.file == "World.set_body()" and error.value.field == field and words in error.value.problem
    assert world.state_hash() == before and world.body_properties(ball) == properties


@pytest.mark.parametrize("keys, field, words", [
    ({"motor": {"speed": 2e5}}, "motor.speed", "expected a speed of at most 100000 rad/s either way, got 200000"),
    ({"motor": {"max_torque": -5}}, "motor.max_torque", "expected a torque from 0 to 1e+12 N m, got -5"),
    ({"motor": {"max_force": 5}}, "motor.max_force", "unknown key"),
    ({"limits": [1, -1]}, "limits", "expected [lower, upper] angles in radians with -pi <= lower <= upper <= pi"),
    ({"twist": [-1, 1]}, "twist", "only a ball joint takes a twist"),
])
def test_bad_joint_values_are_refused_and_change_nothing(keys, field, words):
    world = hinge_wheel(1 / 60)
    world.step(5)
    before, row = world.state_hash(), world.joints()
    with pytest.raises(rbsim.InputError) as error:
        world.set_joint(0, **keys)
    assert error.value.file == "World.set_joint()" and error.value.field == field and words in error.value.problem
    assert world.state_hash() == before
    world.step()
    assert world.joints()["speed"][0] == pytest.approx(1.0, abs=1e-6)  # the motor as it was
    with pytest.raises(rbsim.InputError, match=r"World.remove_joint\(\): joint: no joint has index 1"):
        world.remove_joint(1)
    assert len(row) == 1


def test_body_properties_read_back_what_set_body_set():
    world = rbsim.World()
    body = world.add_body(shape={"type": "box", "extents": [1, 2, 3]}, mass=2.0)
    world.set_body(body, inertia=[1.0, 2.0, 3.0], restitution=0.25, friction_static=0.3,
                   filter={"category": 4, "group": -2})
    p = world.body_properties(body)
    assert p["mass"] == 2.0 and p["inertia"] == ((1, 0, 0), (0, 2, 0), (0, 0, 3))
    # mu_k follows a lowered mu_s, as in a body block
    assert (p["restitution"], p["friction_static"], p["friction_kinetic"]) == (0.25, 0.3, 0.3)
    assert p["filter"] == {"category": 4, "mask": 2**64 - 1, "group": -2}
    with pytest.raises(TypeError):
        world.set_body(body, 2.0)  # keywords only


def section(path):
    """The first code block of the "Changes while running" section of a doc."""
    text = path.read_text().split("## Changes while running", 1)[1]
    return text.split("```", 2)[1].split("\n", 1)[1]


def test_the_python_docs_example_runs_and_prints_what_it_says(tmp_path):
    import subprocess
    import sys
    from conftest import SOURCE
    done = subprocess.run([sys.executable, "-c", section(SOURCE / "docs" / "python.md")], capture_output=True,
                          text=True, timeout=120, cwd=tmp_path)
    assert done.returncode == 0, done.stderr
    assert done.stdout.splitlines() == ["0.9 2.0", "World.set_body(): restitution: expected a coefficient in [0, 1]"]


def test_the_cpp_docs_example_is_the_one_a_test_runs():
    from conftest import SOURCE
    block = section(SOURCE / "docs" / "cpp-api.md")
    test = (SOURCE / "tests" / "engine" / "world" / "changes_doc_example_test.cpp").read_text()
    ran = test.split("// docs/cpp-api.md begin\n", 1)[1].split("  // docs/cpp-api.md end", 1)[0]
    assert [line.strip() for line in ran.splitlines()] == [line.strip() for line in block.splitlines()]


def test_a_compound_bodys_materials_and_filters_are_its_shapes():
    world = rbsim.World()
    body = world.add_body(shapes=[{"type": "box", "extents": [1, 0.1, 0.1]},
                                  {"type": "sphere", "radius": 0.2, "position": [0.5, 0, 0]}], mass=2.0)
    for keys, field in (({"restitution": 0.5}, "restitution"), ({"filter": {"mask": 0}}, "filter")):
        with pytest.raises(rbsim.InputError, match="a compound body's") as error:
            world.set_body(body, **keys)
        assert error.value.field == field
    world.set_body(body, mass=4.0)  # its mass is its own
    assert set(world.body_properties(body)) == {"mass", "inertia"} and world.body_properties(body)["mass"] == 4.0
