#!/usr/bin/python3
"""The Python module on the bundled data: exact, heat and curvature-flow geodesics on the spot
cow, the tape measurements of the bundled body, and the body dressed in the bundled shirt.

    PYTHONPATH=build/python /usr/bin/python3 python/examples/quickstart.py [data-dir]
"""
import os
import sys

import numpy as np

import tapeline
from tapeline import geodesic, pattern

data = sys.argv[1] if len(sys.argv) > 1 else os.path.join(os.path.dirname(__file__), "..", "..",
                                                          "data")
V, F, report = tapeline.read_mesh(os.path.join(data, "spot.obj"))
print(f"spot.obj: {len(V)} vertices, {len(F)} triangles")
exact = geodesic.distances(V, F, 0)
for method in ["heat", "heat-idt", "gcf-window:8", "dijkstra"]:
    d = geodesic.distances(V, F, 0, method=method)
    err = np.abs(d - exact).mean() / exact.mean()
    print(f"  {method:>12}: mean error against exact MMP {100 * err:.2f} %")
points, length = geodesic.ExactMmpSolver(V, F).path(0, 1500)
_, flow = geodesic.CurvatureFlowPathSolver(V, F).path(0, 1500)
print(f"  path 0 -> 1500: exact {length:.6f} ({len(points)} points), curvature flow {flow:.6f}")

V, F, _ = tapeline.read_mesh(os.path.join(data, "bodies", "mh_female_average.obj"))
m = tapeline.measure(V, F, units="dm")
print(f"mh_female_average.obj: height {m['frame']['height_mm']:.1f} mm, "
      f"{len(m['measurements'])} measurements, {len(m['missing'])} missing")
for name in ["bust_girth", "waist_girth", "hip_girth", "neck_girth"]:
    x = next((x for x in m["measurements"] if x["name"] == name), None)
    if x:
        print(f"  {name:>12}: {x['value_mm']:7.1f} mm  ISO 8559-1 {x['iso_number']}, "
              f"FreeSewing '{x['freesewing_name']}'")

shirt = pattern.read(os.path.join(data, "patterns", "shirt_mean_specification.json"))
d = tapeline.dress(V, F, shirt, units="dm", resolution_mm=30)  # a coarse cloth: seconds
r = d["report"]
failed = [g["name"] for g in r["gates"] if not g["passed"]]
print(f"shirt on it: {len(d['V'])} vertices, {len(d['F'])} triangles, p95 stretch "
      f"{r['quality']['stretch_p95']:.3f}, quality gates "
      + ("passed" if not failed else "failed: " + ", ".join(failed)))
