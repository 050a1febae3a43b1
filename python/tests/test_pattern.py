"""tapeline.pattern against `tapeline pattern` on the same files and database."""
import json
import os

import pytest

import tapeline
from tapeline import pattern

from conftest import DATA

AARON = os.path.join(DATA, "patterns", "aaron_cisFemaleAdult36.json")
SHIRT = os.path.join(DATA, "patterns", "shirt_mean_specification.json")


def test_read_gives_the_pattern_json(cli, tmp_path):
    p = pattern.read(AARON)
    assert p["name"] and len(p["pieces"]) == 4
    # The tool's pattern JSON of the same file is the same document.
    db = tmp_path / "p.sqlite"
    out = tmp_path / "a.json"
    cli("pattern", "import", AARON, "--db", str(db))
    cli("pattern", "export", p["name"], "--db", str(db), "--json", str(out))
    stored = json.loads(out.read_text())
    with pattern.Database(str(db), read_only=True) as d:
        assert len(d) == 1 and p["name"] in d
        assert d.get(p["name"]) == stored


def test_database_round_trip_and_search(tmp_path):
    with pattern.Database(str(tmp_path / "p.sqlite")) as d:
        r = d.import_file(AARON)
        assert r["replaced"] is False and r["stored_bytes"] > 0
        shirt = pattern.read(SHIRT)
        d.store(shirt)
        assert len(d) == 2
        names = [s["name"] for s in d.list()]
        assert sorted(names) == sorted([r["name"], shirt["name"]])
        assert [s["name"] for s in d.list(name=shirt["name"][:4].upper())] == [shirt["name"]]
        # Stored geometry is quantised within the reported error; the topology is exact.
        back = d.get(shirt["name"])
        assert [len(x["outline"]) for x in back["pieces"]] == \
            [len(x["outline"]) for x in shirt["pieces"]]
        with pytest.raises(tapeline.InvalidInput, match="already|exists"):
            d.store(shirt)
        assert d.store(shirt, replace=True)["replaced"] is True
        assert d.remove(shirt["name"]) is True and d.remove(shirt["name"]) is False
        with pytest.raises(tapeline.InvalidInput, match="no pattern named"):
            d.get(shirt["name"])
    with pytest.raises(tapeline.InvalidInput, match="closed"):
        len(d)


def test_svg_equals_the_command_line(cli, tmp_path):
    db = tmp_path / "p.sqlite"
    cli("pattern", "import", SHIRT, "--db", str(db))
    with pattern.Database(str(db)) as d:
        name = d.list()[0]["name"]
        p = d.get(name)
    out = tmp_path / "s.svg"
    cli("pattern", "export", name, "--db", str(db), "--svg", str(out))
    assert pattern.svg(p) == out.read_text()


def test_bad_patterns_are_refused(tmp_path):
    p = pattern.read(AARON)
    assert pattern.check(p) == pattern.check(pattern.check(p))
    broken = dict(p)
    broken["pieces"] = "no"
    with pytest.raises(tapeline.InvalidInput):
        pattern.check(broken)
    with pytest.raises(tapeline.InvalidInput):
        pattern.read(str(tmp_path / "missing.json"))
    with pytest.raises(tapeline.InvalidInput):
        pattern.Database(str(tmp_path / "none.sqlite"), create=False)
    with pytest.raises(tapeline.InvalidInput, match="read-only|read only"):
        pattern.Database(str(tmp_path / "ro.sqlite")).close()
        pattern.Database(str(tmp_path / "ro.sqlite"), read_only=True).store(p)
