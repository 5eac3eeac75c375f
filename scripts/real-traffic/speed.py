#!/usr/bin/env python3
"""The occupancy table of a traffic sample against the 58 European FIRs, by the `traffic`
package and by `polyguard encounters`, timed in one run on one machine, whole process
each: traffic imports, loads the sample and the FIRs, and loops `flight.intersects(fir)`
(with the FIRs' altitude limits, as its `Airspace` applies them); polyguard reads the
exported CSV and FIR GeoJSON and writes every pair's certified intervals (which contain
the table). Both run as child processes, one after the other; their wall and CPU
(user + system) times and the ratios are printed as a markdown table and as JSON.

Usage: speed.py [--sample quickstart] [--data /work/data/real] [--polyguard PATH]
                [--python /work/venv-rd/bin/python] [--repeat 3]
polyguard's time is the best of --repeat runs (the machine is shared); traffic runs once.
"""

import argparse
import json
import os
import resource
import subprocess
import sys
import time

TRAFFIC = r"""
import time
t0 = time.perf_counter()
from traffic.data import eurofirs, samples
flights = list(getattr(samples, "{sample}").assign_id().eval())
firs = list(eurofirs)
t1 = time.perf_counter()
table = {{(f.flight_id, a.designator): bool(f.intersects(a)) for f in flights for a in firs}}
t2 = time.perf_counter()
print(len(flights), len(firs), len(table), sum(table.values()), t1 - t0, t2 - t1)
"""


def child(cmd):
    """Runs `cmd`; its stdout, wall seconds and CPU seconds (user + system)."""
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    t = time.perf_counter()
    out = subprocess.run(cmd, check=True, capture_output=True, text=True).stdout
    wall = time.perf_counter() - t
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    cpu = (after.ru_utime - before.ru_utime) + (after.ru_stime - before.ru_stime)
    return out, wall, cpu


def main(argv=None):
    ap = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    ap.add_argument("--sample", default="quickstart")
    ap.add_argument("--data", default="/work/data/real")
    ap.add_argument("--polyguard", default="target/release/polyguard")
    ap.add_argument("--python", default="/work/venv-rd/bin/python")
    ap.add_argument("--repeat", type=int, default=3)
    a = ap.parse_args(argv)
    ours_cmd = [a.polyguard, "encounters", os.path.join(a.data, f"{a.sample}.csv"),
                os.path.join(a.data, "firs.geojson"), "--max-gap", "600", "--quiet",
                "-o", os.devnull]
    ours = [child(ours_cmd)[1:] for _ in range(max(1, a.repeat))]
    o_wall, o_cpu = min(ours)
    out, t_wall, t_cpu = child([a.python, "-c", TRAFFIC.format(sample=a.sample)])
    n_f, n_a, pairs, true, load_s, loop_s = out.split()
    res = {
        "sample": a.sample, "flights": int(n_f), "firs": int(n_a), "pairs": int(pairs),
        "traffic": {"process_wall_s": t_wall, "process_cpu_s": t_cpu,
                    "load_s": float(load_s), "intersects_loop_s": float(loop_s)},
        "polyguard": {"process_wall_s": o_wall, "process_cpu_s": o_cpu, "runs": len(ours)},
    }
    res["ratio_wall_process"] = t_wall / o_wall
    res["ratio_loop_vs_our_process"] = float(loop_s) / o_wall
    print(f"| {a.sample}: {n_f} flights × {n_a} FIRs | wall (s) | CPU (s) |")
    print("| --- | ---: | ---: |")
    print(f"| traffic, whole process | {t_wall:.2f} | {t_cpu:.2f} |")
    print(f"| traffic, the intersects loop alone | {float(loop_s):.2f} | |")
    print(f"| polyguard encounters, whole process (best of {len(ours)}) | {o_wall:.3f} | {o_cpu:.3f} |")
    print(f"| ratio, whole processes | {res['ratio_wall_process']:.0f}× | {t_cpu / o_cpu:.0f}× |")
    print(f"| ratio, traffic's loop alone / polyguard's whole process | {res['ratio_loop_vs_our_process']:.0f}× | |")
    print(json.dumps(res))
    return 0


if __name__ == "__main__":
    sys.exit(main())
