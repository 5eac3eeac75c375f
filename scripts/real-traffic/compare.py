#!/usr/bin/env python3
"""Compares the intervals of `polyguard encounters` with the `traffic` package's clip
intervals (baseline.py), pair by pair (mover, area).

Ours: JSON Lines, one object per pair met, as ``polyguard encounters`` prints them:
``{"mover", "callsign", "area", "inside": [SPAN...], "near": [...], ...}`` with SPAN =
``{"start": [lo, hi], "end": [lo, hi], "certain": bool, ...}`` (epoch seconds; each end
an enclosure of the exact instant). The ``inside`` spans are used (``--ours-field``).

Either side may also be an exact answer of export.py (``expected-*.jsonl``, in
baseline.py's format): as the first file it is read as exact spans (traffic against the
truth), as the second it checks that our enclosures hold the exact ends (``--tol 0``).

Traffic's: baseline.py's ``baseline-S-clip.jsonl``; the intervals are ``pieces``
(``Flight.clip_iterate``: ends snapped to the fixes strictly inside), or with
``--traffic-field crossings`` the instants Shapely interpolates at the boundary, or
``clip`` (one interval from first entry to last exit).

Movers are matched by ``--key``: traffic's ``mover`` (its flight_id, the default, for an
encounters run on export.py's CSV grouped by flight_id), or ``icao24`` / ``callsign``
when our mover ids are those; traffic's intervals of one key and area are then pooled.

For each pair the intervals of both sides that overlap (each widened by ``--tol``
seconds) form groups. A group of ours alone is an interval traffic lacks
(``ours_only``), one of traffic's alone an interval we lack (``traffic_only``). In a
group with both, each outer end of traffic is compared with our enclosure of that end:
its distance to the enclosure (0 inside it) over ``--tol`` is ``ends_differ``; a
different count of intervals on each side is ``split_differs``. A pair with none of
these agrees. Each pair is classed by its first flag in the order traffic_only,
ours_only, ends_differ, split_differs, agree.

With ``--occupancy`` it also tables yes/no per pair (ours: at least one span) against
traffic's ``Flight.intersects`` (with the FIR's altitude limits, or without them by
``--occupancy-field intersects_2d``).

Prints a markdown table (also written to ``--md``) and writes every difference to
``--json`` for inspection.
"""

from __future__ import annotations

import argparse
import json
import sys
from datetime import datetime, timezone
from pathlib import Path

ORDER = ("traffic_only", "ours_only", "ends_differ", "split_differs", "agree")


def utc(t: float) -> str:
    """Epoch seconds as ISO 8601 UTC, for reading the tables."""
    return datetime.fromtimestamp(t, timezone.utc).strftime("%Y-%m-%dT%H:%M:%S.%fZ")[:-4] + "Z"


def read_ours(path: Path, field: str) -> dict:
    """Our spans per (mover, area): lists of (start_lo, start_hi, end_lo, end_hi, certain).
    A line with ``pieces`` and without ``field`` (baseline.py's format, as export.py's
    exact answers are written) gives exact spans."""
    out: dict = {}
    with path.open() as fh:
        for n, line in enumerate(fh, 1):
            if not line.strip():
                continue
            o = json.loads(line)
            if field not in o and "pieces" in o:
                # A file in baseline.py's format (an exact answer of export.py):
                # each end known exactly.
                spans = [{"start": [a, a], "end": [b, b], "certain": True} for a, b in o["pieces"]]
            else:
                spans = o.get(field) or []
            key = (str(o["mover"]), str(o["area"]))
            lst = out.setdefault(key, [])
            for s in spans:
                (slo, shi), (elo, ehi) = s["start"], s["end"]
                if not (slo <= shi <= ehi or slo <= elo <= ehi):
                    raise ValueError(f"{path}:{n}: span ends out of order: {s}")
                lst.append((float(slo), float(shi), float(elo), float(ehi), bool(s.get("certain"))))
    for v in out.values():
        v.sort()
    return out


def read_traffic(path: Path, field: str, key: str) -> dict:
    """Traffic's intervals per (key, area), pooled over the flights sharing the key."""
    out: dict = {}
    with path.open() as fh:
        for line in fh:
            if not line.strip():
                continue
            o = json.loads(line)
            iv = o.get(field)
            if iv is None:
                iv = []
            elif field == "clip":
                iv = [iv]
            k = (str(o[key]), str(o["area"]))
            out.setdefault(k, []).extend((float(a), float(b)) for a, b in iv)
    for v in out.values():
        v.sort()
    return out


def off(x: float, lo: float, hi: float) -> float:
    """Signed distance from x to the enclosure [lo, hi]: 0 inside, negative before."""
    return x - lo if x < lo else (x - hi if x > hi else 0.0)


def groups(ours: list, theirs: list, tol: float) -> list:
    """Clusters of our spans and traffic's intervals that overlap once widened by tol,
    in time order: each a dict with the members of both sides."""
    items = [(s[0], s[3], "ours", s) for s in ours] + [(a, b, "traffic", (a, b)) for a, b in theirs]
    items.sort(key=lambda x: (x[0], x[1]))
    out, cur, reach = [], None, None
    for lo, hi, side, it in items:
        if cur is not None and lo - tol <= reach + tol:
            cur[side].append(it)
            reach = max(reach, hi)
        else:
            cur = {"ours": [], "traffic": []}
            cur[side].append(it)
            out.append(cur)
            reach = hi
    return out


def classify(ours: list, theirs: list, tol: float) -> tuple[list, list]:
    """The flags of one pair and the details of each group."""
    flags, details = set(), []
    for g in groups(ours, theirs, tol):
        d = {"ours": [list(s[:4]) + [s[4]] for s in g["ours"]],
             "traffic": [list(x) for x in g["traffic"]]}
        if not g["traffic"]:
            d["flag"] = "ours_only"
        elif not g["ours"]:
            d["flag"] = "traffic_only"
        else:
            first = min(g["ours"], key=lambda s: s[0])
            last = max(g["ours"], key=lambda s: s[3])
            t0 = min(a for a, _ in g["traffic"])
            t1 = max(b for _, b in g["traffic"])
            d["d_start"] = off(t0, first[0], first[1])
            d["d_end"] = off(t1, last[2], last[3])
            d["traffic_start_utc"], d["traffic_end_utc"] = utc(t0), utc(t1)
            if max(abs(d["d_start"]), abs(d["d_end"])) > tol:
                d["flag"] = "ends_differ"
            elif len(g["ours"]) != len(g["traffic"]):
                d["flag"] = "split_differs"
            else:
                d["flag"] = "agree"
        flags.add(d["flag"])
        details.append(d)
    return sorted(flags, key=ORDER.index), details


def compare(ours: dict, theirs: dict, tol: float) -> dict:
    """Every pair classified; the summary counts and the largest end differences."""
    pairs, counts, flag_counts = [], {c: 0 for c in ORDER}, {c: 0 for c in ORDER}
    ends = []
    empty = 0
    for key in sorted(set(ours) | set(theirs)):
        o, t = ours.get(key, []), theirs.get(key, [])
        if not o and not t:
            empty += 1
            continue
        flags, details = classify(o, t, tol)
        cls = flags[0]
        counts[cls] += 1
        for f in flags:
            flag_counts[f] += 1
        for d in details:
            for end in ("d_start", "d_end"):
                if end in d:
                    ends.append((abs(d[end]), key, end, d))
        if cls != "agree":
            pairs.append({"mover": key[0], "area": key[1], "class": cls, "flags": flags,
                          "groups": details})
    ends.sort(key=lambda x: -x[0])
    diffs = [x[0] for x in ends]
    return {
        "pairs": sum(counts.values()), "pairs_without_intervals": empty,
        "classes": counts, "flags": flag_counts, "tol_s": tol,
        "ends_compared": len(diffs),
        "end_diff_max_s": diffs[0] if diffs else None,
        "end_diff_median_s": sorted(diffs)[len(diffs) // 2] if diffs else None,
        "ends_over_tol": sum(1 for x in diffs if x > tol),
        "largest": [{"mover": k[0], "area": k[1], "end": e, "diff_s": d[e],
                     "traffic_utc": d["traffic_start_utc" if e == "d_start" else "traffic_end_utc"],
                     "ours": d["ours"], "traffic": d["traffic"]}
                    for _, k, e, d in ends[:10]],
        "differences": pairs,
    }


def read_occupancy(path: Path, field: str, key: str) -> dict:
    """Traffic's yes/no per (key, area) from baseline.py's occupancy JSONL (any flight of
    the key counts)."""
    out: dict = {}
    with path.open() as fh:
        for line in fh:
            if line.strip():
                o = json.loads(line)
                k = (str(o[key]), str(o["area"]))
                out[k] = out.get(k, False) or bool(o[field])
    return out


def occupancy(ours: dict, occ: dict) -> dict:
    """The yes/no table: ours = at least one span, against traffic's ``intersects``. Pairs
    absent from our file are ours = no; pairs absent from traffic's file are counted
    apart (traffic did not test them)."""
    table = {"both": 0, "ours_only": 0, "traffic_only": 0, "neither": 0, "untested": 0}
    ours_only, traffic_only = [], []
    for k in sorted(set(ours) | set(occ)):
        a = bool(ours.get(k))
        if k not in occ:
            table["untested"] += 1
            continue
        b = occ[k]
        if a and b:
            table["both"] += 1
        elif a:
            table["ours_only"] += 1
            ours_only.append(list(k))
        elif b:
            table["traffic_only"] += 1
            traffic_only.append(list(k))
        else:
            table["neither"] += 1
    return {"table": table, "ours_only": ours_only, "traffic_only": traffic_only}


def markdown(r: dict, title: str) -> str:
    """The summary as a short markdown report."""
    lines = [f"## {title}", "",
             f"{r['pairs']} pairs (mover, area) with an interval on either side; "
             f"tolerance {r['tol_s']:g} s.", "",
             "| class | pairs | pairs with this flag |", "| --- | ---: | ---: |"]
    for c in ORDER:
        lines.append(f"| {c} | {r['classes'][c]} | {r['flags'][c]} |")
    lines += ["", f"Ends compared: {r['ends_compared']}; over tolerance: {r['ends_over_tol']}; "
              f"median {fmt(r['end_diff_median_s'])} s, largest {fmt(r['end_diff_max_s'])} s.", ""]
    if r["largest"]:
        lines += ["| mover | area | end | traffic (UTC) | traffic − our enclosure (s) |",
                  "| --- | --- | --- | --- | ---: |"]
        for x in r["largest"]:
            lines.append(f"| {x['mover']} | {x['area']} | {x['end'][2:]} | {x['traffic_utc']} | "
                         f"{x['diff_s']:+.3f} |")
    return "\n".join(lines) + "\n"


def fmt(x) -> str:
    return "-" if x is None else f"{x:.3f}"


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("ours", type=Path, help="our encounters JSONL")
    ap.add_argument("traffic", type=Path, help="baseline.py's clip JSONL")
    ap.add_argument("--ours-field", default="inside", choices=["inside", "near"])
    ap.add_argument("--traffic-field", default="pieces", choices=["pieces", "crossings", "clip"])
    ap.add_argument("--key", default="mover", choices=["mover", "icao24", "callsign"],
                    help="traffic's field that our mover ids are (default mover = flight_id)")
    ap.add_argument("--areas", default="",
                    help="comma-separated areas to keep (default: all in either file)")
    ap.add_argument("--tol", type=float, default=5.0, help="seconds (default 5)")
    ap.add_argument("--occupancy", type=Path,
                    help="also compare yes/no with baseline.py's occupancy JSONL")
    ap.add_argument("--occupancy-field", default="intersects",
                    choices=["intersects", "intersects_2d"],
                    help="intersects: traffic with the FIR's altitude limits; intersects_2d: without")
    ap.add_argument("--json", type=Path, help="write the differences here")
    ap.add_argument("--md", type=Path, help="write the markdown table here")
    args = ap.parse_args(argv)

    ours = read_ours(args.ours, args.ours_field)
    theirs = read_traffic(args.traffic, args.traffic_field, args.key)
    if args.areas:
        keep = set(args.areas.split(","))
        ours = {k: v for k, v in ours.items() if k[1] in keep}
        theirs = {k: v for k, v in theirs.items() if k[1] in keep}
    r = compare(ours, theirs, args.tol)
    md = markdown(r, f"{args.ours.name} ({args.ours_field}) vs {args.traffic.name} "
                     f"({args.traffic_field})")
    if args.occupancy:
        occ = read_occupancy(args.occupancy, args.occupancy_field, args.key)
        if args.areas:
            occ = {k: v for k, v in occ.items() if k[1] in keep}
        r["occupancy"] = occupancy(ours, occ)
        t = r["occupancy"]["table"]
        md += (f"\nOccupancy against traffic's `{args.occupancy_field}` ({args.occupancy.name}): "
               f"both {t['both']}, neither {t['neither']}, ours only {t['ours_only']}, "
               f"traffic only {t['traffic_only']}, not tested by traffic {t['untested']}.\n")
    print(md, end="")
    if args.md:
        args.md.write_text(md)
    if args.json:
        args.json.write_text(json.dumps(r, indent=1) + "\n")
    return 0


if __name__ == "__main__":
    sys.exit(main())
