"""What one step may be asked to hold, from Python as from a scene (issue 56, item 2): a spawner's
period is held to the time step, and bodies piled into one place are refused by the step that
would list their pairs, leaving the world as it was."""
import pytest
import rbsim

BALL = {"shape": {"type": "sphere", "radius": 0.1}, "mass": 1.0}
AT_ONE_POINT = {"min": [0, 1, 0], "max": [0, 1, 0]}


def test_a_spawner_period_shorter_than_the_step_is_refused():
    world = rbsim.World(dt=1 / 60)
    with pytest.raises(rbsim.InputError, match=r"period: 1e-09 s is shorter than the time step"):
        world.add_spawner(period=1e-9, body=BALL, region=AT_ONE_POINT)
    world.step(2)
    assert len(world) == 0
    world.add_spawner(period=1 / 60, body=BALL, region=AT_ONE_POINT)
    world.step(2)
    assert len(world) == 2  # a burst a step


def test_bodies_piled_at_one_point_are_refused_by_the_step():
    world = rbsim.World(dt=1 / 60)
    world.add_spawner(period=1.0, count=2897, body=BALL, region=AT_ONE_POINT)  # 4.19e6 pairs: one past the bound
    with pytest.raises(rbsim.SimulationError, match=r"overlap in more than 4194304 pairs"):
        world.step()
    # The failed step is undone with its burst: the world is as it was, and the same step fails
    # the same way again rather than piling a second burst on the first.
    assert len(world) == 0
    assert world.time == 0.0
    with pytest.raises(rbsim.SimulationError, match=r"overlap in more than 4194304 pairs"):
        world.step()
    assert len(world) == 0
