"""detect_batch on numpy arrays against a Python loop of detect (paper A on many pairs)."""

import numpy as np
import pytest

import polyguard
from conftest import workload


def loop_answer(w, buff, fac=1e-4):
    """Every pair through detect: the (point, polygon, kind code) of the detected ones."""
    out = []
    for i in range(len(w["pos"])):
        for j, (p, v) in enumerate(zip(w["polys"], w["vels"])):
            slab = {}
            if "slabs" in w:
                slab = dict(zip(("bottom", "top", "vz"), w["slabs"][j]))
            d = polyguard.detect(w["lookahead"], w["pos"][i], w["vel"][i], p, v, buff=buff,
                                 fac=fac, **slab)
            if d.detected:
                code = polyguard.KIND_EXACT if d.kind == "exact" else polyguard.KIND_CONSERVATIVE
                out.append((i, j, code))
    return out


def as_list(answer):
    pi, qi, kind = answer
    assert pi.dtype == np.int64 and qi.dtype == np.int64 and kind.dtype == np.uint8
    assert len(pi) == len(qi) == len(kind)
    return list(zip(pi.tolist(), qi.tolist(), kind.tolist()))


@pytest.mark.parametrize("seed", [1, 2, 3])
def test_batch_finds_exactly_the_pairs_detect_finds(seed):
    w = workload(seed, 60, 40, 8)
    want = loop_answer(w, 0.05)
    # the workload has hits and misses, rigid and warping polygons
    assert 5 < len(want) < 60 * 40 // 2
    got = polyguard.detect_batch(w["lookahead"], w["pos"], w["vel"], np.stack(w["polys"]),
                                 None, np.stack(w["vels"]), buff=0.05)
    assert as_list(got) == want


def test_offsets_layout_with_mixed_vertex_counts():
    w = workload(4, 50, 30, (3, 12))
    want = loop_answer(w, 0.05)
    assert len(want) > 5
    counts = [len(p) for p in w["polys"]]
    assert len(set(counts)) > 3
    offsets = np.concatenate([[0], np.cumsum(counts)])
    got = polyguard.detect_batch(w["lookahead"], w["pos"], w["vel"], np.concatenate(w["polys"]),
                                 offsets, np.concatenate(w["vels"]), buff=0.05)
    assert as_list(got) == want
    # offsets as a list of Python ints read the same
    got2 = polyguard.detect_batch(w["lookahead"], w["pos"], w["vel"],
                                  np.concatenate(w["polys"]), offsets.tolist(),
                                  np.concatenate(w["vels"]), buff=0.05)
    assert as_list(got2) == want


def test_drift_per_polygon_equals_the_same_velocity_per_vertex():
    w = workload(5, 80, 30, 6, warping=0.0)
    drift = np.stack([v[0] for v in w["vels"]])
    per_vertex = np.stack(w["vels"])
    verts = np.stack(w["polys"])
    a = polyguard.detect_batch(w["lookahead"], w["pos"], w["vel"], verts, None, drift, buff=0.05)
    b = polyguard.detect_batch(w["lookahead"], w["pos"], w["vel"], verts, None, per_vertex,
                               buff=0.05)
    assert as_list(a) == as_list(b) == loop_answer(w, 0.05)
    assert len(as_list(a)) > 3


def test_layouts_and_dtypes_do_not_change_the_answer():
    w = workload(6, 50, 25, 8)
    verts, vels = np.stack(w["polys"]), np.stack(w["vels"])
    base = as_list(polyguard.detect_batch(w["lookahead"], w["pos"], w["vel"], verts, None, vels,
                                          buff=0.05))
    assert len(base) > 3
    # Fortran order, a strided slice of a larger array, float32, nested lists
    wide = np.zeros((50, 4))
    wide[:, ::2] = w["pos"]
    variants = [
        (np.asfortranarray(w["pos"]), np.asfortranarray(w["vel"]), np.asfortranarray(verts)),
        (wide[:, ::2], w["vel"], verts),
        (w["pos"], w["vel"].tolist(), verts.tolist()),
    ]
    assert not variants[1][0].flags.c_contiguous
    for pos, vel, vv in variants:
        got = polyguard.detect_batch(w["lookahead"], pos, vel, vv, None, vels, buff=0.05)
        assert as_list(got) == base
    # float32 rounds the inputs: the answer is detect's on the rounded values
    pos32, vel32 = w["pos"].astype(np.float32), w["vel"].astype(np.float32)
    w32 = dict(w, pos=pos32.astype(np.float64), vel=vel32.astype(np.float64))
    got = polyguard.detect_batch(w["lookahead"], pos32, vel32, verts, None, vels, buff=0.05)
    assert as_list(got) == loop_answer(w32, 0.05)


def test_one_thread_answers_as_many():
    w = workload(7, 300, 40, 8)
    args = (w["lookahead"], w["pos"], w["vel"], np.stack(w["polys"]), None, np.stack(w["vels"]))
    assert as_list(polyguard.detect_batch(*args, buff=0.05, parallel=False)) == \
        as_list(polyguard.detect_batch(*args, buff=0.05, parallel=True))


def test_3d_batch_matches_detect():
    w = workload(8, 60, 30, 8, three_d=True)
    want = loop_answer(w, 0.05)
    assert len(want) > 3
    got = polyguard.detect_batch(w["lookahead"], w["pos"], w["vel"], np.stack(w["polys"]), None,
                                 np.stack(w["vels"]), buff=0.05, poly_slabs=w["slabs"])
    assert as_list(got) == want


def test_empty_batches_answer_nothing():
    verts = np.stack([np.array([[0, 0], [1, 0], [0, 1]], float)])
    for pos, vv in [(np.zeros((0, 2)), verts), (np.zeros((3, 2)), np.zeros((0, 3, 2)))]:
        got = polyguard.detect_batch(1.0, pos, pos, vv, buff=0.1)
        assert as_list(got) == []


def test_batch_releases_the_gil():
    from test_detect import longest_stall
    w = workload(9, 4000, 1000, 8, side=40.0)
    args = (w["lookahead"], w["pos"], w["vel"], np.stack(w["polys"]), None, np.stack(w["vels"]))
    gap, took = longest_stall(lambda: polyguard.detect_batch(*args, buff=0.05, parallel=False))
    assert gap < 0.5 * took, (gap, took)
