#!/usr/bin/env python3
"""Scaling and convergence of the drape: one garment on one body at several cloth resolutions
(20, 10, 5 mm) and thread counts (1, 2).

Per run: cloth vertices, frames, wall time of the drape, ms per solver step per 10k cloth vertices,
the gates that failed. Per thread count: whether the garment came out bit-identical (the solver
promises the same output for a given thread count; across thread counts it colours its constraints
so that it is the same too). Per resolution step (coarse -> fine, same threads): how much the
drape changed: the hem height (the garment's lowest point) and the silhouette, the mean distance
between the two draped surfaces (each garment's vertices to the nearest vertex or triangle centroid
of the other, averaged both ways; a point-to-point stand-in for the surface distance that reads
high by at most a third of the finer edge length).

  usage: drape_scaling.py TAPELINE DATA_DIR OUT.md [--body PATH] [--pattern PATH]
                          [--resolutions 20 10 5] [--threads 1 2] [--substeps N] [--to-body]
  DATA_DIR: ../shared/data. Needs numpy (Debian: python3-numpy; run with /usr/bin/python3).
"""
import argparse
import hashlib
import json
import os
import subprocess
import sys
import tempfile
import time

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from drape_population import to_body_args  # noqa: E402


def read_obj(path):
    """Vertices and triangles of an OBJ (v and f lines; f corners as v, v/t or v/t/n)."""
    vs, fs = [], []
    with open(path) as f:
        for line in f:
            if line.startswith("v "):
                vs.append([float(x) for x in line.split()[1:4]])
            elif line.startswith("f "):
                idx = [int(c.split("/")[0]) - 1 for c in line.split()[1:]]
                for k in range(1, len(idx) - 1):
                    fs.append([idx[0], idx[k], idx[k + 1]])
    return np.array(vs), np.array(fs, dtype=np.int64)


def nearest(a, b, chunk=128):
    """Distance from every row of a to its nearest row of b (brute force, in chunks)."""
    out = np.empty(len(a))
    bb = (b * b).sum(1)
    for s in range(0, len(a), chunk):
        q = a[s:s + chunk]
        d2 = (q * q).sum(1)[:, None] - 2 * q @ b.T + bb[None, :]
        out[s:s + chunk] = np.sqrt(np.maximum(d2.min(1), 0))
    return out


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tapeline")
    ap.add_argument("data")
    ap.add_argument("out")
    ap.add_argument("--body", default=None, help="default: DATA/bodies/mh_female_average.obj")
    ap.add_argument("--pattern", default=None,
                    help="default: DATA/patterns/freesewing/teagan_cisFemaleAdult36.json")
    ap.add_argument("--resolutions", nargs="*", type=float, default=[20, 10, 5])
    ap.add_argument("--threads", nargs="*", type=int, default=[1, 2])
    ap.add_argument("--substeps", type=int, default=0, help="0: the tool's default")
    ap.add_argument("--no-grading", action="store_true",
                    help="dress a FreeSewing draft as drafted (default: graded to the body)")
    a = ap.parse_args()
    body = a.body or os.path.join(a.data, "bodies", "mh_female_average.obj")
    pattern = a.pattern or os.path.join(a.data, "patterns", "freesewing",
                                        "teagan_cisFemaleAdult36.json")
    tmp = tempfile.TemporaryDirectory(prefix="drape_scaling_")  # removed when the script ends
    work = tmp.name
    runs = []
    todo = [(r, t) for r in a.resolutions for t in a.threads]
    for k, (res, threads) in enumerate(todo):
        tag = "r%g_t%d" % (res, threads)
        obj = os.path.join(work, tag + ".obj")
        rep = os.path.join(work, tag + ".json")
        cmd = [a.tapeline, "dress", body, "--units", "dm", pattern, "--out", obj, "--report", rep,
               "--resolution", str(res), "--threads", str(threads)]
        if a.substeps > 0:
            cmd += ["--substeps", str(a.substeps)]
        if "freesewing" in pattern and not a.no_grading:
            cmd += to_body_args(a.data)
        t0 = time.time()
        p = subprocess.run(cmd, capture_output=True, text=True)
        wall = time.time() - t0
        run = {"resolution": res, "threads": threads, "exit": p.returncode, "wall": wall}
        if p.returncode == 0:
            r = json.load(open(rep))
            run.update({"vertices": r["mesh"]["cloth_vertices"],
                        "frames": r["simulation"]["frames"],
                        "ms_per_step_10k": r["simulation"]["ms_per_step_per_10k_vertices"],
                        "drape_s": r["timings_seconds"]["drape"],
                        "failed": [g["name"] for g in r["gates"] if not g["passed"]],
                        "stretch_p95": r["quality"]["stretch_p95"],
                        "hash": hashlib.sha256(open(obj, "rb").read()).hexdigest(),
                        "obj": obj})
        else:
            run["error"] = (p.stderr.strip().splitlines() or ["exit %d" % p.returncode])[-1]
        runs.append(run)
        print("[%d/%d] %s: %s %.1f s" % (k + 1, len(todo), tag,
                                         "ok" if p.returncode == 0 else run["error"], wall),
              file=sys.stderr)

    lines = ["# Drape scaling and convergence", "",
             "Command: `/usr/bin/python3 benchmarks/scripts/drape_scaling.py build/apps/tapeline "
             "../shared/data %s --body %s --pattern %s --resolutions %s --threads %s%s%s`" % (
                 a.out, os.path.join("../shared/data", os.path.relpath(body, a.data)),
                 os.path.join("../shared/data", os.path.relpath(pattern, a.data)),
                 " ".join("%g" % r for r in a.resolutions), " ".join(map(str, a.threads)),
                 " --substeps %d" % a.substeps if a.substeps > 0 else "",
                 " --no-grading" if a.no_grading else ""), "",
             "## Time", "",
             "| resolution mm | threads | cloth vertices | frames | drape s | ms/step/10k vertices "
             "| wall s | p95 stretch | gates failed |",
             "|---:|---:|---:|---:|---:|---:|---:|---:|---|"]
    for r in runs:
        if "error" in r:
            lines.append("| %g | %d | | | | | %.1f | | %s |" % (r["resolution"], r["threads"],
                                                               r["wall"], r["error"]))
        else:
            lines.append("| %g | %d | %d | %d | %.1f | %.0f | %.1f | %.3f | %s |" % (
                r["resolution"], r["threads"], r["vertices"], r["frames"], r["drape_s"],
                r["ms_per_step_10k"], r["wall"], r["stretch_p95"], ", ".join(r["failed"]) or "-"))
    lines += ["", "Thread scaling (drape time, 1 thread / the others) and determinism across "
              "thread counts:", ""]
    for res in a.resolutions:
        done = [r for r in runs if r["resolution"] == res and "error" not in r]
        if len(done) < 2:
            continue
        base = done[0]
        for r in done[1:]:
            lines.append("- %g mm: %d -> %d threads: %.2fx faster; garment %s" % (
                res, base["threads"], r["threads"], base["drape_s"] / max(r["drape_s"], 1e-9),
                "bit-identical" if r["hash"] == base["hash"] else "**differs**"))
    lines += ["", "## Convergence (with %d threads)" % max(a.threads), "",
              "| step | hem: lowest point, mm in the body's frame (coarse -> fine) | hem change mm "
              "| silhouette change mm |",
              "|---|---|---:|---:|"]
    t = max(a.threads)
    fine = [r for r in runs if r["threads"] == t and "error" not in r]
    fine.sort(key=lambda r: -r["resolution"])
    prev = None
    for r in fine:
        v, f = read_obj(r["obj"])
        v = v * 100.0  # dm -> mm
        pts = np.vstack([v, v[f].mean(1)])
        hem = v[:, 1].min()
        if prev is not None:
            pv, ppts, phem, pres = prev
            sil = 0.5 * (nearest(pv, pts).mean() + nearest(v, ppts).mean())
            lines.append("| %g -> %g mm | %.1f -> %.1f | %.1f | %.2f |" % (
                pres, r["resolution"], phem, hem, abs(hem - phem), sil))
        prev = (v, pts, hem, r["resolution"])
    lines.append("")
    with open(a.out, "w") as f:
        f.write("\n".join(lines) + "\n")


if __name__ == "__main__":
    main()
