"""Worlds on disk from Python (issue 57): World.save_scene writes a scene file that loads back into
the same World; World.run and rbsim.run write the program's trace, recording and glTF, byte for
byte; rbsim.read_recording reads a recording back as the World's arrays."""
import numpy as np
import pytest
import rbsim

from conftest import SCENES, SOURCE, run_cli

MESH = SOURCE / "assets" / "meshes" / "l_bracket.obj"


def every_kind_of_world(dt, spawner=True):
    """A World with every body shape, a compound, a mesh, static and kinematic bodies, forces,
    springs, a set_pose event, joints, planes, a spawner, a kill volume and changed settings."""
    w = rbsim.World(dt=dt, integrator="rk4", contact_hertz=40.0, gravity=(0.1, -9.7, 0.05))
    w.add_plane()
    w.add_plane(normal=(1, 0.2, 0), point=(-3, 0, 0), restitution=0.3)
    shapes = [{"type": "box", "extents": (0.4, 0.3, 0.2)}, {"type": "sphere", "radius": 0.21},
              {"type": "capsule", "radius": 0.1, "length": 0.3},
              {"type": "rounded_box", "extents": (0.3, 0.3, 0.3), "radius": 0.05},
              {"type": "torus", "major_radius": 0.3, "minor_radius": 0.08},
              {"type": "mesh", "file": str(MESH), "scale": 0.5}]
    for i, shape in enumerate(shapes):
        w.add_body(shape=shape, mass=1.0 + i / 3, position=(0.9 * i - 2, 0.6 + 0.1 * i, 0.1 * i),
                   orientation={"axis_angle_deg": (1, 2, 3, 17.0 * i)}, velocity=(0.1, 0.2 / 3, 0),
                   angular_velocity=(0.3, -1 / 7, 0.2))
    table = w.add_body(name="table", mass=3, position=(0, 2, 1),
                       shapes=[{"type": "box", "extents": (1.2, 0.06, 0.8), "position": (0, 0.73, 0)},
                               {"type": "box", "extents": (0.06, 0.7, 0.06), "position": (-0.55, 0.35, -0.35)}])
    w.add_force(table, force=(0.5, 0, 0), point=(0.1, 0, 0))
    w.add_body(name="wall", static=True, mass=1, shape={"type": "box", "extents": (0.2, 2, 2)}, position=(4, 1, 0))
    w.add_body(name="drum", kinematic=True, mass=1, shape={"type": "box", "extents": (0.5, 0.1, 0.5)}, position=(2, 3, 2),
               motion={"pivot": (2, 3, 2), "angular_velocity": (0, 1, 0)})
    w.add_body(name="bob", shape={"type": "sphere", "radius": 0.1}, mass=0.5, position=(0, 4, -2),
               springs=[{"anchor": (0, 5, -2), "stiffness": 40.0, "damping": 0.3}],
               forces=[{"force": (0, 2, 0), "start": 0.1, "end": 0.5}],
               set_pose=[{"time": 0.4, "velocity": (0.2, 0, 0)}])
    w.add_body(name="rod", shape={"type": "box", "extents": (0.8, 0.1, 0.1)}, mass=1.0, position=(-1, 4, 2))
    w.add_body(name="door", shape={"type": "box", "extents": (0.8, 1.0, 0.05)}, mass=2.0, position=(1, 4, 2))
    w.add_joint(type="ball", body_a="rod", anchor=(-1.4, 4, 2))
    w.add_joint(type="hinge", body_a="door", body_b="rod", anchor=(0.6, 4, 2), axis=(0, 1, 0),
                motor={"speed": 1.0, "max_torque": 2.0}, limits=(-1, 1), name="hinge")
    if spawner:
        w.add_spawner(name="rock", period=0.3, count=2, seed=5, body={"shape": {"type": "sphere", "radius": 0.1}, "mass": 1.0},
                      region={"min": (-1, 5, -1), "max": (1, 6, 1)})
    w.kill_volume = (-20, -5, -20, 20, 30, 20)
    removed = w.add_body(shape={"type": "sphere", "radius": 0.1}, mass=1, position=(9, 9, 9))
    w.add_body(name="last", mass=1, shape={"type": "box", "extents": (0.2, 0.2, 0.2)}, position=(-3, 1, -1))
    w.remove_body(removed)  # "last" takes its row: the file must keep the World's order
    w.set_pose(w.id_at(0), position=(-2, 0.7, 0.05), velocity=(0, 0.5, 0))
    return w


@pytest.mark.parametrize("dt", [1 / 60, 1 / 240])
def test_a_saved_scene_loads_back_into_the_same_world(tmp_path, dt):
    world = every_kind_of_world(dt)
    path = tmp_path / "world.json"
    world.save_scene(path)
    loaded = rbsim.load_scene(str(path)).world()
    assert loaded.names == world.names
    assert loaded.state_hash() == world.state_hash()
    for w in (world, loaded):
        w.step(300)
    assert len(world) > 13  # the spawner's rocks came, the bodies are all there
    np.testing.assert_array_equal(loaded.x, world.x)
    assert loaded.state_hash() == world.state_hash()


def test_a_scene_saved_after_steps_holds_the_poses_then(tmp_path):
    world = rbsim.World(dt=1 / 60)
    world.add_plane()
    for i in range(3):
        world.add_body(shape={"type": "box", "extents": (0.3, 0.3, 0.3)}, mass=1, position=(i, 2 + i, 0),
                       angular_velocity=(1, 2, 3))
    world.add_body(shape={"type": "capsule", "radius": 0.1, "length": 0.4}, mass=1, position=(0, 4, 1))
    world.step(20)  # falling, not yet touching: no warm starts to lose
    assert world.contact_count == 0
    path = tmp_path / "later.json"
    world.save_scene(path)
    loaded = rbsim.load_scene(str(path)).world()
    np.testing.assert_array_equal(loaded.x, world.x)
    np.testing.assert_allclose(loaded.q, world.q, rtol=0, atol=1e-15)
    np.testing.assert_allclose(loaded.v, world.v, rtol=1e-15, atol=1e-15)
    np.testing.assert_allclose(loaded.omega, world.omega, rtol=1e-14, atol=1e-15)
    world.step(10)  # still in free flight: the same motion to rounding
    loaded.step(10)
    np.testing.assert_allclose(loaded.x, world.x, rtol=0, atol=1e-13)
    np.testing.assert_allclose(loaded.q, world.q, rtol=0, atol=1e-13)
    world.step(200)  # landed tumbling: contacts amplify the last bits, not the outcome
    loaded.step(200)
    np.testing.assert_allclose(loaded.x[:, 1], world.x[:, 1], atol=1e-6)
    np.testing.assert_allclose(loaded.x, world.x, atol=2e-3)


def test_what_a_scene_file_cannot_say_after_steps_is_refused(tmp_path):
    world = every_kind_of_world(1 / 60, spawner=False)
    world.step(1)
    path = tmp_path / "no.json"
    with pytest.raises(rbsim.InputError, match=r"World.save_scene\(\).*has run 1 steps.*save it before the first step"):
        world.save_scene(path)
    assert not path.exists()
    loaded = rbsim.load_scene(str(SCENES / "contact_stacking.json")).world()
    with pytest.raises(rbsim.InputError, match=r"loaded from .*contact_stacking.json"):
        loaded.save_scene(path)


def test_a_bad_place_is_an_input_error_naming_the_file_and_leaves_nothing(tmp_path):
    world = every_kind_of_world(1 / 60)
    missing = tmp_path / "no" / "such" / "world.json"
    with pytest.raises(rbsim.InputError, match=r"world.json: World.save_scene\(\): cannot write"):
        world.save_scene(missing)
    blocker = tmp_path / "a_file"
    blocker.write_text("not a folder")
    with pytest.raises(rbsim.InputError) as e:
        world.save_scene(blocker / "w.json")
    assert e.value.file == str(blocker / "w.json") and "Not a directory" in e.value.problem
    with pytest.raises(rbsim.InputError, match=r"a_file/t.csv: --trace: cannot create the trace file's folder"):
        world.run(10, trace=blocker / "t.csv")
    assert sorted(p.name for p in tmp_path.iterdir()) == ["a_file"]  # no partial file anywhere
    assert world.step_count == 0
    with pytest.raises(rbsim.InputError, match=r"cannot write"):
        world.save_scene("/dev/full")
    old = tmp_path / "old.json"
    old.write_text("kept")
    with pytest.raises(TypeError, match=r"World.save_scene\(\): path"):
        world.save_scene(3)
    assert old.read_text() == "kept"


def program_outputs(binary, tmp_path, scene, *args):
    out = {k: tmp_path / f"cli.{k}" for k in ("csv", "rbrec", "glb")}
    code, err = run_cli(binary, "run", str(scene), "--no-render", "--quiet", "--trace", str(out["csv"]), "--trace-every",
                        "3", "--record", str(out["rbrec"]), "--gltf", str(out["glb"]), *args)
    assert code == 0, err
    return {k: p.read_bytes() for k, p in out.items()}


@pytest.mark.parametrize("scene", ["contact_stacking.json", "assignment2_f_joints.json"])
def test_the_outputs_are_the_programs_byte_for_byte(rbsim_binary, tmp_path, scene):
    path = SCENES / scene
    overrides = ["world.steps=150"]
    cli = program_outputs(rbsim_binary, tmp_path, path, "--set", overrides[0])
    out = {k: tmp_path / f"py.{k}" for k in ("csv", "rbrec", "glb")}
    summary = rbsim.run(path, overrides, trace=out["csv"], trace_every=3, record=out["rbrec"], gltf=out["glb"])
    assert summary["steps"] == 150 and summary["record_bytes"] == len(cli["rbrec"])
    for k in out:
        assert out[k].read_bytes() == cli[k], k
    # A World loaded from the scene, stepped by World.run: the same trace and glTF (a recording of
    # a loaded World is rbsim.run's, which knows the overrides).
    world = rbsim.load_scene(str(path), overrides).world()
    world.run(150, trace=tmp_path / "w.csv", trace_every=3, gltf=tmp_path / "w.glb")
    assert world.step_count == 150
    assert (tmp_path / "w.csv").read_bytes() == cli["csv"]
    assert (tmp_path / "w.glb").read_bytes() == cli["glb"]
    again = rbsim.load_scene(str(path), overrides).world()
    again.step(150)
    assert again.state_hash() == world.state_hash()


@pytest.mark.parametrize("dt", [1 / 60, 1 / 240])
def test_a_world_built_in_python_runs_as_its_saved_scene_runs_in_the_program(rbsim_binary, tmp_path, dt):
    world = every_kind_of_world(dt, spawner=False)
    world.kill_volume = None  # recordings keep no spawned or removed bodies yet
    scene = tmp_path / "built.json"
    world.save_scene(scene)
    cli = program_outputs(rbsim_binary, tmp_path, scene, "--set", "world.steps=300")
    out = {k: tmp_path / f"py.{k}" for k in ("csv", "rbrec", "glb")}
    twin = rbsim.load_scene(str(scene)).world()
    world.run(300, trace=out["csv"], trace_every=3, record=out["rbrec"], gltf=out["glb"])
    assert out["csv"].read_bytes() == cli["csv"]
    assert out["glb"].read_bytes() == cli["glb"]
    twin.step(300)
    assert world.state_hash() == twin.state_hash()
    # The recording holds the saved scene's text (the header differs in its file's name only), and
    # every step's state: read back, each equals the World's at that step.
    rec = rbsim.read_recording(out["rbrec"])
    assert rec["names"] == world.names and rec["worlds"] == 1 and rec["file"] == "World.run()"
    assert rec["x"].shape == (300, len(world), 3) and rec["q"].shape == (300, len(world), 4)
    np.testing.assert_array_equal(rec["step"], np.arange(1, 301))
    replayed = rbsim.load_scene(str(scene)).world()
    for step in (1, 7, 150, 300):
        replayed.step(step - replayed.step_count)
        row = step - 1
        assert rec["time"][row] == replayed.time
        for key in ("x", "q", "v", "omega", "P", "L", "awake"):
            np.testing.assert_array_equal(rec[key][row], getattr(replayed, key), err_msg=key)
    # The program replays it: the trace of the replay is the run's.
    code, err = run_cli(rbsim_binary, "replay", str(out["rbrec"]), "--no-render", "--quiet", "--trace",
                        str(tmp_path / "replay.csv"), "--trace-every", "3")
    assert code == 0, err
    assert (tmp_path / "replay.csv").read_bytes() == cli["csv"]
    cli_rec = rbsim.read_recording(tmp_path / "cli.rbrec")
    for key in ("step", "time", "x", "q", "P", "L", "awake"):
        np.testing.assert_array_equal(cli_rec[key], rec[key], err_msg=key)


def test_a_bad_recording_is_an_input_error_naming_the_file(tmp_path):
    rec = tmp_path / "r.rbrec"
    summary = rbsim.run(SCENES / "contact_stacking.json", ["world.steps=40"], record=rec)
    data = rec.read_bytes()
    assert summary["record_bytes"] == len(data)
    cut = tmp_path / "cut.rbrec"
    cut.write_bytes(data[: len(data) - 9])
    with pytest.raises(rbsim.InputError, match=r"cut.rbrec.*truncated"):
        rbsim.read_recording(cut)
    junk = tmp_path / "junk.rbrec"
    junk.write_bytes(b"not a recording at all")
    with pytest.raises(rbsim.InputError) as e:
        rbsim.read_recording(junk)
    assert e.value.file == str(junk)
    with pytest.raises(rbsim.InputError, match=r"nothing.rbrec"):
        rbsim.read_recording(tmp_path / "nothing.rbrec")
    with pytest.raises(rbsim.InputError, match=r"read_recording\(\): world: expected a world from 0 to 1 - 1"):
        rbsim.read_recording(rec, world=1)


def test_a_recording_whose_bodies_change_is_refused_naming_the_step(tmp_path):
    # machinery_rain's first ragdolls are spawned in step 1 (a burst a second from t = 0).
    rec = tmp_path / "rain.rbrec"
    rbsim.run(SCENES / "machinery_rain.json", ["world.steps=3"], record=rec)
    with pytest.raises(rbsim.InputError, match=r"rain.rbrec: world: world 0's bodies change at step 1") as e:
        rbsim.read_recording(rec)
    assert e.value.file == str(rec)


def test_run_refuses_what_it_cannot_write(tmp_path):
    world = every_kind_of_world(1 / 60, spawner=False)
    with pytest.raises(rbsim.InputError, match=r"World.run\(\): steps"):
        world.run(0, trace=tmp_path / "t.csv")
    with pytest.raises(rbsim.InputError, match=r"trace_every"):
        world.run(5, trace=tmp_path / "t.csv", trace_every=0)
    world.step(1)
    with pytest.raises(rbsim.InputError, match=r"World.run\(\): record: a recording or a glTF holds a run from step 0"):
        world.run(5, record=tmp_path / "r.rbrec")
    assert not (tmp_path / "r.rbrec").exists() and not (tmp_path / "t.csv").exists()
    world.run(5, trace=tmp_path / "t.csv", trace_every=2)  # a trace may start anywhere
    steps = [line.split(",")[0] for line in (tmp_path / "t.csv").read_text().splitlines()[1:]]
    assert sorted(set(map(int, steps))) == [2, 4, 6]
    assert world.step_count == 6
