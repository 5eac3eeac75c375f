"""docs/dask.md's recipe: fixes partitioned by flight on a LocalCluster of two worker
processes, the areas broadcast as a plain object, `encounters` on every partition; the
answer, once sorted, is the single-process frame, row for row and bit for bit."""

import json

import pytest

import polyguard
from conftest import REPO

pd = pytest.importorskip("pandas")
dd = pytest.importorskip("dask.dataframe")
distributed = pytest.importorskip("dask.distributed")

DATA = REPO / "crates" / "earth" / "tests" / "data" / "moving"
KEY = ["mover", "area", "relation", "start_lo", "end_hi"]


def in_time_order(part):
    """A partition's fixes in time order (a shuffle keeps each flight whole, not its
    rows' order); the stable sort keeps a flight's fixes as the file has them."""
    return part.sort_values("timestamp", kind="stable")


@pytest.mark.parametrize("areas_file,opts", [
    ("cells-2.mf.json", {"sep": 5.0, "sep_v": 1000.0}),
    ("fir-LFFF.geojson", {"sep": 0.0}),
])
def test_partitions_by_flight_answer_as_one_process(areas_file, opts):
    fixes = pd.read_csv(DATA / "quickstart-3.csv",
                        dtype={"icao24": str, "callsign": str, "flight_id": str})
    fixes["timestamp"] = pd.to_datetime(fixes["timestamp"])
    areas = json.loads((DATA / areas_file).read_text())
    single = polyguard.encounters(fixes, areas, **opts)
    assert len(single) > 0
    meta = polyguard.encounters(fixes.iloc[:0], areas, **opts)
    with distributed.LocalCluster(n_workers=2, threads_per_worker=1,
                                  dashboard_address=None) as cluster, \
            distributed.Client(cluster):
        parts = dd.from_pandas(fixes, npartitions=3).shuffle("flight_id")
        parts = parts.map_partitions(in_time_order)
        spread = parts.map_partitions(polyguard.encounters, areas, meta=meta, **opts)
        got = spread.compute()
    want = single.sort_values(KEY).reset_index(drop=True)
    got = got.sort_values(KEY).reset_index(drop=True)
    pd.testing.assert_frame_equal(got, want, check_exact=True)
