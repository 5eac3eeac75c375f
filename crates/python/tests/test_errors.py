"""Bad input raises CaseError / ScenarioError (ValueError) naming the field."""

import json
import math

import numpy as np
import pytest

import polyguard

SQUARE = [[0.0, 0.0], [2.0, 0.0], [2.0, 2.0], [0.0, 2.0]]
GOOD = dict(lookahead=10.0, pos=[5.0, -3.0], vel=[0.0, 1.0], vertices=SQUARE, buff=0.01)


def field_of(fn, *args, **kwargs):
    with pytest.raises(polyguard.CaseError) as info:
        fn(*args, **kwargs)
    e = info.value
    assert isinstance(e, ValueError) and isinstance(e, polyguard.Error)
    # the message starts with the field, as the CLI's error lines do
    assert str(e).startswith(e.field + ": "), (str(e), e.field)
    return e.field


@pytest.mark.parametrize("change, field", [
    (dict(lookahead=0.0), "lookahead"),
    (dict(lookahead=math.inf), "lookahead"),
    (dict(lookahead="10"), "lookahead"),
    (dict(buff=-1.0), "buff"),
    (dict(buff=math.nan), "buff"),
    (dict(fac=1.0), "fac"),
    (dict(kappa_deg=180.0), "kappa"),
    (dict(pos=[1.0, 2.0, 3.0, 4.0]), "point.pos"),
    (dict(pos=["a", 1.0]), "point.pos[0]"),
    (dict(pos="12"), "point.pos"),
    (dict(vel=[0.0, 1.0, 2.0]), "point.vel"),
    (dict(vel=[0.0, math.inf]), "point.vel"),
    (dict(vertices=SQUARE[:2]), "polygon.vertices"),
    (dict(vertices=[[0, 0], [2, 0], [2, math.nan], [0, 2]]), "polygon.vertices[2][1]"),
    (dict(vertices=[[0, 0], [2, 0, 1], [2, 2], [0, 2]]), "polygon.vertices[1]"),
    (dict(vertices=SQUARE[::-1]), "polygon.vertices"),  # clockwise
    (dict(vertices=[[0, 0], [2, 2], [2, 0], [0, 2]]), "polygon.vertices"),  # bow tie
    (dict(velocities=[[0.0, 0.0]] * 3), "polygon.velocities"),
    (dict(velocities=[[0.0, 0.0]] * 3 + [[0.0, math.nan]]), "polygon.velocities[3][1]"),
    (dict(bottom=0.0, top=1.0), "polygon.vz"),
    (dict(pos=[5.0, -3.0, 0.0], vel=[0.0, 1.0, 0.0]), "polygon.bottom"),
    (dict(bottom=0.0, top=1.0, vz=0.0), "point.pos"),
    (dict(pos=[5.0, -3.0, 0.0], vel=[0.0, 1.0, 0.0], bottom=2.0, top=1.0, vz=0.0),
     "polygon.top"),
])
def test_every_rule_names_its_field(change, field):
    kwargs = dict(GOOD, **change)
    args = [kwargs.pop(k) for k in ("lookahead", "pos", "vel", "vertices")]
    for fn in (polyguard.detect, polyguard.detect_time, polyguard.truth):
        assert field_of(fn, *args, **kwargs) == field


CASE = {"id": "x", "lookahead": 10.0, "buff": 0.01,
        "point": {"pos": [5.0, -3.0], "vel": [0.0, 1.0]},
        "polygon": {"vertices": SQUARE}}


def test_case_objects_are_read_strictly():
    bad = json.loads(json.dumps(CASE))
    bad["polygon"]["velocity"] = [[1.0, 0.0]] * 4
    assert field_of(polyguard.detect_case, bad) == "polygon.velocity"
    with pytest.raises(polyguard.CaseError, match="did you mean velocities"):
        polyguard.detect_case(bad)
    # Python's json writes NaN as a literal JSON does not have: named, not misread
    nan = json.loads(json.dumps(CASE))
    nan["point"]["pos"][1] = math.nan
    assert field_of(polyguard.detect_case, nan) == "point.pos[1]"
    missing = json.loads(json.dumps(CASE))
    del missing["buff"]
    assert field_of(polyguard.truth_case, missing) == "buff"
    # a repeated key is an error of the line as a whole, as in `polyguard detect`
    assert field_of(polyguard.detect_time_case, '{"lookahead": 1, "lookahead": 2}') == "line"
    with pytest.raises(polyguard.CaseError, match="duplicate key `lookahead`"):
        polyguard.detect_case('{"lookahead": 1, "lookahead": 2}')
    with pytest.raises(TypeError):
        polyguard.detect_case({"lookahead": object()})


def batch(**change):
    verts = np.array([[[0, 0], [1, 0], [1, 1], [0, 1]], [[5, 5], [6, 5], [6, 6], [5, 6]]],
                     float)
    args = dict(lookahead=1.0, points_pos=np.zeros((3, 2)), points_vel=np.ones((3, 2)),
                poly_vertices=verts, buff=0.1)
    args.update(change)
    return args


@pytest.mark.parametrize("change, field", [
    (dict(points_pos=np.zeros((3, 4))), "points_pos"),
    (dict(points_vel=np.ones((2, 2))), "points_vel"),
    (dict(points_pos=np.array([[0, 0], [0, np.nan], [0, 0]], float)), "points[1].pos"),
    (dict(poly_vertices=np.zeros((2, 4, 3))), "poly_vertices"),
    (dict(poly_vertices=np.array([[[0, 0], [1, 0], [1, 1], [0, 1]],
                                  [[5, 5], [5, 6], [6, 6], [6, 5]]], float)),
     "polygons[1].vertices"),  # the second runs clockwise
    (dict(poly_vertices=np.zeros((8, 2))), "poly_offsets"),
    (dict(poly_vertices=np.zeros((8, 2)), poly_offsets=[0, 4, 7]), "poly_offsets"),
    (dict(poly_vertices=np.zeros((8, 2)), poly_offsets=[0, 5, 4, 8]), "poly_offsets[2]"),
    (dict(poly_vertices=np.zeros((8, 2)), poly_offsets=[0.0, 4.5, 8.0]), "poly_offsets"),
    (dict(poly_velocities=np.zeros((3, 2))), "poly_velocities"),
    (dict(poly_velocities=np.array([[0, 0], [0, np.inf]], float)),
     "polygons[1].velocities[0][1]"),
    (dict(points_pos=np.zeros((3, 3)), points_vel=np.zeros((3, 3))), "poly_slabs"),
    (dict(poly_slabs=np.zeros((2, 3))), "points_pos"),
    (dict(points_pos=np.zeros((3, 3)), points_vel=np.zeros((3, 3)),
          poly_slabs=np.array([[0, 1, 0], [2, 1, 0]], float)), "polygons[1].top"),
    (dict(lookahead=-1.0), "lookahead"),
    (dict(buff=0.0), "buff"),
    (dict(fac=2.0), "fac"),
    (dict(points_pos=[["a", "b"]]), "points_pos"),
])
def test_batch_errors_name_the_array_or_the_item(change, field):
    assert field_of(polyguard.detect_batch, **batch(**change)) == field


def test_scenario_errors_carry_field_and_line():
    with pytest.raises(polyguard.ScenarioError) as info:
        polyguard.conflicts('{"type": "FeatureCollection", "features": [\n  oops')
    assert isinstance(info.value, ValueError)
    assert info.value.line == 2, str(info.value)
    assert isinstance(info.value.field, str)
    with pytest.raises(polyguard.ScenarioError) as info:
        polyguard.conflicts('{"type": "FeatureCollection", "features": []}', "flat")
    assert info.value.field == "geodesy" and info.value.line is None
    with pytest.raises(polyguard.ScenarioError) as info:
        polyguard.conflicts('{"type": "FeatureCollection", "features": []}', tolerance_s=0.0)
    assert info.value.field == "tolerance_s"
