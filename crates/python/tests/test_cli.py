"""The Python answers are the CLI's: `polyguard detect` (f64, --time, --engine truth) on
examples/cases.jsonl and on bad lines, `polyguard conflicts` on examples/example3.geojson."""

import json

import pytest

import polyguard
from conftest import EXAMPLES, jsonl, run_cli


def test_detect_matches_the_cli(example_cases):
    code, out, err = run_cli("detect", EXAMPLES / "cases.jsonl")
    assert code == 0, err
    answers = jsonl(out)
    assert len(answers) == len(example_cases) >= 7
    for line, cli in zip(example_cases, answers):
        mine = {"id": json.loads(line)["id"], **polyguard.detect_case(line).to_dict()}
        assert mine == cli


def test_detect_time_matches_the_cli(example_cases):
    code, out, err = run_cli("detect", "--time", EXAMPLES / "cases.jsonl")
    assert code == 0, err
    for line, cli in zip(example_cases, jsonl(out)):
        e = polyguard.detect_time_case(line)
        assert e.kind == cli["entry"]
        assert (e.lo, e.hi) == (cli.get("entry_lo"), cli.get("entry_hi"))


def test_truth_matches_the_cli(example_cases):
    code, out, err = run_cli("detect", "--engine", "truth", EXAMPLES / "cases.jsonl")
    assert code == 0, err
    for line, cli in zip(example_cases, jsonl(out)):
        t = polyguard.truth_case(line)
        assert (t is not None) == cli["detected"]
        if t is not None:
            assert t.entry_time == cli["entry_time"]
            assert t.entry_time_exact == cli["entry_time_exact"]


def test_bad_lines_get_the_cli_message(example_cases, tmp_path):
    good = json.loads(example_cases[0])
    bads = []
    for path, value in [(("polygon", "velocity"), [[0, 0]] * 4),
                        (("point", "pos"), [1.0, "x"]),
                        (("polygon", "vertices"), good["polygon"]["vertices"][::-1]),
                        (("buff",), -1.0)]:
        case = json.loads(json.dumps(good))
        target = case
        for key in path[:-1]:
            target = target[key]
        target[path[-1]] = value
        bads.append(json.dumps(case))
    f = tmp_path / "bad.jsonl"
    f.write_text("\n".join(bads + [example_cases[0]]) + "\n")
    code, out, err = run_cli("detect", f)
    assert code == 1  # some lines failed; the good one is still answered
    answers = jsonl(out)
    for line, cli in zip(bads, answers):
        with pytest.raises(polyguard.CaseError) as info:
            polyguard.detect_case(line)
        assert str(info.value) == cli["error"]
        assert cli["error"].startswith(info.value.field + ":")
    assert answers[-1]["detected"] is True


@pytest.mark.parametrize("geodesy", ["sphere", "wgs84"])
def test_conflicts_match_the_cli(geodesy):
    path = EXAMPLES / "example3.geojson"
    code, out, err = run_cli("conflicts", path, "--geodesy", geodesy)
    assert code == 0, err
    cli = json.loads(out)
    mine = polyguard.conflicts(path.read_text(), geodesy)
    # the timings are the run's own; everything else is the same answer
    for answer in (cli, mine):
        del answer["stats"]["timings_ms"]
    assert mine == cli
    assert len(mine["conflicts"]) == 1 and mine["stats"]["geodesy"] == geodesy


def test_conflicts_with_a_bad_feature_answer_the_good_ones_like_the_cli(tmp_path):
    scenario = json.loads((EXAMPLES / "example3.geojson").read_text())
    bad = json.loads(json.dumps(scenario["features"][0]))
    bad["properties"]["id"] = "broken"
    bad["properties"]["speed_kn"] = -3
    scenario["features"].append(bad)
    text = json.dumps(scenario, indent=1)
    f = tmp_path / "bad.geojson"
    f.write_text(text)
    code, out, err = run_cli("conflicts", f)
    assert code == 1  # a rejected feature
    cli = json.loads(out)
    mine = polyguard.conflicts(text)
    for answer in (cli, mine):
        del answer["stats"]["timings_ms"]
    assert mine == cli
    assert len(mine["errors"]) == 1 and len(mine["conflicts"]) == 1
    # regions=False is --no-regions
    code, out, _ = run_cli("conflicts", f, "--no-regions")
    lean = polyguard.conflicts(text, regions=False)
    cli = json.loads(out)
    for answer in (cli, lean):
        del answer["stats"]["timings_ms"]
    assert lean == cli
    assert "region" not in lean["conflicts"][0] and lean["conflicts"][0]["projection_windows"] is None


def test_detect_batch_matches_the_cli_on_the_example_files():
    points = jsonl((EXAMPLES / "batch-points.jsonl").read_text())
    polygons = jsonl((EXAMPLES / "batch-polygons.jsonl").read_text())
    code, out, err = run_cli("detect-batch", EXAMPLES / "batch-points.jsonl",
                             EXAMPLES / "batch-polygons.jsonl", "--lookahead", "10",
                             "--buff", "0.1")
    assert code == 0, err
    cli = [(h["point"], h["polygon"], h["kind"]) for h in jsonl(out)]
    assert len(cli) >= 3
    # polygons of different sizes: the (V, 2) layout with offsets; velocities per vertex
    # (zero where a polygon has none)
    verts = [q["vertices"] for q in polygons]
    vels = [q.get("velocities", [[0, 0]] * len(q["vertices"])) for q in polygons]
    offsets = [0]
    for v in verts:
        offsets.append(offsets[-1] + len(v))
    pi, qi, kind = polyguard.detect_batch(
        10.0, [p["pos"] for p in points], [p["vel"] for p in points],
        [xy for v in verts for xy in v], offsets, [xy for v in vels for xy in v], buff=0.1)
    names = {polyguard.KIND_EXACT: "exact", polyguard.KIND_CONSERVATIVE: "conservative"}
    mine = [(int(i), int(j), names[int(k)]) for i, j, k in zip(pi, qi, kind)]
    assert mine == cli
