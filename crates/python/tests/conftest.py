"""Shared fixtures: the repository's examples, the polyguard CLI, and seeded workloads."""

import json
import os
import subprocess
from pathlib import Path

import numpy as np
import pytest

REPO = Path(__file__).resolve().parents[3]
EXAMPLES = REPO / "examples"


def cli_command():
    """The polyguard binary: $POLYGUARD_BIN (CI sets it), else `cargo run` in the repo."""
    binary = os.environ.get("POLYGUARD_BIN")
    if binary:
        return [binary]
    return ["cargo", "run", "--quiet", "--manifest-path", str(REPO / "Cargo.toml"),
            "--bin", "polyguard", "--"]


def run_cli(*args, stdin=None):
    """Runs the CLI; returns (exit code, stdout, stderr)."""
    proc = subprocess.run(cli_command() + [str(a) for a in args], input=stdin,
                          capture_output=True, text=True, cwd=REPO, timeout=600)
    return proc.returncode, proc.stdout, proc.stderr


def jsonl(text):
    return [json.loads(line) for line in text.splitlines() if line.strip()]


@pytest.fixture(scope="session")
def example_cases():
    """The lines of examples/cases.jsonl, as text."""
    return [l for l in (EXAMPLES / "cases.jsonl").read_text().splitlines() if l.strip()]


def star(rng, centre, n, r_lo=0.3, r_hi=0.6):
    """A star-shaped polygon of n vertices around `centre`, counterclockwise (its angles
    increase, one per sector), so simple whatever the radii."""
    angles = (np.arange(n) + rng.uniform(0.1, 0.9, n)) * (2 * np.pi / n)
    radii = rng.uniform(r_lo, r_hi, n)
    return np.stack([centre[0] + radii * np.cos(angles),
                     centre[1] + radii * np.sin(angles)], axis=1)


def workload(seed, n_points, n_polys, n_vertices, side=8.0, warping=0.3, aimed=0.3,
             three_d=False):
    """A seeded batch: polygons in a square of `side`, some warping; points uniform or
    aimed at a vertex so that some pairs touch or nearly touch. Returns a dict of the
    arrays detect_batch takes, and the polygons as a list (their vertex counts may
    differ when n_vertices is a range)."""
    rng = np.random.default_rng(seed)
    polys, vels = [], []
    for _ in range(n_polys):
        n = n_vertices if isinstance(n_vertices, int) else int(rng.integers(*n_vertices))
        c = rng.uniform(0, side, 2)
        p = star(rng, c, n)
        drift = rng.uniform(-1, 1, 2)
        v = np.tile(drift, (n, 1))
        if rng.uniform() < warping:
            v = v + rng.uniform(-0.05, 0.05, (n, 2))
        polys.append(p)
        vels.append(v)
    T = 5.0
    pos = rng.uniform(0, side, (n_points, 2))
    vel = rng.uniform(-2, 2, (n_points, 2))
    for i in range(n_points):
        if rng.uniform() < aimed:
            j = int(rng.integers(n_polys))
            k = int(rng.integers(len(polys[j])))
            t = rng.uniform(0.5, T)
            target = polys[j][k] + t * vels[j][k]
            # arrive at the vertex at time t, give or take a little
            target = target + rng.choice([0.0, 0.01, 0.05, 0.1]) * rng.normal(size=2)
            pos[i] = target - t * vel[i]
    out = {"lookahead": T, "polys": polys, "vels": vels, "pos": pos, "vel": vel}
    if three_d:
        out["pos"] = np.column_stack([pos, rng.uniform(0, 1000, n_points)])
        out["vel"] = np.column_stack([vel, rng.uniform(-100, 100, n_points)])
        bottoms = rng.uniform(0, 800, n_polys)
        out["slabs"] = np.column_stack([bottoms, bottoms + rng.uniform(50, 300, n_polys),
                                        rng.uniform(-20, 20, n_polys)])
    return out
