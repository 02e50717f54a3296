"""World.particles() (issue 39): every live particle of the scene's particle systems, as one
structured array, against what the fountain's emitter was told to make."""
import numpy as np
import pytest
import rbsim


def test_the_fountain_s_particles_are_what_its_emitter_makes():
    w = rbsim.load_scene("particles_fountain").world()
    w.step(240)  # one second at dt = 1/240: 2500 particles a second, none old enough to die (3-4 s)
    p = w.particles()
    assert p.dtype.names == ("system", "x", "v", "mass", "age", "lifetime")
    assert len(p) == pytest.approx(2500, abs=2)
    assert set(p["system"]) == {0}
    assert p["mass"].min() >= 0.001 and p["mass"].max() <= 0.002
    assert p["lifetime"].min() >= 3.0 and p["lifetime"].max() <= 4.0
    assert p["age"].max() <= 1.0 + 1e-9
    # The youngest have hardly slowed: speeds drawn from [6, 7] m/s, less a step of g and drag.
    young = p[p["age"] <= p["age"].min() + 1e-12]
    speeds = np.linalg.norm(young["v"], axis=1)
    assert speeds.min() > 6.0 - 9.81 / 240 * 2 and speeds.max() <= 7.0
    # None below the ground they bounce on (radius 0.01 m).
    assert p["x"][:, 1].min() >= 0.0


def test_a_world_without_particles_has_an_empty_array():
    assert rbsim.World().particles().shape == (0,)
