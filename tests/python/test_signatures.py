"""Explicit keyword signatures (issue 39): each call's defaults, as inspect.signature shows them,
are what the scene format does when the key is left out, and None leaves a key out. A default
written in a docstring that drifted from the parser fails here."""
import inspect
import math

import pytest
import rbsim

BOX = {"type": "box", "extents": [0.4, 0.3, 0.2]}
TILT = tuple(c / math.sqrt(0.96 ** 2 + 0.2 ** 2 + 0.1 ** 2 + 0.17 ** 2) for c in (0.96, 0.2, 0.1, 0.17))


def defaults(call, skip=()):
    return {p.name: p.default for p in inspect.signature(call).parameters.values()
            if p.default is not inspect.Parameter.empty and p.name not in skip}


def test_world_defaults_are_the_world_block_s():
    plain = rbsim.World().settings
    for key, value in defaults(rbsim.World).items():
        assert rbsim.World(**{key: value}).settings == plain, key
    assert set(defaults(rbsim.World)) == set(plain) | {"steps"}  # the settings name every key but steps


# The keys run() gives itself.
GIVEN_BY_RUN = {"body": {"name", "shape", "mass"}, "plane": {"point"}, "joint": {"type", "body_a", "body_b", "anchor"}}


def run(body=None, plane=None, force=None, joint=None):
    """A tilted box thrown onto a plane 2 m down, optionally pushed and hung: its state after 0.5 s."""
    w = rbsim.World(dt=1 / 120, sleep=False)
    w.add_plane(point=(0, -2, 0), **(plane or {}))
    b = w.add_body(name="box", shape=BOX, mass=2.0, **(body or {}))
    w.set_pose(b, orientation=TILT, velocity=(1.0, 0.0, 0.5), angular_velocity=(0.0, 3.0, 1.0))
    if force is not None:
        w.add_force(b, **force)
    if joint is not None:
        w.add_body(name="post", shape=BOX, mass=1.0, static=True, position=(0, 3, 0))
        w.add_joint(type="ball", body_a="box", body_b="post", anchor=(0, 1, 0), **joint)
    w.step(60)
    return w.state_hash()


@pytest.mark.parametrize("call,argument", [
    (rbsim.World.add_body, "body"), (rbsim.World.add_plane, "plane"), (rbsim.World.add_force, "force"),
    (rbsim.World.add_joint, "joint"),
])
def test_each_default_given_is_the_key_left_out_and_so_is_none(call, argument):
    plain = run(**{argument: {}})
    params = inspect.signature(call).parameters
    for name, p in params.items():
        if p.kind is not inspect.Parameter.KEYWORD_ONLY or p.default is inspect.Parameter.empty:
            continue
        if name in GIVEN_BY_RUN.get(argument, ()):
            continue
        given = run(**{argument: {name: p.default}})
        assert given == plain, (argument, name, p.default)
    assert any(p.default is not None and p.default is not inspect.Parameter.empty for p in params.values())


def test_none_for_a_key_without_a_none_default_is_still_the_key_left_out():
    assert run(body={"position": None, "velocity": None, "static": None}) == run()
