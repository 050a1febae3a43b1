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
