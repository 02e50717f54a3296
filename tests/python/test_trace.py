"""The state arrays equal the program's CSV trace bit for bit, for the same scene and overrides.

The trace prints every number with 17 significant digits (%.17g), which reads back as the exact
double, so equality here is equality of the bits."""
import csv

import numpy as np
import pytest
import rbsim

from conftest import SCENES, run_cli

EVERY = 10  # trace every 10th step


def traced_states(binary, tmp_path, scene, overrides):
    trace = tmp_path / "trace.csv"
    args = ["run", str(scene), "--no-render", "--quiet", "--trace", str(trace), "--trace-every", str(EVERY)]
    for o in overrides:
        args += ["--set", o]
    code, err = run_cli(binary, *args)
    assert code == 0, err
    rows = {}
    with open(trace, newline="") as f:
        for row in csv.DictReader(f):
            rows.setdefault(int(row["step"]), []).append(row)
    return rows


def columns(rows, names):
    return np.array([[float(r[n]) for n in names] for r in rows])


def assert_matches(world, rows):
    assert [r["body"] for r in rows] == world.names
    np.testing.assert_array_equal(world.x, columns(rows, ["x", "y", "z"]))
    np.testing.assert_array_equal(world.q, columns(rows, ["qw", "qx", "qy", "qz"]))
    np.testing.assert_array_equal(world.v, columns(rows, ["vx", "vy", "vz"]))
    np.testing.assert_array_equal(world.omega, columns(rows, ["wx", "wy", "wz"]))
    np.testing.assert_array_equal(world.L, columns(rows, ["Lx", "Ly", "Lz"]))
    np.testing.assert_array_equal(world.ke, columns(rows, ["ke"])[:, 0])
    assert world.time == float(rows[0]["t"])


def compare_run(binary, tmp_path, scene, overrides):
    rows = traced_states(binary, tmp_path, scene, overrides)
    world = rbsim.load_scene(str(scene), overrides).world()
    steps = sorted(rows)
    assert len(steps) > 2
    for step in steps:
        world.step(step - world.step_count)
        assert_matches(world, rows[step])


# A pile coming to rest (contacts, soft step, sleep), round shapes rolling, and forces at points.
@pytest.mark.parametrize("scene,steps", [("contact_stacking.json", 120), ("round_shapes.json", 120),
                                         ("assignment2_c_force_at_point.json", 200)])
def test_scene_states_equal_the_trace(rbsim_binary, tmp_path, scene, steps):
    compare_run(rbsim_binary, tmp_path, SCENES / scene, [f"world.steps={steps}"])


@pytest.mark.parametrize("integrator", rbsim.integrators())
def test_every_integrator_equals_the_trace_at_60_hz(rbsim_binary, tmp_path, integrator):
    compare_run(rbsim_binary, tmp_path, SCENES / "assignment2_b_velocity.json",
                ["world.steps=120", "world.dt=0.016666666666666666", f"world.integrator={integrator}"])


def test_pgs_solver_equals_the_trace(rbsim_binary, tmp_path):
    compare_run(rbsim_binary, tmp_path, SCENES / "contact_stacking.json",
                ["world.steps=60", "world.solver=pgs", "world.dt=0.016666666666666666"])
