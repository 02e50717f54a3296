"""Saved states and live settings (issue 39): going on from World.set_state is bit for bit the
uninterrupted run, on the shipped scenes with sleeping stacks, joints, particles and soft bodies;
the settings a running World takes are read and checked as in a scene file."""
import numpy as np
import pytest
import rbsim

SCENES = ["contact_stacking", "assignment2_f_joints", "particles_fountain", "soft_jelly", "fracture_wall"]


@pytest.mark.parametrize("name", SCENES)
def test_going_on_from_a_restored_state_is_the_uninterrupted_run_bit_for_bit(name):
    w = rbsim.load_scene(name).world()
    w.step(60)
    state = w.get_state()
    w.step(60)
    uninterrupted = (w.state_hash(), w.x.copy(), w.q.copy(), w.contacts().tobytes())
    for _ in range(2):  # a state restores more than once
        w.set_state(state)
        assert w.step_count == 60 and w.time == state.time
        w.step(60)
        assert w.state_hash() == uninterrupted[0]
        assert np.array_equal(w.x, uninterrupted[1]) and np.array_equal(w.q, uninterrupted[2])
        assert w.contacts().tobytes() == uninterrupted[3]  # NaN impulses of sleeping pairs too


def test_rewinding_with_another_integrator_changes_the_run_and_the_state_brings_back_the_first():
    w = rbsim.World(gravity=(0, 0, 0), dt=1 / 60, integrator="euler-quat")
    body = w.add_body(shape={"type": "box", "extents": [1, 2, 3]}, mass=1, angular_velocity=(0.1, 4, 0.1))
    state = w.get_state()
    w.step(120)
    euler = w.q.copy()
    w.set_state(state)
    w.integrator = "rk4"
    w.step(120)
    rk4 = w.q.copy()
    w.set_state(state)
    assert w.integrator == "euler-quat"  # the settings come back with the state
    exact = w.exact_rotation(body, [2.0])  # the closed-form orientation at t = 2 s
    w.step(120)
    assert np.array_equal(w.q, euler)
    # Aligned for the quaternion's sign: rk4 lands far nearer the exact spin than forward Euler.
    def error(q):
        return min(np.linalg.norm(q - exact[0]), np.linalg.norm(q + exact[0]))
    assert error(rk4[0]) < 0.01 * error(euler[0])


def test_a_state_goes_back_only_into_its_own_world_and_ids_added_since_go():
    a, b = rbsim.World(), rbsim.World()
    state = a.get_state()
    with pytest.raises(rbsim.InputError) as error:
        b.set_state(state)
    assert error.value.field == "state" and "another World" in error.value.problem
    with pytest.raises(TypeError, match="expected an rbsim.State"):
        a.set_state("state")
    added = a.add_body(shape={"type": "sphere", "radius": 0.5}, mass=1)
    a.set_state(state)
    assert not a.is_valid(added) and len(a) == 0
    assert repr(state) == f"State(world={state.world}, step_count=0, bodies=0)"


def test_a_new_time_step_counts_from_now_and_time_goes_on():
    w = rbsim.World(dt=1 / 60)
    w.add_body(shape={"type": "sphere", "radius": 0.5}, mass=1, position=(0, 100, 0))
    w.step(30)
    w.dt = 1 / 240
    assert w.time == pytest.approx(0.5, abs=1e-15) and w.dt == 1 / 240
    w.step(120)
    assert w.time == pytest.approx(1.0, abs=1e-12)
    assert w.settings["dt"] == 1 / 240


def test_new_gravity_acts_from_the_next_step_as_the_closed_form_says():
    w = rbsim.World(dt=0.01, gravity=(0, 0, 0))
    w.add_body(shape={"type": "sphere", "radius": 0.5}, mass=1)
    w.gravity = [0, 0, -2]
    assert w.gravity == (0, 0, -2)
    w.step(50)
    assert w.v[0] == pytest.approx((0, 0, -2 * 0.5), abs=1e-12)


def test_every_live_setting_reads_back_what_was_set():
    w = rbsim.World()
    for key, value in [("integrator", "rk4"), ("solver", "pgs"), ("substeps", 8), ("friction", "seed000"),
                       ("restitution_threshold", 0.25), ("solver", "soft-step")]:
        setattr(w, key, value)
        assert getattr(w, key) == value and w.settings[key] == value


@pytest.mark.parametrize("key,value,problem", [
    ("dt", -1.0, "positive time step"), ("dt", "fast", "number"), ("substeps", 0, "substeps"), ("substeps", 2.5, "integer"),
    ("integrator", "rk5", "did you mean"), ("solver", "gauss", "soft-step"), ("friction", "sticky", "cone"),
    ("gravity", (0, 1), "3"), ("gravity", (0, float("nan"), 0), ""), ("restitution_threshold", -1, ""),
])
def test_a_bad_setting_is_the_scene_files_error_and_changes_nothing(key, value, problem):
    w = rbsim.World()
    before = w.settings
    with pytest.raises(rbsim.InputError) as error:
        setattr(w, key, value)
    assert error.value.field == key and problem in error.value.problem
    assert w.settings == before


def test_pgs_is_refused_while_the_world_has_joints():
    w = rbsim.World()
    w.add_body(name="bob", shape={"type": "sphere", "radius": 0.1}, mass=1, position=(0, -1, 0))
    w.add_joint(type="ball", body_a="bob", anchor=(0, 0, 0))
    with pytest.raises(rbsim.InputError, match="PGS"):
        w.solver = "pgs"
    assert w.solver == "soft-step"


def test_settings_that_are_not_live_stay_read_only():
    w = rbsim.World()
    with pytest.raises(AttributeError):
        w.broad_phase = "brute-force"
