#!/usr/bin/python3
"""Reads a DXF file with ezdxf (an independent reader) and prints what the Tapeline DXF test
compares, as JSON on stdout: header units, layers, and per block the boundary polylines, points,
lines, open polylines and texts by layer, plus the modelspace INSERTs.

Usage: /usr/bin/python3 dxf_extract.py file.dxf
Exit status 3 when ezdxf is missing (Debian: apt install python3-ezdxf).
"""
import json
import sys

try:
    import ezdxf
    from ezdxf import recover
except ImportError:
    print("python3-ezdxf is not installed (apt install python3-ezdxf)", file=sys.stderr)
    sys.exit(3)


def xy(v):
    return [float(v[0]), float(v[1])]


def entity(e):
    kind = e.dxftype()
    out = {"type": kind, "layer": e.dxf.layer}
    if kind == "POLYLINE":
        out["points"] = [xy(v.dxf.location) for v in e.vertices]
        out["closed"] = bool(e.is_closed)
    elif kind == "LWPOLYLINE":
        out["points"] = [xy(p) for p in e.get_points("xy")]
        out["closed"] = bool(e.closed)
    elif kind == "POINT":
        out["point"] = xy(e.dxf.location)
    elif kind == "LINE":
        out["start"] = xy(e.dxf.start)
        out["end"] = xy(e.dxf.end)
    elif kind == "TEXT":
        out["text"] = e.dxf.text
        out["point"] = xy(e.dxf.insert)
    elif kind == "INSERT":
        out["block"] = e.dxf.name
        out["point"] = xy(e.dxf.insert)
    return out


def main():
    path = sys.argv[1]
    doc, auditor = recover.readfile(path)
    result = {
        "dxfversion": doc.dxfversion,
        "insunits": doc.header.get("$INSUNITS", None),
        "measurement": doc.header.get("$MEASUREMENT", None),
        "audit_errors": len(auditor.errors),
        "layers": sorted(layer.dxf.name for layer in doc.layers),
        "blocks": [],
        "modelspace": [entity(e) for e in doc.modelspace()],
    }
    for block in doc.blocks:
        if block.name.startswith("*"):
            continue
        result["blocks"].append({"name": block.name, "entities": [entity(e) for e in block]})
    json.dump(result, sys.stdout)


if __name__ == "__main__":
    main()
