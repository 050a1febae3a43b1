"""tapeline.grade against `tapeline grade` on the same pattern and measurement sets."""
import json
import os

import numpy as np
import pytest

import tapeline
from tapeline import pattern

from conftest import DATA

AARON = os.path.join(DATA, "patterns", "aaron_cisFemaleAdult36.json")
BASE = os.path.join(DATA, "patterns", "aaron_cisFemaleAdult36_measurements.json")

pytestmark = pytest.mark.skipif(not hasattr(tapeline, "grade"), reason="built without grading")

SMALL = dict(seed=7, population=16, generations=8)


def scaled_set(factor):
    """The base set with every length scaled (the shoulder slope is an angle: kept)."""
    base = json.load(open(BASE))
    return {k: (v if k == "shoulderSlope" else v * factor) for k, v in base.items()}


def test_grade_equals_the_command_line(cli, tmp_path):
    target = scaled_set(1.06)
    target_file = tmp_path / "target.json"
    target_file.write_text(json.dumps(target))
    out, rep = tmp_path / "g.json", tmp_path / "r.json"
    cli("grade", AARON, "--from", BASE, "--to", str(target_file), "--out", str(out), "--report",
        str(rep), "--seed", "7", "--population", "16", "--generations", "8", "--threads", "1")
    graded, report = tapeline.grade(pattern.read(AARON), BASE, target, threads=1, **SMALL)
    assert graded == json.loads(out.read_text())
    expected = json.loads(rep.read_text())
    # The command line's fit rows also say where each binding came from (aaron's chest: the
    # importer's help line; the rest: FreeSewing's table).
    assert {(r["measurement"], r.pop("origin")) for r in expected["fit"]} == {
        ("chest", "pattern")} | {(r["measurement"], "FreeSewing table") for r in report["fit"]
                                  if r["measurement"] != "chest"}
    assert report["fit"] == expected["fit"] and report["seams"] == expected["seams"]
    assert report["chosen"] == expected["chosen"]


def test_grading_to_a_larger_set_grows_the_pattern_and_reports_its_front():
    p = pattern.read(AARON)
    graded, report = tapeline.grade(p, BASE, scaled_set(1.10), **SMALL)
    front = report["pareto"]
    n = len(report["front"])
    assert n > 0 and front["fit"].shape == (n,) and front["style"].dtype == np.float64
    assert 0 <= report["chosen"] < n
    assert front["fit"][report["chosen"]] == pytest.approx(report["front"][report["chosen"]]["fit"])
    # Every bound measurement lands near its target, and the pieces grew.
    for row in report["fit"]:
        assert abs(row["error_mm"]) < 0.05 * row["target_mm"], row
    assert report["options"]["seed"] == 7 and report["options"]["generations"] == 8


def test_grade_takes_a_measured_body(body):
    _, V, F = body
    m = tapeline.measure(V, F, units="dm")
    graded, report = tapeline.grade(pattern.read(AARON), BASE, m, **SMALL)
    assert graded["pieces"] and report["to"]


def test_grade_refusals():
    p = pattern.read(AARON)
    with pytest.raises(tapeline.InvalidInput):
        tapeline.grade(p, BASE, {"chest": -5.0}, **SMALL)
    with pytest.raises(ValueError, match="target: expected a measurement file path or a dict"):
        tapeline.grade(p, BASE, 42, **SMALL)
    with pytest.raises(TypeError, match="unexpected keyword argument 'generation'"):
        tapeline.grade(p, BASE, scaled_set(1.0), generation=3)
    with pytest.raises(ValueError, match="ease='loose': expected one of proportional, keep_mm"):
        tapeline.grade(p, BASE, scaled_set(1.0), ease="loose")
    with pytest.raises(TypeError, match="seed='x': expected int"):
        tapeline.grade(p, BASE, scaled_set(1.0), seed="x")
