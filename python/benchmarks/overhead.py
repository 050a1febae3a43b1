#!/usr/bin/python3
"""What calling the library from Python costs on top of the library's own work.

For each method, the same call is timed from Python (wall clock around the call) and inside the
library (measured in C++: the method's preparation plus query, and the mesh loader's checks and
repairs that a C++ program reading the same mesh pays too), in one run, on one mesh. What is left
is the binding's own share: checking and copying the arrays across the boundary and mapping the
result back to the input's vertex order. Medians of --repeat runs.

    PYTHONPATH=build/python /usr/bin/python3 python/benchmarks/overhead.py MESH [--repeat 5]
"""
import argparse
import statistics
import sys
import time

import numpy as np

import tapeline
from tapeline import geodesic as g


def timed(f):
    t0 = time.perf_counter()
    out = f()
    return time.perf_counter() - t0, out


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("mesh")
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--source", type=int, default=0)
    ap.add_argument("--methods", default="exact-mmp,heat,dijkstra,gcf-window:8")
    a = ap.parse_args()
    V, F, report = tapeline.read_mesh(a.mesh)
    print(f"{a.mesh}: {len(V)} vertices, {len(F)} triangles; medians of {a.repeat} runs",
          file=sys.stderr)
    mesh_build = statistics.median(timed(lambda: tapeline.check_mesh(V, F))[0]
                                   for _ in range(a.repeat))
    print("| call | Python wall s | C++ method s | C++ mesh build s | binding s | binding % of C++ |")
    print("|---|---:|---:|---:|---:|---:|")
    for method in a.methods.split(","):
        walls, libs, builds = [], [], []
        for _ in range(a.repeat):
            wall, (d, r) = timed(lambda: g.distances(V, F, a.source, method=method,
                                                     with_report=True))
            walls.append(wall)
            libs.append(r["seconds"])
            builds.append(r["mesh_seconds"])
        w, l, b = statistics.median(walls), statistics.median(libs), statistics.median(builds)
        print(f"| distances(V, F, method='{method}') | {w:.4f} | {l:.4f} | {b:.4f} | "
              f"{w - l - b:.4f} | {100 * (w - l - b) / (l + b):.1f} |")
    # Solver objects: the mesh is built once; each call pays only the conversion of the result.
    heat = g.HeatSolver(V, F)
    walls, libs = [], []
    for _ in range(a.repeat):
        wall, d = timed(lambda: heat.distances(a.source))
        walls.append(wall)
        libs.append(heat.report["query_seconds"])
    w, l = statistics.median(walls), statistics.median(libs)
    print(f"| HeatSolver.distances (prefactored) | {w:.4f} | {l:.4f} | 0 | {w - l:.4f} | "
          f"{100 * (w - l) / l:.1f} |")
    print(f"\nmesh construction from (V, F) alone (check_mesh): {mesh_build:.4f} s")


if __name__ == "__main__":
    main()
