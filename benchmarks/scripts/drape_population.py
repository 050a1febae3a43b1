#!/usr/bin/python3
"""Runs `tapeline dress` for every pattern on every body (FreeSewing drafts graded to the body
first with --to-body, from the set they were drafted for) and writes a table: per drape the gates
(stitch gap, cloth edges crossing the body, depth, self-intersections, p95 stretch, static, the
top's drop from its placement), the success, the vertices and the times; then the success rate, the
median time and every failure with its reason. With --table-only the table is written again from
an earlier run's --json file, without running anything.

usage: drape_population.py TAPELINE DATA_DIR OUT.md [--bodies bundled|dev|holdout|all]
                           [--patterns NAME ...] [--resolution MM] [--threads N] [--substeps N]
                           [--json OUT.jsonl] [--no-grading] [--no-waistband]
                           [--waistband-sag MM] [--grade-from-body BODY]
                           [--table-only RUN.jsonl]
  DATA_DIR: ../shared/data (bodies/, bodies/population/, patterns/)
  --bodies: a body file, or bundled: the bundled MakeHuman bodies (nine); dev: mh_pop_000 ... mh_pop_029;
  holdout: mh_pop_030 ... mh_pop_039 (kept out of development).
  --grade-from-body BODY: grade the GarmentCode patterns to each body first too, from the body
           they are laid on (tapeline dress --to-body --base-body BODY --base-units dm: bindings
           found on that body); BODY is relative to DATA_DIR (e.g. bodies/mh_female_average.obj).
"""
import argparse
import json
import os
import statistics
import subprocess
import sys
import tempfile
import time

PATTERNS = {
    "gc_shirt": ("patterns/garmentcode/shirt_mean_specification.json", []),
    "gc_dress_pencil": ("patterns/garmentcode/dress_pencil_specification.json", []),
    "gc_hoody_without_hood": ("patterns/garmentcode/hoody_mean_specification.json",
                              ["left_hood", "right_hood"]),
    "gc_jumpsuit": ("patterns/garmentcode/js_mean_all_specification.json", []),
    "fs_aaron_without_bindings": ("patterns/freesewing/aaron_cisFemaleAdult36.json",
                                  ["aaron.armBinding", "aaron.neckBinding"]),
    "fs_brian": ("patterns/freesewing/brian_cisFemaleAdult36.json", []),
    "fs_teagan": ("patterns/freesewing/teagan_cisFemaleAdult36.json", []),
    "fs_simon": ("patterns/freesewing/simon_cisFemaleAdult36.json", []),
    "fs_titan": ("patterns/freesewing/titan_cisFemaleAdult36.json", []),
}


def to_body_args(data):
    """`tapeline dress` arguments that grade a FreeSewing draft to the body first, from the set
    the drafts of ../shared/data were made for."""
    return ["--to-body", "--from", os.path.join(data, "patterns/freesewing/measurement_sets.json"),
            "--from-set", "cisFemaleAdult36"]


def bodies(data, which):
    if os.path.isfile(which):
        return [which]  # one body file
    out = []
    if which in ("bundled", "all"):
        for f in sorted(os.listdir(os.path.join(data, "bodies"))):
            if f.endswith(".obj"):
                out.append(os.path.join(data, "bodies", f))
    pop = os.path.join(data, "bodies", "population")
    rng = {"dev": range(0, 30), "holdout": range(30, 40), "all": range(0, 40)}.get(which, [])
    for i in rng:
        p = os.path.join(pop, "mh_pop_%03d.ply" % i)
        if os.path.exists(p):
            out.append(p)
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tapeline")
    ap.add_argument("data")
    ap.add_argument("out")
    ap.add_argument("--bodies", default="bundled")
    ap.add_argument("--patterns", nargs="*", default=list(PATTERNS))
    ap.add_argument("--resolution", type=float, default=10)
    ap.add_argument("--threads", type=int, default=0)
    ap.add_argument("--substeps", type=int, default=40)
    ap.add_argument("--json")
    ap.add_argument("--no-relax", action="store_true",
                    help="end with the drape's last frame (tapeline dress --no-relax)")
    ap.add_argument("--waistband-sag", type=float,
                    help="tapeline dress --waistband-sag MM (default: dress's own)")
    ap.add_argument("--no-waistband", action="store_true",
                    help="tapeline dress --no-waistband: open waists not held")
    ap.add_argument("--no-grading", action="store_true",
                    help="dress the FreeSewing drafts as drafted (default: --to-body)")
    ap.add_argument("--grade-from-body", metavar="BODY",
                    help="grade the GarmentCode patterns from this body (DATA_DIR-relative)")
    ap.add_argument("--table-only", metavar="RUN_JSONL",
                    help="write the table from this earlier --json output; run nothing")
    a = ap.parse_args()
    if a.table_only:
        with open(a.table_only) as f:
            rows = [json.loads(line) for line in f if line.strip()]
        write_table(rows, a)
        return
    rows = []
    tmp = tempfile.TemporaryDirectory(prefix="drape_")  # removed when the script ends
    work = tmp.name
    todo = [(b, p) for b in bodies(a.data, a.bodies) for p in a.patterns]
    for k, (body, pat) in enumerate(todo):
        rel, without = PATTERNS[pat]
        name = os.path.splitext(os.path.basename(body))[0]
        rep = os.path.join(work, "%s_%s.json" % (name, pat))
        cmd = [a.tapeline, "dress", body, "--units", "dm", os.path.join(a.data, rel),
               "--out", os.path.join(work, "%s_%s.obj" % (name, pat)), "--report", rep,
               "--resolution", str(a.resolution), "--threads", str(a.threads),
               "--substeps", str(a.substeps)]
        for w in without:
            cmd += ["--without", w]
        if a.no_relax:
            cmd += ["--no-relax"]
        if a.no_waistband:
            cmd += ["--no-waistband"]
        if a.waistband_sag is not None:
            cmd += ["--waistband-sag", "%g" % a.waistband_sag]
        if rel.startswith("patterns/freesewing/") and not a.no_grading:
            cmd += to_body_args(a.data)
        if rel.startswith("patterns/garmentcode/") and a.grade_from_body:
            cmd += ["--to-body", "--base-body", os.path.join(a.data, a.grade_from_body),
                    "--base-units", "dm"]
        t0 = time.time()
        p = subprocess.run(cmd, capture_output=True, text=True)
        wall = time.time() - t0
        row = {"body": name, "pattern": pat, "exit": p.returncode, "wall_seconds": wall}
        if p.returncode == 0 and os.path.exists(rep):
            r = json.load(open(rep))
            row.update({"passed": r["passed"], "gates": r["gates"], "quality": r["quality"],
                        "mesh": r["mesh"], "simulation": r["simulation"],
                        "placement": r["placement"], "timings": r["timings_seconds"]})
            row["reason"] = ", ".join("%s %.3g > %.3g" % (g["name"], g["value"], g["limit"])
                                      for g in r["gates"] if not g["passed"])
        else:
            row["passed"] = False
            row["reason"] = (p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[-1]
        rows.append(row)
        print("[%d/%d] %s %s: %s %.1f s %s" % (k + 1, len(todo), name, pat,
                                               "ok" if row["passed"] else "FAILED", wall,
                                               row.get("reason", "")), file=sys.stderr)
    if a.json:
        with open(a.json, "w") as f:
            for r in rows:
                f.write(json.dumps(r) + "\n")
    write_table(rows, a)


def static_solves(sim):
    """The static solves of a drape: how many, the last one's iterations and why it stopped."""
    n = sim.get("static_solves", 0)
    if not n:
        return "none"
    last = sim["static_solve"]
    return "%d: %d, %s" % (n, last["iterations"], last.get("stop", "converged" if last["converged"]
                                                               else "not converged"))


def write_table(rows, a):
    ok = [r for r in rows if r["passed"]]
    ran = [r for r in rows if "quality" in r]
    lines = ["# Drape benchmark", "",
             "Command: `benchmarks/scripts/drape_population.py %s %s %s --bodies %s --resolution %g"
             " --threads %d --substeps %d --patterns %s%s`" % (
                 "build/apps/tapeline", "../shared/data", a.out, a.bodies, a.resolution,
                 a.threads, a.substeps, " ".join(a.patterns),
                 (" --no-grading" if a.no_grading else "") +
                 (" --no-relax" if a.no_relax else "") +
                 (" --no-waistband" if getattr(a, "no_waistband", False) else "") +
                 (" --waistband-sag %g" % a.waistband_sag
                  if getattr(a, "waistband_sag", None) is not None else "") +
                 (" --grade-from-body %s" % a.grade_from_body
                  if getattr(a, "grade_from_body", None) else "")), "",
             "Success: %d of %d drapes (%.0f %%); median wall time of the drapes that ran: %s s." %
             (len(ok), len(rows), 100.0 * len(ok) / max(len(rows), 1),
              "%.1f" % statistics.median([r["wall_seconds"] for r in ran]) if ran else "-"), "",
             "| body | pattern | passed | gap max mm | edges x body | depth mm | self-x | "
             "p95 stretch | on body / off | % on body | moving % | top drop mm | vertices | "
             "frames | ms/step/10k | static solves: last one's iterations, stop | wall s | reason |",
             "|---|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---|---:|---|"]
    for r in rows:
        if "quality" in r:
            q = r["quality"]
            lines.append("| %s | %s | %s | %.2f | %d | %.2f | %d | %.3f | %.3f / %.3f | %.0f | "
                         "%.1f | %s | %d | %d | %.0f | %s | %.1f | %s |" % (
                             r["body"], r["pattern"], "yes" if r["passed"] else "**no**",
                             q["stitch_gap_max_mm"], q["edges_crossing_body"], q["max_depth_mm"],
                             q["self_intersections"], q["stretch_p95"],
                             q["stretch_p95_on_body"], q["stretch_p95_off_body"],
                             q["triangles_on_body_percent"], 100 * q["moving_fraction"],
                             "%.0f" % q["top_drop_mm"] if "top_drop_mm" in q else "-",
                             r["mesh"]["cloth_vertices"],
                             r["simulation"]["frames"],
                             r["simulation"]["ms_per_step_per_10k_vertices"],
                             static_solves(r["simulation"]), r["wall_seconds"], r["reason"]))
        else:
            lines.append("| %s | %s | **no** | | | | | | | | | | | | | | %.1f | %s |" %
                         (r["body"], r["pattern"], r["wall_seconds"], r["reason"]))
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
