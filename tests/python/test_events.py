"""World.contact_events() (issue 57): begin, end and hit of pairs of shapes over the steps of the
last step(n) call, as NumPy arrays; a ball dropped on a box, at dt = 1/60 and 1/240 s."""
import math

import numpy as np
import pytest

import rbsim

G = 9.81      # [m/s^2]
R = 0.25      # the ball's radius [m]
TOP = 0.5     # the box's top [m]
KINDS = ("begin", "end", "hit")


def drop(dt, h, restitution=0.0, **world):
    w = rbsim.World(dt=dt, **world)
    box = w.add_body(shape={"type": "box", "extents": [2, 1, 2]}, mass=1.0, static=True, name="box")
    ball = w.add_body(shape={"type": "sphere", "radius": R}, mass=1.0, position=(0, TOP + R + h, 0),
                      restitution=restitution, name="ball")
    return w, box, ball


def count(events, kind):
    return len(events[f"{kind}_a"])


@pytest.mark.parametrize("dt", [1 / 60, 1 / 240])
def test_a_dropped_ball_begins_once_where_its_manifold_appears_and_hits_at_sqrt_2gh(dt):
    h = 1.0
    w, box, ball = drop(dt, h)
    begins = hits = 0
    for _ in range(int(2 / dt)):
        had_contact = w.contact_count > 0
        bottom = w.x[1][1] - R
        falling = -w.v[1][1]
        w.step()
        e = w.contact_events()
        assert count(e, "end") == 0
        if count(e, "begin"):
            begins += count(e, "begin")
            assert not had_contact and w.contact_count > 0
            assert e["begin_a"].tolist() == [0] and e["begin_b"].tolist() == [1]
            assert e["begin_plane"].tolist() == [-1] and e["begin_child_b"].tolist() == [0]
            assert e["begin_id_a"][0] == box and e["begin_id_b"][0] == ball
            assert e["begin_step"].tolist() == [w.step_count - 1]
            np.testing.assert_allclose(e["begin_normal"], [[0, 1, 0]], atol=1e-12)
            np.testing.assert_allclose(e["begin_point"], [[0, (TOP + bottom) / 2, 0]], atol=1e-9)
        if count(e, "hit"):
            hits += count(e, "hit")
            # The approach before the solve of the step that stops it: the speed the step began with,
            # within g dt of the impact's (plus the integrator's lead of up to a step) of sqrt(2 g h).
            assert e["hit_speed"][0] == pytest.approx(falling, abs=1e-12)
            assert e["hit_speed"][0] == pytest.approx(math.sqrt(2 * G * h), abs=2 * G * dt)
            np.testing.assert_allclose(e["hit_normal"], [[0, 1, 0]], atol=1e-12)
    assert (begins, hits) == (1, 1)


def test_a_bounce_ends_the_pair_and_the_fall_back_begins_it_again():
    w, box, ball = drop(1 / 240, 1.0, restitution=0.5)
    order = []
    for _ in range(int(1.5 * 240)):
        w.step()
        e = w.contact_events()
        order += [k[0] for k in ("begin", "hit", "end") for _ in range(count(e, k))]
    assert "".join(order).startswith("bhebh")


def test_no_hit_below_hit_event_speed_and_one_above_a_lower_one():
    for speed, hits in ((1.0, 0), (0.3, 1)):  # the landing is at sqrt(2 g 0.02) = 0.63 m/s
        w, _, _ = drop(1 / 60, 0.02, hit_event_speed=speed)
        w.step(60)
        e = w.contact_events()
        assert (count(e, "begin"), count(e, "hit")) == (1, hits)


def test_step_n_gathers_the_events_of_its_n_steps():
    a, _, _ = drop(1 / 60, 1.0, restitution=0.5)
    b, _, _ = drop(1 / 60, 1.0, restitution=0.5)
    one_by_one = {k: [] for k in KINDS}
    for _ in range(90):
        a.step()
        e = a.contact_events()
        for k in KINDS:
            one_by_one[k] += e[f"{k}_step"].tolist()
    b.step(90)
    e = b.contact_events()
    for k in KINDS:
        assert e[f"{k}_step"].tolist() == one_by_one[k]
    assert len(one_by_one["begin"]) >= 2
    b.step(0)  # a call without steps has no events
    assert all(count(b.contact_events(), k) == 0 for k in KINDS)


def test_a_removed_body_ends_its_pair_under_its_stale_id():
    w, box, ball = drop(1 / 60, 0.1)
    w.step(60)
    w.remove_body(ball)
    w.step()
    e = w.contact_events()
    assert count(e, "end") == 1
    assert e["end_id_a"][0] == box and e["end_id_b"][0] == ball
    assert e["end_a"].tolist() == [0] and e["end_b"].tolist() == [-1]  # no longer a row
    assert not w.is_valid(ball)


def test_planes_are_side_a_without_a_body():
    w = rbsim.World(dt=1 / 60)
    w.add_plane()
    ball = w.add_body(shape={"type": "sphere", "radius": R}, mass=1.0, position=(0, 1, 0))
    w.step(60)
    e = w.contact_events()
    assert e["begin_plane"].tolist() == [0] and e["begin_a"].tolist() == [-1]
    assert e["begin_id_a"][0] is None and e["begin_id_b"][0] == ball
    assert e["begin_point"].shape == (1, 3) and e["hit_point"].shape == (1, 3)


def test_an_empty_world_has_empty_arrays_of_every_kind():
    e = rbsim.World().contact_events()
    for k in KINDS:
        assert e[f"{k}_a"].shape == (0,) and e[f"{k}_id_a"].dtype == object
    assert e["begin_point"].shape == (0, 3) and e["hit_speed"].shape == (0,)
