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


def decode_png(data):
    """RGBA rows of an 8-bit RGBA PNG (any row filter), decoded here with zlib alone."""
    import struct
    import zlib
    import numpy as np
    assert data[:8] == b"\x89PNG\r\n\x1a\n"
    pos, idat, width, height = 8, b"", 0, 0
    while pos < len(data):
        n, kind = struct.unpack(">I4s", data[pos:pos + 8])
        body = data[pos + 8:pos + 8 + n]
        if kind == b"IHDR":
            width, height, depth, colour = struct.unpack(">IIBB", body[:10])
            assert (depth, colour) == (8, 6), (depth, colour)
        elif kind == b"IDAT":
            idat += body
        pos += 12 + n
    raw = zlib.decompress(idat)
    stride, bpp = 4 * width, 4
    prev, rows = bytearray(stride), []
    for y in range(height):
        start = y * (stride + 1)
        f, line = raw[start], raw[start + 1:start + 1 + stride]
        row = bytearray(stride)
        for x in range(stride):
            a = row[x - bpp] if x >= bpp else 0
            b = prev[x]
            c = prev[x - bpp] if x >= bpp else 0
            if f == 0:
                pred = 0
            elif f == 1:
                pred = a
            elif f == 2:
                pred = b
            elif f == 3:
                pred = (a + b) // 2
            else:
                p = a + b - c
                pa, pb, pc = abs(p - a), abs(p - b), abs(p - c)
                pred = a if pa <= pb and pa <= pc else (b if pb <= pc else c)
            row[x] = (line[x] + pred) & 255
        rows.append(bytes(row))
        prev = row
    return np.frombuffer(b"".join(rows), np.uint8).reshape(height, width, 4)


def test_dxf_and_png_equal_the_command_line(cli, tmp_path):
    p = pattern.read(AARON)
    db = tmp_path / "p.sqlite"
    with pattern.Database(str(db)) as d:
        d.store(p)
        stored = d.get(p["name"])
    dxf, png = tmp_path / "a.dxf", tmp_path / "a.png"
    cli("pattern", "export", p["name"], "--db", str(db), "--dxf", str(dxf), "--png", str(png),
        "--pixels-per-mm", "0.25")
    assert pattern.dxf(stored) == dxf.read_text()
    data = pattern.png(stored, pixels_per_mm=0.25)
    assert data == png.read_bytes()
    # The raster is the PNG's pixels (decoded independently), ink on a white page.
    image = pattern.raster(stored, pixels_per_mm=0.25)
    assert image.dtype.name == "uint8" and image.shape[2] == 4
    assert (image == decode_png(data)).all()
    assert (image[..., :3] < 128).any() and (image[0, 0] == 255).all()
    with pytest.raises(tapeline.InvalidInput, match="resolution|pixels"):
        pattern.raster(stored, pixels_per_mm=0)
