#!/usr/bin/env python3
"""The `traffic` package's answer to "when is each flight in each FIR", timed, as the
baseline that `polyguard encounters` is compared with (compare.py).

It calls traffic the way its users do, in one process:

1. Occupancy: for every flight of the sample (``for flight in traffic``, the flights of
   ``Traffic.assign_id``, the same grouping as export.py's ``flight_id``) and every FIR
   of ``traffic.data.eurofirs`` (``for fir in eurofirs``, each an ``Airspace``):
   - ``flight.intersects(fir)``: with an ``Airspace`` traffic applies its altitude limits
     (a vertex of the lon/lat/altitude intersection must lie strictly between
     100 x lower and 100 x upper; fixes without altitude are dropped first);
   - ``flight.intersects(fir.shape)``: the 2D test on the Shapely polygon alone.
   Each loop is timed separately, in wall time and in this process's CPU time.
2. Intervals: for every pair whose 2D test holds,
   - ``flight.clip_iterate(fir)``: the pieces, each a ``Flight`` whose start/stop are
     the first and last fixes strictly inside the crossing times (``between(...,
     strict=True)``), so each end is up to one fix interval inside the true crossing;
   - ``flight.clip(fir)``: one piece from the first entry to the last exit (its ends
     are cut strictly once more, so they lie one further fix inside);
   - ``crossings``: the instants traffic computes before snapping to fixes: the time
     carried as Z of ``LineString(flight.xy_time).intersection(fir.shape)`` (GEOS
     interpolates Z at the new boundary points), merged as ``clip_iterate`` merges them.
   ``clip`` ignores altitude (it intersects the 2D shape). The geometry is the straight
   line in lon/lat degrees between fixes and between FIR vertices (Shapely on
   unprojected coordinates), where polyguard uses rhumb lines (straight on Mercator).

Outputs in ``--out`` (default /work/data/real), for sample S:
``baseline-S-occupancy.jsonl`` (one line per flight x FIR),
``baseline-S-clip.jsonl`` (one line per intersecting pair:
``{"mover", "icao24", "callsign", "area", "flight": [start, stop], "pieces": [[start,
stop], ...], "clip": [start, stop] or null, "crossings": [[t0, t1], ...]}``, epoch
seconds UTC), and ``baseline-S-timing.json``.
"""

import time

T_PROCESS = time.perf_counter()

import argparse  # noqa: E402
import json  # noqa: E402
import os  # noqa: E402
import platform  # noqa: E402
import sys  # noqa: E402
import warnings  # noqa: E402
from pathlib import Path  # noqa: E402


class Clock:
    """Wall time (``time.perf_counter``) and this process's CPU time
    (``time.process_time``) of a block: on a shared machine the wall time grows with
    the load, the CPU time much less."""

    def __enter__(self):
        self.w0, self.c0 = time.perf_counter(), time.process_time()
        return self

    def __exit__(self, *exc):
        self.wall = time.perf_counter() - self.w0
        self.cpu = time.process_time() - self.c0


def epoch(ts) -> float:
    """A pandas Timestamp as epoch seconds."""
    return ts.value / 1e9


def crossings(flight, shape) -> list:
    """The entry and exit instants traffic computes inside ``clip_iterate``: the Z (time)
    of the intersection of the (lon, lat, t) line with the polygon, per piece, merged
    where pieces overlap in time (the same merge as ``clip_iterate``)."""
    from shapely.geometry import LineString

    coords = list(flight.xy_time)
    if len(coords) < 2:
        return []
    ix = LineString(coords).intersection(shape)
    if ix.is_empty:
        return []
    lines = [ix] if ix.geom_type == "LineString" else [
        g for g in getattr(ix, "geoms", []) if g.geom_type == "LineString"]
    spans = []
    for g in lines:
        zs = [c[2] for c in g.coords]
        lo, hi = min(zs), max(zs)
        if spans and lo <= spans[-1][1]:
            spans[-1] = [min(spans[-1][0], lo), max(spans[-1][1], hi)]
        else:
            spans.append([lo, hi])
    return spans


def main(argv=None) -> int:
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sample", default="quickstart", help="traffic sample (default quickstart)")
    ap.add_argument("--out", type=Path, default=Path("/work/data/real"))
    ap.add_argument("--limit", type=int, default=0,
                    help="only the first N flights (by flight_id), to time a subset")
    ap.add_argument("--firs", default="", help="comma-separated designators (default all)")
    args = ap.parse_args(argv)

    warnings.simplefilter("ignore")
    t_import = time.perf_counter()
    import movingpandas  # noqa: F401  (only for the version line)
    import pandas
    import shapely
    import traffic
    from traffic.data import eurofirs, samples

    t = getattr(samples, args.sample).assign_id().eval()
    flights = list(t)
    flights.sort(key=lambda f: f.flight_id)
    if args.limit:
        flights = flights[: args.limit]
    firs = list(eurofirs)
    if args.firs:
        keep = set(args.firs.split(","))
        firs = [a for a in firs if a.designator in keep]
    t_loaded = time.perf_counter()
    print(f"{args.sample}: {len(flights)} flights, {len(firs)} FIRs, "
          f"{sum(len(f) for f in flights)} fixes; loaded in {t_loaded - t_import:.1f} s")

    args.out.mkdir(parents=True, exist_ok=True)
    tag = args.sample + (f"-first{args.limit}" if args.limit else "")
    shapes = {a.designator: a.shape for a in firs}

    with Clock() as c_occ3:
        occ3 = {(f.flight_id, a.designator): bool(f.intersects(a)) for f in flights for a in firs}
    print(f"intersects (Airspace, with altitude limits): {len(occ3)} pairs in {c_occ3.wall:.1f} s "
          f"(CPU {c_occ3.cpu:.1f} s), "
          f"{sum(occ3.values())} true")

    with Clock() as c_occ2:
        occ2 = {(f.flight_id, a.designator): bool(f.intersects(shapes[a.designator]))
                for f in flights for a in firs}
    print(f"intersects (fir.shape, 2D): {len(occ2)} pairs in {c_occ2.wall:.1f} s "
          f"(CPU {c_occ2.cpu:.1f} s), "
          f"{sum(occ2.values())} true")

    with (args.out / f"baseline-{tag}-occupancy.jsonl").open("w") as fh:
        for f in flights:
            for a in firs:
                k = (f.flight_id, a.designator)
                fh.write(json.dumps({"mover": f.flight_id, "icao24": f.icao24,
                                     "callsign": f.callsign, "area": a.designator,
                                     "intersects": occ3[k], "intersects_2d": occ2[k]}) + "\n")

    pairs = [(f, a) for f in flights for a in firs if occ2[(f.flight_id, a.designator)]]
    with Clock() as c_iter:
        pieces = {(f.flight_id, a.designator): [[epoch(p.start), epoch(p.stop)]
                                                for p in f.clip_iterate(a)] for f, a in pairs}
    clips = {}
    with Clock() as c_clip:
        for f, a in pairs:
            c = f.clip(a)
            clips[(f.flight_id, a.designator)] = None if c is None else [epoch(c.start), epoch(c.stop)]
    with Clock() as c_cross:
        cross = {(f.flight_id, a.designator): crossings(f, shapes[a.designator]) for f, a in pairs}
    n_pieces = sum(len(v) for v in pieces.values())
    print(f"clip_iterate: {len(pairs)} pairs, {n_pieces} pieces in {c_iter.wall:.1f} s "
          f"(CPU {c_iter.cpu:.1f} s); clip: {c_clip.wall:.1f} s (CPU {c_clip.cpu:.1f} s); "
          f"crossings: {c_cross.wall:.1f} s (CPU {c_cross.cpu:.1f} s)")

    with (args.out / f"baseline-{tag}-clip.jsonl").open("w") as fh:
        for f, a in pairs:
            k = (f.flight_id, a.designator)
            fh.write(json.dumps({"mover": f.flight_id, "icao24": f.icao24,
                                 "callsign": f.callsign, "area": a.designator,
                                 "flight": [epoch(f.start), epoch(f.stop)],
                                 "pieces": pieces[k], "clip": clips[k],
                                 "crossings": cross[k]}) + "\n")

    t_end = time.perf_counter()
    timing = {
        "sample": args.sample, "flights": len(flights), "firs": len(firs),
        "fixes": sum(len(f) for f in flights), "pairs": len(occ3),
        "intersects_true": sum(occ3.values()), "intersects_2d_true": sum(occ2.values()),
        "pieces": n_pieces,
        "seconds": {"import_and_load": t_loaded - t_import,
                    "intersects_airspace_loop": c_occ3.wall, "intersects_shape_loop": c_occ2.wall,
                    "clip_iterate_loop": c_iter.wall, "clip_loop": c_clip.wall,
                    "crossings_loop": c_cross.wall, "process": t_end - T_PROCESS},
        "cpu_seconds": {"intersects_airspace_loop": c_occ3.cpu,
                        "intersects_shape_loop": c_occ2.cpu, "clip_iterate_loop": c_iter.cpu,
                        "clip_loop": c_clip.cpu, "crossings_loop": c_cross.cpu,
                        "process": time.process_time()},
        "load_average": os.getloadavg(),
        "versions": {"traffic": traffic.__version__, "pandas": pandas.__version__,
                     "shapely": shapely.__version__, "geos": ".".join(map(str, shapely.geos_version)),
                     "python": sys.version.split()[0]},
        "machine": {"node": platform.node(), "cpus": os.cpu_count(),
                    "processor": platform.processor() or platform.machine(),
                    "nice": os.nice(0)},
        "utc": time.strftime("%Y-%m-%dT%H:%M:%SZ", time.gmtime()),
    }
    (args.out / f"baseline-{tag}-timing.json").write_text(json.dumps(timing, indent=1) + "\n")
    print(f"process: {t_end - T_PROCESS:.1f} s; wrote baseline-{tag}-*.json[l]")
    return 0


if __name__ == "__main__":
    sys.exit(main())
