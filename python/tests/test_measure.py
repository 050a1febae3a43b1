"""tapeline.measure against `tapeline measure` on the same body, and its refusals."""
import json

import numpy as np
import pytest

import tapeline


def without_timings(j):
    """The JSON without wall-clock figures (keys ending in _seconds) and the tool's own timings."""
    if isinstance(j, dict):
        return {k: without_timings(v) for k, v in j.items()
                if not k.endswith("_seconds") and k != "timings_seconds"}
    if isinstance(j, list):
        return [without_timings(v) for v in j]
    return j


@pytest.fixture(scope="module")
def measured(body):
    path, V, F = body
    return path, V, F, tapeline.measure(V, F, units="dm", name=path)


def test_measure_equals_the_command_line(measured, cli, tmp_path):
    path, _, _, m = measured
    out = tmp_path / "m.json"
    cli("measure", path, "--units", "dm", "--out", str(out))
    expected = json.loads(out.read_text())
    assert without_timings(m) == without_timings(expected)


def test_measurements_carry_their_names_and_plausible_values(measured):
    _, V, _, m = measured
    assert m["format"] == "tapeline-measurements"
    by_name = {x["name"]: x for x in m["measurements"]}
    # Every measurement has a value in mm; the height is the mesh's extent along +Y in mm.
    height = (V[:, 1].max() - V[:, 1].min()) * 100.0
    assert m["frame"]["height_mm"] == pytest.approx(height, abs=0.01)
    assert len(by_name) > 30
    girths = [x for x in m["measurements"] if x.get("kind") == "girth"]
    assert girths, "no girth measured"
    for x in m["measurements"]:
        if x["kind"] != "angle":
            assert x["value_mm"] > 0, x["name"]
    assert by_name["stature"]["value_mm"] == pytest.approx(height, abs=0.01)
    assert by_name["neck_girth"]["iso_number"] == "5.3.2"
    assert by_name["neck_girth"]["freesewing_name"] == "neck"
    # A tape around the body is shorter than the stature and longer than 10 cm.
    for x in girths:
        assert 100 < x["value_mm"] < height


def test_flat_facets_equal_the_command_line_and_lie_inside(measured, cli, tmp_path):
    """smooth_surface=False is `tapeline measure --flat-facets`; the tapes round the flat facets
    lie inside those round the smooth surface, by at most a few millimetres on this body."""
    path, V, F, m = measured
    flat = tapeline.measure(V, F, units="dm", name=path, smooth_surface=False)
    out = tmp_path / "f.json"
    cli("measure", path, "--units", "dm", "--out", str(out), "--flat-facets")
    assert without_timings(flat) == without_timings(json.loads(out.read_text()))
    assert m["report"]["smooth_surface"] is True
    assert flat["report"]["smooth_surface"] is False
    smooth = {x["name"]: x["value_mm"] for x in m["measurements"] if x["kind"] == "girth"}
    facets = {x["name"]: x["value_mm"] for x in flat["measurements"] if x["kind"] == "girth"}
    assert smooth.keys() == facets.keys()
    diffs = [smooth[n] - facets[n] for n in smooth]
    assert max(abs(d) for d in diffs) < 5.0
    assert sum(diffs) / len(diffs) > 0  # convex parts: the facets' chords cut inside


def test_measure_refusals(body):
    _, V, F = body
    with pytest.raises(tapeline.InvalidInput, match="units"):
        tapeline.measure(V, F, units="furlongs")
    with pytest.raises(tapeline.InvalidInput, match="up"):
        tapeline.measure(V, F, up="+Q")
    with pytest.raises(tapeline.InvalidInput, match="landmarks"):
        tapeline.measure(V, F, units="dm", landmarks={"nolandmarks": {}})
    with pytest.raises(ValueError, match="V: expected a float array"):
        tapeline.measure(V.astype(np.int32), F)
