#!/usr/bin/python3
"""Grades patterns without measurement bindings (the four GarmentCode patterns) from the body they
are laid on (`tapeline grade --base-body`) to the measurements of other bodies, and writes a table:
per pattern and body the bindings found (a length bound once per piece is listed with its count),
the largest fit error and seam mismatch, the largest change of an outline angle, the time, and a
self-check computed here from the files: every bound girth and length of the graded pattern (its
points, the bindings file's counts) against the target plus the scaled base ease (within 2 mm).

usage: grade_any_pattern.py TAPELINE DATA_DIR OUT.md [--base BODY] [--bodies bundled|holdout|...]
                            [--patterns NAME ...] [--threads N]
  DATA_DIR: ../shared/data; --base: the body the patterns are laid on (default: the bundled
  mh_female_average); --bodies as drape_population.py (bundled: nine, holdout: mh_pop_030-039).
"""
import argparse
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from drape_population import bodies  # noqa: E402

PATTERNS = {
    "gc_shirt": "patterns/garmentcode/shirt_mean_specification.json",
    "gc_hoody": "patterns/garmentcode/hoody_mean_specification.json",
    "gc_jumpsuit": "patterns/garmentcode/js_mean_all_specification.json",
    "gc_dress_pencil": "patterns/garmentcode/dress_pencil_specification.json",
}


def edge_length(edge):
    """Length of a tapeline pattern JSON outline edge (a line, or a cubic sampled 2000 times)."""
    if edge["type"] == "line":
        (ax, ay), (bx, by) = edge["a"], edge["b"]
        return math.hypot(bx - ax, by - ay)
    if edge["type"] != "cubic":
        sys.exit("grade_any_pattern.py: an outline edge of type %r" % edge["type"])
    (x0, y0), (x1, y1), (x2, y2), (x3, y3) = edge["p"]
    total, px, py = 0.0, x0, y0
    for k in range(1, 2001):
        t = k / 2000.0
        u = 1 - t
        x = u * u * u * x0 + 3 * u * u * t * x1 + 3 * u * t * t * x2 + t * t * t * x3
        y = u * u * u * y0 + 3 * u * u * t * y1 + 3 * u * t * t * y2 + t * t * t * y3
        total += math.hypot(x - px, y - py)
        px, py = x, y
    return total


def girth_check(graded, bindings, base, target):
    """Largest |graded span sum - (target + ease * target / base)| over the bindings, mm."""
    pieces = {p["name"]: p for p in graded["pieces"]}
    worst = 0.0
    for b in bindings["bindings"]:
        m = b["measurement"]
        got = 0.0
        for f in b["features"]:
            if f.get("edges"):  # a length along outline edges
                outline = pieces[f["piece"]]["outline"]
                got += f["count"] * sum(edge_length(outline[e]) for e in f["edges"])
                continue
            pts = pieces[f["piece"]]["points"]
            (ax, ay), (bx, by) = pts[f["from_point"]], pts[f["to_point"]]
            got += f["count"] * math.hypot(bx - ax, by - ay)
        want = target[m] + b["ease"] * target[m] / base[m]
        worst = max(worst, abs(got - want))
    return worst


def values(measure_json):
    return {e["name"]: e["value_mm"] for e in measure_json["measurements"]
            if e["value_mm"] is not None}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tapeline")
    ap.add_argument("data")
    ap.add_argument("out")
    ap.add_argument("--base", default=None)
    ap.add_argument("--bodies", default="bundled")
    ap.add_argument("--patterns", nargs="+", default=list(PATTERNS))
    ap.add_argument("--threads", type=int, default=1)
    a = ap.parse_args()
    base = a.base or os.path.join(a.data, "bodies", "mh_female_average.obj")
    unknown = [p for p in a.patterns if p not in PATTERNS]
    if unknown:
        sys.exit("grade_any_pattern.py: unknown pattern %s (known: %s)" % (
            unknown[0], ", ".join(PATTERNS)))
    targets = [b for b in bodies(a.data, a.bodies) if os.path.abspath(b) != os.path.abspath(base)]
    if not targets:
        sys.exit("grade_any_pattern.py: no bodies for --bodies %s in %s" % (a.bodies, a.data))
    rows = []
    with tempfile.TemporaryDirectory() as work:
        def measure(body):
            out = os.path.join(work, os.path.basename(body) + ".json")
            subprocess.run([a.tapeline, "--quiet", "measure", body, "--units", "dm", "--out", out],
                           check=True, stdout=subprocess.DEVNULL)
            return out
        base_json = measure(base)
        base_values = values(json.load(open(base_json)))
        total = len(targets) * len(a.patterns)
        for body in targets:
            target_json = measure(body)
            target_values = values(json.load(open(target_json)))
            for name in a.patterns:
                g, r, bfile = (os.path.join(work, x) for x in ("g.json", "r.json", "b.json"))
                t0 = time.time()
                p = subprocess.run(
                    [a.tapeline, "grade", os.path.join(a.data, PATTERNS[name]), "--base-body",
                     base, "--base-units", "dm", "--to", target_json, "--out", g, "--report", r,
                     "--bindings-out", bfile, "--threads", str(a.threads)],
                    capture_output=True, text=True)
                secs = time.time() - t0
                row = {"pattern": name, "body": os.path.basename(body), "seconds": secs,
                       "exit": p.returncode}
                if p.returncode == 0:
                    rep = json.load(open(r))
                    bound = json.load(open(bfile))
                    row.update(
                        bound=[x["measurement"] for x in bound["bindings"]],
                        fit=rep.get("max_fit_error_mm"),
                        seam=rep.get("max_seam_mismatch_mm"),
                        angle=rep.get("style", {}).get("max_angle_change_deg"),
                        check=girth_check(json.load(open(g)), bound, base_values,
                                          target_values))
                else:
                    row["error"] = (p.stderr.strip().splitlines() or ["?"])[-1]
                rows.append(row)
                print("[%d/%d] %s on %s: %s (%.1f s)" % (
                    len(rows), total, name, row["body"],
                    "ok" if p.returncode == 0 else row["error"], secs), file=sys.stderr)
    write(rows, a, base)


def bound_list(names):
    """The bound measurements in order, a measurement bound per piece once with its count."""
    counts = {}
    for n in names:
        counts[n] = counts.get(n, 0) + 1
    return ", ".join(n if c == 1 else "%s ×%d" % (n, c) for n, c in counts.items())


def write(rows, a, base):
    ok = [r for r in rows if r["exit"] == 0]
    lines = ["# Grading patterns without bindings: girths found on the base body",
             "",
             "Command: `benchmarks/scripts/grade_any_pattern.py %s` (base body %s; %d runs, "
             "threads %d)." % (" ".join(sys.argv[1:]), os.path.basename(base), len(rows),
                               a.threads),
             "",
             "| pattern | body | bound | max fit error mm | max seam mismatch mm | max angle "
             "change ° | binding self-check mm | s |",
             "|---|---|---|---:|---:|---:|---:|---:|"]
    for r in rows:
        if r["exit"] == 0:
            lines.append("| %s | %s | %s | %.2f | %.2f | %.2f | %.2f | %.1f |" % (
                r["pattern"], r["body"], bound_list(r["bound"]), r["fit"], r["seam"], r["angle"],
                r["check"], r["seconds"]))
        else:
            lines.append("| %s | %s | refused: %s | | | | | %.1f |" % (
                r["pattern"], r["body"], r["error"].replace("|", "/"), r["seconds"]))
    lines += ["", "Summary: %d of %d graded; largest fit error %.2f mm, largest seam mismatch "
              "%.2f mm, largest angle change %.2f°, largest binding self-check difference %.2f mm "
              "(limit 2); median time %.1f s." % (
                  len(ok), len(rows), max((r["fit"] for r in ok), default=0),
                  max((r["seam"] for r in ok), default=0),
                  max((r["angle"] for r in ok), default=0),
                  max((r["check"] for r in ok), default=0),
                  statistics.median(r["seconds"] for r in rows)), ""]
    with open(a.out, "w") as f:
        f.write("\n".join(lines))
    print(a.out)
    return 0


if __name__ == "__main__":
    main()
