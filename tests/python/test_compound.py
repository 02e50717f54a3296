"""Compound bodies, collision filters and kinematic motion from Python: the keys "shapes",
"filter" and "motion" of World.add_body, as in a scene's "bodies"."""
import math

import numpy as np
import pytest
import rbsim


def table_shapes():
    shapes = [{"type": "box", "extents": [1.2, 0.06, 0.8], "position": [0, 0.73, 0]}]
    for x in (-0.55, 0.55):
        for z in (-0.35, 0.35):
            shapes.append({"type": "box", "extents": [0.06, 0.7, 0.06], "position": [x, 0.35, z]})
    return shapes


@pytest.mark.parametrize("dt", [1 / 60, 1 / 240])
def test_a_table_of_five_boxes_stands_on_its_four_legs(dt):
    world = rbsim.World(dt=dt)
    world.add_plane()
    table = world.add_body(name="table", shapes=table_shapes(), mass=12.0, position=[0, 0.5, 0])
    world.step(round(2.0 / dt))
    i = world.index_of(table)
    # The centre of mass: the top's 0.0576 m^3 at 0.73 m and four legs' 0.00252 m^3 each at 0.35 m.
    top, leg = 1.2 * 0.06 * 0.8, 0.06 * 0.7 * 0.06
    centre = (top * 0.73 + 4 * leg * 0.35) / (top + 4 * leg)
    assert world.x[i][1] == pytest.approx(centre, abs=1e-3)
    c = world.contacts()
    legs = c[c["plane"] == 0]
    assert sorted(set(legs["shape_b"].tolist())) == [1, 2, 3, 4]
    assert np.allclose(legs["normal"], [0, 1, 0])


def test_filters_let_a_group_pass_through_itself():
    world = rbsim.World(dt=1 / 240)
    world.add_plane()
    world.add_body(name="low", shape={"type": "sphere", "radius": 0.5}, mass=1.0, position=[0, 0.5, 0],
                   filter={"group": -1})
    world.add_body(name="high", shape={"type": "sphere", "radius": 0.5}, mass=1.0, position=[0, 1.6, 0],
                   filter={"group": -1})
    world.add_body(name="other", shape={"type": "sphere", "radius": 0.5}, mass=1.0, position=[3, 0.5, 0],
                   filter={"category": 2, "mask": 1})
    world.step(240)
    # The two of group -1 overlap on the ground, the other rests on it.
    assert world.x[0][1] == pytest.approx(0.5, abs=1e-3)
    assert world.x[1][1] == pytest.approx(0.5, abs=1e-3)
    assert world.x[2][1] == pytest.approx(0.5, abs=1e-3)
    with pytest.raises(rbsim.InputError, match=r"filter.group"):
        world.add_body(shape={"type": "sphere", "radius": 0.5}, mass=1.0, filter={"group": 1.5})


def test_python_ints_read_as_a_scene_file_reads_them():
    # Issue 56, item 6: every int became a signed JSON integer, so a hull's indices (unsigned in the
    # parser) were refused and masks with bit 63 could not be given.
    corners = [[x, y, z] for x in (-0.5, 0.5) for y in (-0.5, 0.5) for z in (-0.5, 0.5)]
    # The cube's twelve triangles, wound outward (vertex index = 4 x + 2 y + z over the corners).
    triangles = [[0, 1, 3], [0, 3, 2], [4, 6, 7], [4, 7, 5], [0, 4, 5], [0, 5, 1],
                 [2, 3, 7], [2, 7, 6], [0, 2, 6], [0, 6, 4], [1, 5, 7], [1, 7, 3]]
    world = rbsim.World(dt=1 / 240)
    world.add_plane()
    world.add_body(name="hull", mass=1.0, position=[0, 0.5, 0],
                   shapes=[{"type": "hull", "vertices": corners, "triangles": triangles}])
    top_bit = 1 << 63
    world.add_body(name="high", shape={"type": "sphere", "radius": 0.5}, mass=1.0, position=[3, 0.5, 0],
                   filter={"category": top_bit, "mask": (1 << 64) - 1})
    # Bit 63 only: it meets no plane or body of the default category 1, and falls through the ground.
    world.add_body(name="ghost", shape={"type": "sphere", "radius": 0.5}, mass=1.0, position=[-3, 0.5, 0],
                   filter={"category": top_bit, "mask": top_bit})
    world.step(240)
    assert world.x[0][1] == pytest.approx(0.5, abs=1e-3)  # the unit cube hull rests on its face
    assert world.x[1][1] == pytest.approx(0.5, abs=1e-3)
    assert world.x[2][1] < -1.0
    with pytest.raises(rbsim.InputError, match=r"mask"):
        world.add_body(shape={"type": "sphere", "radius": 0.5}, mass=1.0, filter={"mask": 1 << 64})
    with pytest.raises(rbsim.InputError, match=r"triangles"):
        world.add_body(mass=1.0, shapes=[{"type": "hull", "vertices": corners,
                                          "triangles": [[-1, 1, 3]] + triangles[1:]}])


def test_a_turntable_carries_a_box_round():
    world = rbsim.World(dt=1 / 240)
    world.add_body(name="table", shape={"type": "box", "extents": [2, 0.2, 2]}, mass=10.0, kinematic=True,
                   motion={"pivot": [0, 0, 0], "angular_velocity": [0, 1, 0]})
    world.add_body(name="box", shape={"type": "box", "extents": [0.2, 0.2, 0.2]}, mass=1.0, position=[0.5, 0.2, 0])
    world.step(480)
    x, v = world.x[1], world.v[1]
    assert math.hypot(x[0], x[2]) == pytest.approx(0.5, abs=0.01)
    assert np.linalg.norm(v) == pytest.approx(0.5, rel=0.01)  # omega r
    with pytest.raises(rbsim.InputError, match=r"motion"):
        world.add_body(shape={"type": "sphere", "radius": 0.5}, mass=1.0, motion={"pivot": [0, 0, 0]})


def test_a_spawner_rains_balls_and_the_kill_volume_takes_them_away():
    world = rbsim.World(dt=1 / 60)
    world.add_spawner(name="ball", period=0.25, count=2, seed=3, end=2.0,
                      body={"shape": {"type": "sphere", "radius": 0.1}, "mass": 1.0},
                      region={"min": [-1, 4, -1], "max": [1, 5, 1]})
    world.kill_volume = (-5, -1, -5, 5, 6, 5)
    assert world.kill_volume == (-5.0, -1.0, -5.0, 5.0, 6.0, 5.0)
    world.step(30)  # 0.5 s: bursts at 0, 0.25 s
    assert len(world) == 4
    first = world.id_at(0)
    world.step(90)  # a ball from 4-5 m falls below -1 m after about 1.1 s
    assert not world.is_valid(first)
    assert len(world) < 16
    assert all(x[1] >= -1.5 for x in world.x)
    with pytest.raises(rbsim.InputError, match=r"World.add_spawner\(\): period"):
        world.add_spawner(body={"shape": {"type": "sphere", "radius": 0.1}, "mass": 1.0},
                          region={"min": [0, 0, 0], "max": [0, 0, 0]})
    with pytest.raises(rbsim.InputError, match=r"kill_volume"):
        world.kill_volume = (0, 0, 0, -1, 1, 1)
    world.kill_volume = None
    assert world.kill_volume is None


def test_the_solver_cannot_switch_to_one_without_joints_while_a_ragdoll_spawner_waits():
    # Issue 56, item 6: the switch was taken, and every later burst failed mid-step, leaving eleven
    # jointless bones each time.
    world = rbsim.World(dt=1 / 60)
    world.add_plane()
    world.add_spawner(name="fig", period=0.5, start=0.25, ragdoll={}, region={"min": (0, 2, 0), "max": (0, 2, 0)})
    for solver in ("pgs", "lcp"):
        with pytest.raises(rbsim.InputError, match=r"World: solver: .*spawner 'fig' makes ragdolls"):
            world.solver = solver
    assert world.solver == "soft-step"
    world.step(20)  # t = 0.33 s: the first burst is in, every bone with its joints
    assert len(world) == 11 and len(world.joints()) == 10


def test_names_made_while_the_world_steps_stay_unique():
    # Issue 56, item 4: spawners, the bones of spawned ragdolls and add_body could each give two
    # bodies one name, and two unnamed spawners were both "spawn".
    world = rbsim.World(dt=1 / 60)
    world.add_plane()
    world.add_spawner(period=0.25, region={"min": (0, 2, 0), "max": (1, 3, 1)},
                      body={"shape": {"type": "sphere", "radius": 0.1}, "mass": 1})
    world.add_spawner(period=0.25, region={"min": (3, 2, 0), "max": (4, 3, 1)},
                      body={"shape": {"type": "sphere", "radius": 0.1}, "mass": 1})
    world.add_spawner(name="fig", period=0.5, ragdoll={}, region={"min": (-3, 2, 0), "max": (-3, 2, 0)})
    with pytest.raises(rbsim.InputError, match=r'World.add_body\(\): name: the spawner "spawn1" .* may make "spawn1_4"'):
        world.add_body(name="spawn1_4", shape={"type": "sphere", "radius": 0.1}, mass=1)
    with pytest.raises(rbsim.InputError, match=r'may make "fig_2_head"'):
        world.add_body(name="fig_2_head", shape={"type": "sphere", "radius": 0.1}, mass=1)
    world.add_body(name="fig_2", shape={"type": "sphere", "radius": 0.1}, mass=1, position=(8, 1, 0))  # not a bone's
    with pytest.raises(rbsim.InputError, match=r'World.add_spawner\(\): name: another spawner is named "fig"'):
        world.add_spawner(name="fig", period=1.0, ragdoll={}, region={"min": (0, 2, 0), "max": (0, 2, 0)})
    world.add_body(name="drop_3", shape={"type": "sphere", "radius": 0.1}, mass=1, position=(9, 1, 0))
    with pytest.raises(rbsim.InputError, match=r'its bodies are named drop_k .* a body is already named "drop_3"'):
        world.add_spawner(name="drop", period=1.0, region={"min": (0, 2, 0), "max": (0, 2, 0)},
                          body={"shape": {"type": "sphere", "radius": 0.1}, "mass": 1})
    world.step(60)
    names = world.names
    assert len(names) == len(set(names))
    assert {"spawn_0", "spawn1_0", "fig_0_pelvis", "fig_1_head", "fig_2", "drop_3"} <= set(names)


def test_a_spawner_drops_ragdolls_at_offsets_and_clears_them_at_their_age():
    world = rbsim.World(dt=1 / 60)
    world.add_plane()
    world.add_spawner(name="fig", period=0.5, lifetime=0.75, random_orientation=False,
                      ragdoll={"mass": 60, "joint_friction": 5, "joint_hertz": 1, "joint_damping_ratio": 0.7},
                      offsets=[(0, 0, 0), (1, 0, 0)], region={"min": (0, 2, 0), "max": (0, 2, 0)})
    world.step(1)
    assert len(world) == 22 and len(world.joints()) == 20
    pelvis = world.id_at(0)
    assert world.names[0] == "fig_0_pelvis" and world.names[11] == "fig_1_pelvis"
    # The second figure stands 1 m along x from the first (both feet at y = 2 m, then one step of fall).
    assert abs(world.x[11][0] - world.x[0][0] - 1.0) < 1e-12
    world.step(30)  # t = 0.52 s: the second burst is in
    assert len(world) == 44 and len(world.joints()) == 40
    world.step(15)  # t = 0.77 s: the first burst is gone, joints with it
    assert len(world) == 22 and len(world.joints()) == 20
    assert not world.is_valid(pelvis)
    assert world.names[0].startswith("fig_2") or world.names[0].startswith("fig_3")
    with pytest.raises(rbsim.InputError, match=r"World.add_spawner\(\): lifetime"):
        world.add_spawner(period=1.0, lifetime=0, ragdoll={}, region={"min": (0, 2, 0), "max": (0, 2, 0)})
    with pytest.raises(rbsim.InputError, match=r"World.add_spawner\(\): body"):
        world.add_spawner(period=1.0, region={"min": (0, 2, 0), "max": (0, 2, 0)})
