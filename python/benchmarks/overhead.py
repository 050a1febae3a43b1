#!/usr/bin/python3
"""What calling the library from Python costs on top of the library's own work.

For each method, the same call is timed from Python (wall clock around the call) and inside the
library (the report's seconds: preparation plus query, measured in C++ around the solver), in one
run, on one mesh; the difference is the binding's share: checking and copying the arrays, building
the mesh, mapping the result back to the input's vertex order. Medians of --repeat runs.

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
    print(f"| call | Python wall s | library s | overhead s | overhead % |")
    print(f"|---|---:|---:|---:|---:|")
    for method in a.methods.split(","):
        walls, libs = [], []
        for _ in range(a.repeat):
            wall, (d, r) = timed(lambda: g.distances(V, F, a.source, method=method,
                                                     with_report=True))
            walls.append(wall)
            libs.append(r["seconds"])
        w, l = statistics.median(walls), statistics.median(libs)
        print(f"| distances(V, F, method='{method}') | {w:.4f} | {l:.4f} | {w - l:.4f} | "
              f"{100 * (w - l) / l:.1f} |")
    # Solver objects: the mesh is built once; each call pays only the conversion of the result.
    heat = g.HeatSolver(V, F)
    walls, libs = [], []
    for _ in range(a.repeat):
        wall, d = timed(lambda: heat.distances(a.source))
        walls.append(wall)
        libs.append(heat.report["query_seconds"])
    w, l = statistics.median(walls), statistics.median(libs)
    print(f"| HeatSolver.distances (prefactored) | {w:.4f} | {l:.4f} | {w - l:.4f} | "
          f"{100 * (w - l) / l:.1f} |")
    print(f"\nmesh construction from (V, F) alone (check_mesh): {mesh_build:.4f} s")


if __name__ == "__main__":
    main()
