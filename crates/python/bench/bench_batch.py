"""Times polyguard from Python: detect_batch on 10^6 point-polygon pairs (ns per pair) and
single detect calls in a Python loop (µs per call), for comparison with PolyCARP's Python
figure (about 127 µs per detection).

    python bench_batch.py [--points 1000] [--polygons 1000] [--repeat 5] [--single 20000]

Workloads (seeded; polygons of 8 vertices, star-shaped, about 1 across):
- dense: every pair is a candidate. Polygons in a 10 x 10 square, every point's path
  crosses the whole square diagonally within T, so the broad phase keeps all N*M pairs
  and paper A's functions decide each one.
- sparse: the density of the batch branch's generator (polygon centres uniform in a square
  of side 31.6*sqrt(M), points at 5-15 units per time unit, T = 10, BUFF = 0.05, a quarter
  of the polygons warping): the broad phase keeps a few pairs per point.
Times are the best of --repeat runs, the call only (the arrays are built beforehand).
"""

import argparse
import os
import time

import numpy as np

import polyguard

PAPER_POLYCARP_PY_US = 127.0


def stars(rng, centres, n=8):
    m = len(centres)
    angles = (np.arange(n)[None, :] + rng.uniform(0.1, 0.9, (m, n))) * (2 * np.pi / n)
    radii = rng.uniform(0.3, 0.6, (m, n))
    return np.stack([centres[:, :1] + radii * np.cos(angles),
                     centres[:, 1:] + radii * np.sin(angles)], axis=2)


def drifts(rng, m, n=8, warping=0.25):
    v = np.repeat(rng.uniform(-1, 1, (m, 1, 2)), n, axis=1)
    warp = rng.uniform(size=m) < warping
    v[warp] += rng.uniform(-0.02, 0.02, (int(warp.sum()), n, 2))
    return v


def dense(rng, n_points, m):
    T = 10.0
    verts = stars(rng, rng.uniform(0, 10, (m, 2)))
    vels = drifts(rng, m) * 0.01  # nearly still: they stay in the square
    start = -5.0 + rng.uniform(0, 1, (n_points, 2))
    end = 15.0 + rng.uniform(0, 1, (n_points, 2))
    return T, start, (end - start) / T, verts, vels, 0.05


def sparse(rng, n_points, m):
    T = 10.0
    side = 31.6 * np.sqrt(m)
    verts = stars(rng, rng.uniform(0, side, (m, 2)))
    vels = drifts(rng, m)
    speed = rng.uniform(5, 15, n_points)
    a = rng.uniform(0, 2 * np.pi, n_points)
    vel = np.stack([speed * np.cos(a), speed * np.sin(a)], axis=1)
    return T, rng.uniform(0, side, (n_points, 2)), vel, verts, vels, 0.05


def best_of(repeat, fn):
    best, out = float("inf"), None
    for _ in range(repeat):
        t0 = time.perf_counter()
        out = fn()
        best = min(best, time.perf_counter() - t0)
    return best, out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("--points", type=int, default=1000)
    ap.add_argument("--polygons", type=int, default=1000)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--single", type=int, default=20000, help="single detect calls timed")
    ap.add_argument("--seed", type=int, default=1)
    args = ap.parse_args()
    pairs = args.points * args.polygons
    print(f"polyguard {polyguard.__version__}, {os.cpu_count()} CPUs, "
          f"{args.points} points x {args.polygons} polygons of 8 vertices = {pairs:,} pairs")
    for name, make in (("dense", dense), ("sparse", sparse)):
        rng = np.random.default_rng(args.seed)
        T, pos, vel, verts, vels, buff = make(rng, args.points, args.polygons)
        for parallel in (False, True):
            secs, (pi, qi, kind) = best_of(args.repeat, lambda: polyguard.detect_batch(
                T, pos, vel, verts, None, vels, buff=buff, parallel=parallel))
            print(f"detect_batch {name:6s} {'threads' if parallel else '1 thread':8s}: "
                  f"{secs * 1e3:8.1f} ms, {secs * 1e9 / pairs:7.1f} ns per pair, "
                  f"{len(pi):,} hits ({int((kind == polyguard.KIND_CONSERVATIVE).sum())} "
                  f"conservative)")
    # single calls from Python: pairs drawn from the dense workload (point i against
    # polygon j), the arguments as Python lists (the usual way a Python caller holds them)
    rng = np.random.default_rng(args.seed)
    T, pos, vel, verts, vels, buff = dense(rng, args.points, args.polygons)
    pick = np.random.default_rng(args.seed + 1)
    ii = pick.integers(args.points, size=args.single)
    jj = pick.integers(args.polygons, size=args.single)
    calls = [(pos[i].tolist(), vel[i].tolist(), verts[j].tolist(), vels[j].tolist())
             for i, j in zip(ii, jj)]

    def loop():
        hits = 0
        for p, v, q, w in calls:
            hits += polyguard.detect(T, p, v, q, w, buff=buff).detected
        return hits

    secs, hits = best_of(args.repeat, loop)
    us = secs * 1e6 / args.single
    print(f"detect (Python loop, lists)  : {us:7.2f} µs per call over {args.single:,} calls "
          f"({hits:,} detected); PolyCARP's Python ~{PAPER_POLYCARP_PY_US:.0f} µs per "
          f"detection: {PAPER_POLYCARP_PY_US / us:.0f}x")
    calls_np = [(pos[i], vel[i], verts[j], vels[j]) for i, j in zip(ii, jj)]

    def loop_np():
        hits = 0
        for p, v, q, w in calls_np:
            hits += polyguard.detect(T, p, v, q, w, buff=buff).detected
        return hits

    secs, hits2 = best_of(args.repeat, loop_np)
    assert hits2 == hits
    print(f"detect (Python loop, numpy)  : {secs * 1e6 / args.single:7.2f} µs per call")


if __name__ == "__main__":
    main()
