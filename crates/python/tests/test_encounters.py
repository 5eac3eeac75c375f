"""`polyguard.encounters` answers what `polyguard encounters` answers (docs/moving-features.md):
the same spans, in the same order, with the same f64 values, for MF-JSON movers, for a
pandas frame of fixes read from the CSV the CLI reads, and for a GeoDataFrame of areas."""

import json
import warnings

import pytest

import polyguard
from conftest import REPO, jsonl, run_cli

pd = pytest.importorskip("pandas")

DATA = REPO / "crates" / "earth" / "tests" / "data" / "moving"
CASES = [("fir-LFFF.geojson", []), ("fir-LFRR.geojson", ["--sep", "120", "--sep-v", "30000"]),
         ("cells-2.mf.json", ["--sep", "5", "--sep-v", "1000"])]


def options(args):
    """The CLI's flags as the keyword arguments of polyguard.encounters."""
    names = {"--sep": "sep", "--sep-v": "sep_v", "--max-gap": "max_gap"}
    return {names[k]: float(v) for k, v in zip(args[::2], args[1::2])}


def cli_rows(movers, areas, args):
    """The CLI's lines as rows (mover, callsign, area, relation, start, end, certain)."""
    code, out, err = run_cli("encounters", DATA / movers, DATA / areas, "--quiet", *args)
    assert code == 0, err
    rows = []
    for line in jsonl(out):
        for relation in ("inside", "near"):
            for s in line[relation]:
                rows.append((line["mover"], line["callsign"], line["area"], relation,
                             *s["start"], *s["end"], s["certain"]))
    return rows


def frame_rows(frame):
    assert list(frame.columns) == ["mover", "callsign", "area", "relation", "start_lo",
                                   "start_hi", "end_lo", "end_hi", "certain", "start",
                                   "end"]
    assert (frame["start"] == pd.to_datetime(frame["start_lo"], unit="s", utc=True)).all()
    cols = frame.columns[:9]
    return [tuple(None if isinstance(v, float) and v != v else v for v in r)
            for r in frame[cols].itertuples(index=False, name=None)]


def fixes_frame():
    """quickstart-3.csv as traffic holds it: a pandas frame with datetime timestamps."""
    f = pd.read_csv(DATA / "quickstart-3.csv",
                    dtype={"icao24": str, "callsign": str, "flight_id": str})
    f["timestamp"] = pd.to_datetime(f["timestamp"])
    return f


@pytest.mark.parametrize("areas,args", CASES)
def test_mfjson_movers_answer_as_the_cli(areas, args):
    want = cli_rows("quickstart-3.mf.json", areas, args)
    movers = json.loads((DATA / "quickstart-3.mf.json").read_text())
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")  # MovingPandas' times without offset: remarks
        got = polyguard.encounters(movers, (DATA / areas).read_text(), **options(args))
        listed = polyguard.encounters(movers["features"], json.loads((DATA / areas).read_text()),
                                      **options(args))
    assert frame_rows(got) == want
    assert frame_rows(listed) == want
    if areas == "fir-LFFF.geojson":
        assert len(want) > 0


@pytest.mark.parametrize("areas,args", CASES)
def test_a_frame_of_fixes_answers_as_the_cli_on_its_csv(areas, args):
    want = cli_rows("quickstart-3.csv", areas, args)
    got = polyguard.encounters(fixes_frame(), (DATA / areas).read_text(), **options(args))
    assert frame_rows(got) == want


def test_a_datetime_index_without_zone_is_utc():
    want = cli_rows("quickstart-3.csv", "cells-2.mf.json", CASES[2][1])
    f = fixes_frame()
    f = f.set_index(f["timestamp"].dt.tz_localize(None)).drop(columns="timestamp")
    got = polyguard.encounters(f, (DATA / "cells-2.mf.json").read_text(), sep=5, sep_v=1000)
    assert frame_rows(got) == want and len(want) > 0


def test_a_geodataframe_of_areas_answers_as_its_geojson():
    gpd = pytest.importorskip("geopandas")
    fc = json.loads((DATA / "fir-LFRR.geojson").read_text())
    gdf = gpd.GeoDataFrame.from_features(fc["features"])
    gdf.index = [f["id"] for f in fc["features"]]
    assert "ceiling_ft" in gdf.columns
    want = cli_rows("quickstart-3.csv", "fir-LFRR.geojson", CASES[1][1])
    got = polyguard.encounters(fixes_frame(), gdf, **options(CASES[1][1]))
    assert len(want) > 0
    assert frame_rows(got) == want


def test_bad_rows_warn_and_the_rest_is_answered():
    f = fixes_frame()
    f.loc[5, "latitude"] = 95.0
    with pytest.warns(UserWarning, match="row 5, column latitude"):
        got = polyguard.encounters(f, (DATA / "fir-LFFF.geojson").read_text())
    assert len(got) > 0


def test_nothing_readable_raises():
    f = fixes_frame()
    f["latitude"] = 95.0
    with pytest.raises(polyguard.Error, match="no movers could be read"):
        polyguard.encounters(f, (DATA / "fir-LFFF.geojson").read_text())
    with pytest.raises(polyguard.Error):
        polyguard.encounters("not json", (DATA / "fir-LFFF.geojson").read_text())
    with pytest.raises(polyguard.Error, match="sep"):
        polyguard.encounters(fixes_frame(), (DATA / "fir-LFFF.geojson").read_text(), sep=-1)
    with pytest.raises(polyguard.Error, match="geodesy"):
        polyguard.encounters(fixes_frame(), (DATA / "fir-LFFF.geojson").read_text(),
                             geodesy="flat")


def test_epoch_seconds_as_numbers_are_the_same_instants():
    f = fixes_frame()
    want = polyguard.encounters(f, (DATA / "cells-2.mf.json").read_text(), sep=5, sep_v=1000)
    epoch = pd.Timestamp(0, tz="UTC")
    f["timestamp"] = (f["timestamp"] - epoch).dt.total_seconds()
    got = polyguard.encounters(f, (DATA / "cells-2.mf.json").read_text(), sep=5, sep_v=1000)
    assert frame_rows(got) == frame_rows(want) and len(want) > 0
