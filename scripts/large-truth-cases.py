#!/usr/bin/env python3
"""Large-polygon detection cases for timing `polyguard detect --engine truth`:
for each vertex count, a convex circle and a non-convex star, at
rest, translating and warping, 2D and 3D, with point tracks that enter, graze a vertex
exactly and miss by a hair. One JSON line per case (docs/cases.md), on standard output.

usage: scripts/large-truth-cases.py N [N ...] > cases.jsonl
"""
import json
import math
import sys


def circle(n, r=1e4):
    return [[r * math.cos(2 * math.pi * k / n), r * math.sin(2 * math.pi * k / n)] for k in range(n)]


def star(n, r=1e4, lobes=64, depth=0.3):
    out = []
    for k in range(n):
        a = 2 * math.pi * k / n
        rr = r * (1 + depth * math.sin(lobes * a))
        out.append([rr * math.cos(a), rr * math.sin(a)])
    return out


def spiky(n, r=1e4):
    """Alternating radii: sharp corners everywhere (breaks §II.J rule 3)."""
    out = []
    for k in range(n):
        a = 2 * math.pi * k / n
        rr = r if k % 2 == 0 else 0.6 * r
        out.append([rr * math.cos(a), rr * math.sin(a)])
    return out


def case(cid, verts, pos, vel, vels=None, slab=None, lookahead=20.0, buff=0.1):
    poly = {"vertices": verts}
    if vels is not None:
        poly["velocities"] = vels
    if slab is not None:
        poly["bottom"], poly["top"], poly["vz"] = slab
    return {"id": cid, "lookahead": lookahead, "buff": buff,
            "point": {"pos": pos, "vel": vel}, "polygon": poly}


def cases(n):
    c = circle(n)
    s = star(n)
    top = max(v[1] for v in c)  # vertex n/4 lies at y = 1e4 exactly when 4 | n
    out = []
    tag = f"{n // 1024}k"
    # at rest
    out.append(case(f"circle-{tag}-enter", c, [-2e4, 0.5], [1000.0, 0.0]))
    out.append(case(f"circle-{tag}-graze", c, [-2e4, top], [2000.0, 0.0]))
    out.append(case(f"circle-{tag}-miss", c, [-2e4, top + 1e-3], [2000.0, 0.0]))
    out.append(case(f"star-{tag}-enter", s, [-2e4, 0.5], [1000.0, 0.0]))
    out.append(case(f"star-{tag}-miss", s, [-2e4, 1.35e4], [2000.0, 0.0]))
    # translating (detect_same_2d) and warping (detect_diff_2d): growing about the origin
    same = [[-300.0, 10.0]] * n
    out.append(case(f"circle-{tag}-moving-enter", c, [-2e4, 0.5], [700.0, 0.0], same))
    out.append(case(f"circle-{tag}-moving-miss", c, [-2e4, 1.2e4], [700.0, 0.0], same))
    grow = [[0.01 * x, 0.01 * y] for x, y in c]
    out.append(case(f"circle-{tag}-warp-enter", c, [-2e4, 0.5], [800.0, 0.0], grow))
    out.append(case(f"circle-{tag}-warp-miss", c, [-2e4, 1.3e4], [800.0, 0.0], grow))
    sgrow = [[0.01 * x + 5.0, 0.01 * y] for x, y in s]
    out.append(case(f"star-{tag}-warp-enter", s, [-2e4, 0.5], [800.0, 0.0], sgrow))
    out.append(case(f"star-{tag}-warp-miss", s, [-2e4, 1.7e4], [800.0, 0.0], sgrow))
    # 3D: the slab is met from t = 5 to 15
    out.append(case(f"circle-{tag}-3d-enter", c, [-2e4, 0.5, 0.0], [1000.0, 0.0, 1.0], same,
                    slab=(5.0, 15.0, 0.0)))
    out.append(case(f"star-{tag}-3d-miss", s, [-2e4, 0.5, 0.0], [500.0, 0.0, 1.0], sgrow,
                    slab=(5.0, 15.0, 0.0)))
    # sharp corners (not well formed), and a start inside
    out.append(case(f"spiky-{tag}-enter", spiky(n), [-2e4, 0.5], [1000.0, 0.0]))
    out.append(case(f"circle-{tag}-inside", c, [0.5, 0.5], [1.0, 0.0]))
    return out


def main():
    for arg in sys.argv[1:] or ["16384"]:
        for c in cases(int(arg)):
            print(json.dumps(c, separators=(",", ":")))


if __name__ == "__main__":
    main()
