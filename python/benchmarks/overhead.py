#!/usr/bin/python3
"""What calling the library from Python costs on top of the same call made from C++.

Side by side in one run, on one mesh, for each method: the wall time of
tapeline.geodesic.distances(V, F, source, method) from Python, and the wall time of a C++
program (overhead_baseline, python/benchmarks/overhead_baseline.cpp) that holds the same mesh as
flat arrays and does what a C++ function taking them and returning the field does: the arrays to
the loader's polygon soup, the mesh built and checked, bench::run_distance_method (the code
behind distances() and `tapeline geodesic distances`), the result in the input's vertex order,
the mesh destroyed. Each repeat runs the C++ program (two calls, the second timed), then the
Python call; the median of
the pairs' ratios compares whole calls (two processes: a few per cent of noise). The binding's
own cost is measured inside each: the wall time outside the mesh build and the method call (in
C++: the arrays to the soup, the result reordered, the mesh destroyed; in Python the same plus
the binding's checks and copies across the boundary), and their difference. Medians of --repeat
runs.

    cmake --build build --target tapeline_python_overhead_baseline
    PYTHONPATH=build/python /usr/bin/python3 python/benchmarks/overhead.py MESH [--repeat 9]
"""
import argparse
import json
import os
import statistics
import subprocess
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
    ap.add_argument("--baseline", default=os.path.join(
        os.path.dirname(tapeline.__file__), "..", "overhead_baseline"),
        help="the C++ baseline program (default: beside the built module)")
    a = ap.parse_args()
    if not os.path.exists(a.baseline):
        sys.exit(f"overhead.py: no C++ baseline at {a.baseline}: cmake --build build --target "
                 "tapeline_python_overhead_baseline")
    V, F, report = tapeline.read_mesh(a.mesh)
    print(f"{a.mesh}: {len(V)} vertices, {len(F)} triangles; medians of {a.repeat} runs",
          file=sys.stderr)
    mesh_build = statistics.median(timed(lambda: tapeline.check_mesh(V, F))[0]
                                   for _ in range(a.repeat))
    print("| call | Python wall s | C++ program wall s | Python / C++ (median of pairs) "
          "| outside mesh build and method: C++ program s | the same in Python s "
          "| binding (difference) s | binding % of the C++ program |")
    print("|---|---:|---:|---:|---:|---:|---:|---:|")
    for method in a.methods.split(","):
        walls, cxx, pairs, cxx_rest, binding = [], [], [], [], []
        for _ in range(a.repeat):
            # A C++ run (its own process: the mesh read there is not timed; the second of two
            # calls, as the Python process is warm too), then the same call from Python, so that
            # both see the machine in the same state.
            run = subprocess.run([a.baseline, a.mesh, str(a.source), "2", method],
                                 capture_output=True, text=True, check=True).stdout
            c = json.loads(run.splitlines()[-1])
            wall, d = timed(lambda: g.distances(V, F, a.source, method=method))
            assert abs(d[-1] - c["d_last"]) <= 1e-9 * max(1.0, abs(d[-1])), (d[-1], c)
            walls.append(wall)
            cxx.append(c["wall_s"])
            pairs.append(wall / c["wall_s"])
            cxx_rest.append(c["wall_s"] - c["build_s"] - c["call_s"])
            wall2, (d2, r) = timed(lambda: g.distances(V, F, a.source, method=method,
                                                       with_report=True))
            binding.append(wall2 - r["call_seconds"] - r["mesh_seconds"])
        w, c = statistics.median(walls), statistics.median(cxx)
        q = statistics.median(pairs)
        py_rest, c_rest = statistics.median(binding), statistics.median(cxx_rest)
        print(f"| distances(V, F, method='{method}') | {w:.4f} | {c:.4f} | {q:.3f} "
              f"| {c_rest:.4f} | {py_rest:.4f} | {py_rest - c_rest:.4f} "
              f"| {100 * (py_rest - c_rest) / c:.2f} |")
    heat = g.HeatSolver(V, F)
    walls, libs = [], []
    for _ in range(a.repeat):
        wall, d = timed(lambda: heat.distances(a.source))
        walls.append(wall)
        libs.append(heat.report["query_seconds"])
    w, l = statistics.median(walls), statistics.median(libs)
    print(f"\nHeatSolver.distances (prefactored): Python wall {w:.4f} s, the C++ query {l:.4f} s "
          f"(its own timer): {100 * (w - l) / l:.1f} % more")
    print(f"\nmesh construction from (V, F) alone (check_mesh): {mesh_build:.4f} s")


if __name__ == "__main__":
    main()
