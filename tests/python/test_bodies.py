"""Bodies built from Python: free fall against the closed forms, every shape, ids, forces, planes."""
import numpy as np
import pytest
import rbsim

G = np.array([0.0, -9.81, 0.0])
X0 = np.array([1.0, 5.0, -2.0])
V0 = np.array([0.5, 3.0, 0.25])

# How each integrator moves x under constant gravity, as a closed form after n steps of dt:
# half kicks and RK4 are exact, x0 + v0 t + g t^2/2; explicit Euler moves with the old velocity,
# x0 + v0 t + g dt^2 n(n-1)/2; semi-implicit (symplectic) Euler with the new one, g dt^2 n(n+1)/2.
FALL = {
    "euler-matrix": "explicit", "euler-quat": "explicit", "expmap": "explicit",
    "symplectic-euler": "semi-implicit", "implicit-gyro": "semi-implicit",
    "rk4": "exact", "dlm": "exact", "exact": "exact", "exact4": "exact", "newmark": "exact",
}


def test_every_integrator_is_in_the_table():
    assert sorted(FALL) == sorted(rbsim.integrators())


@pytest.mark.parametrize("dt", [1 / 60, 1 / 240])
@pytest.mark.parametrize("integrator", sorted(FALL))
def test_body_added_from_python_falls_as_its_integrator_says(integrator, dt):
    world = rbsim.World(dt=dt, integrator=integrator, collisions=False)
    body = world.add_body(shape={"type": "box", "extents": [0.2, 0.3, 0.4]}, mass=2.0, position=X0,
                          velocity=V0, angular_velocity=[1.0, 2.0, 3.0])
    n = 90
    world.step(n)
    t = n * dt
    assert world.time == pytest.approx(t, rel=1e-15)
    drop = {"exact": t * t / 2, "explicit": dt * dt * n * (n - 1) / 2, "semi-implicit": dt * dt * n * (n + 1) / 2}
    expected = X0 + V0 * t + G * drop[FALL[integrator]]
    i = world.index_of(body)
    np.testing.assert_allclose(world.x[i], expected, rtol=0, atol=1e-12)
    np.testing.assert_allclose(world.v[i], V0 + G * t, rtol=0, atol=1e-12)
    np.testing.assert_allclose(world.P[i], 2.0 * (V0 + G * t), rtol=0, atol=1e-12)
    if FALL[integrator] == "exact":  # and x0 + v0 t + g t^2 / 2 itself
        np.testing.assert_allclose(world.x[i], X0 + V0 * t + 0.5 * G * t * t, rtol=0, atol=1e-12)


def test_state_arrays_are_consistent():
    world = rbsim.World(dt=1 / 120, gravity=[0, 0, 0], collisions=False)
    world.add_body(shape={"type": "box", "extents": [1.0, 0.2, 0.5]}, mass=3.0, angular_velocity=[0.3, 4.0, 0.2])
    world.add_body(shape={"type": "capsule", "radius": 0.1, "length": 0.5}, density=500, velocity=[1, 0, 0])
    world.step(37)
    s = world.state()
    assert s["x"].shape == (2, 3) and s["q"].shape == (2, 4) and s["R"].shape == (2, 3, 3)
    for R, q in zip(s["R"], s["q"]):
        w, x, y, z = q
        assert np.allclose(R @ R.T, np.eye(3), atol=1e-12) and np.linalg.det(R) == pytest.approx(1.0)
        # R from the quaternion (w, x, y, z)
        Rq = np.array([[1 - 2 * (y * y + z * z), 2 * (x * y - w * z), 2 * (x * z + w * y)],
                       [2 * (x * y + w * z), 1 - 2 * (x * x + z * z), 2 * (y * z - w * x)],
                       [2 * (x * z - w * y), 2 * (y * z + w * x), 1 - 2 * (x * x + y * y)]])
        np.testing.assert_allclose(R, Rq, atol=1e-12)
    np.testing.assert_allclose(s["P"], world.mass[:, None] * s["v"], rtol=1e-14)
    ke = 0.5 * (np.einsum("ij,ij->i", s["P"], s["v"]) + np.einsum("ij,ij->i", s["L"], s["omega"]))
    np.testing.assert_allclose(s["ke"], ke, rtol=1e-12)
    # Torque-free: L and the kinetic energy are conserved by the default (exact) integrator.
    np.testing.assert_allclose(world.L[0], [3.0 / 12 * (0.2**2 + 0.5**2) * 0.3, 3.0 / 12 * (1 + 0.25) * 4.0,
                                            3.0 / 12 * (1 + 0.04) * 0.2], rtol=1e-12)
    # The vertex list: p' = R p + x for every vertex (seed 004).
    body = world.id_at(0)
    np.testing.assert_allclose(world.vertices(body), world.body_vertices(body) @ s["R"][0].T + s["x"][0], atol=1e-12)
    assert world.vertices(body).shape == (8, 3)


@pytest.mark.parametrize("shape,radius", [
    ({"type": "sphere", "radius": 0.3}, 0.3),
    ({"type": "box", "extents": [0.4, 0.4, 0.4]}, 0.2),
    ({"type": "capsule", "radius": 0.15, "length": 0.6}, 0.15),  # lies down: its radius
    ({"type": "torus", "major_radius": 0.3, "minor_radius": 0.1}, 0.1),  # a hull, lies flat
    ({"type": "mesh", "file": "assets/meshes/l_bracket.obj", "scale": 0.5}, None),
])
def test_every_shape_comes_to_rest_on_a_plane(shape, radius):
    import conftest
    if shape["type"] == "mesh":
        shape = dict(shape, file=str(conftest.SOURCE / shape["file"]))
    world = rbsim.World(dt=1 / 60)
    world.add_plane(normal=[0, 1, 0], point=[0, 0, 0])
    world.add_body(shape=shape, density=1000, position=[0, 1.0, 0], orientation={"axis_angle_deg": [1, 0, 0, 90]})
    world.step(240)
    assert np.abs(world.v).max() < 0.02
    lowest = world.vertices(world.id_at(0))[:, 1].min()
    assert -0.01 < lowest < 0.02  # resting on the plane, not in it, not above it
    if radius is not None and shape["type"] in ("sphere", "capsule"):
        assert world.x[0, 1] == pytest.approx(radius, abs=0.01)


def test_ids_survive_removal():
    world = rbsim.World(collisions=False)
    ids = [world.add_body(name=f"b{k}", shape={"type": "sphere", "radius": 0.1}, mass=1, position=[k, 0, 0])
           for k in range(4)]
    world.remove_body(ids[1])
    assert not world.is_valid(ids[1]) and len(world) == 3
    assert world.names == ["b0", "b3", "b2"]  # the last took the hole
    assert world.x[world.index_of(ids[3]), 0] == 3.0
    again = world.add_body(name="b1", shape={"type": "sphere", "radius": 0.1}, mass=1)
    assert again != ids[1] and again.slot == ids[1].slot  # slot reused, generation bumped
    with pytest.raises(rbsim.InputError) as e:
        world.x[world.index_of(ids[1])]
    assert e.value.field == "body"


def test_force_from_python_accelerates_as_f_over_m():
    world = rbsim.World(dt=1 / 100, gravity=[0, 0, 0], integrator="dlm")
    body = world.add_body(shape={"type": "sphere", "radius": 0.2}, mass=4.0)
    world.add_force(body, force=[8.0, 0, 0], end=0.5)
    world.step(100)
    # a = 2 m/s^2 for 0.5 s: v = 1, x = 0.25 + 1 * 0.5
    np.testing.assert_allclose(world.v[0], [1.0, 0, 0], atol=1e-12)
    np.testing.assert_allclose(world.x[0], [0.75, 0, 0], atol=1e-12)


def test_set_pose_moves_and_wakes():
    world = rbsim.World(dt=1 / 60)
    world.add_plane()
    body = world.add_body(shape={"type": "box", "extents": [0.5, 0.5, 0.5]}, mass=1, position=[0, 0.25, 0])
    world.step(120)
    assert not world.awake[0]
    world.set_pose(body, position=[0, 2, 0], velocity=[1, 0, 0])
    assert world.awake[0] and world.x[0, 1] == 2.0 and world.v[0, 0] == 1.0
    before = world.state()
    with pytest.raises(rbsim.InputError) as e:
        world.set_pose(body, position=[5, 5, 5], orientation=[1, 1, 0, 0])
    assert e.value.field == "orientation"
    np.testing.assert_array_equal(world.x, before["x"])  # a refused call changes nothing
    np.testing.assert_array_equal(world.q, before["q"])


def test_settings_and_names():
    world = rbsim.World(dt=0.01, integrator="rk4", solver="pgs", gravity=[0, -1.62, 0])
    assert world.settings["integrator"] == "rk4" and world.settings["solver"] == "pgs"
    assert world.settings["gravity"] == (0, -1.62, 0) and world.dt == 0.01
    assert set(rbsim.solvers()) == {"soft-step", "pgs", "lcp"}
