#!/usr/bin/python3
"""Runs `tapeline measure` on the MakeHuman population and the bundled bodies and writes a table:
per body, landmarks found, missing measurements, self-check warnings, each girth against
MakeHuman's ruler (difference in mm; MakeHuman's ruler is a vertex loop on the base mesh, a sanity
band, not truth) and the time. On bodies with MakeHuman's base-mesh vertices it also holds the bust,
waist, hip, knee and ankle levels against the mean height of MakeHuman's ruler loops there (fixed
vertex loops carried along by every shape: an independent placement of those levels).

usage: measure_population.py TAPELINE DATA_DIR OUT.md [--bodies dev|holdout|all] [--json OUT.json]
                             [--population DIR]
  dev:     bundled bodies and mh_pop_000 ... mh_pop_029 (the part used while developing)
  holdout: mh_pop_030 ... mh_pop_039 only
  all:     both
  --population DIR: instead, every body of another population made by
           ../shared/data_tools/mh_population.py (DIR/population.json and its PLY files), e.g. one
           drawn with a new seed that no rule of the measurement was tuned on.
"""
import argparse
import json
import os
import statistics
import struct
import subprocess
import sys
import tempfile
import time

# MakeHuman ruler name -> our girth name.
RULERS = [("neck_circ", "neck_girth"), ("bust_circ", "bust_girth"),
          ("underbust_circ", "underbust_girth"), ("waist_circ", "waist_girth"),
          ("hips_circ", "hip_girth"), ("upperarm_circ", "upper_arm_girth"),
          ("wrist_circ", "wrist_girth"), ("thigh_circ", "thigh_girth"),
          ("knee_circ", "knee_girth"), ("calf_circ", "calf_girth"),
          ("ankle_circ", "ankle_girth")]
HOLDOUT = range(30, 40)
# Our landmark -> MakeHuman ruler loop whose mean height places the same level (by MakeHuman's
# own definition, which need not be ours: its waist loop is lower than the narrowest girth).
# How a loop places the level: "mean", its mean height; "side", the height of its vertex furthest
# to the body's left (+x), where MakeHuman's tilted neck loop passes the side of the neck.
LEVELS = [("side_neck_left", "neck_circ", "side"), ("bust_left", "bust_circ", "mean"),
          ("waist_front", "waist_circ", "mean"), ("hip_back", "hips_circ", "mean"),
          ("knee_left", "knee_circ", "mean"), ("ankle_left", "ankle_circ", "mean")]


def level_label(loop, how):
    return loop + " side" if how == "side" else loop
BASE_MESH_VERTICES = 13380


def vertices(path):
    """The (x, y, z) of every vertex of a binary little-endian PLY (float properties, x y z first)
    or an OBJ; [] for any other PLY."""
    if path.endswith(".obj"):
        return [tuple(float(c) for c in line.split()[1:4]) for line in open(path)
                if line.startswith("v ")]
    data = open(path, "rb").read()
    end = data.index(b"end_header\n") + len(b"end_header\n")
    header = data[:end].decode().splitlines()
    if "format binary_little_endian 1.0" not in header:
        return []
    n = int(next(h for h in header if h.startswith("element vertex")).split()[2])
    props = []
    for h in header[header.index(next(h for h in header if h.startswith("element vertex"))) + 1:]:
        if not h.startswith("property"):
            break
        props.append(h.split()[1])
    if props[:3] != ["float"] * 3 or any(t != "float" for t in props):
        return []
    stride = 4 * len(props)
    return [struct.unpack_from("<fff", data, end + i * stride) for i in range(n)]


def loop_levels(path, loops):
    """Height above the floor (mm, decimetre input) at which each loop of LEVELS places its level,
    keyed by level_label, or {} when the mesh does not carry MakeHuman's base-mesh vertices."""
    xy = [(x, y) for x, y, _ in vertices(path)]
    if len(xy) != BASE_MESH_VERTICES:
        return {}
    floor = min(y for _, y in xy)
    out = {}
    for _, loop, how in LEVELS:
        points = [xy[i] for i in loops[loop]]
        y = (max(points, key=lambda p: p[0])[1] if how == "side" else
             statistics.mean(p[1] for p in points))
        out[level_label(loop, how)] = 100.0 * (y - floor)
    return out


def bodies(data, which):
    out = []
    if which in ("dev", "all"):
        bundled = json.load(open(os.path.join(data, "measurements.json")))["bodies"]
        for f in sorted(os.listdir(data)):
            if not f.endswith(".obj"):
                continue
            name = f[:-4]
            base = name.replace("_female_generic", "").replace("_male_generic", "")
            ruler = bundled.get(base, {}).get("makehuman_ruler_cm", {})
            out.append((name, os.path.join(data, f), ruler))
    pop = json.load(open(os.path.join(data, "population", "population.json")))["bodies"]
    for i in range(40):
        held = i in HOLDOUT
        if (which == "dev" and held) or (which == "holdout" and not held):
            continue
        name = "mh_pop_%03d" % i
        out.append((name, os.path.join(data, "population", name + ".ply"),
                    pop[name]["makehuman_ruler_cm"]))
    return out


def population_bodies(directory):
    meta = json.load(open(os.path.join(directory, "population.json")))
    prefix = os.path.basename(directory.rstrip("/")) + "/"
    return [(prefix + name, os.path.join(directory, name + ".ply"), body["makehuman_ruler_cm"])
            for name, body in sorted(meta["bodies"].items())], meta.get("seed")


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tapeline")
    ap.add_argument("data")
    ap.add_argument("out")
    ap.add_argument("--bodies", default="dev", choices=["dev", "holdout", "all"])
    ap.add_argument("--json")
    ap.add_argument("--population")
    a = ap.parse_args()
    if a.population:
        todo, seed = population_bodies(a.population)
        a.bodies = "population of %s, seed %s" % (os.path.basename(a.population.rstrip("/")), seed)
        a.drawn = ("`MAKEHUMAN_GIT=… MAKEHUMAN_ASSETS_GIT=… ../shared/data_tools/mh_population.py "
                   "%s %d %s`, then " % (a.population.rstrip("/"), len(todo), seed))
    else:
        todo = bodies(a.data, a.bodies)
    loops = json.load(open(os.path.join(a.data, "measurements.json"))).get(
        "ruler_vertex_sequences", {})
    rows = []
    with tempfile.TemporaryDirectory() as work:
        for name, path, ruler in todo:
            out = os.path.join(work, name.replace("/", "_") + ".json")
            t0 = time.monotonic()
            p = subprocess.run([a.tapeline, "measure", path, "--units", "dm", "--out", out],
                               capture_output=True, text=True)
            wall = time.monotonic() - t0
            row = {"body": name, "exit": p.returncode, "wall": wall}
            if p.returncode != 0 or not os.path.exists(out):
                row["error"] = (p.stderr.strip().splitlines() or ["?"])[-1]
                rows.append(row)
                continue
            j = json.load(open(out))
            vals = {m["name"]: m["value_mm"] for m in j["measurements"]}
            row.update({
                "vertices": j["report"]["vertices"],
                "landmarks": "%d/%d" % (j["report"]["landmarks_found"], len(j["landmarks"])),
                "landmarks_found": j["report"]["landmarks_found"],
                "landmarks_total": len(j["landmarks"]),
                "missing": [m["name"] for m in j["missing"]],
                "warnings": ["%s: %s" % (w["rule"], w["message"]) for w in j.get("warnings", [])],
                "time": j["timings_seconds"]["total"],
                "diff": {},
            })
            for mh, ours in RULERS:
                if mh in ruler and ours in vals:
                    row["diff"][ours] = vals[ours] - 10.0 * ruler[mh]
            points = {l["name"]: l.get("point") for l in j["landmarks"]}
            row["level"] = {}
            levels = loop_levels(path, loops) if all(k in loops for _, k, _ in LEVELS) else {}
            for ours, loop, how in LEVELS:
                if level_label(loop, how) in levels and points.get(ours):
                    row["level"][ours] = points[ours][1] - levels[level_label(loop, how)]
            rows.append(row)
            print("%-36s %s" % (name, row.get("landmarks", row.get("error"))), file=sys.stderr)
    if a.json:
        json.dump(rows, open(a.json, "w"), indent=1)
    write_table(rows, a)


def write_table(rows, a):
    names = [g for _, g in RULERS]
    short = {g: g.replace("_girth", "") for g in names}
    ok = [r for r in rows if "error" not in r]
    full = sum(1 for r in ok if r["landmarks_found"] == r["landmarks_total"])
    nwarn = sum(len(r["warnings"]) for r in ok)
    times = [r["time"] for r in ok]
    L = ["# Body measurement on a population of bodies", "",
         getattr(a, "drawn", "") + "`%s` (bodies: %s). Girth columns: our value minus MakeHuman's ruler, mm (the ruler is "
         "a fixed vertex loop on MakeHuman's base mesh: a sanity band, not truth). `time`: the "
         "CLI's total seconds (load, landmarks, girths, lengths along the skin) on a shared, "
         "loaded machine." % (" ".join(["benchmarks/scripts/measure_population.py",
                                         "build/apps/tapeline", "../shared/data/bodies", "OUT.md"] +
                                        (["--population", a.population.rstrip("/")]
                                         if a.population else
                                         ["--bodies", a.bodies])), a.bodies), "",
         "Bodies measured: %d of %d; all landmarks found on %d; self-check warnings: %d; "
         "bodies with a missing measurement: %d; time median %.2f s, max %.2f s." % (
             len(ok), len(rows), full, nwarn, sum(1 for r in ok if r["missing"]),
             statistics.median(times) if times else 0, max(times) if times else 0), "",
         "| girth | n | mean diff mm | mean abs mm | worst mm (body) |",
         "|---|---|---|---|---|"]
    for g in names:
        d = [(r["diff"][g], r["body"]) for r in ok if g in r["diff"]]
        if not d:
            continue
        worst = max(d, key=lambda x: abs(x[0]))
        L.append("| %s | %d | %+.1f | %.1f | %+.1f (%s) |" % (
            g, len(d), statistics.mean(x for x, _ in d), statistics.mean(abs(x) for x, _ in d),
            worst[0], worst[1]))
    L += ["", "Landmark levels against MakeHuman's ruler loops (our height minus the loop's mean "
          "height, mm; `neck_circ side`: the height where the tilted neck loop passes the left "
          "side of the neck, its vertex furthest to the left; bodies with MakeHuman's base-mesh "
          "vertices):", "",
          "| landmark | loop | n | mean diff mm | sd mm | mean abs mm | worst mm (body) |",
          "|---|---|---|---|---|---|---|"]
    for ours, loop, how in LEVELS:
        mh = level_label(loop, how)
        d = [(r["level"][ours], r["body"]) for r in ok if ours in r.get("level", {})]
        if not d:
            continue
        worst = max(d, key=lambda x: abs(x[0]))
        L.append("| %s | %s | %d | %+.1f | %.1f | %.1f | %+.1f (%s) |" % (
            ours, mh, len(d), statistics.mean(x for x, _ in d),
            statistics.pstdev(x for x, _ in d), statistics.mean(abs(x) for x, _ in d),
            worst[0], worst[1]))
    L += ["", "| body | landmarks | missing | warnings | " +
          " | ".join(short[g] for g in names) + " | time s |",
          "|---|---|---|---|" + "---|" * len(names) + "---|"]
    for r in rows:
        if "error" in r:
            L.append("| %s | refused: %s |" % (r["body"], r["error"].replace("|", "/")) +
                     " |" * (len(names) + 3))
            continue
        cells = ["%+.0f" % r["diff"][g] if g in r["diff"] else "–" for g in names]
        L.append("| %s | %s | %s | %s | %s | %.2f |" % (
            r["body"], r["landmarks"], ", ".join(r["missing"]) or "–",
            "; ".join(r["warnings"]).replace("|", "/") or "–", " | ".join(cells), r["time"]))
    open(a.out, "w").write("\n".join(L) + "\n")


if __name__ == "__main__":
    main()
