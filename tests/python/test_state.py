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


# Pickled states (issue 57): a State pickles as the World's snapshot with its scene file, and a
# worker process given it steps bit for bit as this process does.
def _step_in_worker(name, pickled, steps, from_state):
    import pickle
    state = pickle.loads(pickled)
    if from_state:
        w = rbsim.World.from_state(state)
    else:
        w = rbsim.load_scene(name).world()
        w.set_state(state)
    hashes = []
    for _ in range(steps):
        w.step()
        hashes.append(w.state_hash())
    return hashes, w.contacts().tobytes(), pickle.dumps(w.get_state())


PICKLED_SCENES = ["contact_stacking", "assignment2_f_joints", "fracture_wall"]


@pytest.mark.parametrize("name", PICKLED_SCENES)
def test_a_pickled_state_steps_in_a_spawned_worker_bit_for_bit_as_here(name):
    import multiprocessing
    import pickle
    w = rbsim.load_scene(name).world()
    w.step(150)
    pickled = pickle.dumps(w.get_state())
    here = []
    for _ in range(200):
        w.step()
        here.append(w.state_hash())
    with multiprocessing.get_context("spawn").Pool(1) as pool:
        for from_state in (False, True):
            hashes, contacts, after = pool.apply(_step_in_worker, (name, pickled, 200, from_state))
            assert hashes == here  # at every step, not only the last
            assert contacts == w.contacts().tobytes()
            # The same snapshot; only the number of the World that gave it ("world", the last key
            # of the CBOR map) differs between the processes.
            theirs, ours = pickle.loads(after).__getstate__(), w.get_state().__getstate__()
            assert theirs[: theirs.rindex(b"eworld")] == ours[: ours.rindex(b"eworld")]


def test_a_pickled_state_round_trips_byte_for_byte_and_keeps_what_it_reports():
    import pickle
    w = rbsim.load_scene("contact_stacking").world()
    w.step(30)
    state = w.get_state()
    again = pickle.loads(pickle.dumps(state))
    assert again.__getstate__() == state.__getstate__()
    assert (again.time, again.step_count, again.world, again.scene) == (state.time, 30, state.world, state.scene)
    assert repr(again) == repr(state)
    # Into another World built from the same scene (the serial check is for states taken here).
    other = rbsim.load_scene("contact_stacking").world()
    other.set_state(again)
    w.step(60)
    other.step(60)
    assert other.state_hash() == w.state_hash() and np.array_equal(other.x, w.x)


def test_a_pickled_state_of_a_world_built_in_python_goes_into_one_built_alike():
    import pickle

    def build():
        w = rbsim.World(dt=1 / 60)
        w.add_plane(normal=(0, 1, 0), point=(0, 0, 0))
        w.add_body(name="box", shape={"type": "box", "extents": [1, 1, 1]}, mass=2, position=(0, 0.5, 0))
        w.add_body(name="ball", shape={"type": "sphere", "radius": 0.3}, mass=1, position=(0.2, 2, 0))
        return w

    w = build()
    w.step(20)
    state = pickle.loads(pickle.dumps(w.get_state()))
    alike = build()
    alike.set_state(state)
    w.step(100)
    alike.step(100)
    assert alike.state_hash() == w.state_hash()
    with pytest.raises(rbsim.InputError) as error:
        rbsim.World.from_state(state)
    assert error.value.field == "state" and "built in Python" in error.value.problem
    unlike = rbsim.World(dt=1 / 60)
    unlike.add_body(name="ball", shape={"type": "sphere", "radius": 0.3}, mass=1)
    before = unlike.state_hash()
    with pytest.raises(rbsim.InputError) as error:
        unlike.set_state(state)
    assert error.value.field == "state" and "'box'" in error.value.problem
    assert unlike.state_hash() == before and len(unlike) == 1  # a failed set_state changes nothing


def test_a_state_with_particles_is_refused_by_name_when_pickled():
    import pickle
    state = rbsim.load_scene("particles_fountain").world().get_state()
    with pytest.raises(rbsim.InputError) as error:
        pickle.dumps(state)
    assert error.value.file == "State.__getstate__()" and "step listeners" in error.value.problem


def test_save_writes_the_pickled_bytes_whole_and_load_state_reads_them(tmp_path):
    w = rbsim.load_scene("assignment2_f_joints").world()
    w.step(40)
    state = w.get_state()
    path = tmp_path / "joints.state"
    state.save(path)
    assert path.read_bytes() == state.__getstate__()
    assert sorted(p.name for p in tmp_path.iterdir()) == ["joints.state"]  # no temporary left behind
    state.save(str(path))  # replaces it whole
    loaded = rbsim.load_state(path)
    assert loaded.__getstate__() == state.__getstate__()
    w.step(50)
    other = rbsim.World.from_state(loaded)
    other.step(50)
    assert other.state_hash() == w.state_hash()


def test_a_corrupted_or_truncated_state_file_is_an_input_error_naming_the_file(tmp_path):
    w = rbsim.load_scene("contact_stacking").world()
    w.step(10)
    good = w.get_state().__getstate__()
    cases = {
        "flipped.state": good[:-40] + bytes([good[-40] ^ 0xFF]) + good[-39:],  # inside the snapshot
        "cut.state": good[: len(good) // 2],
        "empty.state": b"",
        "text.state": b"not a state",
    }
    for name, data in cases.items():
        path = tmp_path / name
        path.write_bytes(data)
        with pytest.raises(rbsim.InputError) as error:
            rbsim.load_state(path)
        assert error.value.file == str(path), name
    with pytest.raises(rbsim.InputError) as error:
        rbsim.load_state(tmp_path / "missing.state")
    assert error.value.file == str(tmp_path / "missing.state")
