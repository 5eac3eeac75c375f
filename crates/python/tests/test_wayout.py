"""The way out from Python (the engine's polyguard::bands, polyguard::recovery and
polyguard::offset): course, speed and vertical speed bands checked course by course with
``polyguard.intervals`` (a course inside a clear band never loses separation, one inside
a conflict band does); recovery points at least D from the polygon by a plain distance;
offsets containing sampled points of the true buffer and within D(1 + eps); insets; and
the errors naming the field."""

import math

import pytest

import polyguard

SQUARE = [[3.0, -1.0], [5.0, -1.0], [5.0, 1.0], [3.0, 1.0]]
DRIFT = [[-0.1, 0.0]] * 4
TRIANGLE = [[-1.0, 4.0], [1.0, 4.0], [0.0, 6.0]]
OBSTACLES = [
    {"vertices": SQUARE, "velocities": DRIFT},
    {"vertices": TRIANGLE},
]


def seg_dist(x, a, b):
    """The distance from x to the segment a b (plain floats: a check)."""
    ex, ey = b[0] - a[0], b[1] - a[1]
    u = ((x[0] - a[0]) * ex + (x[1] - a[1]) * ey) / (ex * ex + ey * ey)
    u = min(1.0, max(0.0, u))
    return math.hypot(a[0] + u * ex - x[0], a[1] + u * ey - x[1])


def ring_dist(x, ring):
    return min(seg_dist(x, ring[i], ring[(i + 1) % len(ring)]) for i in range(len(ring)))


def inside(x, ring):
    """Crossing parity: is x strictly inside the ring?"""
    c = False
    for i in range(len(ring)):
        a, b = ring[i], ring[(i + 1) % len(ring)]
        if (a[1] > x[1]) != (b[1] > x[1]):
            if x[0] < a[0] + (x[1] - a[1]) * (b[0] - a[0]) / (b[1] - a[1]):
                c = not c
    return c


def dist_to_polygon(x, ring):
    return 0.0 if inside(x, ring) else ring_dist(x, ring)


def in_region(x, region):
    return inside(x, region["outer"]) and not any(inside(x, h) for h in region["holes"])


def near_spans(pos, vel, obstacle, sep, sep_v=0.0, lookahead=10.0):
    """polyguard.intervals' near_D spans of one obstacle for the velocity vel."""
    polygon = {"vertices": obstacle["vertices"]}
    if "velocities" in obstacle:
        polygon["velocities"] = obstacle["velocities"]
    for k in ("bottom", "top", "vz"):
        if k in obstacle:
            polygon[k] = obstacle[k]
    case = {"lookahead": lookahead, "buff": 1.0, "point": {"pos": pos, "vel": vel},
            "polygon": polygon}
    return polyguard.intervals(case, "near", sep=sep, sep_v=sep_v)


def check_course_bands(answer, pos, speed, obstacles, sep, vz=None, sep_v=0.0):
    bands = answer["bands"]
    assert bands[0][0] == 0.0 and math.isclose(bands[-1][1], 360.0)
    for (a, b, _), (c, _, _) in zip(bands, bands[1:]):
        assert b == c, "the bands tile [0, 360]"
    kinds = {k for _, _, k in bands}
    assert {"clear", "conflict"} <= kinds
    for lo, hi, kind in bands:
        if kind == "unknown":
            continue
        for frac in (0.25, 0.5, 0.75):
            th = math.radians(lo + frac * (hi - lo))
            vel = [speed * math.sin(th), speed * math.cos(th)]
            if vz is not None:
                vel.append(vz)
            spans = [s for o in obstacles for s in near_spans(pos, vel, o, sep, sep_v)]
            if kind == "clear":
                assert spans == [], (lo, hi, frac)
            else:
                assert any(s["certain"] for s in spans), (lo, hi, frac)


def test_course_bands_2d_hold_course_by_course():
    answer = polyguard.course_bands([0.0, 0.0], [0.6, 0.8], OBSTACLES, lookahead=10.0,
                                    sep=0.5, unknown_max_deg=0.5)
    assert answer["met"] and answer["unknown_total_deg"] <= 0.5
    check_course_bands(answer, [0.0, 0.0], 1.0, OBSTACLES, 0.5)


def test_course_bands_3d_hold_course_by_course():
    obstacles = [dict(o, bottom=0.0, top=10.0, vz=0.0) for o in OBSTACLES]
    answer = polyguard.course_bands([0.0, 0.0, 5.0], [0.0, 2.0, 0.5], obstacles,
                                    lookahead=10.0, sep=0.5, sep_v=1.0, speed=1.0)
    check_course_bands(answer, [0.0, 0.0, 5.0], 1.0, obstacles, 0.5, vz=0.5, sep_v=1.0)
    # well above the slabs (z from 20, climbing): every course clear
    high = polyguard.course_bands([0.0, 0.0, 20.0], [0.0, 1.0, 1.0], obstacles,
                                  lookahead=10.0, sep=0.5, sep_v=1.0)
    assert [k for _, _, k in high["bands"]] == ["clear"]


def test_speed_and_vertical_speed_bands():
    east = polyguard.speed_bands([0.0, 0.0], [1.0, 0.0], OBSTACLES, lookahead=10.0,
                                 sep=0.5, min=0.0, max=2.0)
    assert east["bands"][0][:2] == (0.0, east["bands"][0][1]) and east["bands"][0][2] == "clear"
    assert east["bands"][-1][1] == 2.0 and east["bands"][-1][2] == "conflict"
    for lo, hi, kind in east["bands"]:
        if kind == "unknown":
            continue
        sp = 0.5 * (lo + hi)
        spans = [s for o in OBSTACLES for s in near_spans([0.0, 0.0], [sp, 0.0], o, 0.5)]
        assert (spans == []) == (kind == "clear"), (lo, hi)
    obstacles = [dict(o, bottom=0.0, top=10.0, vz=0.0) for o in OBSTACLES]
    vert = polyguard.vertical_speed_bands([0.0, 0.0, 15.0], [1.0, 0.0, 0.0], obstacles,
                                          lookahead=10.0, sep=0.5, sep_v=1.0,
                                          min=-3.0, max=3.0)
    assert vert["bands"][0][0] == -3.0 and vert["bands"][-1][1] == 3.0
    for lo, hi, kind in vert["bands"]:
        if kind == "unknown":
            continue
        vz = 0.5 * (lo + hi)
        spans = [s for o in obstacles
                 for s in near_spans([0.0, 0.0, 15.0], [1.0, 0.0, vz], o, 0.5, 1.0)]
        assert (spans == []) == (kind == "clear"), (lo, hi)
    assert {k for _, _, k in vert["bands"]} >= {"clear", "conflict"}


@pytest.mark.parametrize("s", [[2.8, 0.3], [4.0, 0.0], [3.2, -1.1], [6.0, 2.0]])
def test_recovery_out_is_sep_away(s):
    r = polyguard.recover(SQUARE, s, 0.5)
    assert dist_to_polygon(r["point"], SQUARE) >= 0.5
    assert r["min_lo"] <= r["distance"]
    assert math.dist(r["point"], s) <= r["distance"]
    assert r["moved"] == (dist_to_polygon(s, SQUARE) < 0.5)


def test_recovery_in_and_impossible():
    r = polyguard.recover(SQUARE, [2.8, 0.3], 0.5, fence="keep_in")
    assert inside(r["point"], SQUARE) and ring_dist(r["point"], SQUARE) >= 0.5
    assert r["min_lo"] <= 0.7 <= r["distance"]
    assert polyguard.recover(SQUARE, [4.0, 0.0], 1.5, fence="keep_in") == {
        "impossible": "no point of P is D from its boundary: its inradius is below D"}
    # the square drifting west: at t = 10 it is [2, 4] x [-1, 1]
    moved = polyguard.recover(SQUARE, [1.8, 0.0], 0.5, velocities=DRIFT, t=10.0)
    shifted = [[x - 1.0, y] for x, y in SQUARE]
    assert dist_to_polygon(moved["point"], shifted) >= 0.5 and moved["moved"]


def test_offset_contains_the_buffer_and_stays_close():
    d, eps = 0.5, 0.01
    regions = polyguard.offset(SQUARE, d, eps)
    assert len(regions) == 1 and regions[0]["holes"] == []
    for v in regions[0]["outer"]:
        assert ring_dist(v, SQUARE) <= d * (1 + eps)
    for k in range(400):
        a = 2 * math.pi * k / 400
        c = SQUARE[k % 4]
        x = [c[0] + d * math.cos(a), c[1] + d * math.sin(a)]
        if dist_to_polygon(x, SQUARE) >= d * (1 - 1e-12):
            assert in_region(x, regions[0]), x
    # a cavity [1, 3]^2 with a mouth 0.4 wide: the mouth closes, the middle is a hole
    cavity = [[0, 0], [4, 0], [4, 1.8], [3, 1.8], [3, 1], [1, 1], [1, 3], [3, 3],
              [3, 2.2], [4, 2.2], [4, 4], [0, 4]]
    grown = polyguard.offset(cavity, d, eps)
    assert len(grown) == 1 and len(grown[0]["holes"]) == 1
    assert not in_region([2.0, 2.0], grown[0])
    assert in_region([3.5, 2.0], grown[0])


def test_inset():
    assert polyguard.inset(SQUARE, 1.5) == []
    pieces = polyguard.inset(SQUARE, 0.5, 0.01)
    assert len(pieces) == 1
    for v in pieces[0]["outer"]:
        assert inside(v, SQUARE) and ring_dist(v, SQUARE) >= 0.5
    assert in_region([4.0, 0.0], pieces[0])
    # a dumbbell: two squares joined by a thin bar, inset wider than the bar: two pieces
    dumbbell = [[0, 0], [2, 0], [2, 0.9], [4, 0.9], [4, 0], [6, 0], [6, 2], [4, 2],
                [4, 1.1], [2, 1.1], [2, 2], [0, 2]]
    assert len(polyguard.inset(dumbbell, 0.3)) == 2


@pytest.mark.parametrize("call, field", [
    (lambda: polyguard.course_bands([0, 0], [1, 0], OBSTACLES, lookahead=-1, sep=0.5),
     "lookahead"),
    (lambda: polyguard.course_bands([0, 0], [1, 0], OBSTACLES, lookahead=1, sep=-0.5),
     "sep"),
    (lambda: polyguard.course_bands([0, 0], [1, 0], [{"vertices": [[0, 0], [1, float("nan")],
                                                                    [0, 1]]}],
                                    lookahead=1, sep=0.5), "obstacles[0].vertices[1][1]"),
    (lambda: polyguard.course_bands([0, 0], [1, 0], [{"vertices": [[0, 0], [1, 0]]}],
                                    lookahead=1, sep=0.5), "obstacles[0].vertices"),
    (lambda: polyguard.course_bands([0, 0], [1, 0], [dict(OBSTACLES[0], bottom=0, top=1,
                                                          vz=0)],
                                    lookahead=1, sep=0.5), "obstacles[0].bottom"),
    (lambda: polyguard.course_bands([0, 0], [1, 0], OBSTACLES, lookahead=1, sep=0.5,
                                    unknown_max_deg=0), "unknown_max_deg"),
    (lambda: polyguard.course_bands([0, 0, 1], [1, 0], OBSTACLES, lookahead=1, sep=0.5),
     "vel"),
    (lambda: polyguard.course_bands([0, 0], [1, 0], [OBSTACLES[0], SQUARE], lookahead=1,
                                    sep=0.5), "obstacles[1]"),
    (lambda: polyguard.course_bands([0, 0], [1, 0], [{"velocities": DRIFT}], lookahead=1,
                                    sep=0.5), "obstacles[0].vertices"),
    (lambda: polyguard.speed_bands([0, 0], [1, 0], OBSTACLES, lookahead=1, sep=0.5,
                                   min=2, max=1), "max"),
    (lambda: polyguard.vertical_speed_bands([0, 0], [1, 0], OBSTACLES, lookahead=1,
                                            sep=0.5, sep_v=1, min=-1, max=1), "pos"),
    (lambda: polyguard.recover(SQUARE, [0, 0], -1), "sep"),
    (lambda: polyguard.recover(SQUARE, [0, 0], 1, fence="inside"), "fence"),
    (lambda: polyguard.recover(SQUARE[::-1], [0, 0], 1), "vertices"),
    (lambda: polyguard.recover(SQUARE, [0, "a"], 1), "s[1]"),
    (lambda: polyguard.offset(SQUARE, -1), "d"),
    (lambda: polyguard.offset(SQUARE, 1, 0), "eps"),
    (lambda: polyguard.inset(SQUARE[::-1], 1), "vertices"),
    (lambda: polyguard.offset(SQUARE, 1, velocities=DRIFT, t=float("inf")), "t"),
])
def test_errors_name_the_field(call, field):
    with pytest.raises(polyguard.Error) as e:
        call()
    assert e.value.field == field, str(e.value)
    assert str(e.value).startswith(field), str(e.value)
