"""One World used from two Python threads (issue 56, item 6): step() releases the GIL, so another
thread's calls on the same World wait for the step to end instead of running inside it (the
interpreter once died of a segmentation fault here; other runs raised "broad phase move: no proxy
200" and a false divergence)."""
import threading

import numpy as np
import pytest
import rbsim


STEPS = 600  # more than one chunk between signal checks (256 steps), so a chunk boundary is crossed


def crowded_world():
    w = rbsim.World(dt=1 / 60)
    w.add_plane(normal=(0, 1, 0), point=(0, 0, 0))
    for i in range(200):
        w.add_body(shape={"type": "box", "extents": [0.5, 0.5, 0.5]}, mass=1,
                   position=(0.6 * (i % 10), 0.3 + 0.6 * (i // 10), 0.0))
    return w


def test_calls_from_another_thread_wait_for_the_step_and_never_see_it_half_done():
    w = crowded_world()
    dt = w.dt
    seen_times, errors = [], []
    done = threading.Event()

    def stepper():
        try:
            w.step(STEPS)
        except Exception as e:  # noqa: BLE001 - reported by the assertion below
            errors.append(e)
        done.set()

    worker = threading.Thread(target=stepper)
    worker.start()
    added = 0
    while not done.is_set():
        # Every call waits while the step runs: the World it sees is before or after the whole call.
        seen_times.append(w.time)
        body = w.add_body(shape={"type": "sphere", "radius": 0.1}, mass=1, position=(20.0 + added, 1.0, 0.0))
        w.ray_cast((0.0, 50.0, 0.0), (0.0, -1.0, 0.0))
        w.remove_body(body)
        added += 1
    worker.join()
    assert errors == []
    assert added >= 1
    # A time of 0 or of the whole call only: never a chunk's end inside the call.
    assert all(t == 0.0 or t == pytest.approx(STEPS * dt) for t in seen_times), sorted(set(seen_times))
    assert w.step_count == STEPS
    assert len(w.x) == 200
    assert np.isfinite(w.x).all() and (w.x[:, 1] > 0.0).all()
    assert len(set(w.names)) == 200


def test_a_second_step_from_another_thread_waits_for_the_first():
    w = crowded_world()
    threads = [threading.Thread(target=w.step, args=(STEPS,)) for _ in range(2)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    once = crowded_world()
    once.step(2 * STEPS)
    # Two whole calls one after the other: the state of 2 x STEPS steps on one thread, bit for bit.
    assert w.step_count == 2 * STEPS
    assert np.array_equal(w.x, once.x) and np.array_equal(w.q, once.q)
