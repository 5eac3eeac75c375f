"""detect, detect_case, detect_time, truth (paper A §II.H, §II.I, §III, and the oracle)."""

import json
import math

import numpy as np
import pytest

import polyguard
from conftest import star

SQUARE = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]
EAST = [[1.0, 0.0]] * 4


def test_drifting_square_is_entered_at_t3():
    # The square drifts east at 1; the point climbs north at x = 5: the square's east
    # edge reaches x = 5 at t = 3, when the point is at y = 0, the square's corner.
    d = polyguard.detect(10.0, [5.0, -3.0], [0.0, 1.0], SQUARE, EAST, buff=0.01)
    assert d.detected and bool(d)
    assert (d.kind, d.decided_by, d.well_formed) == ("exact", "detect_same_2d", True)
    assert d.well_formed_reason is None
    t = polyguard.truth(10.0, [5.0, -3.0], [0.0, 1.0], SQUARE, EAST, buff=0.01)
    assert t.entry_time == 3.0 and t.entry_time_exact == "3/1"
    kind, lo, hi = polyguard.detect_time(10.0, [5.0, -3.0], [0.0, 1.0], SQUARE, EAST,
                                         buff=0.01)
    assert kind == "enters" and lo <= 3.0 <= hi and hi - lo < 1e-6


def test_before_the_square_arrives_is_a_miss():
    # T = 2.5 < 3: the point has passed y = 0..2 only partly and the square is not there.
    d = polyguard.detect(2.5, [5.0, -3.0], [0.0, 1.0], SQUARE, EAST, buff=0.01)
    assert not d.detected and d.kind == "exact"
    assert polyguard.truth(2.5, [5.0, -3.0], [0.0, 1.0], SQUARE, EAST, buff=0.01) is None
    e = polyguard.detect_time(2.5, [5.0, -3.0], [0.0, 1.0], SQUARE, EAST, buff=0.01)
    assert (e.kind, e.lo, e.hi) == ("never", None, None)


def test_buff_decides_a_near_pass():
    # A point passing 0.05 to the right of a square at rest: within BUFF 0.1, not 0.01.
    args = (10.0, [2.05, -3.0], [0.0, 1.0], SQUARE)
    assert polyguard.detect(*args, buff=0.1).detected
    assert not polyguard.detect(*args, buff=0.01).detected
    assert polyguard.truth(*args, buff=0.1) is None  # never inside: BUFF is slack only


def test_warping_and_3d_dispatch():
    warp = [[-0.1, -0.05], [0.1, -0.05], [0.1, 0.05], [-0.1, 0.05]]
    d = polyguard.detect(300.0, [-50.0, 5.0], [0.5, 0.0], [[0, 0], [10, 0], [10, 10], [0, 10]],
                         warp, buff=0.001)
    assert d.decided_by == "detect_diff_2d" and d.detected
    # 3D: descending into a slab 0..1000 under the point's path, or passing over it.
    common = dict(buff=0.01, bottom=0.0, top=1000.0, vz=0.0)
    down = polyguard.detect(10.0, [1.0, 1.0, 2000.0], [0.0, 0.0, -500.0], SQUARE, **common)
    over = polyguard.detect(10.0, [1.0, 1.0, 2000.0], [0.0, 0.0, 0.0], SQUARE, **common)
    assert down.decided_by == over.decided_by == "detect_3d"
    assert down.detected and not over.detected
    t = polyguard.truth(10.0, [1.0, 1.0, 2000.0], [0.0, 0.0, -500.0], SQUARE, **common)
    assert t.entry_time == 2.0


def test_sliver_is_not_well_formed_but_still_detected():
    # A 5.7° corner at (10, 0), sharper than κ = 10°: §II.J rule 3 fails; the point
    # starts inside, so it is detected all the same.
    d = polyguard.detect(1.0, [1.0, 0.5], [0.0, 0.0], [[0, 0], [10, 0], [0, 1]], buff=0.01,
                         kappa_deg=10.0)
    assert d.detected and not d.well_formed
    assert "§II.J" in d.well_formed_reason
    assert d.to_dict()["well_formed_reason"] == d.well_formed_reason
    # with the default κ = 5° the same corner passes
    assert polyguard.detect(1.0, [1.0, 0.5], [0.0, 0.0], [[0, 0], [10, 0], [0, 1]],
                            buff=0.01).well_formed


def test_numpy_inputs_read_like_lists():
    p = np.array(SQUARE)
    a = polyguard.detect(np.float64(10.0), np.array([5.0, -3.0]), (0.0, 1), p,
                         np.asfortranarray(np.array(EAST)), buff=np.float32(0.01))
    b = polyguard.detect(10.0, [5.0, -3.0], [0.0, 1.0], SQUARE, EAST, buff=0.01)
    assert a == b


def test_case_objects_answer_like_arguments(example_cases):
    for line in example_cases:
        obj = json.loads(line)
        pt, pg = obj["point"], obj["polygon"]
        kwargs = {k: pg[k] for k in ("bottom", "top", "vz") if k in pg}
        if "fac" in obj:
            kwargs["fac"] = obj["fac"]
        args = (obj["lookahead"], pt["pos"], pt["vel"], pg["vertices"], pg.get("velocities"))
        assert polyguard.detect_case(obj) == polyguard.detect_case(line) \
            == polyguard.detect(*args, buff=obj["buff"], **kwargs), obj["id"]
        assert polyguard.detect_time_case(obj) == polyguard.detect_time(
            *args, buff=obj["buff"], **kwargs)
        assert polyguard.truth_case(obj) == polyguard.truth(*args, buff=obj["buff"], **kwargs)


def random_case(rng):
    n = int(rng.integers(3, 9))
    p = star(rng, rng.uniform(-2, 2, 2), n, 0.5, 2.0)
    v = np.tile(rng.uniform(-1, 1, 2), (n, 1))
    if rng.uniform() < 0.4:
        v = v + rng.uniform(-0.2, 0.2, (n, 2))
    T = float(rng.uniform(1, 10))
    # aim the point at a vertex, arriving at a random time, give or take a little
    k, t = int(rng.integers(n)), float(rng.uniform(0, T))
    vel = rng.uniform(-3, 3, 2)
    target = p[k] + t * v[k] + rng.choice([0.0, 1e-3, 0.1, 0.5]) * rng.normal(size=2)
    pos = target - t * vel
    return (T, pos, vel, p, v), float(rng.choice([1e-3, 0.05, 0.2]))


def test_no_missed_entry_and_the_time_enclosure_holds_on_seeded_cases():
    """The contract from Python: whenever the exact truth says the point enters, detect
    says detected, and detect_time's enclosure holds the exact time."""
    rng = np.random.default_rng(13)
    entered = 0
    for _ in range(150):
        args, buff = random_case(rng)
        t = polyguard.truth(*args, buff=buff)
        d = polyguard.detect(*args, buff=buff)
        e = polyguard.detect_time(*args, buff=buff)
        if t is None:
            assert e.kind != "enters", args
        else:
            entered += 1
            assert d.detected, args
            assert e.kind in ("enters", "possible"), args
            assert e.lo <= t.entry_time <= e.hi, (args, t, e)
    # the workload must exercise both answers
    assert 20 < entered < 140


def test_truth_releases_the_gil():
    """While truth works on a 30,000-vertex circle (about 0.2 s) in another thread, this
    thread keeps running Python: it could not if the GIL were held throughout."""
    n = 30000
    ang = np.arange(n) * 2 * math.pi / n
    circle = np.stack([np.cos(ang), np.sin(ang)], axis=1)
    gap, took = longest_stall(
        lambda: polyguard.truth(10.0, [-3.0, 0.0], [1.0, 0.0], circle, buff=0.01))
    assert gap < 0.5 * took, (gap, took)


def test_the_stall_probe_sees_a_call_that_holds_the_gil():
    """The canary of the probe above: str.count on a 100 MB string holds the GIL (C code
    that never gives it up), and the probe sees this thread stall for most of it."""
    text = "ab" * 50_000_000
    gap, took = longest_stall(lambda: text.count("ba"))
    assert gap >= 0.5 * took, (gap, took)


def longest_stall(call):
    """Runs `call` in another thread while this one loops; returns (the longest time this
    thread made no progress while `call` ran, how long `call` took). A call that holds
    the GIL stalls this thread for about its whole duration."""
    import threading
    import time
    done, took = [False], []

    def work():
        t0 = time.perf_counter()
        call()
        took.append(time.perf_counter() - t0)
        done[0] = True

    th = threading.Thread(target=work)
    last, gap = time.perf_counter(), 0.0
    th.start()
    while not done[0]:
        now = time.perf_counter()
        gap = max(gap, now - last)
        last = now
    th.join()
    return gap, took[0]
