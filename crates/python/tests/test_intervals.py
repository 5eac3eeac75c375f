"""intervals and detect_exit (docs/cases.md, "Separation and fences"): the CLI's answers
on examples/intervals.jsonl and on a large polygon, the two examples worked out by hand,
the separation rule (a case's own sep and sep_v win, as over the CLI's flags), and the
errors naming `sep`, `sep_v` and `relation`."""

import json
import math

import numpy as np
import pytest

import polyguard
from conftest import EXAMPLES, jsonl, run_cli

RELATIONS = ("inside", "near", "breach")


@pytest.fixture(scope="session")
def interval_cases():
    """The lines of examples/intervals.jsonl, as text."""
    text = (EXAMPLES / "intervals.jsonl").read_text()
    return [line for line in text.splitlines() if line.strip()]


def as_json(value):
    """Tuples as JSON lists, so that an answer compares with the CLI's."""
    return json.loads(json.dumps(value))


def check_against_cli(lines, cli_answers, **sep):
    assert len(lines) == len(cli_answers)
    for line, cli in zip(lines, cli_answers):
        mine = polyguard.intervals(line, relation=None, **sep)
        assert as_json(mine) == cli["intervals"], json.loads(line).get("id")
        for r in RELATIONS:
            assert polyguard.intervals(line, r, **sep) == mine[r]


@pytest.mark.parametrize("flags, sep", [
    ([], {}),
    # the lines' own sep (and the drone's sep_v) win; the first line takes sep_v = 4
    (["--sep", "3", "--sep-v", "4"], dict(sep=3.0, sep_v=4.0)),
])
def test_intervals_match_the_cli(interval_cases, flags, sep):
    code, out, err = run_cli("detect", "--intervals", *flags, EXAMPLES / "intervals.jsonl")
    assert code == 0, err
    answers = jsonl(out)
    check_against_cli(interval_cases, answers, **sep)
    assert [a["intervals"]["sep_v"] for a in answers] == [sep.get("sep_v", 0.0), 10.0]


def test_detect_exit_matches_the_cli(interval_cases):
    code, out, err = run_cli("detect", "--fence", "keep-in", "--sep", "10", "--sep-v", "10",
                             EXAMPLES / "intervals.jsonl")
    assert code == 0, err
    for line, cli in zip(interval_cases, jsonl(out)):
        d = polyguard.detect_exit(line, sep=10.0, sep_v=10.0)
        assert d == {"exits": cli["exits"], "kind": cli["exit_kind"]}


def test_a_large_warping_polygon_matches_the_cli(tmp_path):
    # 80 vertices (answered without the GIL), growing, crossed by a point; D = 0.3.
    k = np.arange(80)
    angle = 2 * np.pi * k / 80
    radius = 2.0 + 0.3 * np.cos(5 * angle)
    vertices = np.stack([radius * np.cos(angle), radius * np.sin(angle)], axis=1)
    case = {"id": "big", "lookahead": 10.0, "buff": 0.01, "sep": 0.3,
            "point": {"pos": [-6.0, 0.4], "vel": [1.2, 0.0]},
            "polygon": {"vertices": vertices.tolist(),
                        "velocities": (0.02 * vertices).tolist()}}
    f = tmp_path / "big.jsonl"
    f.write_text(json.dumps(case) + "\n")
    code, out, err = run_cli("detect", "--intervals", "--fence", "keep-in", f)
    assert code == 0, err
    (cli,) = jsonl(out)
    mine = polyguard.intervals(case, relation=None)
    assert as_json(mine) == cli["intervals"]
    assert len(mine["inside"]) == 1 and len(mine["breach"]) >= 2
    assert polyguard.detect_exit(case) == {"exits": cli["exits"], "kind": cli["exit_kind"]}


def encloses(span, a, b, width=1e-9):
    (s0, s1), (e0, e1) = span["start"], span["end"]
    return (span["certain"] and s0 <= a <= s1 and e0 <= b <= e1
            and s1 - s0 <= width and e1 - e0 <= width)


def test_the_examples_by_hand(interval_cases):
    # The cell drifts west at 60, the point flies east at 480 along y = 30: the relative
    # x is 540 t. At y = 30 the walls are x in [40, 55] and [85, 100] (D = 5 from the
    # case): inside on [40, 55]/540 and [85, 100]/540, near on [35, 60]/540 and
    # [80, 105]/540, more than 5 inside only for x in (45, 50) and (90, 95).
    cell, drone = interval_cases
    k = lambda x: x / 540.0
    spans = polyguard.intervals(cell, relation=None)
    assert [encloses(s, k(a), k(b)) for s, (a, b) in
            zip(spans["inside"], [(40, 55), (85, 100)])] == [True, True]
    assert [encloses(s, k(a), k(b)) for s, (a, b) in
            zip(spans["near"], [(35, 60), (80, 105)])] == [True, True]
    breach = spans["breach"]
    assert len(breach) == 3 and encloses(breach[0], 0.0, k(45))
    assert encloses(breach[1], k(50), k(90)) and encloses(breach[2], k(95), 0.25)
    assert spans["loss_of_separation"] == spans["near"][0]["start"]
    # The drone at height 100 + 2t in the box [0, 120] (D = H = 10 from the case): inside
    # until the ceiling at t = 10, near until 130 at t = 15, breaching from 110 at t = 5
    # (x = 50 + t is more than 10 from the walls until t = 40), so it exits.
    assert [encloses(s, 0.0, 10.0, 1e-8) for s in polyguard.intervals(drone, "inside")] == [True]
    assert [encloses(s, 0.0, 15.0, 1e-8) for s in polyguard.intervals(drone)] == [True]
    assert [encloses(s, 5.0, 60.0, 1e-8) for s in polyguard.intervals(drone, "breach")] == [True]
    assert polyguard.detect_exit(drone) == {"exits": True, "kind": "exact"}
    short = json.loads(drone)
    short["lookahead"] = 4.0  # height 108 at most: no exit
    assert polyguard.detect_exit(short) == {"exits": False, "kind": "exact"}
    assert polyguard.intervals(short, "breach") == []


SQUARE = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]
CROSSING = {"lookahead": 10.0, "buff": 0.01,
            "point": {"pos": [1.0, -2.0], "vel": [0.0, 1.0]}, "polygon": {"vertices": SQUARE}}


def test_the_separation_arguments_apply_to_a_case_without_its_own():
    # (1, -2) moving north across the 2x2 square: inside on [2, 4]; near_0 is inside;
    # within D = 0.5 on [1.5, 4.5]; breach_0.5 on [0, 2.5] and [3.5, 10].
    (inside,) = polyguard.intervals(CROSSING, "inside")
    assert encloses(inside, 2.0, 4.0)
    assert polyguard.intervals(CROSSING) == [inside]
    (near,) = polyguard.intervals(CROSSING, sep=0.5)
    assert encloses(near, 1.5, 4.5)
    first, second = polyguard.intervals(CROSSING, "breach", sep=0.5)
    assert first["start"] == (0.0, 0.0) and encloses(first, 0.0, 2.5)
    assert second["end"] == (10.0, 10.0) and encloses(second, 3.5, 10.0)
    # the case's own sep wins over the argument, as a line's over --sep
    own = dict(CROSSING, sep=0.5)
    assert polyguard.intervals(own, sep=1.5) == [near]
    assert polyguard.intervals(json.dumps(own))[0] == near
    assert polyguard.intervals(own, relation=None, sep=1.5)["sep"] == 0.5


@pytest.mark.parametrize("call, field", [
    (lambda: polyguard.intervals(CROSSING, sep=-1.0), "sep"),
    (lambda: polyguard.intervals(CROSSING, sep="1"), "sep"),
    (lambda: polyguard.intervals(CROSSING, sep_v=math.nan), "sep_v"),
    (lambda: polyguard.intervals(CROSSING, sep_v=math.inf), "sep_v"),
    (lambda: polyguard.detect_exit(CROSSING, sep=-0.5), "sep"),
    (lambda: polyguard.detect_exit(CROSSING, sep_v=[1.0]), "sep_v"),
    # the argument is checked even where the case's own value wins
    (lambda: polyguard.intervals(dict(CROSSING, sep=1.0), sep=-1.0), "sep"),
    (lambda: polyguard.intervals(dict(CROSSING, sep=-1.0)), "sep"),
    (lambda: polyguard.detect_exit(dict(CROSSING, sep_v="high")), "sep_v"),
    (lambda: polyguard.intervals(dict(CROSSING, lookahead=0.0)), "lookahead"),
    (lambda: polyguard.detect_exit({**CROSSING, "polygon": {"vertices": SQUARE[::-1]}}),
     "polygon.vertices"),
])
def test_errors_name_the_field(call, field):
    with pytest.raises(polyguard.CaseError) as info:
        call()
    assert isinstance(info.value, ValueError)
    assert info.value.field == field
    assert str(info.value).startswith(field + ": "), str(info.value)


@pytest.mark.parametrize("relation", ["nearby", "Near", 3, b"near"])
def test_an_unknown_relation_is_an_error_naming_it(relation):
    with pytest.raises(polyguard.Error) as info:
        polyguard.intervals(CROSSING, relation)
    assert isinstance(info.value, ValueError)
    assert not isinstance(info.value, polyguard.CaseError)
    assert info.value.field == "relation"
    assert str(info.value).startswith("relation: ")
