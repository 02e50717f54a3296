"""Bad input raises, with the field named and the command line's own words."""
import json
import math

import numpy as np
import pytest
import rbsim

from conftest import SOURCE, run_cli

BAD = SOURCE / "tests" / "data" / "bad"


def scene_cases():
    """The bad-input corpus's cases that are a scene file and --set overrides (others are flags
    of the program: --png-level, --window, ...)."""
    with open(BAD / "cases.json") as f:
        cases = json.load(f)["cases"]
    for case in cases:
        args = [a.replace("{dir}", str(BAD)) for a in case["args"]]
        if args[0] != "run" or case.get("env") or "{tmp}" in " ".join(args):
            continue
        rest, overrides = args[2:], []
        while rest and rest[0] in ("--set", "--no-render"):
            if rest[0] == "--set":
                overrides.append(rest[1])
            rest = rest[2:] if rest[0] == "--set" else rest[1:]
        if not rest:
            yield pytest.param(args, args[1], overrides, id=case["name"])


@pytest.mark.parametrize("args,scene,overrides", list(scene_cases()))
def test_corpus_case_fails_in_python_as_on_the_command_line(rbsim_binary, args, scene, overrides):
    code, stderr = run_cli(rbsim_binary, *args, "--no-render", "--quiet")
    try:
        # load_comparison reads a plain scene as one world, and a "compare" block as the program does
        for _, scene_of_value in rbsim.load_comparison(scene, overrides):
            scene_of_value.world().step(scene_of_value.steps)
    except (rbsim.InputError, rbsim.SimulationError) as e:
        assert code != 0, f"Python refused what the program ran: {e}"
        assert str(e) in stderr, f"Python: {e}\nprogram: {stderr}"
        return
    assert code == 0, f"the program refused what Python ran: {stderr}"


def test_the_corpus_gives_cases():
    assert len(list(scene_cases())) > 100


@pytest.mark.parametrize("keywords,field,words", [
    ({"dt": 0}, "dt", "expected a positive time step"),
    ({"dt": math.nan}, "dt", "finite"),
    ({"integrator": "rk5"}, "integrator", 'did you mean "rk4"'),
    ({"solver": "fast"}, "solver", 'expected "soft-step", "pgs" or "lcp"'),
    ({"gravty": [0, 0, 0]}, "gravty", 'did you mean "gravity"'),
    ({"substeps": 2.5}, "substeps", "expected an integer"),
    ({"gravity": [0, -9.81]}, "gravity", "3"),
])
def test_bad_world_keywords(keywords, field, words):
    with pytest.raises(rbsim.InputError) as e:
        rbsim.World(**keywords)
    assert e.value.file == "World()" and e.value.field == field and words in e.value.problem
    assert isinstance(e.value, ValueError)


@pytest.mark.parametrize("keywords,field", [
    ({"shape": {"type": "sphere", "radius": -1}, "mass": 1}, "shape.radius"),
    ({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "position": [0, math.nan, 0]}, "position"),
    ({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "velocity": [3e8, 0, 0]}, "velocity"),
    ({"shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 0}, "mass"),
    ({"shape": {"type": "cone"}, "mass": 1}, "shape.type"),
    ({"shape": {"type": "box", "extents": [1, 1, 1]}, "mass": 1, "static": True, "kinematic": True}, "kinematic"),
    ({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "forces": [{"force": [1, 0, 0], "end": -1}]},
     "forces[0].end"),
    ({"shape": {"type": "sphere", "radius": 1}, "mass": 1, "colour": [1, 0, 0]}, "colour"),
    ({"shape": {"type": "sphere", "radius": 1}, "mass": np.float64("inf")}, "mass"),
    ({"shape": {"type": "mesh", "file": "/no/such.obj"}, "mass": 1}, "shape.file"),
])
def test_bad_body_keywords_name_the_field(keywords, field):
    world = rbsim.World()
    with pytest.raises(rbsim.InputError) as e:
        world.add_body(**keywords)
    assert e.value.field == field or e.value.file == "/no/such.obj", str(e.value)
    assert len(world) == 0  # nothing half-added


def test_python_values_the_scene_format_has_no_word_for():
    world = rbsim.World()
    with pytest.raises(rbsim.InputError) as e:
        world.add_body(shape={"type": "sphere", "radius": 1}, mass=1, position=object())
    assert e.value.field == "position" and "got a object" in e.value.problem
    deep = []
    for _ in range(100):
        deep = [deep]
    with pytest.raises(rbsim.InputError) as e:
        world.add_body(shape={"type": "sphere", "radius": 1}, mass=1, position=deep)
    assert "nested deeper" in e.value.problem


def test_duplicate_name_and_stale_id():
    world = rbsim.World()
    body = world.add_body(name="ball", shape={"type": "sphere", "radius": 1}, mass=1)
    with pytest.raises(rbsim.InputError) as e:
        world.add_body(name="ball", shape={"type": "sphere", "radius": 1}, mass=1)
    assert e.value.field == "name" and "duplicate" in e.value.problem
    world.remove_body(body)
    for call in (lambda: world.remove_body(body), lambda: world.add_force(body, force=[1, 0, 0]),
                 lambda: world.set_pose(body, position=[0, 0, 0]), lambda: world.vertices(body)):
        with pytest.raises(rbsim.InputError) as e:
            call()
        assert e.value.field == "body"


def test_an_id_of_another_world_is_refused_naming_the_call():
    """Ids carry their World (issue 37): before, remove_body with another World's id removed a
    body of this one."""
    first, second = rbsim.World(), rbsim.World()
    ball = dict(shape={"type": "sphere", "radius": 0.5}, mass=1)
    mine = first.add_body(name="mine", **ball)
    theirs = second.add_body(name="theirs", **ball)
    assert mine.slot == theirs.slot and mine.generation == theirs.generation and mine != theirs
    for name, call in (("World.remove_body()", lambda: first.remove_body(theirs)),
                       ("World.set_pose()", lambda: first.set_pose(theirs, position=[0, 1, 0])),
                       ("World.add_force()", lambda: first.add_force(theirs, force=[1, 0, 0])),
                       ("World.index_of()", lambda: first.index_of(theirs)),
                       ("World.vertices()", lambda: first.vertices(theirs))):
        with pytest.raises(rbsim.InputError) as e:
            call()
        assert e.value.file == name and e.value.field == "body" and "another World" in e.value.problem, str(e.value)
        assert "command line" not in str(e.value)
    assert first.names == ["mine"] and not first.is_valid(theirs) and first.is_valid(mine)
    first.remove_body(mine)
    with pytest.raises(rbsim.InputError) as e:
        first.remove_body(mine)
    assert e.value.file == "World.remove_body()" and "removed" in e.value.problem


def test_default_names_stay_unique_after_removals():
    world = rbsim.World()
    ball = dict(shape={"type": "sphere", "radius": 0.5}, mass=1)
    ids = [world.add_body(**ball) for _ in range(3)]
    world.remove_body(ids[0])
    added = [world.add_body(**ball) for _ in range(3)]  # refused as duplicates before
    assert len(set(world.names)) == len(world.names) == 5
    assert all(world.is_valid(i) for i in ids[1:] + added)


@pytest.mark.parametrize("keywords,field", [
    (dict(velocity=[1e300, 0, 0]), "velocity"),            # gave inf before
    (dict(velocity=[3e8, 0, 0]), "velocity"),              # faster than light
    (dict(position=[2e6, 0, 0]), "position"),              # past the scene's 1e6 m
    (dict(angular_velocity=[0, 1e10, 0]), "angular_velocity"),
])
def test_set_pose_applies_the_scenes_ranges(keywords, field):
    world = rbsim.World()
    body = world.add_body(shape={"type": "sphere", "radius": 0.5}, mass=1)
    before = world.x.copy()
    with pytest.raises(rbsim.InputError) as e:
        world.set_pose(body, **keywords)
    assert e.value.field == field and e.value.file == "World.set_pose()"
    assert (world.x == before).all() and np.isfinite(world.v).all()


@pytest.mark.parametrize("call,words", [
    (lambda w, b: w.step("10"), "World.step(): steps: expected an int, got str"),
    (lambda w, b: w.step(2.5), "World.step(): steps: expected an int, got float"),
    (lambda w, b: w.step(True), "World.step(): steps: expected an int, got bool"),
    (lambda w, b: w.remove_body("ball"), "World.remove_body(): body: expected a BodyId"),
    (lambda w, b: w.remove_body(0), "World.remove_body(): body: expected a BodyId (from add_body or id_at), got int"),
    (lambda w, b: w.set_pose(b.slot, position=[0, 1, 0]), "World.set_pose(): body: expected a BodyId"),
    (lambda w, b: w.add_force(None, force=[1, 0, 0]), "World.add_force(): body: expected a BodyId (from add_body or id_at), got NoneType"),
    (lambda w, b: w.index_of([b]), "World.index_of(): body: expected a BodyId"),
    (lambda w, b: w.vertices("ball"), "World.vertices(): body: expected a BodyId"),
    (lambda w, b: w.exact_rotation(b, "soon"), "World.exact_rotation(): times: expected numbers"),
    (lambda w, b: w.id_at("0"), "World.id_at(): index: expected an int, got str"),
    (lambda w, b: w.add_body({"shape": {"type": "sphere", "radius": 1}}), "World.add_body() takes keyword arguments only"),
    (lambda w, b: w.add_plane([0, 1, 0]), "World.add_plane() takes keyword arguments only"),
    (lambda w, b: rbsim.World(1 / 60), "World() takes keyword arguments only"),
    (lambda w, b: rbsim.load_scene(3), "rbsim.load_scene(): path: expected a path (str or pathlib.Path), got int"),
    (lambda w, b: rbsim.load_scene("x.json", "world.dt=0.01"), "rbsim.load_scene(): overrides: expected a list of str"),
    (lambda w, b: rbsim.load_comparison("x.json", [1]), "rbsim.load_comparison(): overrides[0]: expected a str, got int"),
    (lambda w, b: rbsim.Renderer(width="640"), "Renderer(): width: expected an int, got str"),
    (lambda w, b: rbsim.Renderer(gl=1), "Renderer(): gl: expected a str, got int"),
    (lambda w, b: rbsim.Renderer(64, 64).render(b), "Renderer.render(): world: expected a World, got BodyId"),
    (lambda w, b: rbsim.Renderer(64, 64).render(w, selected=0), "Renderer.render(): selected: expected a BodyId"),
    (lambda w, b: rbsim.VideoWriter(None, 64, 64), "VideoWriter(): path: expected a path"),
])
def test_argument_type_errors_name_the_call_the_parameter_and_the_type(call, words):
    """Issue 37: pybind11 said "Unable to cast Python instance to C++ type" or listed signatures;
    now a TypeError names the call, the parameter and the type it expects, and changes nothing."""
    world = rbsim.World()
    ball = world.add_body(name="ball", shape={"type": "sphere", "radius": 0.5}, mass=1)
    with pytest.raises(TypeError) as e:
        call(world, ball)
    assert words in str(e.value) and "Unable to cast" not in str(e.value)
    assert world.names == ["ball"] and world.step_count == 0


def test_signatures_show_the_parameters_not_pybind11_s_object():
    """The types are the stubs' (python/rbsim/__init__.pyi, test_stubs.py); help() and inspect show
    each parameter with its default, never pybind11's "arg0: object"."""
    import inspect
    assert str(inspect.signature(rbsim.World.step)) == "(self, /, steps=1)"
    assert str(inspect.signature(rbsim.World.set_pose)).startswith("(self, /, body, position=None")
    for name in ("exact_rotation", "ray_cast", "add_force", "step"):
        assert "object" not in str(inspect.signature(getattr(rbsim.World, name)))


def test_paths_may_be_pathlib_paths(tmp_path):
    scene = tmp_path / "scene.json"
    scene.write_text('{"bodies": [{"shape": {"type": "sphere", "radius": 0.5}, "mass": 1}]}')
    assert len(rbsim.load_scene(scene).world()) == 1
    world = rbsim.World()
    with pytest.raises(rbsim.InputError) as e:
        world.id_at(-1)
    assert e.value.field == "index"


def test_bad_plane_force_pose_and_steps():
    world = rbsim.World()
    with pytest.raises(rbsim.InputError) as e:
        world.add_plane(normal=[0, 0, 0])
    assert e.value.field == "normal"
    wall = world.add_body(shape={"type": "box", "extents": [1, 1, 1]}, mass=1, static=True)
    with pytest.raises(rbsim.InputError) as e:
        world.add_force(wall, force=[1, 0, 0])
    assert e.value.field == "body" and "static" in e.value.problem
    with pytest.raises(rbsim.InputError) as e:
        world.set_pose(wall, velocity=[1, 0, 0])
    assert e.value.field == "velocity"
    with pytest.raises(rbsim.InputError) as e:
        world.step(-1)
    assert e.value.field == "steps" and e.value.file == "World.step()"


def test_scene_errors_carry_the_command_lines_message(rbsim_binary, tmp_path):
    scene = tmp_path / "scene.json"
    scene.write_text('{"bodies": [{"shape": {"type": "sphere", "radius": 0.5}, "mass": 1}]}')
    for overrides, field in ((["world.dt=-1"], "world.dt"), (["bodies[0].mass=-2"], "bodies[0].mass"),
                             (["world.integrator=\"rk5\""], "world.integrator"), (["no_equals"], "--set no_equals")):
        with pytest.raises(rbsim.InputError) as e:
            rbsim.load_scene(str(scene), overrides)
        assert e.value.field == field and e.value.file == str(scene)
        args = ["run", str(scene), "--no-render"] + [a for o in overrides for a in ("--set", o)]
        code, stderr = run_cli(rbsim_binary, *args)
        assert code == 2 and str(e.value) in stderr
    with pytest.raises(rbsim.InputError) as e:
        rbsim.load_scene(str(tmp_path / "missing.json"))
    assert "missing.json" in str(e.value)


def test_diverging_integrator_raises_simulation_error():
    # Explicit Euler on a stiff spring at dt = 0.01 s: omega dt = 10, far past its stability
    # limit, so the amplitude grows tenfold a step until the state is no longer finite.
    world = rbsim.World(dt=0.01, integrator="euler-quat", gravity=[0, 0, 0], collisions=False)
    world.add_body(shape={"type": "sphere", "radius": 0.1}, mass=1, position=[1, 0, 0],
                   springs=[{"anchor": [0, 0, 0], "stiffness": 1e6}])
    with pytest.raises(rbsim.SimulationError) as e:
        world.step(100000)
    assert isinstance(e.value, RuntimeError) and "body0" in str(e.value)
    assert world.step_count < 1000


def test_a_failed_step_leaves_the_world_as_it_was():
    # Issue 56, item 6: a step() that raised left the World half-stepped (the bodies before the
    # diverging one had moved). Now it is undone, and the World steps on once the cause is gone.
    w = rbsim.World(dt=1 / 60)
    w.add_plane()
    for i in range(5):
        w.add_body(shape={"type": "box", "extents": [1, 1, 1]}, mass=1, position=(0, 0.5 + 1.0 * i, 0))
    w.step(30)
    x, q, v, steps = w.x.copy(), w.q.copy(), w.v.copy(), w.step_count
    wild = w.add_body(shape={"type": "sphere", "radius": 0.1}, mass=1e-10, position=(5, 1, 0))
    w.add_force(wild, force=[1e308, 0, 0])  # dt |F| / m overflows
    with pytest.raises(rbsim.SimulationError, match=r"body5.*stopped being finite at step 30"):
        w.step(3)
    assert w.step_count == steps
    assert np.array_equal(w.x[:5], x) and np.array_equal(w.q[:5], q) and np.array_equal(w.v[:5], v)
    assert w.x[5].tolist() == [5.0, 1.0, 0.0]
    w.remove_body(wild)
    w.step(3)
    assert w.step_count == steps + 3
