#!/usr/bin/python3
"""Measures bodies and re-meshed copies of them and writes how far each copy's measurements are
from the original's, against ISO 20685-1 (girths 4 mm, 9 mm the large torso and thigh girths;
heights 4 mm; lengths along the skin 5 mm). The copies are made by the tool itself:
`tapeline mesh remesh --edge` (CGAL isotropic remeshing) and `tapeline mesh simplify --vertices`
(CGAL edge collapse, Garland-Heckbert quadrics). A measurement must not depend on the triangles.

usage: measure_remeshed.py TAPELINE DATA_DIR OUT.md [--bodies population|bundled|all]
                           [--jobs N] [--json OUT.json] [--flat-facets]
  --flat-facets: girths round the meshes' flat facets (tapeline measure --flat-facets), not round
                 the smooth surface their vertices and normals stand for
  population: the 40 bodies of DATA_DIR/population (decimetres)
  bundled:    the bundled *.obj bodies of DATA_DIR
"""
import argparse
import concurrent.futures
import json
import os
import statistics
import subprocess
import sys
import tempfile

# (label, tool arguments); the bodies are in decimetres: --edge 0.05 is 5 mm.
VARIANTS = [("isotropic 5 mm", ["remesh", "--edge", "0.05"]),
            ("isotropic 20 mm", ["remesh", "--edge", "0.2"]),
            ("decimated 5k", ["simplify", "--vertices", "5000"])]
LARGE = ("bust_girth", "underbust_girth", "high_bust_girth", "waist_girth", "high_hip_girth",
         "hip_girth", "thigh_girth", "mid_thigh_girth")


def tolerance(m):
    if m["kind"] == "length":
        return 5.0
    if m["kind"] != "girth":
        return 4.0
    return 9.0 if m["name"].startswith(LARGE) else 4.0


def bodies(data, which):
    out = []
    if which in ("bundled", "all"):
        out += [(f[:-4], os.path.join(data, f)) for f in sorted(os.listdir(data))
                if f.endswith(".obj")]
    if which in ("population", "all"):
        d = os.path.join(data, "population")
        out += [(f[:-4], os.path.join(d, f)) for f in sorted(os.listdir(d)) if f.endswith(".ply")]
    return out


def run(cmd):
    p = subprocess.run(cmd, capture_output=True, text=True)
    if p.returncode != 0:
        raise RuntimeError((p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[-1])
    return p


MEASURE_FLAGS = []  # --flat-facets when asked


def measure(tool, mesh, out):
    run([tool, "measure", mesh, "--units", "dm", "--out", out] + MEASURE_FLAGS)
    j = json.load(open(out))
    return j


def one_body(tool, name, path, work):
    row = {"body": name, "variants": {}}
    try:
        base = measure(tool, path, os.path.join(work, name + ".json"))
    except RuntimeError as e:
        row["error"] = str(e)
        return row
    ref = {m["name"]: m for m in base["measurements"] if m["kind"] != "angle"}
    row["vertices"] = base["report"]["vertices"]
    for label, args in VARIANTS:
        v = {"label": label}
        mesh = os.path.join(work, "%s_%s.ply" % (name, args[-1]))
        try:
            run([tool, "mesh", args[0], path] + args[1:] + ["--out", mesh])
            j = measure(tool, mesh, os.path.join(work, "%s_%s.json" % (name, args[-1])))
        except RuntimeError as e:
            v["error"] = str(e)
            row["variants"][label] = v
            continue
        vals = {m["name"]: m["value_mm"] for m in j["measurements"] if m["kind"] != "angle"}
        v["vertices"] = j["report"]["vertices"]
        v["landmarks"] = (j["report"]["landmarks_found"], len(j["landmarks"]))
        v["warnings"] = ["%s: %s" % (w["rule"], w["message"]) for w in j.get("warnings", [])]
        v["time"] = j["timings_seconds"]["total"]
        v["missing"] = sorted(set(ref) - set(vals))
        v["diffs"] = {n: (vals[n] - m["value_mm"], tolerance(m), m["kind"])
                      for n, m in ref.items() if n in vals}
        row["variants"][label] = v
        os.remove(mesh)
    return row


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tapeline")
    ap.add_argument("data")
    ap.add_argument("out")
    ap.add_argument("--bodies", default="population", choices=["population", "bundled", "all"])
    ap.add_argument("--jobs", type=int, default=2)
    ap.add_argument("--json")
    ap.add_argument("--flat-facets", action="store_true")
    a = ap.parse_args()
    if a.flat_facets:
        MEASURE_FLAGS.append("--flat-facets")
    todo = bodies(a.data, a.bodies)
    rows = []
    with tempfile.TemporaryDirectory() as work, \
            concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futures = [pool.submit(one_body, a.tapeline, n, p, work) for n, p in todo]
        for k, f in enumerate(concurrent.futures.as_completed(futures), 1):
            r = f.result()
            rows.append(r)
            out = [("%s: %d outside" % (lab, sum(1 for d, t, _ in v["diffs"].values()
                                                  if abs(d) > t)))
                   if "diffs" in v else "%s: %s" % (lab, v["error"])
                   for lab, v in r["variants"].items()]
            print("[%d/%d] %s %s" % (k, len(todo), r["body"], r.get("error", "; ".join(out))),
                  file=sys.stderr, flush=True)
    rows.sort(key=lambda r: r["body"])
    if a.json:
        json.dump(rows, open(a.json, "w"), indent=1)
    write_table(rows, a)


def write_table(rows, a):
    L = ["# Measurements of re-meshed bodies against the original mesh", "",
         "`benchmarks/scripts/measure_remeshed.py build/apps/tapeline %s OUT.md "
         "--bodies %s%s`. Each body is measured as it is and as re-meshed by `tapeline mesh remesh "
         "--edge 0.05` / `--edge 0.2` (CGAL isotropic remeshing to 5 / 20 mm edges, 3 rounds) "
         "and `tapeline mesh simplify --vertices 5000` (CGAL edge collapse, Garland-Heckbert); "
         "every measurement of the original (girths, heights, lengths along the skin; not the "
         "shoulder angles) is compared. ISO 20685-1: girths 4 mm (9 mm bust, underbust, high "
         "bust, waist, high hip, hip, thigh, mid-thigh), heights 4 mm, lengths 5 mm." % (
             a.data, a.bodies, " --flat-facets" if a.flat_facets else ""),
         ""]
    ok = [r for r in rows if "error" not in r]
    L += ["Bodies: %d (%d refused as they are). Original meshes: %s vertices." % (
        len(rows), len(rows) - len(ok),
        "/".join(sorted({str(r["vertices"]) for r in ok}))), ""]
    L += ["| variant | vertices (median) | all landmarks | bodies with warnings | measurements "
          "compared | outside ISO | bodies all within ISO | worst girth mm (body, measurement) | "
          "worst length or height mm (body, measurement) | time median / max s |",
          "|---|---|---|---|---|---|---|---|---|---|"]
    for label, _ in VARIANTS:
        vs = [(r["body"], r["variants"].get(label, {})) for r in ok]
        good = [(b, v) for b, v in vs if "diffs" in v]
        if not good:
            L.append("| %s | refused on every body |" % label)
            continue
        compared = sum(len(v["diffs"]) for _, v in good)
        outside = sum(1 for _, v in good for d, t, _ in v["diffs"].values() if abs(d) > t)
        clean = sum(1 for _, v in good
                    if not v["missing"] and all(abs(d) <= t for d, t, _ in v["diffs"].values()))
        full = sum(1 for _, v in good if v["landmarks"][0] == v["landmarks"][1])

        def worst(kinds):
            c = [(d, b, n) for b, v in good for n, (d, t, k) in v["diffs"].items() if k in kinds]
            w = max(c, key=lambda x: abs(x[0]))
            return "%+.1f (%s, %s)" % w
        times = [v["time"] for _, v in good]
        L.append("| %s | %d | %d / %d | %d | %d | %d | %d / %d | %s | %s | %.2f / %.2f |" % (
            label, statistics.median(v["vertices"] for _, v in good), full, len(vs),
            sum(1 for _, v in good if v["warnings"]), compared, outside, clean, len(vs),
            worst(("girth",)), worst(("length", "height")), statistics.median(times), max(times)))
    L += ["", "Measurements most often outside ISO 20685-1 (count over the bodies, mean and "
          "worst difference to the original, mm):", "",
          "| variant | measurement | tolerance | outside | mean diff | worst |",
          "|---|---|---|---|---|---|"]
    for label, _ in VARIANTS:
        per = {}
        for r in ok:
            v = r["variants"].get(label, {})
            for n, (d, t, _) in v.get("diffs", {}).items():
                per.setdefault(n, []).append((d, t))
        ranked = sorted(((sum(1 for d, t in x if abs(d) > t), n, x) for n, x in per.items()),
                        reverse=True)
        for count, n, x in ranked[:8]:
            if count == 0:
                break
            L.append("| %s | %s | %.0f | %d / %d | %+.1f | %+.1f |" % (
                label, n, x[0][1], count, len(x), statistics.mean(d for d, _ in x),
                max((d for d, _ in x), key=abs)))
    L += ["", "Per body: measurements outside ISO 20685-1 (missing ones, warnings) per variant.", "",
          "| body | " + " | ".join(lab for lab, _ in VARIANTS) + " |",
          "|---|" + "---|" * len(VARIANTS)]
    for r in rows:
        if "error" in r:
            L.append("| %s | refused: %s |" % (r["body"], r["error"].replace("|", "/")))
            continue
        cells = []
        for label, _ in VARIANTS:
            v = r["variants"].get(label, {})
            if "error" in v:
                cells.append("error: " + v["error"].replace("|", "/"))
                continue
            out = ["%s %+.1f" % (n, d) for n, (d, t, _) in sorted(v["diffs"].items())
                   if abs(d) > t]
            extra = (["missing " + ", ".join(v["missing"])] if v["missing"] else []) + \
                ["%d warning(s)" % len(v["warnings"])] * bool(v["warnings"])
            cells.append("; ".join(out + extra) or "–")
        L.append("| %s | %s |" % (r["body"], " | ".join(cells)))
    open(a.out, "w").write("\n".join(L) + "\n")


if __name__ == "__main__":
    main()
