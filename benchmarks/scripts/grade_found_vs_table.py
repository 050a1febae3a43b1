#!/usr/bin/python3
"""FreeSewing designs graded with bindings found on a body against grading with the hand-written
table (grading/freesewing_bindings.h), both checked against FreeSewing's own draft of the other
size (cisFemaleAdult36 -> 42 and 42 -> 36).

Per design and direction, three gradings of the same base draft to the same target set:
  table  `grade --from SET`: the table's bindings (the run of benchmarks/run_grading.sh);
  found  `grade --base-body BODY`: the girths and lengths found by laying the draft on BODY,
         eased against the values the draft declares; the table fills in what was not found (a
         scooped neckline, girths whose level crosses an opening such as a buttoned front);
  found only  as found with `--freesewing-seams-only`: the design's seams, no binding from the
         table.
For each: the mean outline deviation from FreeSewing's draft of the target size (the mean over
pieces of `--compare`'s mean distance) and from the table grading's pieces. The bindings are
compared too: per girth bound both ways, the height of the found level on the draft against the
table's points and the difference of the two garment girths.

usage: grade_found_vs_table.py TAPELINE DATA_DIR OUT.md [--body BODY] [--threads N]
  DATA_DIR: ../shared/data; --body: the body the drafts are laid on (default: the bundled
  mh_female_average, decimetres).
"""
import argparse
import json
import math
import os
import subprocess
import sys
import tempfile
import time

DESIGNS = ["aaron", "brian", "simon", "teagan", "titan"]
SIZES = [("36", "42"), ("42", "36")]
# FreeSewing's girths (the table binds biceps and wrist on one sleeve, count 1).
GIRTHS = {"chest", "underbust", "waist", "hips", "seat", "neck", "biceps", "wrist", "knee"}


def mean_deviation(report):
    c = report.get("comparison", [])
    return sum(p["graded_mean_mm"] for p in c) / len(c) if c else float("nan")


def spans(bindings_file):
    """measurement -> (garment girth, [(first point's name, a, b)]) of the girth bindings (count > 1 or
    several pieces) of a tapeline-bindings file, straight spans only."""
    points = bindings_file["points"]
    out = {}
    for b in bindings_file["bindings"]:
        feats = [f for f in b["features"] if f["from_point"]]
        if not feats or len(feats) != len(b["features"]):
            continue
        if b["measurement"] not in GIRTHS:
            continue
        total, where = 0.0, []
        for f in feats:
            pa = points[f["piece"]][f["from_point"]]
            pb = points[f["piece"]][f["to_point"]]
            total += f["count"] * math.hypot(pb[0] - pa[0], pb[1] - pa[1])
            where.append((f["from_point"], pa, pb))
        out[b["measurement"]] = (total, where)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tapeline")
    ap.add_argument("data")
    ap.add_argument("out")
    ap.add_argument("--body", default=None)
    ap.add_argument("--threads", type=int, default=1)
    a = ap.parse_args()
    body = a.body or os.path.join(a.data, "bodies", "mh_female_average.obj")
    fs = os.path.join(a.data, "patterns", "freesewing")
    sets = os.path.join(fs, "measurement_sets.json")
    if not os.path.isdir(fs) or not os.path.isfile(body):
        sys.exit("grade_found_vs_table.py: %s or %s not found" % (fs, body))
    rows, binding_rows = [], []
    total = len(DESIGNS) * len(SIZES)
    with tempfile.TemporaryDirectory() as work:
        for design in DESIGNS:
            for frm, to in SIZES:
                draft = os.path.join(fs, "%s_cisFemaleAdult%s.json" % (design, frm))
                other = os.path.join(fs, "%s_cisFemaleAdult%s.json" % (design, to))
                common = ["--to", sets, "--to-set", "cisFemaleAdult" + to, "--threads",
                          str(a.threads)]
                row = {"design": design, "run": "%s -> %s" % (frm, to)}

                def grade(tag, extra, compare):
                    g, r, b = (os.path.join(work, "%s.%s" % (tag, x))
                               for x in ("json", "report.json", "bindings.json"))
                    t0 = time.time()
                    p = subprocess.run([a.tapeline, "grade", draft] + extra + common +
                                       ["--out", g, "--report", r, "--bindings-out", b,
                                        "--compare", compare], capture_output=True, text=True)
                    secs = time.time() - t0
                    if p.returncode != 0:
                        return None, (p.stderr.strip().splitlines() or ["?"])[-1], secs
                    return (json.load(open(r)), json.load(open(b)), g), None, secs

                table, err, secs = grade("table", ["--from", sets, "--from-set",
                                                   "cisFemaleAdult" + frm], other)
                if table is None:
                    sys.exit("grade_found_vs_table.py: %s %s with the table: %s" % (
                        design, row["run"], err))
                row["table"] = mean_deviation(table[0])
                row["table_bound"] = len(table[0]["fit"])
                body_args = ["--base-body", body, "--base-units", "dm"]
                for tag, extra in (("found", []), ("only", ["--freesewing-seams-only"])):
                    res, err, secs = grade(tag, body_args + extra, other)
                    if res is None:
                        row[tag + "_error"] = err
                        continue
                    row[tag] = mean_deviation(res[0])
                    row[tag + "_bound"] = len(res[0]["fit"])
                    row[tag + "_fit"] = res[0]["max_fit_error_mm"]
                    row[tag + "_s"] = secs
                    # The same grading compared with the table grading's pieces.
                    again, err, _ = grade(tag + "_vs", body_args + extra, table[2])
                    row[tag + "_vs_table"] = mean_deviation(again[0])
                    if tag == "found":
                        found_spans = spans(res[1])
                        table_spans = spans(table[1])
                        for m, (girth, where) in sorted(found_spans.items()):
                            if not all(w[0].startswith("girth:") for w in where):
                                continue  # the table's, filled in
                            t = table_spans.get(m)
                            binding_rows.append({
                                "design": design, "run": row["run"], "measurement": m,
                                "found": girth, "table": t[0] if t else None,
                                "dy": (sum(w[1][1] + w[2][1] for w in where) / (2 * len(where)) -
                                       sum(w[1][1] + w[2][1] for w in t[1]) / (2 * len(t[1])))
                                if t else None})
                rows.append(row)
                print("[%d/%d] %s %s: table %.2f, found %s, found only %s" % (
                    len(rows), total, design, row["run"], row["table"],
                    "%.2f" % row["found"] if "found" in row else row.get("found_error"),
                    "%.2f" % row["only"] if "only" in row else row.get("only_error")),
                    file=sys.stderr)
    write(rows, binding_rows, a, body)


def cell(row, key, fmt="%.2f"):
    return fmt % row[key] if key in row else "refused"


def write(rows, binding_rows, a, body):
    lines = [
        "# FreeSewing designs graded with bindings found on a body, against the table",
        "",
        "Command: `benchmarks/scripts/grade_found_vs_table.py %s` (drafts laid on %s; threads %d)."
        % (" ".join(sys.argv[1:]), os.path.basename(body), a.threads),
        "",
        "Mean outline deviation (mm; per piece the mean distance of `tapeline grade --compare`, "
        "averaged over pieces) of each grading from FreeSewing's own draft of the target size, "
        "and of the found gradings from the table grading. *found*: girths and lengths found on "
        "the body, the table for the rest; *found only*: `--freesewing-seams-only` (the design's "
        "seams, no binding from the table).",
        "",
        "| design | run | table: bound / vs FreeSewing | found: bound / vs FreeSewing / vs table "
        "| found only: bound / vs FreeSewing / vs table |",
        "|---|---|---|---|---|"]
    for r in rows:
        def part(tag):
            if tag not in r:
                return "refused: " + r.get(tag + "_error", "?").replace("|", "/")
            return "%d / %.2f / %.2f" % (r[tag + "_bound"], r[tag], r[tag + "_vs_table"])
        lines.append("| %s | %s | %d / %.2f | %s | %s |" % (
            r["design"], r["run"], r["table_bound"], r["table"], part("found"), part("only")))
    found = [r for r in rows if "found" in r]
    only = [r for r in rows if "only" in r]
    lines += ["",
              "Found (the table for what was not found): %d of %d runs graded; largest "
              "difference from the table grading %.2f mm (mean outline deviation; goal 0.5); "
              "largest change of the deviation from FreeSewing's draft against the table's "
              "%+.2f mm. Found only: largest difference from the table grading %.2f mm; "
              "deviation from FreeSewing's draft %.2f-%.2f mm (the table's %.2f-%.2f)." % (
                  len(found), len(rows),
                  max((r["found_vs_table"] for r in found), default=float("nan")),
                  max((r["found"] - r["table"] for r in found), default=float("nan")),
                  max((r["only_vs_table"] for r in only), default=float("nan")),
                  min((r["only"] for r in only), default=float("nan")),
                  max((r["only"] for r in only), default=float("nan")),
                  min((r["table"] for r in only), default=float("nan")),
                  max((r["table"] for r in only), default=float("nan"))),
              "",
              "## The girths found against the table's",
              "",
              "Per girth bound both ways: the garment girth of the draft at the found level and "
              "at the table's points (mm), and the found level's height on the draft minus the "
              "table's (mm; the draft's y axis points up).",
              "",
              "| design | run | measurement | found mm | table mm | level offset mm |",
              "|---|---|---|---:|---:|---:|"]
    for b in binding_rows:
        lines.append("| %s | %s | %s | %.1f | %s | %s |" % (
            b["design"], b["run"], b["measurement"], b["found"],
            "%.1f" % b["table"] if b["table"] is not None else "not in the table",
            "%+.1f" % b["dy"] if b["dy"] is not None else ""))
    lines.append("")
    with open(a.out, "w") as f:
        f.write("\n".join(lines))
    print(a.out)


if __name__ == "__main__":
    main()
