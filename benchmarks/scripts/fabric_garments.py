#!/usr/bin/python3
"""Dresses one body in one garment cut from several fabrics (`tapeline dress --fabric F`) and
writes a table of the gates and of the silhouette each fabric gives: the hem's width, depth, hull
perimeter, folds and its clearance from the body (the dress report's `openings`), and a picture:
the front view of each drape (`tapeline dress --picture`) beside the hems seen from above, with
the body's section at the hem's height.

usage: fabric_garments.py TAPELINE DATA_DIR OUT.md [--body FILE] [--pattern NAME]
                          [--fabrics NAME ...] [--resolution MM] [--substeps N] [--keep DIR]
  DATA_DIR: ../shared/data; --pattern: a name of drape_population.py's PATTERNS.
  The picture goes beside OUT.md as OUT.png.
"""
import argparse
import json
import os
import shutil
import subprocess
import sys
import tempfile
import time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from drape_population import PATTERNS, to_body_args  # noqa: E402


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tapeline")
    ap.add_argument("data")
    ap.add_argument("out")
    ap.add_argument("--body", default="bodies/mh_female_average.obj")
    ap.add_argument("--pattern", default="fs_teagan")
    ap.add_argument("--fabrics", nargs="*", default=["cotton_jersey", "cotton_shirting", "denim"])
    ap.add_argument("--resolution", type=float, default=20)
    ap.add_argument("--substeps", type=int, default=40)
    ap.add_argument("--keep", help="keep the drapes (OBJ, report, picture) in this folder")
    a = ap.parse_args()

    body = a.body if os.path.isabs(a.body) else os.path.join(a.data, a.body)
    pattern_file, without = PATTERNS[a.pattern]
    pattern = os.path.join(a.data, pattern_file)
    work = a.keep or tempfile.mkdtemp(prefix="fabric_garments_")
    os.makedirs(work, exist_ok=True)
    tool_rev = subprocess.run(["git", "describe", "--always", "--dirty"], capture_output=True,
                              text=True, cwd=os.path.dirname(os.path.abspath(__file__))).stdout.strip()
    rows = []
    for fabric in a.fabrics:
        obj = os.path.join(work, fabric + ".obj")
        rep = os.path.join(work, fabric + ".json")
        pic = os.path.join(work, fabric + ".png")
        for f in (obj, rep, pic):  # an earlier run's files in --keep are not this run's
            if os.path.exists(f):
                os.remove(f)
        cmd = [a.tapeline, "dress", body, "--units", "dm", pattern, "--fabric", fabric,
               "--resolution", str(a.resolution), "--substeps", str(a.substeps), "--out", obj,
               "--report", rep, "--picture", pic]
        if a.pattern.startswith("fs_"):
            cmd += to_body_args(a.data)
        for p in without:
            cmd += ["--without", p]
        t0 = time.time()
        run = subprocess.run(cmd, capture_output=True, text=True)
        wall = time.time() - t0
        print("%s: exit %d, %.0f s" % (fabric, run.returncode, wall), file=sys.stderr)
        if not os.path.exists(rep):
            rows.append({"fabric": fabric, "error": run.stderr.strip().splitlines()[-1:]})
            continue
        r = json.load(open(rep))
        rows.append({"fabric": fabric, "report": r, "obj": obj, "picture": pic, "wall": wall})

    # Bending length per fabric (geometric mean of warp and weft) from `tapeline fabric list`.
    bending = {}
    for line in subprocess.run([a.tapeline, "fabric", "list"], capture_output=True,
                               text=True).stdout.splitlines()[1:]:
        t = line.split()
        if len(t) >= 4:
            bending[t[0]] = (float(t[2]) * float(t[3])) ** 0.5

    lines = ["# One garment, %d fabrics: %s on %s at %g mm" %
             (len(a.fabrics), a.pattern, os.path.basename(body), a.resolution), "",
             "```sh", "benchmarks/scripts/fabric_garments.py build/apps/tapeline ../shared/data %s "
             "--body %s --pattern %s --fabrics %s --resolution %g --substeps %d" %
             (a.out, a.body, a.pattern, " ".join(a.fabrics), a.resolution, a.substeps),
             "```", "", "Tool at %s. The hem is the garment's lowest opening; its figures are the "
             "dress report's `openings[0]` (garment/README.md, \"Openings\")." % tool_rev, ""]
    lines.append("| fabric | bending length mm | gates | failed | hem height mm | hem width mm | "
                 "hem depth mm | hem hull perimeter mm | hem length mm | hem folds | deepest fold mm "
                 "| hem clearance mean / max mm | wall s |")
    lines.append("|---|---:|---|---|---:|---:|---:|---:|---:|---:|---:|---|---:|")
    for row in rows:
        if "error" in row:
            lines.append("| %s | | error: %s | | | | | | | | | | |" %
                         (row["fabric"], " ".join(row["error"])))
            continue
        r = row["report"]
        hem = r["openings"][0] if r.get("openings") else None
        failed = [g["name"] for g in r["gates"] if not g["passed"]]
        c_text = "%.1f" % bending[row["fabric"]] if row["fabric"] in bending else ""
        lines.append("| %s | %s | %s | %s | %.0f | %.0f | %.0f | %.0f | %.0f | %d | %.1f | %.1f / %.1f "
                     "| %.0f |" % (row["fabric"], c_text,
                                   "all passed" if r["passed"] else "%d of %d" %
                                   (len(r["gates"]) - len(failed), len(r["gates"])),
                                   ", ".join(failed) or "–", hem["height_mm"], hem["width_mm"],
                                   hem["depth_mm"], hem["hull_perimeter_mm"], hem["length_mm"],
                                   hem["folds"], hem["deepest_fold_mm"], hem["clearance_mean_mm"],
                                   hem["clearance_max_mm"], row["wall"]))
    lines.append("")
    ok = [r for r in rows if "report" in r and r["report"].get("openings")]
    if len(ok) >= 2:
        h0, h1 = ok[0]["report"]["openings"][0], ok[-1]["report"]["openings"][0]
        lines += ["%s against %s: hem hull perimeter %+.0f mm, width %+.0f mm, depth %+.0f mm, "
                  "mean clearance from the body %+.1f mm, folds %d → %d." %
                  (ok[-1]["fabric"], ok[0]["fabric"],
                   h1["hull_perimeter_mm"] - h0["hull_perimeter_mm"], h1["width_mm"] - h0["width_mm"],
                   h1["depth_mm"] - h0["depth_mm"], h1["clearance_mean_mm"] - h0["clearance_mean_mm"],
                   h0["folds"], h1["folds"]), ""]
    png = os.path.splitext(a.out)[0] + ".png"
    if ok:
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.image as mpimg
        import matplotlib.pyplot as plt
        fig = plt.figure(figsize=(4.2 * (len(ok) + 1), 6))
        for k, row in enumerate(ok):
            axp = fig.add_subplot(1, len(ok) + 1, k + 1)
            if os.path.exists(row["picture"]):
                axp.imshow(mpimg.imread(row["picture"]))
            axp.set_title(row["fabric"])
            axp.axis("off")
        ax = fig.add_subplot(1, len(ok) + 1, len(ok) + 1)
        colours = ["tab:blue", "tab:orange", "tab:green", "tab:red", "tab:purple"]
        for k, row in enumerate(ok):
            loop = row["report"]["openings"][0]["loop_canonical_mm"]
            xs = [p[0] for p in loop] + [loop[0][0]]
            zs = [p[2] for p in loop] + [loop[0][2]]
            ax.plot(xs, zs, color=colours[k % len(colours)], lw=1.2, marker=".", ms=3,
                    label="%s (folds: %d)" % (row["fabric"], row["report"]["openings"][0]["folds"]))
        ax.set_aspect("equal")
        ax.set_xlabel("x (left), mm")
        ax.set_ylabel("z (front), mm")
        ax.set_title("hems from above")
        ax.legend(fontsize=7, loc="upper right")
        fig.tight_layout()
        fig.savefig(png, dpi=110)
        lines += ["![%s in %s](%s)" % (a.pattern, ", ".join(r["fabric"] for r in ok),
                                       os.path.basename(png)), ""]
    with open(a.out, "w") as fh:
        fh.write("\n".join(lines))
    print("\n".join(lines))
    if not a.keep:
        shutil.rmtree(work)


if __name__ == "__main__":
    main()
