#!/usr/bin/env python3
"""Tests of compare.py on the hand-made pair of files in testdata/ (each pair there is
built to land in one class) and on small frames made here. Runs with the standard
library alone: ``python3 test_compare.py``."""

import json
import sys
import tempfile
import unittest
from pathlib import Path

HERE = Path(__file__).parent
sys.path.insert(0, str(HERE))

import compare  # noqa: E402


def span(s0, s1, e0, e1, certain=True):
    return {"start": [s0, s1], "end": [e0, e1], "certain": certain}


class TinyFiles(unittest.TestCase):
    """Each pair of testdata/ lands in the class it was made for."""

    def setUp(self):
        self.ours = compare.read_ours(HERE / "testdata" / "ours-tiny.jsonl", "inside")
        self.theirs = compare.read_traffic(HERE / "testdata" / "traffic-tiny.jsonl", "pieces", "mover")
        self.r = compare.compare(self.ours, self.theirs, 5.0)
        self.cls = {(d["mover"], d["area"]): d["class"] for d in self.r["differences"]}

    def test_classes(self):
        self.assertEqual(self.cls, {
            ("A", "F2"): "ours_only",       # no traffic line at all
            ("B", "F1"): "traffic_only",    # ours near only
            ("B", "F2"): "ends_differ",     # traffic enters 29.5 s after our enclosure
            ("C", "F1"): "split_differs",   # we split at a gap, traffic joins
            ("C", "F2"): "ours_only",       # one group agrees, a later one is ours alone
        })
        self.assertEqual(self.r["classes"]["agree"], 1)       # A/F1
        self.assertEqual(self.r["pairs_without_intervals"], 1)  # D/F1: near only, no traffic
        self.assertEqual(self.r["flags"]["agree"], 2)          # A/F1 and C/F2's first group

    def test_largest_difference(self):
        top = self.r["largest"][0]
        self.assertEqual((top["mover"], top["area"], top["end"]), ("B", "F2", "d_start"))
        self.assertAlmostEqual(top["diff_s"], 29.5)
        self.assertEqual(self.r["ends_over_tol"], 1)

    def test_tolerance_moves_the_class(self):
        loose = compare.compare(self.ours, self.theirs, 30.0)
        classes = {(d["mover"], d["area"]): d["class"] for d in loose["differences"]}
        self.assertNotIn(("B", "F2"), classes)  # 29.5 s is within 30 s: agrees

    def test_cli_writes_table_and_json(self):
        with tempfile.TemporaryDirectory() as tmp:
            j, md = Path(tmp) / "d.json", Path(tmp) / "t.md"
            rc = compare.main([str(HERE / "testdata" / "ours-tiny.jsonl"),
                               str(HERE / "testdata" / "traffic-tiny.jsonl"),
                               "--json", str(j), "--md", str(md)])
            self.assertEqual(rc, 0)
            self.assertEqual(json.loads(j.read_text())["classes"], self.r["classes"])
            self.assertIn("| ends_differ | 1 | 1 |", md.read_text())


class Frames(unittest.TestCase):
    """Properties on frames built here."""

    def write(self, tmp, name, rows):
        p = Path(tmp) / name
        p.write_text("".join(json.dumps(r) + "\n" for r in rows))
        return p

    def test_key_icao24_pools_flights(self):
        # Two traffic flights of one aircraft; our mover id is the icao24.
        with tempfile.TemporaryDirectory() as tmp:
            o = self.write(tmp, "o.jsonl", [{"mover": "abc123", "area": "X",
                                             "inside": [span(0, 1, 10, 11), span(100, 101, 110, 111)]}])
            t = self.write(tmp, "t.jsonl", [
                {"mover": "F_000", "icao24": "abc123", "area": "X", "pieces": [[1, 10]]},
                {"mover": "F_001", "icao24": "abc123", "area": "X", "pieces": [[101, 110]]}])
            r = compare.compare(compare.read_ours(o, "inside"),
                                compare.read_traffic(t, "pieces", "icao24"), 5.0)
            self.assertEqual(r["classes"]["agree"], 1)
            self.assertEqual(r["differences"], [])

    def test_inside_enclosure_is_zero_distance(self):
        for x, lo, hi, want in [(5, 4, 6, 0), (3, 4, 6, -1), (8, 4, 6, 2), (4, 4, 4, 0)]:
            self.assertEqual(compare.off(x, lo, hi), want)

    def test_clip_field_is_one_interval(self):
        with tempfile.TemporaryDirectory() as tmp:
            t = self.write(tmp, "t.jsonl", [{"mover": "M", "area": "X", "clip": [3, 9]},
                                            {"mover": "N", "area": "X", "clip": None}])
            got = compare.read_traffic(t, "clip", "mover")
            self.assertEqual(got, {("M", "X"): [(3.0, 9.0)], ("N", "X"): []})

    def test_occupancy_table(self):
        with tempfile.TemporaryDirectory() as tmp:
            t = self.write(tmp, "occ.jsonl", [
                {"mover": "A", "area": "X", "intersects": True},
                {"mover": "A", "area": "Y", "intersects": False},
                {"mover": "B", "area": "X", "intersects": True},
                {"mover": "B", "area": "Y", "intersects": False}])
            ours = {("A", "X"): [(0, 1, 2, 3, True)], ("A", "Y"): [(0, 1, 2, 3, True)],
                    ("B", "Y"): [], ("C", "X"): [(0, 1, 2, 3, True)]}
            r = compare.occupancy(ours, compare.read_occupancy(t, "intersects", "mover"))
            self.assertEqual(r["table"], {"both": 1, "ours_only": 1, "traffic_only": 1,
                                          "neither": 1, "untested": 1})
            self.assertEqual(r["ours_only"], [["A", "Y"]])
            self.assertEqual(r["traffic_only"], [["B", "X"]])

    def test_exact_answer_as_first_file(self):
        with tempfile.TemporaryDirectory() as tmp:
            e = self.write(tmp, "e.jsonl", [{"mover": "M", "area": "X", "pieces": [[3, 9]]}])
            self.assertEqual(compare.read_ours(e, "inside"), {("M", "X"): [(3, 3, 9, 9, True)]})

    def test_disjoint_sides_are_separate_groups(self):
        gs = compare.groups([(0, 1, 10, 11, True)], [(50.0, 60.0)], 5.0)
        self.assertEqual([(len(g["ours"]), len(g["traffic"])) for g in gs], [(1, 0), (0, 1)])


if __name__ == "__main__":
    unittest.main(verbosity=1)
