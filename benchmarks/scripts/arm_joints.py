#!/usr/bin/python3
"""Holds the elbow and wrist landmarks of `tapeline measure` against MakeHuman's own skeleton
joints, an independent placement of the same levels: MakeHuman puts each joint at the mean of a
few helper vertices that every shape target carries along with the body (its default skeleton,
makehuman/data/rigs/default.mhskel, CC0). For every body of a population made by
../shared/data_tools/mh_population.py, the body is morphed again from its sliders in
population.json (all vertices, the helpers included; the body's own vertices must come out as in
its PLY file, or the script stops), and each landmark is compared with its joint along the arm
(the direction from MakeHuman's shoulder joint to its wrist joint; positive: towards the hand).
The olecranon and the wrist's outer point lie on the skin, the joints inside the arm, so the
offset along the arm is what is compared; the distance is printed too.

usage: MAKEHUMAN_GIT=... MAKEHUMAN_ASSETS_GIT=... arm_joints.py TAPELINE POPULATION_DIR OUT.md
           --data-tools ../shared/data_tools [--jobs N]
"""
import argparse
import concurrent.futures
import json
import math
import os
import statistics
import subprocess
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from measure_population import BASE_MESH_VERTICES, vertices  # noqa: E402

# Our landmark -> MakeHuman joint (default skeleton) on each side.
JOINTS = {"elbow": "lowerarm01.%s____head", "wrist": "wrist.%s____head"}
SHOULDER = "upperarm01.%s____head"
SIDES = (("left", "L"), ("right", "R"))


def morph(mb, base, sliders, cache):
    """MakeHuman's base mesh (helpers included) morphed by the macro targets of `sliders`."""
    p = dict(mb.DEFAULTS)
    p.update(sliders)
    f = mb.factor_values(p)
    V = base.copy()
    for path, vars_ in cache["targets"]:
        w = 1.0
        for v in vars_:
            w *= f[v]
        if w <= 1e-9:
            continue
        if path not in cache:
            cache[path] = mb.load_target(path)
        idx, d = cache[path]
        if len(idx):
            V[idx] += w * d
    return V


def measure(tool, ply, out):
    p = subprocess.run([tool, "measure", ply, "--units", "dm", "--out", out], capture_output=True,
                       text=True)
    if p.returncode != 0:
        raise RuntimeError("%s: %s" % (ply, (p.stderr.strip().splitlines() or ["exit?"])[-1]))
    return {l["name"]: l for l in json.load(open(out))["landmarks"]}


def main():
    ap = argparse.ArgumentParser()
    ap.add_argument("tapeline")
    ap.add_argument("population")
    ap.add_argument("out")
    ap.add_argument("--data-tools", required=True)
    ap.add_argument("--jobs", type=int, default=2)
    a = ap.parse_args()
    meta_path = os.path.join(a.population, "population.json")
    if not os.path.isfile(meta_path):
        sys.exit("arm_joints.py: %s: no population.json (a folder written by mh_population.py)"
                 % a.population)
    if not os.path.isfile(os.path.join(a.data_tools, "mh_bodies.py")):
        sys.exit("arm_joints.py: --data-tools %s: no mh_bodies.py there" % a.data_tools)
    for var in ("MAKEHUMAN_GIT", "MAKEHUMAN_ASSETS_GIT"):
        if not os.path.isdir(os.environ.get(var, "")):
            sys.exit("arm_joints.py: %s is not set to the git folder of MakeHuman's repository "
                     "(makehumancommunity/makehuman%s)"
                     % (var, "-assets" if var == "MAKEHUMAN_ASSETS_GIT" else ""))
    sys.path.insert(0, a.data_tools)
    import mh_bodies as mb  # reads MAKEHUMAN_GIT / MAKEHUMAN_ASSETS_GIT

    skel = json.loads(mb.git_show(os.environ["MAKEHUMAN_GIT"],
                                  "makehuman/data/rigs/default.mhskel").decode())
    meta = json.load(open(meta_path))
    base, _, _ = mb.read_base()
    cache = {"targets": mb.macro_targets()}
    names = sorted(meta["bodies"])
    rows = []
    with tempfile.TemporaryDirectory() as work, \
            concurrent.futures.ThreadPoolExecutor(max_workers=a.jobs) as pool:
        futures = {n: pool.submit(measure, a.tapeline, os.path.join(a.population, n + ".ply"),
                                  os.path.join(work, n + ".json")) for n in names}
        for k, n in enumerate(names, 1):
            try:
                lm = futures[n].result()
            except RuntimeError as e:
                sys.exit("arm_joints.py: tapeline measure failed on %s" % e)
            V = morph(mb, base, meta["bodies"][n]["sliders"], cache)
            body = np.array(vertices(os.path.join(a.population, n + ".ply")))
            if body.shape != (BASE_MESH_VERTICES, 3):
                sys.exit("arm_joints.py: %s.ply: not a binary PLY of MakeHuman's %d base-mesh "
                         "vertices" % (n, BASE_MESH_VERTICES))
            drift = float(np.abs(V[:len(body)] - body).max()) * 100  # dm -> mm
            if drift > 0.5:
                sys.exit("arm_joints.py: %s: the body morphed from population.json's sliders is "
                         "%.2f mm from its PLY file: not the same draw" % (n, drift))
            for side, s in SIDES:
                joint = {k: V[skel["joints"][j % s]].mean(axis=0) * 100 for k, j in JOINTS.items()}
                shoulder = V[skel["joints"][SHOULDER % s]].mean(axis=0) * 100
                axis = (joint["wrist"] - shoulder) / np.linalg.norm(joint["wrist"] - shoulder)
                for ours in JOINTS:
                    p = np.array(lm[ours + "_" + side]["point_input"]) * 100
                    rows.append({"body": n, "side": side, "landmark": ours,
                                 "along": float((p - joint[ours]) @ axis),
                                 "distance": float(np.linalg.norm(p - joint[ours]))})
            print("[%d/%d] %s" % (k, len(names), n), file=sys.stderr, flush=True)
    write_table(rows, a, len(names))


def write_table(rows, a, count):
    out = ["# Elbow and wrist against MakeHuman's skeleton joints", "",
           "`MAKEHUMAN_GIT=… MAKEHUMAN_ASSETS_GIT=… benchmarks/scripts/arm_joints.py "
           "build/apps/tapeline %s OUT.md --data-tools ../shared/data_tools`. %d bodies, both "
           "sides. Along the arm: our landmark minus MakeHuman's joint, projected on the direction "
           "from its shoulder joint to its wrist joint (mm; positive towards the hand). The "
           "olecranon lies behind the elbow joint and the wrist's outer point beside the wrist "
           "joint, so the distance is about the arm's radius there." % (a.population, count), "",
           "| landmark | n | along: mean | sd | min | max | distance: mean | max |",
           "|---|---:|---:|---:|---:|---:|---:|---:|"]
    for ours in JOINTS:
        r = [x for x in rows if x["landmark"] == ours]
        al = [x["along"] for x in r]
        di = [x["distance"] for x in r]
        out.append("| %s | %d | %+.1f | %.1f | %+.1f (%s) | %+.1f (%s) | %.1f | %.1f |" % (
            ours, len(r), statistics.mean(al), statistics.stdev(al) if len(al) > 1 else math.nan,
            min(al), min(r, key=lambda x: x["along"])["body"], max(al),
            max(r, key=lambda x: x["along"])["body"], statistics.mean(di), max(di)))
    out += ["", "| body | side | elbow along | elbow distance | wrist along | wrist distance |",
            "|---|---|---:|---:|---:|---:|"]
    by = {(x["body"], x["side"], x["landmark"]): x for x in rows}
    for body, side in sorted({(x["body"], x["side"]) for x in rows}):
        e, w = by[(body, side, "elbow")], by[(body, side, "wrist")]
        out.append("| %s | %s | %+.1f | %.1f | %+.1f | %.1f |" % (
            body, side, e["along"], e["distance"], w["along"], w["distance"]))
    open(a.out, "w").write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
