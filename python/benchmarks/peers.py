#!/usr/bin/python3
"""Tapeline's geodesics from Python next to potpourri3d's (geometry-central's Python bindings)
and libigl's exact geodesic.

On each mesh, from 3 fixed source vertices (0, n/3, 2n/3), the script measures:

- the heat method in both libraries, in two pairings of the same discretisation:
  cotan Laplacian (tapeline HeatSolver(intrinsic_delaunay=False) against
  potpourri3d MeshHeatMethodDistanceSolver(V, F, use_robust=False)) and intrinsic Delaunay
  (tapeline HeatSolver(intrinsic_delaunay=True), i.e. method "heat-idt", against
  potpourri3d MeshHeatMethodDistanceSolver(V, F), whose default use_robust=True builds the
  mollified intrinsic Delaunay ("robust") Laplacian). Both use the time step t = (mean edge
  length)^2. Two times each: setup (construction plus the first query, less one later query:
  building the operators and factorising) and per query (a distance field from a prefactored
  solver);
- tapeline's exact polyhedral distances (method "exact-mmp"), the reference: errors are
  mean and max |d - exact| / max(exact) over the vertices. On a mesh whose vertices all lie on
  the unit sphere, every method is also compared with the great-circle distance
  arccos(p_s . p_i), the smooth truth;
- exact distances next to libigl's igl.exact_geodesic (Kirsanov's implementation of MMP, with
  the signature of libigl's Python bindings exact_geodesic(v, f, vs, vt)) when a module `igl`
  with that function is importable: time per source and the largest difference from Tapeline's
  exact-mmp (both exact: they should agree to rounding);
- shortest paths between 3 fixed vertex pairs: potpourri3d EdgeFlipGeodesicSolver
  find_geodesic_path (edge flips from a Dijkstra path) and tapeline CurvatureFlowPathSolver.path,
  their lengths relative to tapeline ExactMmpSolver.path (exact, timed once: construction and
  one propagation from the pair's first vertex).

Times are wall-clock medians of --repeat runs around the Python calls. By default the process
is pinned to one CPU before either library is loaded, so both run single-threaded; the
cpu/wall column (process CPU time over wall time of the timed calls, maximum) shows whether a
library used more than one thread. When potpourri3d or igl cannot be imported the script says
so and prints Tapeline's rows only. Nothing is downloaded.

    PYTHONPATH=build/python:/path/to/potpourri3d /usr/bin/python3 python/benchmarks/peers.py \\
        [MESH ...] [--repeat 5] [--threads 1|all] [--peer-commits "potpourri3d abc1234, ..."]

Meshes default to data/spot.obj and data/bodies/mh_female_average.obj; a unit icosphere adds
the great-circle comparison, e.g. build/apps/tapeline mesh generate icosphere:6 --out ico6.off
and pass ico6.off.
"""
import argparse
import os
import statistics
import subprocess
import sys
import time

REPO = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
DEFAULT_MESHES = [os.path.join(REPO, "data", "spot.obj"),
                  os.path.join(REPO, "data", "bodies", "mh_female_average.obj")]


def parse_args():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("meshes", nargs="*", default=DEFAULT_MESHES)
    ap.add_argument("--repeat", type=int, default=5)
    ap.add_argument("--threads", choices=["1", "all"], default="1",
                    help="1: pin the process to one CPU before loading the libraries")
    ap.add_argument("--peer-commits", default="",
                    help="text naming the potpourri3d / geometry-central build, for the header")
    ap.add_argument("--no-paths", action="store_true", help="skip the path comparison")
    return ap.parse_args()


ARGS = parse_args()
# Pin to one CPU (and ask OpenMP / BLAS for one thread) before any library starts its threads.
if ARGS.threads == "1":
    for var in ("OMP_NUM_THREADS", "OPENBLAS_NUM_THREADS", "MKL_NUM_THREADS"):
        os.environ[var] = "1"
    if hasattr(os, "sched_setaffinity"):
        os.sched_setaffinity(0, {min(os.sched_getaffinity(0))})

import numpy as np  # noqa: E402

import tapeline  # noqa: E402
from tapeline import geodesic as g  # noqa: E402

try:
    import potpourri3d as pp3d  # noqa: E402
    PP3D_ERROR = None
except ImportError as e:  # the peer is optional: Tapeline's rows are printed without it
    pp3d = None
    PP3D_ERROR = str(e)

try:
    import igl  # noqa: E402
    IGL_ERROR = None if hasattr(igl, "exact_geodesic") else "igl has no exact_geodesic"
except ImportError as e:
    igl = None
    IGL_ERROR = str(e)
if IGL_ERROR:
    igl = None


class Clock:
    """Wall and process-CPU time of timed calls; keeps the largest cpu/wall ratio seen."""

    def __init__(self):
        self.max_ratio = 0.0

    def __call__(self, f):
        w0, c0 = time.perf_counter(), time.process_time()
        out = f()
        wall, cpu = time.perf_counter() - w0, time.process_time() - c0
        if wall > 0.02:  # shorter calls give a noisy ratio
            self.max_ratio = max(self.max_ratio, cpu / wall)
        return wall, out


CLOCK = {"tapeline": Clock(), "potpourri3d": Clock(), "libigl": Clock()}


def rel_errors(d, ref):
    """Mean and max |d - ref| / max(ref) over the vertices."""
    e = np.abs(np.asarray(d, dtype=float) - ref) / ref.max()
    return float(e.mean()), float(e.max())


def on_unit_sphere(V):
    return bool(np.abs(np.linalg.norm(V, axis=1) - 1.0).max() < 1e-6)


def great_circle(V, s):
    P = V / np.linalg.norm(V, axis=1)[:, None]
    return np.arccos(np.clip(P @ P[s], -1.0, 1.0))


def polyline_length(P):
    P = np.asarray(P, dtype=float)
    return float(np.linalg.norm(np.diff(P, axis=0), axis=1).sum())


def git_short_head(path):
    """The short commit of the work tree at path, marked when tracked files are modified."""
    try:
        run = lambda *a: subprocess.run(["git", "-C", path, *a], capture_output=True,
                                        text=True, check=True).stdout.strip()
        head = run("rev-parse", "--short", "HEAD")
        return head + (" (+ uncommitted changes)"
                       if run("status", "--porcelain", "--untracked-files=no") else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown"


def bench_heat(lib, make, query, sources, repeat):
    """Setup and per-query times of one heat solver, and its distance field from each source.

    Each repeat constructs the solver, queries sources[0] once (the first query also pays
    for any factorisation done lazily), then queries every source. Setup is construction plus
    first query, less the median later query."""
    clock = CLOCK[lib]
    firsts, later, fields = [], [], {}
    for _ in range(repeat):
        t_make, solver = clock(make)
        t_first, _ = clock(lambda: query(solver, sources[0]))
        firsts.append(t_make + t_first)
        for s in sources:
            t, d = clock(lambda: query(solver, s))
            later.append(t)
            fields[s] = np.asarray(d, dtype=float)
    q = statistics.median(later)
    return {"setup": statistics.median(firsts) - q, "query": q, "fields": fields}


def heat_variants():
    """(label, tapeline maker, potpourri3d maker or None) for the two heat discretisations."""
    out = []
    for idt in (False, True):
        label = ("heat, intrinsic Delaunay (tapeline heat-idt; pp3d default use_robust=True)"
                 if idt else "heat, cotan (tapeline heat; pp3d use_robust=False)")
        tl = (lambda V, F, idt=idt: g.HeatSolver(V, F, intrinsic_delaunay=idt))
        pp = None
        if pp3d is not None:
            pp = (lambda V, F, idt=idt: pp3d.MeshHeatMethodDistanceSolver(V, F, use_robust=idt))
        out.append((label, tl, pp))
    return out


def fmt(x, spec=".4f"):
    return "—" if x is None else format(x, spec)


def ratio(a, b):
    return None if a is None or b is None or b == 0 else a / b


def main():
    a = ARGS
    tl_head = git_short_head(REPO)
    if pp3d is not None:
        try:
            from importlib.metadata import version
            pp_version = "potpourri3d " + version("potpourri3d")
        except Exception:
            pp_version = "potpourri3d from " + os.path.dirname(pp3d.__file__)
        if a.peer_commits:
            pp_version += f" ({a.peer_commits})"
    else:
        pp_version = f"potpourri3d not importable ({PP3D_ERROR}): Tapeline's rows only"
    igl_version = ("libigl exact_geodesic from " + os.path.dirname(igl.__file__)
                   if igl is not None else f"libigl not importable ({IGL_ERROR})")
    print(f"# Tapeline {tl_head} vs {pp_version}; {igl_version}")
    print(f"medians of {a.repeat} runs; threads: "
          f"{'pinned to one CPU' if a.threads == '1' else 'unrestricted'}; "
          f"load average at start {os.getloadavg()[0]:.2f} on {os.cpu_count()} CPUs\n")

    heat_rows, source_rows, path_rows, exact_rows = [], [], [], []
    for path in a.meshes:
        V, F, _ = tapeline.read_mesh(path)
        V = np.ascontiguousarray(V, dtype=np.float64)
        F = np.ascontiguousarray(F, dtype=np.int64)
        n = len(V)
        name = os.path.basename(path)
        sphere = on_unit_sphere(V)
        sources = [0, n // 3, (2 * n) // 3]
        print(f"{name}: {n} vertices, {len(F)} triangles"
              f"{', unit sphere' if sphere else ''}; sources {sources}", file=sys.stderr)

        # The reference: exact polyhedral distances, one run per source.
        exact, exact_t, truth = {}, [], {}
        for s in sources:
            t, (d, rep) = CLOCK["tapeline"](
                lambda: g.distances(V, F, s, method="exact-mmp", with_report=True))
            exact[s] = np.asarray(d, dtype=float)
            exact_t.append(t)
            if sphere:
                truth[s] = great_circle(V, s)
        if igl is not None:
            print("  libigl exact_geodesic", file=sys.stderr)
            everyone = np.arange(n, dtype=np.int32)
            Fi = F.astype(np.int32)
            igl_t, igl_err, igl_sph = [], [], []
            for s in sources:
                t, d = CLOCK["libigl"](lambda: igl.exact_geodesic(
                    V, Fi, np.array([s], dtype=np.int32), everyone))
                d = np.asarray(d, dtype=float)
                igl_t.append(t)
                igl_err.append(rel_errors(d, exact[s])[1])
                if sphere:
                    igl_sph.append(rel_errors(d, truth[s])[1])
            exact_rows.append({"mesh": name, "n": n, "tl": statistics.median(exact_t),
                               "igl": statistics.median(igl_t), "diff": max(igl_err),
                               "tl_sph": max(rel_errors(exact[s], truth[s])[1] for s in sources)
                               if sphere else None,
                               "igl_sph": max(igl_sph) if sphere else None})
        ex_sphere = None
        if sphere:
            ex_sphere = [rel_errors(exact[s], truth[s]) for s in sources]
        heat_rows.append({
            "mesh": name, "n": n, "label": "exact-mmp (reference)",
            "tl": {"setup": None, "query": statistics.median(exact_t)}, "pp": None,
            "tl_err": (0.0, 0.0), "pp_err": None,
            "tl_sph": (max(e[0] for e in ex_sphere), max(e[1] for e in ex_sphere))
            if sphere else None, "pp_sph": None})

        for label, tl_make, pp_make in heat_variants():
            print(f"  {label}", file=sys.stderr)
            tl = bench_heat("tapeline", lambda: tl_make(V, F),
                            lambda solver, s: solver.distances(s), sources, a.repeat)
            pp = None
            if pp_make is not None:
                pp = bench_heat("potpourri3d", lambda: pp_make(V, F),
                                lambda solver, s: solver.compute_distance(s), sources, a.repeat)
            errs = {}
            for lib, res in (("tl", tl), ("pp", pp)):
                if res is None:
                    errs[lib], errs[lib + "_sph"] = None, None
                    continue
                per = [rel_errors(res["fields"][s], exact[s]) for s in sources]
                # Mesh summary: mean error averaged over the sources, max error the largest.
                errs[lib] = (statistics.mean(e[0] for e in per), max(e[1] for e in per))
                sph = None
                if sphere:
                    persph = [rel_errors(res["fields"][s], truth[s]) for s in sources]
                    sph = (statistics.mean(e[0] for e in persph), max(e[1] for e in persph))
                errs[lib + "_sph"] = sph
                for s, e in zip(sources, per):
                    source_rows.append((name, label, s, lib, e))
            heat_rows.append({"mesh": name, "n": n, "label": label, "tl": tl, "pp": pp,
                              "tl_err": errs["tl"], "pp_err": errs["pp"],
                              "tl_sph": errs["tl_sph"], "pp_sph": errs["pp_sph"]})

        if a.no_paths:
            continue
        pairs = [(sources[0], sources[1]), (sources[1], sources[2]), (sources[2], sources[0])]
        print("  paths", file=sys.stderr)
        flow_t, flow_solver = CLOCK["tapeline"](lambda: g.CurvatureFlowPathSolver(V, F))
        flip_setup, flip_solver = None, None
        if pp3d is not None and hasattr(pp3d, "EdgeFlipGeodesicSolver"):
            flip_setup = statistics.median(
                CLOCK["potpourri3d"](lambda: pp3d.EdgeFlipGeodesicSolver(V, F))[0]
                for _ in range(a.repeat))
            flip_solver = pp3d.EdgeFlipGeodesicSolver(V, F)
        for (u, v) in pairs:
            # Exact: a fresh solver, so the time includes the propagation from u.
            t_ex, (_, L_ex) = CLOCK["tapeline"](lambda: g.ExactMmpSolver(V, F).path(u, v))
            runs = [CLOCK["tapeline"](lambda: flow_solver.path(u, v)) for _ in range(a.repeat)]
            t_flow = statistics.median(r[0] for r in runs)
            L_flow = runs[-1][1][1]
            t_flip, L_flip = None, None
            if flip_solver is not None:
                runs = [CLOCK["potpourri3d"](lambda: flip_solver.find_geodesic_path(u, v))
                        for _ in range(a.repeat)]
                t_flip = statistics.median(r[0] for r in runs)
                L_flip = polyline_length(runs[-1][1])
            L_gc = float(great_circle(V, u)[v]) if sphere else None
            path_rows.append({"mesh": name, "pair": (u, v), "L_ex": L_ex, "t_ex": t_ex,
                              "L_flow": L_flow, "t_flow": t_flow, "flow_setup": flow_t,
                              "L_flip": L_flip, "t_flip": t_flip, "flip_setup": flip_setup,
                              "L_gc": L_gc})

    # Heat table: times side by side with tapeline / potpourri3d ratios, errors side by side.
    print("## Distances from a vertex (errors relative to max exact distance; "
          "mean over the 3 sources / max over them)\n")
    print("| mesh | V | method | setup s tapeline | setup s pp3d | setup ratio T/P "
          "| query s tapeline | query s pp3d | query ratio T/P "
          "| mean err tapeline | mean err pp3d | max err tapeline | max err pp3d "
          "| vs great circle mean/max tapeline | vs great circle mean/max pp3d |")
    print("|---|---:|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
    for r in heat_rows:
        tl, pp = r["tl"], r["pp"]
        ps = pp["setup"] if pp else None
        pq = pp["query"] if pp else None

        def sph(x):
            return "—" if x is None else f"{x[0]:.2e} / {x[1]:.2e}"
        print(f"| {r['mesh']} | {r['n']} | {r['label']} | {fmt(tl['setup'])} | {fmt(ps)} "
              f"| {fmt(ratio(tl['setup'], ps), '.2f')} | {fmt(tl['query'])} | {fmt(pq)} "
              f"| {fmt(ratio(tl['query'], pq), '.2f')} "
              f"| {fmt(r['tl_err'][0], '.2e')} | {fmt(r['pp_err'][0] if r['pp_err'] else None, '.2e')} "
              f"| {fmt(r['tl_err'][1], '.2e')} | {fmt(r['pp_err'][1] if r['pp_err'] else None, '.2e')} "
              f"| {sph(r['tl_sph'])} | {sph(r['pp_sph'])} |")
    print("\nexact-mmp: one run per source, the query column is the whole call "
          "(construction and propagation).")

    if exact_rows:
        print("\n## Exact distances: Tapeline exact-mmp and libigl exact_geodesic "
              "(one source per call, all vertices as targets; median over the 3 sources)\n")
        print("| mesh | V | tapeline s | libigl s | ratio T/L "
              "| max abs difference / max distance | vs great circle max tapeline "
              "| vs great circle max libigl |")
        print("|---|---:|---:|---:|---:|---:|---:|---:|")
        for r in exact_rows:
            print(f"| {r['mesh']} | {r['n']} | {r['tl']:.4f} | {r['igl']:.4f} "
                  f"| {fmt(ratio(r['tl'], r['igl']), '.2f')} | {r['diff']:.2e} "
                  f"| {fmt(r['tl_sph'], '.2e')} | {fmt(r['igl_sph'], '.2e')} |")

    print("\n## Per source: max |d - exact| / max(exact)\n")
    print("| mesh | method | source | tapeline | pp3d |")
    print("|---|---|---:|---:|---:|")
    by_key = {}
    for name, label, s, lib, e in source_rows:
        by_key.setdefault((name, label, s), {})[lib] = e[1]
    for (name, label, s), e in by_key.items():
        print(f"| {name} | {label} | {s} | {fmt(e.get('tl'), '.2e')} | {fmt(e.get('pp'), '.2e')} |")

    if path_rows:
        print("\n## Paths between vertex pairs (length error relative to the exact length)\n")
        print("| mesh | pair | exact length | exact s (once) | curvature flow rel. err "
              "| edge flip rel. err | curvature flow s/path | edge flip s/path | path ratio T/P "
              "| setup s curvature flow (once) | setup s edge flip | great circle |")
        print("|---|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|")
        for r in path_rows:
            e_flow = (r["L_flow"] - r["L_ex"]) / r["L_ex"]
            e_flip = None if r["L_flip"] is None else (r["L_flip"] - r["L_ex"]) / r["L_ex"]
            print(f"| {r['mesh']} | {r['pair'][0]}–{r['pair'][1]} | {r['L_ex']:.6f} "
                  f"| {r['t_ex']:.3f} | {e_flow:.2e} | {fmt(e_flip, '.2e')} | {r['t_flow']:.4f} "
                  f"| {fmt(r['t_flip'])} | {fmt(ratio(r['t_flow'], r['t_flip']), '.2f')} "
                  f"| {r['flow_setup']:.4f} | {fmt(r['flip_setup'])} "
                  f"| {fmt(r['L_gc'], '.6f')} |")

    print("\nmax cpu/wall of the timed calls (about 1: one thread): "
          + ", ".join(f"{lib} {c.max_ratio:.2f}" for lib, c in CLOCK.items()
                      if lib == "tapeline" or (lib == "potpourri3d" and pp3d is not None)
                      or (lib == "libigl" and igl is not None)))
    print(f"load average at end {os.getloadavg()[0]:.2f}")


if __name__ == "__main__":
    main()
