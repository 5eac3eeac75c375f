#!/usr/bin/env python3
"""Exports real air traffic, the European FIRs and synthetic storm cells as the input
files of `polyguard encounters` (docs/moving-features.md, "Formats").

Everything comes from the `traffic` package's bundled samples (no network):

- ``<name>.csv``: the fixes of the ``quickstart`` and ``switzerland`` samples
  (``traffic.data.samples``), one row per fix, written by ``Traffic.to_csv``. The
  ``flight_id`` column is traffic's own grouping (``Traffic.assign_id``: icao24 and
  callsign, split where no fix is received for 10 minutes), so that a mover here is a
  ``Flight`` there. Rows sorted by flight_id then timestamp; timestamps as pandas
  writes them (``2021-10-07 12:12:53+00:00``, UTC); altitude in feet (barometric), empty
  where the sample has none.
- ``<name>.mf.json``: the same flights as OGC Moving Features JSON (MovingPoint per
  flight), written by MovingPandas' ``TrajectoryCollection.to_mf_json`` with altitude as
  a temporal property. Two things differ from the bare call and are needed to write
  valid JSON at all: missing altitudes (NaN) become ``null``; nothing else is touched
  (MovingPandas writes datetimes without an offset, as UTC wall-clock time, and the
  flight id in ``properties.flight_id``, no Feature ``id``).
- ``firs.geojson``: the FIRs of ``traffic.data.eurofirs`` (the file the package ships)
  as a FeatureCollection, ``id`` = ICAO designator (IDENT), every source property kept,
  plus ``floor_ft`` / ``ceiling_ft`` converted from LOWERLIMIT/LOWERUNIT and
  UPPERLIMIT/UPPERUNIT (FL x 100 ft, M / 0.3048, FT as is). A bound that is unlimited
  (FL 999) is omitted; a floor of 0 (the surface) is omitted too unless
  ``--surface-floor zero``, since barometric altitudes on the ground go below 0 ft.
- ``firs-2d.geojson``: the same polygons without ``floor_ft`` / ``ceiling_ft``: the
  like-for-like input for comparing with ``Flight.clip``, which ignores altitude.
- ``cells-<name>.mf.json``: drifting, growing, rotating convective cells as MF-JSON
  MovingPolygon features (``"interpolation": "Linear"``, one exterior ring per instant
  with the same vertex count at every keyframe, keyframes every 15 minutes over the
  sample's time span), centred on fixes of the sample so that flights meet them;
  ``floor_ft`` / ``ceiling_ft`` properties. Seeded: the same arguments give the same
  bytes.
- ``expected-<name>-<FIR>-gap<S>.jsonl``: the exact answer where it is plain: when the
  sample's bounding box lies inside one FIR (quickstart: Paris) with a margin over twice
  the rhumb deviation of the FIR's edges, every flight is inside that FIR, without
  altitude limits, from its first fix to its last, split at gaps over S seconds (60 and
  600). Written in baseline.py's clip format (``pieces``), so that compare.py checks
  our enclosures against it with ``--tol 0``.
- ``excerpt/``: small files for tests: 3 quickstart flights that cross FL195 (the Paris
  FIR's ceiling), each cut to 150 s either side of that crossing, as CSV (key columns)
  and MF-JSON; the Paris FIR (LFFF, which holds all of quickstart) and the Brest FIR
  (LFRR, the fewest vertices); 2 cells sitting on two of those flights at their
  crossing.

Run with the venv that has ``traffic`` and ``movingpandas`` (see README.md beside this
file)::

    python export.py --out /work/data/real
"""

from __future__ import annotations

import argparse
import json
import math
import random
import sys
import warnings
from pathlib import Path

SAMPLES = ("quickstart", "switzerland")
CSV_FIRST = ["flight_id", "timestamp", "icao24", "callsign", "latitude", "longitude", "altitude"]
KEYFRAME_S = 15 * 60
EXCERPT_FIRS = ("LFFF", "LFRR")
NM_PER_DEG_LAT = 60.0


def load_sample(name: str):
    """The sample as a ``Traffic`` with traffic's ``flight_id`` assigned."""
    from traffic.data import samples

    t = getattr(samples, name)
    return t.assign_id().eval()


def fixes_frame(t):
    """The sample's rows sorted by flight then time, key columns first; rows without a
    position dropped (their count returned)."""
    d = t.data
    has_pos = d.latitude.notna() & d.longitude.notna()
    dropped = int((~has_pos).sum())
    d = d[has_pos]
    cols = CSV_FIRST + [c for c in d.columns if c not in CSV_FIRST]
    d = d[cols].sort_values(["flight_id", "timestamp"], kind="stable").reset_index(drop=True)
    return d, dropped


def data_notes(d) -> dict:
    """Counts a reader must cope with: missing altitudes, repeated instants within a
    flight, gaps between fixes."""
    gaps = d.groupby("flight_id").timestamp.diff().dt.total_seconds()
    return {
        "flights": int(d.flight_id.nunique()),
        "fixes": int(len(d)),
        "icao24": int(d.icao24.nunique()),
        "altitude_missing": int(d.altitude.isna().sum()),
        "altitude_below_0": int((d.altitude < 0).sum()),
        "altitude_max_ft": float(d.altitude.max()),
        "repeated_instants": int(d.duplicated(["flight_id", "timestamp"]).sum()),
        "gaps_over_60s": int((gaps > 60).sum()),
        "largest_gap_s": float(gaps.max()),
        "start": str(d.timestamp.min()),
        "stop": str(d.timestamp.max()),
        "lon": [float(d.longitude.min()), float(d.longitude.max())],
        "lat": [float(d.latitude.min()), float(d.latitude.max())],
    }


def write_csv(t, d, path: Path) -> None:
    """Writes the fixes with traffic's own ``to_csv`` (pandas underneath)."""
    from traffic.core import Traffic

    Traffic(d).to_csv(path, index=False)


def excerpt_flights(d, n: int, ceiling_ft: float = 19500.0, half_window_s: int = 150):
    """The first ``n`` flights (by flight_id) that cross ``ceiling_ft`` (the Paris FIR's
    ceiling), each cut to the fixes within ``half_window_s`` of its first crossing, and
    the row (in the cut frame) of each crossing fix, where the excerpt's cells sit."""
    import pandas as pd

    parts, anchors, start = [], [], 0
    for fid, f in d.groupby("flight_id", sort=True):
        alt = f.altitude.astype("float64")
        above = alt >= ceiling_ft
        ok = alt.notna()
        cross = (above != above.shift()) & ok & ok.shift(fill_value=False)
        cross.iloc[0] = False
        if not cross.any():
            continue
        tc = f.timestamp[cross].iloc[0]
        w = f[(f.timestamp >= tc - pd.Timedelta(seconds=half_window_s))
              & (f.timestamp <= tc + pd.Timedelta(seconds=half_window_s))]
        anchors.append(start + int((w.timestamp < tc).sum()))
        start += len(w)
        parts.append(w)
        if len(parts) == n:
            break
    return pd.concat(parts, ignore_index=True), anchors


def mf_json_of(d) -> dict:
    """The flights as MF-JSON by MovingPandas' ``TrajectoryCollection.to_mf_json``."""
    import movingpandas as mpd

    cols = ["flight_id", "timestamp", "icao24", "callsign", "longitude", "latitude", "altitude"]
    m = d[cols].copy()
    # MovingPandas reads numpy datetimes only (traffic holds pyarrow timestamps); it then
    # drops the zone itself, keeping the UTC wall-clock time.
    m["timestamp"] = m.timestamp.astype("datetime64[ns, UTC]")
    m["altitude"] = m.altitude.astype("float64")
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        tc = mpd.TrajectoryCollection(
            m, traj_id_col="flight_id", t="timestamp", x="longitude", y="latitude"
        )
        doc = tc.to_mf_json(temporal_columns=["altitude"])
    return nan_to_null(doc)


def nan_to_null(x):
    """JSON has no NaN: a missing number becomes null."""
    if isinstance(x, float) and math.isnan(x):
        return None
    if isinstance(x, dict):
        return {k: nan_to_null(v) for k, v in x.items()}
    if isinstance(x, (list, tuple)):
        return [nan_to_null(v) for v in x]
    return x


def height_ft(value: str, unit: str) -> float | None:
    """A limit of the eurofirs data in feet: FL x 100, metres / 0.3048, feet as is;
    None for FL 999 (unlimited)."""
    v = float(value)
    if unit == "FL":
        return None if v >= 999 else v * 100.0
    if unit == "M":
        return v / 0.3048
    if unit == "FT":
        return v
    raise ValueError(f"unknown unit {unit!r}")


def eurofirs_json() -> dict:
    """The FeatureCollection that ``traffic.data.eurofirs`` reads (shipped with traffic)."""
    import traffic.data.eurocontrol.eurofirs as ef

    with Path(ef.__file__).with_name("eurofirs.json").open() as fh:
        return json.load(fh)


def fir_features(surface_floor_zero: bool, with_limits: bool) -> tuple[list, dict]:
    """The FIR features with ``id`` and floor/ceiling in feet, and notes on the rings."""
    from shapely.geometry import shape

    src = eurofirs_json()
    out, notes = [], {"features": 0, "holes": 0, "multipolygons": 0, "vertices": 0,
                      "antimeridian": [], "above_85": [], "invalid": [], "units": {}}
    for f in src["features"]:
        p = dict(f["properties"])
        g = f["geometry"]
        polys = [g["coordinates"]] if g["type"] == "Polygon" else g["coordinates"]
        notes["features"] += 1
        notes["multipolygons"] += g["type"] == "MultiPolygon"
        notes["holes"] += sum(len(poly) - 1 for poly in polys)
        notes["vertices"] += sum(len(r) - 1 for poly in polys for r in poly)
        lons = [c[0] for poly in polys for r in poly for c in r]
        lats = [c[1] for poly in polys for r in poly for c in r]
        if max(lons) - min(lons) > 180 or max(abs(x) for x in lons) > 180:
            notes["antimeridian"].append(p["IDENT"])
        if max(abs(y) for y in lats) > 85:
            notes["above_85"].append([p["IDENT"], max(lats)])
        s = shape(g)
        if not s.is_valid:
            from shapely.validation import explain_validity

            notes["invalid"].append([p["IDENT"], explain_validity(s)])
        key = f'{p["LOWERLIMIT"]} {p["LOWERUNIT"]} .. {p["UPPERLIMIT"]} {p["UPPERUNIT"]}'
        notes["units"][key] = notes["units"].get(key, 0) + 1
        if with_limits:
            floor = height_ft(p["LOWERLIMIT"], p["LOWERUNIT"])
            ceiling = height_ft(p["UPPERLIMIT"], p["UPPERUNIT"])
            if floor is not None and (floor > 0 or surface_floor_zero):
                p["floor_ft"] = floor
            if ceiling is not None:
                p["ceiling_ft"] = ceiling
        out.append({"type": "Feature", "id": p["IDENT"], "properties": p, "geometry": g})
    return out, notes


def cell_features(d, sample: str, n: int, seed: int, vertices: int,
                  anchors: list | None = None, prefix: str = "cell") -> list:
    """Storm cells: star-shaped rings around a centre that drifts at constant velocity,
    grows (or shrinks) linearly and rotates, sampled every 15 minutes over the sample's
    span. Each centre is put on a fix of the sample at that fix's time, so the cell is
    over the traffic then. Rotation per keyframe stays below half the smallest angular
    gap between vertices, so the linear interpolation between keyframes keeps the ring
    star-shaped about its centre, hence simple."""
    rng = random.Random(f"{seed}-{sample}")
    t_all = d.timestamp.astype("int64") // 10**9
    t0 = int(t_all.min()) // KEYFRAME_S * KEYFRAME_S
    t1 = -(-int(t_all.max()) // KEYFRAME_S) * KEYFRAME_S
    times = list(range(t0, t1 + 1, KEYFRAME_S))
    # Row numbers of the fixes the cells sit on at their anchor time.
    picks = anchors if anchors is not None else sorted(rng.sample(range(len(d)), n))
    feats = []
    for i, row_i in enumerate(picks):
        row = d.iloc[row_i]
        tc = int(row.timestamp.value // 10**9)
        lon_c, lat_c = float(row.longitude), float(row.latitude)
        speed_kt = rng.uniform(10, 45)
        heading = math.radians(rng.uniform(180, 300) + 90)  # mostly from the south-west
        r0_nm = rng.uniform(4, 15)
        growth = rng.uniform(-0.5, 1.5)  # relative change of radius per hour
        omega_deg_h = rng.uniform(-20, 20)
        step = 360.0 / vertices
        angles = [k * step + rng.uniform(-0.2, 0.2) * step for k in range(vertices)]
        radii = [rng.uniform(0.7, 1.3) for _ in range(vertices)]
        assert abs(omega_deg_h) / 4 < 0.3 * step  # per keyframe, below half the gap
        floor = rng.choice([None, None, 0.0, 2000.0, 5000.0])
        ceiling = rng.choice([25000.0, 30000.0, 35000.0, 38000.0, 41000.0, 45000.0])
        frames, stamps = [], []
        for t in times:
            h = (t - tc) / 3600.0
            east = speed_kt * h * math.sin(heading)
            north = speed_kt * h * math.cos(heading)
            lat = lat_c + north / NM_PER_DEG_LAT
            lon = lon_c + east / (NM_PER_DEG_LAT * math.cos(math.radians(lat)))
            r = r0_nm * max(0.25, 1 + growth * (t - times[0]) / 3600.0 / max(1.0, (times[-1] - times[0]) / 3600.0))
            rot = omega_deg_h * h
            ring = []
            for a, q in zip(angles, radii):
                th = math.radians(a + rot)
                dx, dy = r * q * math.cos(th), r * q * math.sin(th)
                ring.append([
                    round(lon + dx / (NM_PER_DEG_LAT * math.cos(math.radians(lat))), 7),
                    round(lat + dy / NM_PER_DEG_LAT, 7),
                ])
            ring.append(list(ring[0]))
            frames.append(ring)
            stamps.append(_iso(t))
        props = {"name": f"cell {i}", "kind": "convective cell",
                 "anchor_utc": _iso(tc), "speed_kt": round(speed_kt, 1),
                 "ceiling_ft": ceiling}
        if floor is not None:
            props["floor_ft"] = floor
        feats.append({
            "type": "Feature",
            "id": f"{sample[:2]}-{prefix}-{i:02d}",
            "properties": props,
            "temporalGeometry": {
                "type": "MovingPolygon",
                "datetimes": stamps,
                "coordinates": frames,
                "interpolation": "Linear",
            },
        })
    return feats


def rhumb_deviation_deg(ring: list, samples: int = 32) -> float:
    """The largest latitude gap, in degrees, between an edge drawn straight in lon/lat
    and the rhumb line (straight on Mercator) joining the same vertices, over all edges
    of ``ring``, sampled at ``samples`` points per edge. At a given longitude both lines
    differ in latitude alone (a meridian edge is the same line in both), so this bounds
    how far the area moves between the two readings of its edges."""
    def merc(phi):
        return math.log(math.tan(math.pi / 4 + math.radians(phi) / 2))

    def inv(y):
        return math.degrees(2 * math.atan(math.exp(y)) - math.pi / 2)

    worst = 0.0
    for (_, p1), (_, p2) in zip(ring, ring[1:]):
        y1, y2 = merc(p1), merc(p2)
        for k in range(1, samples):
            s = k / samples
            worst = max(worst, abs(inv(y1 + s * (y2 - y1)) - (p1 + s * (p2 - p1))))
    return worst


def expected_inside(d, fir: dict, max_gap_s: float) -> list | None:
    """The exact inside intervals of every flight in ``fir`` without altitude limits,
    when the sample's bounding box lies inside the FIR with a margin over twice the
    rhumb deviation of its edges: every fix is then inside, and so is every segment
    between fixes (a rhumb segment is straight on Mercator, where the box is a box too),
    in both the lon/lat and the rhumb reading. Each flight is inside from its first to
    its last fix, split where two fixes are more than ``max_gap_s`` apart (the gap is
    outside the domain). None when the box is not inside with that margin."""
    from shapely.geometry import box, shape

    poly = shape(fir["geometry"])
    b = box(d.longitude.min(), d.latitude.min(), d.longitude.max(), d.latitude.max())
    dev = max(rhumb_deviation_deg(r) for r in fir["geometry"]["coordinates"])
    if not poly.contains(b) or poly.exterior.distance(b) <= 2 * dev:
        return None
    rows = []
    for fid, f in d.groupby("flight_id", sort=True):
        t = (f.timestamp.astype("int64") // 10**9).tolist()
        pieces, start = [], t[0]
        for a, c in zip(t, t[1:]):
            if c - a > max_gap_s:
                pieces.append([float(start), float(a)])
                start = c
        pieces.append([float(start), float(t[-1])])
        pieces = [p for p in pieces if p[1] > p[0]]
        rows.append({"mover": fid, "icao24": f.icao24.iloc[0], "callsign": f.callsign.iloc[0],
                     "area": fir["id"], "flight": [float(t[0]), float(t[-1])], "pieces": pieces,
                     "margin_deg": poly.exterior.distance(b), "rhumb_deviation_deg": dev})
    return rows


def _iso(t: int) -> str:
    """Epoch seconds as RFC 3339 UTC."""
    import datetime as dt

    return dt.datetime.fromtimestamp(t, dt.timezone.utc).strftime("%Y-%m-%dT%H:%M:%SZ")


def dump(obj, path: Path) -> int:
    """Writes JSON (no NaN allowed) and returns its size in bytes."""
    text = json.dumps(obj, allow_nan=False, separators=(",", ":"))
    path.write_text(text + "\n")
    return len(text) + 1


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0],
                                 formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--out", type=Path, default=Path("/work/data/real"),
                    help="output folder (default /work/data/real)")
    ap.add_argument("--samples", default=",".join(SAMPLES),
                    help="comma-separated traffic samples (default quickstart,switzerland)")
    ap.add_argument("--mf-json", default="quickstart,switzerland",
                    help="samples also written as MovingPandas MF-JSON")
    ap.add_argument("--cells", type=int, default=30, help="storm cells per sample (default 30)")
    ap.add_argument("--cell-vertices", type=int, default=12, help="vertices per cell ring")
    ap.add_argument("--seed", type=int, default=20211007, help="seed of the cells")
    ap.add_argument("--surface-floor", choices=["omit", "zero"], default="omit",
                    help="a FIR floor at the surface: omitted (default) or floor_ft 0")
    ap.add_argument("--excerpt-flights", type=int, default=3)
    args = ap.parse_args(argv)

    import movingpandas
    import pandas
    import shapely
    import traffic

    out: Path = args.out
    ex = out / "excerpt"
    ex.mkdir(parents=True, exist_ok=True)
    summary = {"versions": {"traffic": traffic.__version__, "movingpandas": movingpandas.__version__,
                            "pandas": pandas.__version__, "shapely": shapely.__version__,
                            "python": sys.version.split()[0]}}

    firs, fir_notes = fir_features(args.surface_floor == "zero", True)
    firs2d, _ = fir_features(False, False)
    dump({"type": "FeatureCollection", "features": firs}, out / "firs.geojson")
    dump({"type": "FeatureCollection", "features": firs2d}, out / "firs-2d.geojson")
    summary["firs"] = fir_notes
    print(f"firs.geojson, firs-2d.geojson: {fir_notes['features']} FIRs, "
          f"{fir_notes['vertices']} vertices, {fir_notes['holes']} holes, "
          f"{fir_notes['multipolygons']} MultiPolygons, antimeridian {fir_notes['antimeridian']}, "
          f"above 85 deg {fir_notes['above_85']}, invalid {fir_notes['invalid']}")
    # The Paris FIR holds all of quickstart (its ceiling FL195 is what the excerpt
    # flights cross); Brest is the FIR with the fewest vertices.
    for fir in firs:
        if fir["id"] in EXCERPT_FIRS:
            dump({"type": "FeatureCollection", "features": [fir]}, ex / f"fir-{fir['id']}.geojson")

    mf_set = {s for s in args.mf_json.split(",") if s}
    for name in [s for s in args.samples.split(",") if s]:
        t = load_sample(name)
        d, dropped = fixes_frame(t)
        notes = data_notes(d)
        notes["rows_without_position_dropped"] = dropped
        summary[name] = notes
        write_csv(t, d, out / f"{name}.csv")
        print(f"{name}.csv: {notes['flights']} flights, {notes['fixes']} fixes "
              f"({dropped} without position dropped), {notes['altitude_missing']} without altitude, "
              f"{notes['repeated_instants']} repeated instants, {notes['gaps_over_60s']} gaps > 60 s "
              f"(largest {notes['largest_gap_s']:.0f} s), {notes['start']} .. {notes['stop']}")
        if name in mf_set:
            size = dump(mf_json_of(d), out / f"{name}.mf.json")
            print(f"{name}.mf.json: {notes['flights']} MovingPoint features, {size} bytes")
        cells = cell_features(d, name, args.cells, args.seed, args.cell_vertices)
        dump({"type": "FeatureCollection", "features": cells}, out / f"cells-{name}.mf.json")
        nk = len(cells[0]["temporalGeometry"]["datetimes"]) if cells else 0
        print(f"cells-{name}.mf.json: {len(cells)} cells x {nk} keyframes x "
              f"{args.cell_vertices} vertices")
        summary[name]["cells"] = {"count": len(cells), "keyframes": nk,
                                  "vertices": args.cell_vertices}
        for fir in firs2d:
            for gap in (60, 600):
                exp = expected_inside(d, fir, gap)
                if exp is not None:
                    fn = f"expected-{name}-{fir['id']}-gap{gap}.jsonl"
                    with (out / fn).open("w") as fh:
                        fh.writelines(json.dumps(r) + "\n" for r in exp)
                    print(f"{fn}: {len(exp)} flights wholly inside {fir['id']} "
                          f"(margin {exp[0]['margin_deg']:.4f} deg, rhumb deviation "
                          f"{exp[0]['rhumb_deviation_deg']:.4f} deg), "
                          f"{sum(len(r['pieces']) for r in exp)} intervals")
        if name == "quickstart":
            e, anchors = excerpt_flights(d, args.excerpt_flights)
            write_csv(t, e[CSV_FIRST], ex / "quickstart-3.csv")
            dump(mf_json_of(e), ex / "quickstart-3.mf.json")
            two = cell_features(e, name, 2, args.seed, args.cell_vertices,
                                anchors=anchors[:2], prefix="excerpt-cell")
            dump({"type": "FeatureCollection", "features": two}, ex / "cells-2.mf.json")
            print(f"excerpt: flights {sorted(e.flight_id.unique())}, "
                  f"{len(e)} fixes, cells {[c['id'] for c in two]}")
    dump(summary, out / "export-summary.json")
    for p in sorted(ex.iterdir()):
        print(f"  excerpt/{p.name}: {p.stat().st_size} bytes")
    return 0


if __name__ == "__main__":
    sys.exit(main())
