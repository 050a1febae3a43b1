#!/usr/bin/python3
"""Reads a DXF file with ezdxf (an independent reader) and prints what the Tapeline DXF test
compares, as JSON on stdout: header units and extents, layers, and per block the boundary
polylines, points, lines, open polylines and texts by layer, plus the modelspace INSERTs; and the
drawing as placed in model space (blocks at their INSERT points): the box of every point of the
geometry, every text with its height, and ezdxf's own bounding box of everything (its font
metrics for the texts).

Usage: /usr/bin/python3 dxf_extract.py file.dxf
Exit status 3 when ezdxf is missing (Debian: apt install python3-ezdxf).
"""
import json
import sys

try:
    import ezdxf
    from ezdxf import bbox, recover
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
    for name in ("$EXTMIN", "$EXTMAX", "$LIMMIN", "$LIMMAX", "$PLIMMIN", "$PLIMMAX", "$PINSBASE"):
        if name in doc.header:
            result[name[1:].lower()] = xy(doc.header[name])
    result["placed"] = placed(doc)
    json.dump(result, sys.stdout)


def placed(doc):
    """Model space with every INSERT expanded (translation only, as Tapeline writes them)."""
    points, texts = [], []

    def add(e, dx, dy):
        kind = e.dxftype()
        if kind == "POLYLINE":
            points.extend((v.dxf.location[0] + dx, v.dxf.location[1] + dy) for v in e.vertices)
        elif kind == "POINT":
            points.append((e.dxf.location[0] + dx, e.dxf.location[1] + dy))
        elif kind == "LINE":
            points.append((e.dxf.start[0] + dx, e.dxf.start[1] + dy))
            points.append((e.dxf.end[0] + dx, e.dxf.end[1] + dy))
        elif kind == "TEXT":
            texts.append([e.dxf.insert[0] + dx, e.dxf.insert[1] + dy, e.dxf.height, len(e.dxf.text)])
        elif kind == "INSERT":
            for b in doc.blocks.get(e.dxf.name):
                add(b, dx + e.dxf.insert[0], dy + e.dxf.insert[1])

    for e in doc.modelspace():
        add(e, 0.0, 0.0)
    xs = [p[0] for p in points]
    ys = [p[1] for p in points]
    box = bbox.extents(doc.modelspace())
    return {"geometry_box": [min(xs), min(ys), max(xs), max(ys)] if points else None,
            "texts": texts,
            "ezdxf_box": [box.extmin[0], box.extmin[1], box.extmax[0], box.extmax[1]]}


if __name__ == "__main__":
    main()
