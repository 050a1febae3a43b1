#!/usr/bin/python3
"""One command for every figure of docs/results.md: the thesis's four geodesic claims, the exact
MMP against CGAL, measurement, grading, drape and fabric figures, and the peers' rows. Called by
benchmarks/reproduce.sh (see `benchmarks/reproduce.sh --help` and docs/benchmarks.md).

Each part runs the tool (`tapeline bench geodesic`, `geodesic distances`, `measure`, `grade`,
`dress`, `fabric test`) and the existing report scripts of benchmarks/scripts/ at the sizes of the
chosen mode, into a staging folder; results.md and results/ are moved into place only at the end,
so an interrupted run leaves the previous results as they were. A part that fails is reported in
results.md with its error and the command exits 1. Exit status 2: a bad option or a tool that does
not run (one line on stderr, nothing written).
"""
import argparse
import datetime
import hashlib
import json
import math
import os
import platform
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

HERE = os.path.dirname(os.path.abspath(__file__))
ROOT = os.path.dirname(os.path.dirname(HERE))
sys.path.insert(0, HERE)
import bench_report as br  # noqa: E402  (the JSON-line reader, exponent fit, tables and plots)
from subdivide_obj import read_obj  # noqa: E402

PROG = "reproduce.sh"
SEED = 1
THREADS = 1

# Sizes per mode. smoke: CI (about a minute); quick: <= 30 min on 2 cores; full: the complete
# figures (hours), the sizes of the run_*.sh scripts.
SIZES = {
    "smoke": dict(
        timeout=120, memory_gb=4,
        a_ico=[1, 2, 3], a_spot=[0, 1], a_repeat=1,
        b_meshes=["icosphere:2"], b_windows=[4, 8],
        c_levels=[1, 2], c_sources=1,
        d_meshes=["icosphere:2"], d_noise=[0.0, 0.005], d_sources=1,
        mmp_surfaces=["icosphere:2"], mmp_sources=1, mmp_repeat=1,
        measure_bodies=["repo"], synthetic=["body:40,10"], population=None,
        grading=[("aaron", "36", "42")],
        drape=(["gc_shirt"], 30), drape_body="repo",
        fabrics=["cotton_jersey"], fabric_tests=[("cantilever", 20), ("cusick", 20),
                                                 ("cusick", 10)],
        wrinkles=dict(bending=[4, 32], resolution=4),
    ),
    "quick": dict(
        timeout=900, memory_gb=8,
        a_ico=[3, 4, 5, 6, 7], a_spot=[0, 1, 2, 3], a_repeat=3,
        b_meshes=["icosphere:3", "icosphere:4", "spot"], b_windows=[2, 4, 8, 16, 32],
        c_levels=[2, 3, 4, 5], c_sources=2,
        d_meshes=["icosphere:4", "ellipsoid:1,1,0.5:4:0.3", "spot"],
        d_noise=[0.0, 0.001, 0.005], d_sources=2,
        mmp_surfaces=["icosphere:4", "icosphere:5", "ellipsoid:1,0.6,0.3:4:0.25",
                      "ellipsoid:1,0.6,0.3:5:0.25"], mmp_sources=2, mmp_repeat=3,
        measure_bodies=["mh_female_average", "mh_male_average"],
        synthetic=["body:40,10", "body:96,4"], population="dev",
        grading=[(d, a, b) for d in ("aaron", "brian", "simon", "teagan", "titan")
                 for a, b in (("36", "42"), ("42", "36"))],
        drape=(["gc_shirt", "fs_teagan"], 20), drape_body="mh_female_average",
        fabrics="all", fabric_tests=[("cantilever", 20), ("cantilever", 10), ("tensile", 5),
                                     ("bias", 5), ("cusick", 20), ("cusick", 10)],
        wrinkles=dict(bending=[0.5, 2, 8, 32], resolution=2.5),
    ),
    "full": dict(
        timeout=1800, memory_gb=16,
        a_ico=[3, 4, 5, 6, 7, 8], a_spot=[0, 1, 2, 3, 4], a_repeat=5,
        b_meshes=["icosphere:3", "icosphere:4", "icosphere:5", "spot", "fandisk"],
        b_windows=[2, 4, 8, 16, 32, 64],
        c_levels=[2, 3, 4, 5, 6], c_sources=3,
        d_meshes=["icosphere:5", "ellipsoid:1,1,0.5:5:0.3", "spot"],
        d_noise=[0.0, 0.001, 0.005, 0.01], d_sources=3,
        mmp_surfaces=["icosphere:5", "icosphere:6", "icosphere:7", "ellipsoid:1,0.6,0.3:5:0.25",
                      "ellipsoid:1,0.6,0.3:6:0.25", "ellipsoid:1,0.6,0.3:7:0.25"],
        mmp_sources=3, mmp_repeat=3,
        measure_bodies=["mh_female_average", "mh_male_average"],
        synthetic=["body:40,10", "body:96,4", "body:128,3"], population="all",
        grading=[(d, a, b) for d in ("aaron", "brian", "simon", "teagan", "titan")
                 for a, b in (("36", "42"), ("42", "36"))],
        drape=(["gc_shirt", "gc_dress_pencil", "gc_hoody_without_hood", "gc_jumpsuit",
                "fs_aaron_without_bindings", "fs_brian", "fs_teagan", "fs_simon", "fs_titan"],
               10), drape_body="bundled",
        fabrics="all", fabric_tests=[("cantilever", 20), ("cantilever", 10), ("cantilever", 5),
                                     ("tensile", 5), ("bias", 5), ("cusick", 20),
                                     ("cusick", 10)],
        wrinkles=dict(bending=[0.5, 1, 2, 5, 10, 20, 50], resolution=2.5),
    ),
}


class PartError(Exception):
    """A part could not produce its figures; the message goes into results.md."""


class UsageError(Exception):
    """A bad option: one line on stderr, exit 2, nothing written."""


def say(msg):
    print("%s: %s" % (PROG, msg), file=sys.stderr, flush=True)


# --------------------------------------------------------------------------------------------
# Running commands


def run(cmd, stdout_path=None):
    """Run a command; its stderr goes through to ours (progress), its last lines are kept for
    the error message. Returns stdout as text (or writes it to stdout_path)."""
    out = open(stdout_path, "w") if stdout_path else subprocess.PIPE
    try:
        p = subprocess.Popen([str(c) for c in cmd], stdout=out, stderr=subprocess.PIPE, text=True)
    except OSError as e:
        raise PartError("cannot run %s: %s" % (cmd[0], e.strerror))
    tail = []
    for line in p.stderr:
        sys.stderr.write(line)
        tail = (tail + [line.rstrip()])[-5:]
    text = p.stdout.read() if not stdout_path else ""
    p.wait()
    if stdout_path:
        out.close()
    if p.returncode != 0:
        last = next((t for t in reversed(tail) if t.strip()), "no message")
        raise PartError("`%s` exited with status %d: %s" % (
            " ".join(os.path.basename(str(c)) if i == 0 else str(c)
                     for i, c in enumerate(cmd[:4])) + " ...", p.returncode, last))
    return text


def read_jsonl(path):
    with open(path) as f:
        return [json.loads(line) for line in f if line.strip()]


def write_jsonl(path, rows):
    with open(path, "w") as f:
        for r in rows:
            f.write(json.dumps(r, sort_keys=True) + "\n")


# --------------------------------------------------------------------------------------------
# Statistics


T975 = {1: 12.706, 2: 4.303, 3: 3.182, 4: 2.776, 5: 2.571, 6: 2.447, 7: 2.365, 8: 2.306,
        9: 2.262, 10: 2.228}


def t975(dof):
    try:
        from scipy.stats import t
        return float(t.ppf(0.975, dof))
    except ImportError:
        return T975.get(dof, 1.96 + 2.5 / dof)


def fit_with_ci(points):
    """OLS of log(y) = k log(V) + b; returns (k, lo, hi, r2, n) with the 95 % confidence
    interval of k (Student t, n - 2 degrees of freedom), lo/hi None below three points."""
    fit = br.fit_exponent(points)
    if fit is None:
        return None
    k, r2, pts = fit
    n = len(pts)
    xs = [math.log(v) for v, _ in pts]
    ys = [math.log(y) for _, y in pts]
    mx, my = sum(xs) / n, sum(ys) / n
    sxx = sum((x - mx) ** 2 for x in xs)
    if n < 3:
        return k, None, None, r2, n
    ss = sum((y - (my + k * (x - mx))) ** 2 for x, y in zip(xs, ys))
    se = math.sqrt(ss / (n - 2) / sxx)
    h = t975(n - 2) * se
    return k, k - h, k + h, r2, n


def fmt(x, spec="%.3g"):
    return "–" if x is None or (isinstance(x, float) and not math.isfinite(x)) else spec % x


def md_cell(c):
    return str(c).replace("\\", "\\\\").replace("|", "\\|").replace("\n", " ")


def md_table(header, rows):
    lines = ["| " + " | ".join(md_cell(h) for h in header) + " |", "|" + "---|" * len(header)]
    for r in rows:
        lines.append("| " + " | ".join(md_cell(c) for c in r) + " |")
    return "\n".join(lines)


# --------------------------------------------------------------------------------------------
# Context: options, folders, provenance


class Context:
    def __init__(self, args):
        self.mode = args.mode
        self.size = SIZES[args.mode]
        self.tool = os.path.abspath(args.tool)
        self.tool_given = self.tool
        self.data = os.path.abspath(args.data)
        self.peers = os.path.abspath(args.peers) if args.peers else None
        self.out = os.path.abspath(args.out)
        self.only = args.only
        self.argv = args.argv
        self.stage = None
        self.work = None
        self.meta = {}
        self.peer_tool = None
        self.peer_git = None

    def part_dir(self, key):
        d = os.path.join(self.stage, "results", key)
        os.makedirs(d, exist_ok=True)
        return d

    def bench(self, args, out):
        s = self.size
        run([self.tool, "--progress", "bench", "geodesic", "--seed", SEED, "--threads", THREADS,
             "--timeout", s["timeout"], "--memory-limit", s["memory_gb"]] + args + ["--out", out])
        return read_jsonl(out)

    def shared(self, *parts):
        return os.path.join(self.data, *parts)

    def mesh_arg(self, name):
        """A mesh of the benchmarks by name: an analytic spec, the repository's spot or a shared
        mesh (None when the shared data is absent)."""
        if ":" in name:
            return ["--surface", name]
        if name == "spot":
            return ["--mesh", os.path.join(ROOT, "data", "spot.obj")]
        for ext in (".obj", ".off", ".ply"):
            p = self.shared("meshes", name + ext)
            if os.path.exists(p):
                return ["--mesh", p]
        return None

    def provenance_line(self):
        m = self.meta
        return ("_Provenance: repository git %s; tool %s (git %s); compiler %s; flags `%s`; "
                "threads %d; machine %s, %d cores; date %s; mode %s, seed %d._" % (
                    m["repo_git"], os.path.relpath(self.tool_given, ROOT)
                    if self.tool_given.startswith(ROOT + os.sep) else self.tool_given,
                    m["tool_git"], m["compiler"], m["flags"], THREADS, m["cpu"],
                    m["cores"], m["date"], self.mode, SEED))


def cpu_model():
    try:
        with open("/proc/cpuinfo") as f:
            for line in f:
                if line.lower().startswith("model name"):
                    return line.split(":", 1)[1].strip()
    except OSError:
        pass
    return platform.processor() or platform.machine() or "unknown"


def repo_git():
    try:
        rev = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short=12", "HEAD"],
                             capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", ROOT, "status", "--porcelain", "--untracked-files=no",
                                "--", ".", ":!docs/results", ":!docs/results.md"],
                               capture_output=True, text=True).stdout.strip()
        return rev + ("-dirty" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        return "unknown (not a git checkout)"


def probe_tool(ctx, work):
    """One tiny benchmark run: does the tool run, and what build is it (git, compiler, flags)."""
    out = os.path.join(work, "probe.jsonl")
    try:
        p = subprocess.run([ctx.tool, "--quiet", "bench", "geodesic", "--surface", "icosphere:0",
                            "--methods", "dijkstra", "--reference", "none", "--out", out],
                           capture_output=True, text=True, timeout=120)
    except (OSError, subprocess.TimeoutExpired) as e:
        raise UsageError("--tool %s does not run: %s" % (ctx.tool, getattr(e, "strerror", e)))
    if p.returncode != 0 or not os.path.exists(out):
        raise UsageError("--tool %s does not run `bench geodesic` (exit %d)" %
                         (ctx.tool, p.returncode))
    rec = read_jsonl(out)[0]
    # The run uses a copy of the tool, so that a rebuild meanwhile cannot mix two builds.
    ctx.tool_given = ctx.tool
    ctx.tool = os.path.join(work, "tapeline")
    shutil.copy2(ctx.tool_given, ctx.tool)
    cf = rec.get("compiler_flags") or "unknown"
    m = re.match(r"^(.*?)\s+(-.*)$", cf)
    compiler, flags = (m.group(1).strip(), m.group(2).strip()) if m else (cf, "")
    ctx.meta = dict(repo_git=repo_git(), tool_git=rec.get("git") or "unknown",
                    compiler=compiler, flags=flags or "none", cpu=cpu_model(),
                    cores=os.cpu_count() or 1,
                    date=datetime.datetime.now(datetime.timezone.utc).strftime(
                        "%Y-%m-%d %H:%M UTC"))


def pyplot():
    return br.import_pyplot()


def bench_report(jsonl_paths, out_dir, title):
    run(["/usr/bin/python3", os.path.join(HERE, "bench_report.py")] + list(jsonl_paths) +
        ["--out-dir", out_dir, "--title", title])


# --------------------------------------------------------------------------------------------
# Parts. Each returns a dict: table (Markdown), plot (file name in its folder or None), verdict
# ("holds", "does not hold", "undecided", "figure", "not run", ...), figure (one line with the
# number), notes (Markdown), links [(label, file)].


def part_a(ctx, d):
    """(a) Algorithm 2 in linear time: gcf-window:8 (and Dijkstra, O(n log n), fitted the same
    way) against |V| on icospheres and on spot under midpoint subdivision."""
    s = ctx.size
    meshes = []
    for lv in s["a_ico"]:
        meshes += ["--surface", "icosphere:%d" % lv]
    spot_files = {}
    for k in s["a_spot"]:
        f = os.path.join(ctx.work, "spot_x%d.obj" % (4 ** k))
        if k == 0:
            shutil.copy(os.path.join(ROOT, "data", "spot.obj"), f)
        else:
            run(["/usr/bin/python3", os.path.join(HERE, "subdivide_obj.py"),
                 os.path.join(ROOT, "data", "spot.obj"), f, k])
        spot_files[os.path.basename(f)] = f
        meshes += ["--mesh", f]
    raw = os.path.join(d, "linear_time.jsonl")
    recs = ctx.bench(["--methods", "gcf-window:8,dijkstra", "--reference", "none", "--sources",
                      1, "--repeat", s["a_repeat"]] + meshes, raw)
    for r in recs:  # the subdivided copies of spot are one family; paths relative to the run
        if r.get("mesh") in spot_files:
            r["family"] = "spot-subdivided"
            r["mesh_file"] = os.path.basename(r["mesh_file"] or r["mesh"])
    write_jsonl(raw, recs)
    bench_report([raw], d, "(a) Algorithm 2 (gcf-window:8) time against |V|")
    groups = {}
    for r in recs:
        if r["status"] == "ok":
            groups.setdefault((r["family"], r["method"]), {}).setdefault(
                r["vertices"], []).append(r["query_seconds"])
    rows, fits, verdicts = [], {}, []
    for (fam, method), per in sorted(groups.items()):
        pts = [(v, statistics.median(ts)) for v, ts in sorted(per.items())]
        f = fit_with_ci(pts)
        fits[(fam, method)] = (pts, f)
        if f is None:
            rows.append([fam, method, len(pts), "–", "–", "–", "–"])
            continue
        k, lo, hi, r2, n = f
        rows.append([fam, method, n, "%d–%d" % (pts[0][0], pts[-1][0]), "%.3f" % k,
                     "[%s, %s]" % (fmt(lo, "%.3f"), fmt(hi, "%.3f")), "%.3f" % r2])
        if method == "gcf-window:8":
            verdicts.append((fam, k, lo, hi))
    bad = [r for r in recs if r["status"] != "ok"]
    table = md_table(["family", "method", "meshes", "|V| range", "time exponent k",
                      "time k 95 % CI", "time fit R²"], rows)
    # Verdict: linear when the upper end of the CI is at most 1.15 on every family.
    if not verdicts or any(lo is None for _, _, lo, _ in verdicts):
        verdict = "undecided"
    elif all(hi <= 1.15 for _, _, _, hi in verdicts):
        verdict = "holds"
    elif any(lo > 1.15 for _, _, lo, _ in verdicts):
        verdict = "does not hold"
    else:
        verdict = "undecided"
    timing_figure = "; ".join("%s k = %.2f [%s, %s]" % (fam, k, fmt(lo, "%.2f"),
                                                        fmt(hi, "%.2f"))
                              for fam, k, lo, hi in verdicts) or "no fit"
    figure = "time exponent of gcf-window:8 with its 95 % CI: " + timing_figure
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for (fam, method), (pts, f) in sorted(fits.items()):
        vs, ts = [p[0] for p in pts], [p[1] for p in pts]
        label = "%s, %s" % (method, fam) + ("" if f is None else " k=%.2f" % f[0] + (
            "" if f[1] is None else " [%.2f, %.2f]" % (f[1], f[2])))
        ax.loglog(vs, ts, "o-" if method.startswith("gcf") else "s--", label=label)
    ax.set_xlabel("|V|")
    ax.set_ylabel("median query time, s")
    ax.set_title("(a) time against |V| (threads %d)" % THREADS)
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "claim.png"), dpi=110)
    plt.close(fig)
    notes = ("Query time (`query_seconds`, median of %d repetitions, one source, seed %d) of "
             "gcf-window:8 (Algorithm 2, W = 8) and of Dijkstra (O(n log n)) on icospheres %s and "
             "on spot under midpoint subdivision (`subdivide_obj.py`, %s); k is fitted by least "
             "squares on the per-mesh medians, the interval is the 95 %% Student-t interval of the "
             "slope. Verdict rule: holds when the upper end of the interval is at most 1.15 on "
             "every family, does not hold when its lower end is above 1.15. Over 10³–10⁵ vertices "
             "V log V fits k ≈ 1.1, so this rule does not tell V from V log V.%s" % (
                 s["a_repeat"], SEED, ", ".join(str(x) for x in s["a_ico"]),
                 ", ".join("×%d" % 4 ** k for k in s["a_spot"]),
                 "" if not bad else " Runs not ok: %d (see table.md)." % len(bad)))
    return dict(table=table, plot="claim.png", verdict=verdict, figure="–",
                timing_figure=figure, notes=notes,
                links=[("all runs", "table.md"), ("time plot", "query_time_vs_vertices.png"),
                       ("JSON lines", "linear_time.jsonl")])


def obj_mesh_stats(path):
    """|V| and the mean edge length of a triangle OBJ."""
    pts, tris = read_obj(path)
    edges = {(min(a, b), max(a, b)) for t in tris for a, b in ((t[0], t[1]), (t[1], t[2]),
                                                                  (t[2], t[0]))}
    total = sum(math.dist(pts[a], pts[b]) for a, b in edges)
    return len(pts), total / len(edges)


def read_distances(path):
    with open(path) as f:
        return [float(x) for x in f.read().split()]


def part_b(ctx, d):
    """(b) |d_W - d_whole| per window against the O(eps m) bound."""
    s = ctx.size
    rows, series, missing, ratio_values = [], {}, [], []
    for name in s["b_meshes"]:
        arg = ctx.mesh_arg(name)
        if arg is None:
            missing.append(name)
            continue
        obj = os.path.join(ctx.work, "b_%s.obj" % re.sub(r"[^A-Za-z0-9]+", "_", name))
        if arg[0] == "--surface":
            run([ctx.tool, "--quiet", "mesh", "generate", name, "--out", obj])
        elif arg[1].endswith(".obj"):
            shutil.copy(arg[1], obj)
        else:  # h̄ is read from an OBJ here
            missing.append(name + " (not an OBJ)")
            continue
        nv, hbar = obj_mesh_stats(obj)
        say("(b) %s: gcf-exact (Algorithm 1, the whole-path flow)" % name)
        whole_f = os.path.join(ctx.work, "whole.txt")
        run([ctx.tool, "--quiet", "geodesic", "distances", obj, "--source", 0, "--method",
             "gcf-exact", "--out", whole_f])
        whole = read_distances(whole_f)
        far = max((i for i in range(len(whole)) if math.isfinite(whole[i])),
                  key=lambda i: whole[i])
        path_json = os.path.join(ctx.work, "path.json")
        run([ctx.tool, "--quiet", "geodesic", "path", obj, "--from", 0, "--to", far, "--out",
             path_json, "--svg", os.path.join(ctx.work, "path.svg")])
        m_faces = json.load(open(path_json)).get("unfold", {}).get("faces")
        for w in s["b_windows"]:
            say("(b) %s: gcf-window:%d" % (name, w))
            wf = os.path.join(ctx.work, "window.txt")
            run([ctx.tool, "--quiet", "geodesic", "distances", obj, "--source", 0, "--method",
                 "gcf-window:%d" % w, "--out", wf])
            dw = read_distances(wf)
            diffs = [abs(a - b) for a, b in zip(dw, whole) if math.isfinite(a) and
                     math.isfinite(b)]
            mx, mean = max(diffs), statistics.mean(diffs)
            eps_needed = mx / (m_faces * hbar) if m_faces else None
            # The bound's terms as the library computes them for this run (bench line: epsilon,
            # max_faces, error_bound = epsilon * max_faces * mean edge), from vertex 0 too.
            bl = os.path.join(ctx.work, "bound.jsonl")
            run([ctx.tool, "--quiet", "bench", "geodesic", "--mesh", obj, "--methods",
                 "gcf-window:%d" % w, "--sources", 1, "--repeat", 1, "--reference", "none",
                 "--seed", SEED, "--threads", THREADS, "--timeout", s["timeout"], "--out", bl])
            line = json.loads(open(bl).read().splitlines()[0])
            if line.get("source") != 0 or line.get("status") != "ok":
                raise PartError("bench geodesic on %s, gcf-window:%d: source %s, status %s" % (
                    name, w, line.get("source"), line.get("status")))
            eps, m, bound = line.get("epsilon"), line.get("max_faces"), line.get("error_bound")
            if bound is None:
                raise PartError("the tool's bench lines carry no error_bound (an older tool?)")
            ratio = mx / bound if bound > 0 else (0.0 if mx == 0 else math.inf)
            ratio_values.append(ratio)
            rows.append([name, nv, "%.4g" % hbar, w, "%.3e" % mx, "%.3e" % mean,
                         "%.3f" % (mx / hbar), fmt(m_faces, "%d"), fmt(eps_needed, "%.2e"),
                         "%.3e" % eps, "%d" % m, "%.3e" % bound,
                         fmt(ratio, "%.3f") if math.isfinite(ratio) else "∞ (bound 0)"])
            series.setdefault(name, []).append((w, mx / hbar, bound / hbar))
    if not rows:
        raise PartError("no mesh available (missing: %s)" % ", ".join(missing))
    table = md_table(["mesh", "|V|", "h̄ (mean edge)", "W", "max |d_W − d_whole|",
                      "mean |d_W − d_whole|", "max / h̄", "m̂ (faces, exact path to the farthest "
                      "vertex)", "ε needed for constant 1: max / (m̂ h̄)", "ε (library)",
                      "m (library)", "bound ε·m·h̄", "max / bound"], rows)
    with open(os.path.join(d, "window_error.json"), "w") as f:
        json.dump({"header": ["mesh", "vertices", "mean_edge", "window", "max_abs", "mean_abs",
                              "max_over_mean_edge", "m_hat", "eps_needed", "epsilon",
                              "max_faces", "error_bound", "max_over_bound"],
                   "rows": rows}, f, indent=1)
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for name, pts in series.items():
        line = ax.semilogy([p[0] for p in pts], [max(p[1], 1e-12) for p in pts], "o-",
                           label=name + " measured")[0]
        ax.semilogy([p[0] for p in pts], [max(p[2], 1e-12) for p in pts], "--",
                    color=line.get_color(), label=name + " bound ε·m")
    ax.set_xscale("log", base=2)
    ax.set_xlabel("window W (samples)")
    ax.set_ylabel("max |d_W − d_whole| / mean edge; bound ε·m")
    ax.set_title("(b) windowed against whole-path flow (source 0)")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "claim.png"), dpi=110)
    plt.close(fig)
    w8 = [r for r in rows if r[3] == 8] or rows
    worst = max(ratio_values)  # inf: a nonzero difference where the bound is 0
    verdict = "holds" if worst <= 1 else "does not hold"
    figure = ("max |d_W − d_whole| / (ε·m·h̄), largest over meshes and windows: %.3f "
              "(rule: ≤ 1, constant 1); at W = %d: %s" % (
                  worst, w8[0][3], ", ".join("%s %s" % (r[0], r[12]) for r in w8)))
    notes = ("d_whole: `tapeline geodesic distances --method gcf-exact` (Algorithm 1, the flow of "
             "the whole path); d_W: `--method gcf-window:W` (Algorithm 2), both Phong-lifted length, "
             "from vertex 0, every vertex compared. h̄: mean edge length of the mesh. The bound "
             "needs ε (the largest length excess a fixed anchor leaves, in mean edge lengths) and "
             "m (the most faces one vertex's path covers); the library computes both for the run "
             "(`CurvatureFlowDistanceReport::epsilon`, `max_faces`, `error_bound` = ε·m·h̄), "
             "read here from the `bench geodesic` line of the same window and source. Verdict "
             "rule: holds when the measured maximum is within the bound with constant 1 on every "
             "mesh and window (O(εm) allows any constant: a ratio above 1 says which constant "
             "the data need). m̂, a cross-check of m: the faces the exact polyhedral path to the "
             "farthest vertex crosses (`geodesic path --svg`), and the ε the bound would need "
             "with it.%s" % ("" if not missing else " Not available: %s." % ", ".join(missing)))
    return dict(table=table, plot="claim.png", verdict=verdict, figure=figure, notes=notes,
                links=[("per-window numbers (JSON)", "window_error.json")])


def part_c(ctx, d):
    """(c) Algorithm 1 closer to the smooth surface than exact polyhedral geodesics."""
    s = ctx.size
    meshes = []
    for lv in s["c_levels"]:
        meshes += ["--surface", "icosphere:%d" % lv, "--surface", "ellipsoid:1,1,0.5:%d:0.25" % lv]
    raw = os.path.join(d, "smooth.jsonl")
    recs = ctx.bench(["--methods", "exact-mmp,gcf-exact,gcf-window:8", "--reference", "exact-mmp",
                      "--sources", s["c_sources"], "--repeat", 1] + meshes, raw)
    bench_report([raw], d, "(c) Algorithm 1 against the smooth truth and exact MMP")
    err = {}
    for r in recs:
        if r["status"] == "ok" and r.get("mean_rel_error_truth") is not None:
            err.setdefault((r["family"], r["mesh"], r["vertices"]), {}).setdefault(
                r["method"], []).append((r["mean_rel_error_truth"], r["max_rel_error_truth"]))
    rows, ratios, plotdata = [], [], {}
    for (fam, mesh, nv), per in sorted(err.items(), key=lambda x: (x[0][0], x[0][2])):
        def mean_of(method, i):
            v = per.get(method)
            return statistics.mean(x[i] for x in v) if v else None
        mmp, gcf, win = mean_of("exact-mmp", 0), mean_of("gcf-exact", 0), mean_of("gcf-window:8", 0)
        ratio = gcf / mmp if gcf is not None and mmp else None
        wratio = win / mmp if win is not None and mmp else None
        if ratio is not None:
            ratios.append((mesh, ratio))
        truth = next(r["truth"] for r in recs if r["mesh"] == mesh and r.get("truth"))
        rows.append([fam, mesh, nv, truth.split(" (")[0], fmt(mmp, "%.2e"), fmt(gcf, "%.2e"),
                     fmt(ratio, "%.3f"), fmt(mean_of("gcf-exact", 1), "%.2e"),
                     fmt(mean_of("exact-mmp", 1), "%.2e"), fmt(wratio, "%.3f")])
        for m, v in (("exact-mmp", mmp), ("gcf-exact", gcf), ("gcf-window:8", win)):
            if v is not None:
                plotdata.setdefault((fam, m), []).append((nv, v))
    if not ratios:
        raise PartError("no run with an error against the smooth truth")
    table = md_table(["family", "mesh", "|V|", "truth", "exact-mmp mean rel err vs truth",
                      "gcf-exact mean rel err vs truth", "ratio gcf-exact / exact-mmp",
                      "gcf-exact max rel err vs truth", "exact-mmp max rel err vs truth",
                      "ratio gcf-window:8 / exact-mmp"], rows)
    worst = max(ratios, key=lambda x: x[1])
    verdict = "holds" if worst[1] < 1 else "does not hold"
    figure = "error ratio gcf-exact / exact-mmp against the smooth truth: %.3f to %.3f " \
             "(largest on %s)" % (min(r for _, r in ratios), worst[1], worst[0])
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4.5))
    for (fam, m), pts in sorted(plotdata.items()):
        pts.sort()
        ax.loglog([p[0] for p in pts], [p[1] for p in pts],
                  {"exact-mmp": "s--", "gcf-exact": "o-", "gcf-window:8": "^:"}[m],
                  label="%s, %s" % (m, fam))
    ax.set_xlabel("|V|")
    ax.set_ylabel("mean relative error against the smooth distance")
    ax.set_title("(c) error against the smooth surface under refinement")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "claim.png"), dpi=110)
    plt.close(fig)
    notes = ("Mean over %d source(s) (vertex 0, then seeded) of the mean relative error against "
             "the smooth distance: the great circle on the icosphere, GeographicLib's "
             "GeodesicExact on the ellipsoid of revolution (1, 1, 0.5; tangential jitter 0.25), "
             "levels %s. exact-mmp is the exact polyhedral distance. Verdict rule: holds when the "
             "ratio is below 1 on every mesh." % (s["c_sources"],
                                                 ", ".join(map(str, s["c_levels"]))))
    return dict(table=table, plot="claim.png", verdict=verdict, figure=figure, notes=notes,
                links=[("all runs", "table.md"), ("JSON lines", "smooth.jsonl")])


def part_d(ctx, d):
    """(d) Algorithm 3 on point clouds: error against exact on the source mesh, with noise."""
    s = ctx.size
    meshes, missing = [], []
    for name in s["d_meshes"]:
        a = ctx.mesh_arg(name)
        if a is None:
            missing.append(name)
        else:
            meshes += a
    raw = os.path.join(d, "points.jsonl")
    recs = []
    for noise in s["d_noise"]:
        part = os.path.join(ctx.work, "points_part.jsonl")
        say("(d) noise %g" % noise)
        lines = ctx.bench(["--methods", "exact-mmp,gcf-points", "--reference", "exact-mmp",
                           "--sources", s["d_sources"], "--repeat", 1, "--noise", noise] + meshes,
                          part)
        for r in lines:
            if noise > 0 and r["method"].startswith("gcf-points"):
                r["method"] += "/noise%g%%" % (100 * noise)
            if noise > 0 and r["method"] == "exact-mmp":
                continue  # the reference is the same at every noise level
            r["noise_sigma"] = noise
            recs.append(r)
    write_jsonl(raw, recs)
    bench_report([raw], d, "(d) Algorithm 3 (gcf-points) against exact MMP on the source mesh")
    agg = {}
    for r in recs:
        if r["method"].startswith("gcf-points"):
            agg.setdefault((r["mesh"], r["vertices"], r["noise_sigma"]), []).append(r)
    rows, clean, plotdata = [], [], {}
    for (mesh, nv, noise), rs in sorted(agg.items()):
        ok = [r for r in rs if r["status"] == "ok"]
        mean = statistics.mean(r["mean_rel_error"] for r in ok) if ok else None
        mx = max(r["max_rel_error"] for r in ok) if ok else None
        tr = [r["mean_rel_error_truth"] for r in ok if r.get("mean_rel_error_truth") is not None]
        rows.append([mesh, nv, "%g %%" % (100 * noise), "%d/%d" % (len(ok), len(rs)),
                     fmt(mean, "%.2e"), fmt(mx, "%.2e"),
                     fmt(statistics.mean(tr) if tr else None, "%.2e")])
        if noise == 0:
            clean.append((mesh, mean, len(ok) == len(rs)))
        if mean is not None:
            plotdata.setdefault(mesh, []).append((100 * noise, mean))
    table = md_table(["mesh", "points", "noise σ (of the bbox diagonal)", "runs ok/total",
                      "mean rel err vs exact", "max rel err vs exact", "mean rel err vs truth"],
                     rows)
    if not clean:
        verdict, figure = "undecided", "no clean run"
    else:
        worst = max(clean, key=lambda c: c[1] if c[1] is not None else math.inf)
        good = all(ok and m is not None and m <= 0.01 for _, m, ok in clean)
        verdict = "holds" if good else "does not hold"
        figure = "clean points: mean rel err vs exact at most %s (%s); with noise: %s" % (
            fmt(worst[1], "%.2e"), worst[0], ", ".join(
                "%s %s" % (r[2], r[4]) for r in rows if r[2] != "0 %" and r[0] == worst[0]))
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6.5, 4.2))
    for mesh, pts in plotdata.items():
        xs = [max(p[0], 0.01) for p in pts]
        ax.loglog(xs, [p[1] for p in pts], "o-", label=mesh)
    ax.set_xlabel("noise σ, % of the bounding-box diagonal (0 drawn at 0.01)")
    ax.set_ylabel("mean relative error against exact MMP")
    ax.set_title("(d) gcf-points against the exact distance on the source mesh")
    ax.grid(True, which="both", alpha=0.3)
    ax.legend(fontsize=8)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "claim.png"), dpi=110)
    plt.close(fig)
    notes = ("gcf-points (Algorithm 3, MLS projection, default cell and d = 16) on the vertices of "
             "each mesh taken as a point cloud, with seeded Gaussian noise; errors against exact "
             "MMP on the clean source mesh, at the clean vertices. Verdict rule: holds when every "
             "clean run is ok with a mean relative error of at most 1 %%.%s" % (
                 "" if not missing else " Not available: %s." % ", ".join(missing)))
    return dict(table=table, plot="claim.png", verdict=verdict, figure=figure, notes=notes,
                links=[("all runs", "table.md"), ("JSON lines", "points.jsonl")])


def part_mmp(ctx, d):
    """Exact MMP against CGAL's exact shortest paths: time, memory, agreement."""
    s = ctx.size
    meshes = []
    for m in s["mmp_surfaces"]:
        meshes += ["--surface", m]
    raw = os.path.join(d, "exact_mmp.jsonl")
    recs = ctx.bench(["--methods", "exact-mmp,exact-cgal", "--reference", "exact-cgal",
                      "--sources", s["mmp_sources"], "--repeat", s["mmp_repeat"]] + meshes, raw)
    bench_report([raw], d, "Exact geodesics: exact-mmp against exact-cgal")
    by = {}
    for r in recs:
        if r["status"] == "ok":
            by.setdefault((r["mesh"], r["vertices"]), {}).setdefault(r["method"], []).append(r)
    rows, worst, ratios = [], 0.0, []
    for (mesh, nv), per in sorted(by.items(), key=lambda x: (x[0][0].split(":")[0], x[0][1])):
        a, b = per.get("exact-mmp", []), per.get("exact-cgal", [])
        if not a or not b:
            continue
        t = lambda rs: statistics.median(r["pre_seconds"] + r["query_seconds"] for r in rs)
        mem = lambda rs: statistics.median(r["peak_rss_bytes"] for r in rs) / 1e6
        dis = max(r["max_rel_error"] for r in a)
        worst = max(worst, dis)
        ratios.append(t(a) / t(b))
        rows.append([mesh, nv, "%d" % len(a), "%.2e" % dis, "%.3g" % (t(a) / t(b)),
                     "%.3g" % mem(a), "%.3g" % mem(b)])
    if not rows:
        raise PartError("no mesh with both exact-mmp and exact-cgal ok")
    table = md_table(["mesh", "|V|", "runs", "max rel disagreement with exact-cgal",
                      "time ratio exact-mmp / exact-cgal (median)", "peak RSS MB exact-mmp",
                      "peak RSS MB exact-cgal"], rows)
    verdict = "holds" if worst <= 1e-8 else "does not hold"
    figure = "largest relative disagreement %.1e (rule: ≤ 1e-8)" % worst
    notes = ("Both methods from the same sources in one run; agreement is the largest relative "
             "difference at any vertex. Peak RSS includes the process baseline.")
    return dict(table=table, plot="query_time_vs_vertices.png", verdict=verdict, figure=figure,
                timing_figure="time ratio exact-mmp / exact-cgal %.2f to %.2f" % (
                    min(ratios), max(ratios)), notes=notes, links=[("all runs", "table.md"), ("memory", "memory_vs_vertices.png"),
                                    ("JSON lines", "exact_mmp.jsonl")])


def measure_json(ctx, body, out):
    run([ctx.tool, "--quiet", "measure", body, "--units", "dm", "--out", out])
    return json.load(open(out))


def part_measure(ctx, d):
    """Measurement: the synthetic body's exact girths (`mesh generate body --truth-out`); the same
    surface subdivided gives the same girths (run_measure.sh's check); the population
    self-checks (measure_population.py)."""
    s = ctx.size
    rows, diffs, worst = [], {}, 0.0
    for name in s["measure_bodies"]:
        body = (os.path.join(ROOT, "data", "bodies", "mh_female_average.obj") if name == "repo"
                else ctx.shared("bodies", name + ".obj"))
        if not os.path.exists(body):
            rows.append([os.path.basename(body), "–", "–", "–", "–", "skipped: %s not found" %
                         body])
            continue
        x4 = os.path.join(ctx.work, "body_x4.obj")
        run(["/usr/bin/python3", os.path.join(HERE, "subdivide_obj.py"), body, x4])
        say("measure %s and its midpoint subdivision" % os.path.basename(body))
        a = measure_json(ctx, body, os.path.join(ctx.work, "m1.json"))
        b = measure_json(ctx, x4, os.path.join(ctx.work, "m4.json"))
        ga = {m["name"]: m["value_mm"] for m in a["measurements"] if m["kind"] == "girth"}
        gb = {m["name"]: m["value_mm"] for m in b["measurements"] if m["kind"] == "girth"}
        common = sorted(set(ga) & set(gb))
        dd = {k: abs(ga[k] - gb[k]) for k in common}
        for k, v in dd.items():
            diffs[k] = max(diffs.get(k, 0.0), v)
        big = max(dd, key=dd.get)
        worst = max(worst, dd[big])
        rows.append([os.path.basename(body), "%d → %d" % (a["report"]["vertices"],
                                                          b["report"]["vertices"]),
                     len(common), "%.2f (%s)" % (dd[big], big),
                     "%.2f / %.2f" % (a["timings_seconds"]["total"],
                                      b["timings_seconds"]["total"]), "ok"])
    table = md_table(["body", "vertices (1× → 4×)", "girths", "largest girth difference mm",
                      "time s 1× / 4×", "status"], rows)
    srows, synthetic_ok, synthetic_worst = [], True, 0.0
    for spec in s["synthetic"]:
        say("measure the synthetic body %s against its exact girths" % spec)
        mesh = os.path.join(ctx.work, "synthetic.obj")
        truth_path = os.path.join(ctx.work, "synthetic_truth.json")
        run([ctx.tool, "--quiet", "mesh", "generate", spec, "--out", mesh, "--truth-out",
             truth_path])
        out = os.path.join(ctx.work, "synthetic_m.json")
        run([ctx.tool, "--quiet", "measure", mesh, "--units", "mm", "--out", out])
        truth, m = json.load(open(truth_path)), json.load(open(out))
        got = {x["name"]: x["value_mm"] for x in m["measurements"]}
        errs = {g["name"]: (abs(got[g["name"]] - g["value_mm"]) if g["name"] in got else None,
                            g["tolerance_mm"]) for g in truth["girths"]}
        missing = [k for k, (e, _) in errs.items() if e is None]
        outside = [k for k, (e, t) in errs.items() if e is not None and e > t]
        found = {k: v for k, v in errs.items() if v[0] is not None}
        big = max(found, key=lambda k: found[k][0]) if found else None
        synthetic_ok &= not missing and not outside
        synthetic_worst = max([synthetic_worst] + [e for e, _ in found.values()])
        srows.append([spec, m["report"]["vertices"], len(truth["girths"]),
                      "%.2f (%s, tolerance %.2f)" % (found[big][0], big, found[big][1])
                      if big else "–",
                      ", ".join(outside + ["%s missing" % k for k in missing]) or "none",
                      "%.2f" % m["timings_seconds"]["total"]])
    stable = md_table(["synthetic body", "vertices", "girths with exact values",
                       "largest error mm", "outside their tolerance", "time s"], srows)
    pop_line = "Population self-checks: not run at this size."
    if s["population"]:
        if os.path.isdir(ctx.shared("bodies", "population")):
            say("measure the population (%s)" % s["population"])
            pj = os.path.join(d, "population.json")
            run(["/usr/bin/python3", os.path.join(HERE, "measure_population.py"), ctx.tool,
                 ctx.shared("bodies"), os.path.join(d, "population.md"), "--bodies",
                 s["population"], "--json", pj])
            pop = json.load(open(pj))
            ok = [r for r in pop if "error" not in r]
            full = sum(1 for r in ok if r["landmarks_found"] == r["landmarks_total"])
            pop_line = ("Population self-checks (`measure_population.py --bodies %s`, "
                        "[table](population.md)): %d of %d bodies measured, all landmarks found "
                        "on %d, bodies with a missing measurement %d, self-check warnings %d." % (
                            s["population"], len(ok), len(pop), full,
                            sum(1 for r in ok if r["missing"]),
                            sum(len(r["warnings"]) for r in ok)))
        else:
            pop_line = "Population self-checks: skipped, %s not found." % ctx.shared(
                "bodies", "population")
    if not diffs:
        raise PartError("no body found")
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4))
    names = sorted(diffs)
    ax.bar(range(len(names)), [max(diffs[n], 1e-4) for n in names])
    ax.set_yscale("log")
    ax.set_xticks(range(len(names)))
    ax.set_xticklabels([n.replace("_girth", "") for n in names], rotation=70, fontsize=6)
    ax.axhline(4.0, color="r", ls="--", lw=1, label="4 mm (ISO 20685-1 girth tolerance)")
    ax.set_ylabel("|girth 4× − girth 1×|, mm (max over bodies)")
    ax.set_title("Measurement: same surface, 4× the triangles")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "claim.png"), dpi=110)
    plt.close(fig)
    verdict = "holds" if worst <= 4.0 and synthetic_ok else "does not hold"
    notes = ("Synthetic truth: `tapeline mesh generate body:AROUND,RING_MM --out b.obj "
             "--truth-out t.json` writes the analytic body of `measurement/synthetic_body.h` and "
             "the exact perimeters of its sections at the levels its construction defines; "
             "`tapeline measure b.obj --units mm` must give each within what the mesh resolves "
             "(twice the polygon's shortfall, plus one scan step of level where the level comes "
             "from landmarks). Then `tapeline measure BODY --units dm` on each body and on its "
             "midpoint subdivision (`subdivide_obj.py`: the same surface, 4× the triangles); a "
             "girth must not depend on the triangles (rule: at most 4 mm, ISO 20685-1's girth "
             "tolerance). " + pop_line)
    return dict(table=[stable, table], plot="claim.png", verdict=verdict,
                figure="synthetic body: largest girth error %.2f mm%s; largest girth difference "
                "after subdivision %.2f mm" % (synthetic_worst, "" if synthetic_ok else
                                               " (outside its tolerance)", worst), notes=notes,
                links=[("population table", "population.md")] if s["population"] and
                os.path.exists(os.path.join(d, "population.md")) else [])


def part_grading(ctx, d):
    """Grading against FreeSewing's own draft of the target size (run_grading.sh's runs)."""
    s = ctx.size
    data = ctx.shared("patterns", "freesewing")
    if not os.path.isdir(data):
        return dict(table=md_table(["run", "status"], [["all", "skipped: %s not found" % data]]),
                    plot=None, verdict="not run", figure="FreeSewing drafts not found",
                    notes="", links=[])
    sets = os.path.join(data, "measurement_sets.json")
    rows, plot = [], []
    for design, a, b in s["grading"]:
        tag = "%s_%sto%s" % (design, a, b)
        say("grade %s" % tag)
        rep = os.path.join(d, tag + "_report.json")
        run([ctx.tool, "--quiet", "grade", os.path.join(data, "%s_cisFemaleAdult%s.json" % (
            design, a)), "--from", sets, "--from-set", "cisFemaleAdult" + a, "--to", sets,
             "--to-set", "cisFemaleAdult" + b, "--out", os.path.join(ctx.work, tag + ".json"),
             "--report", rep, "--compare", os.path.join(data, "%s_cisFemaleAdult%s.json" % (
                 design, b)), "--threads", THREADS])
        r = json.load(open(rep))
        c = r.get("comparison", [])
        mean = lambda k: statistics.mean(p[k] for p in c) if c else None
        mx = lambda k: max(p[k] for p in c) if c else None
        fit = r["fit"]
        seams = [x["mismatch_mm"] for x in r["seams"]]
        rows.append([tag, len(fit), "%.2f" % max([abs(x["error_mm"]) for x in fit] or [0]),
                     "%.2f" % max(seams) if seams else "n/a (no seams)",
                     "%s / %s" % (fmt(mean("graded_mean_mm"), "%.2f"),
                                  fmt(mx("graded_max_mm"), "%.2f")),
                     "%s / %s" % (fmt(mean("unchanged_mean_mm"), "%.2f"),
                                  fmt(mx("unchanged_max_mm"), "%.2f")),
                     "%s / %s" % (fmt(mean("uniform_oracle_mean_mm"), "%.2f"),
                                  fmt(mx("uniform_oracle_max_mm"), "%.2f")),
                     "%.2f" % r["timings_s"]["total"]])
        plot.append((tag, mean("graded_mean_mm"), mean("unchanged_mean_mm"),
                     mean("uniform_oracle_mean_mm")))
    table = md_table(["run", "bindings", "max binding error mm", "seam mismatch mm",
                      "graded mean / max mm", "unchanged mean / max mm",
                      "uniform oracle mean / max mm", "grading time s"], rows)
    better = sum(1 for _, g, u, _ in plot if g is not None and u is not None and g < u)
    beat_oracle = sum(1 for _, g, _, o in plot if g is not None and o is not None and g < o)
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(7, 4))
    xs = range(len(plot))
    for i, (lab, col) in enumerate((("graded", 1), ("unchanged base", 2),
                                    ("uniform oracle", 3))):
        ax.bar([x + 0.27 * (i - 1) for x in xs], [p[col] or 0 for p in plot], 0.27, label=lab)
    ax.set_xticks(list(xs))
    ax.set_xticklabels([p[0] for p in plot], rotation=60, fontsize=7)
    ax.set_ylabel("outline deviation from FreeSewing's draft, mean mm")
    ax.set_title("Grading against FreeSewing's own draft of the target size")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "claim.png"), dpi=110)
    plt.close(fig)
    return dict(table=table, plot="claim.png",
                verdict="holds" if better == len(plot) else "does not hold",
                figure="graded outline closer to FreeSewing's draft than the unchanged base in "
                       "%d of %d runs; closer than the uniform oracle in %d" % (
                           better, len(plot), beat_oracle),
                notes="`tapeline grade` from cisFemaleAdult36 to 42 and back, seed 42, compared "
                      "with FreeSewing's own draft of the target size (`--compare`): mean over "
                      "pieces / max over pieces of each piece's max outline distance. Verdict "
                      "rule: holds when the graded outline is closer than the unchanged base in "
                      "every run.", links=[])


def part_drape(ctx, d):
    """Drape gates and time (drape_population.py)."""
    s = ctx.size
    patterns, res = s["drape"]
    if not os.path.isdir(ctx.shared("patterns")) or not os.path.isdir(ctx.shared("bodies")):
        return dict(table=md_table(["drape", "status"], [["all", "skipped: %s not found" %
                                                          ctx.data]]),
                    plot=None, verdict="not run", figure="data not found", notes="", links=[])
    body = {"repo": os.path.join(ROOT, "data", "bodies", "mh_female_average.obj"),
            "bundled": "bundled"}.get(s["drape_body"], ctx.shared("bodies", s["drape_body"] +
                                                                  ".obj"))
    js = os.path.join(d, "drape.jsonl")
    run(["/usr/bin/python3", os.path.join(HERE, "drape_population.py"), ctx.tool, ctx.data,
         os.path.join(d, "drape.md"), "--bodies", body, "--patterns"] + patterns +
        ["--resolution", res, "--threads", THREADS, "--json", js])
    rows_in = read_jsonl(js)
    rows = []
    for r in rows_in:
        q = r.get("quality", {})
        rows.append([r["body"], r["pattern"], "yes" if r["passed"] else "no",
                     fmt(q.get("stitch_gap_max_mm"), "%.2f"), fmt(q.get("self_intersections"),
                                                                  "%d"),
                     fmt(q.get("stretch_p95"), "%.3f"),
                     fmt(r.get("mesh", {}).get("cloth_vertices"), "%d"),
                     "%.1f" % r["wall_seconds"], r.get("reason") or "–"])
    table = md_table(["body", "pattern", "gates passed", "stitch gap max mm", "self-intersections",
                      "p95 stretch", "cloth vertices", "wall time s", "failed gates"], rows)
    npass = sum(1 for r in rows_in if r["passed"])
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(6, 3.5))
    ax.bar(range(len(rows_in)), [r["wall_seconds"] for r in rows_in],
           color=["tab:green" if r["passed"] else "tab:red" for r in rows_in])
    ax.set_xticks(range(len(rows_in)))
    ax.set_xticklabels(["%s\n%s" % (r["body"], r["pattern"]) for r in rows_in], fontsize=6)
    ax.set_ylabel("wall time, s (green: gates passed)")
    ax.set_title("Drapes at %g mm, %d thread" % (res, THREADS))
    fig.tight_layout()
    fig.savefig(os.path.join(d, "claim.png"), dpi=110)
    plt.close(fig)
    return dict(table=table, plot="claim.png", verdict="figure",
                figure="gates passed on %d of %d drapes at %g mm" % (npass, len(rows_in), res),
                notes="`tapeline dress` through `drape_population.py` (FreeSewing drafts graded "
                      "to the body first), %g mm cloth edges, 40 substeps, %d thread. The gates "
                      "are the drape report's quality gates; the full gate table is in "
                      "[drape.md](results/drape/drape.md)." % (res, THREADS), links=[
                          ("full table", "drape.md")])


def part_fabric(ctx, d):
    """Virtual fabric tests (run_fabric.sh's runs at the mode's sizes; fabric_table.py)."""
    s = ctx.size
    names = s["fabrics"]
    if names == "all":
        text = run([ctx.tool, "fabric", "list"])
        names = [line.split()[0] for line in text.splitlines()[1:] if line.strip()]
    runs = os.path.join(d, "runs")
    os.makedirs(runs, exist_ok=True)
    todo = [(f, t, r) for f in names for t, r in s["fabric_tests"]]
    for i, (f, t, r) in enumerate(todo):
        say("fabric [%d/%d] %s %s %d mm" % (i + 1, len(todo), f, t, r))
        run([ctx.tool, "fabric", "test", f, "--test", t, "--resolution", r, "--threads", THREADS,
             "--report", os.path.join(runs, "%s.%s.%d.json" % (f, t, r))], os.devnull)
    run(["/usr/bin/python3", os.path.join(HERE, "fabric_table.py"), runs],
        os.path.join(d, "fabric.md"))
    miss, total, cant = 0, 0, []
    finest = {}
    for f, t, r in todo:
        finest[(f, t)] = min(r, finest.get((f, t), r))
    for f, t, r in todo:
        j = json.load(open(os.path.join(runs, "%s.%s.%d.json" % (f, t, r))))
        errs = []
        if t == "cantilever":
            errs = [(j["error_warp_pct"], 5), (j["error_weft_pct"], 5)]
            cant.append((f, r, j["target_bending_length_warp_mm"], j["bending_length_warp_mm"]))
        elif t == "tensile":
            errs = [(j["error_%s_at_%d_gf_cm_pct" % (dd, l)], 5) for dd in ("warp", "weft")
                    for l in (5, 20, 100)]
        elif t == "bias":
            errs = [(j["error_pct"], 10)]
        if r == finest[(f, t)]:
            total += len(errs)
            miss += sum(1 for e, tol in errs if abs(e) > tol)
    rows = []
    for f, t, r in todo:
        j = json.load(open(os.path.join(runs, "%s.%s.%d.json" % (f, t, r))))
        if t == "cantilever":
            v = "C warp %.2f mm (%+.1f %%), weft %.2f mm (%+.1f %%)" % (
                j["bending_length_warp_mm"], j["error_warp_pct"], j["bending_length_weft_mm"],
                j["error_weft_pct"])
        elif t == "tensile":
            v = "strain error %% warp %s, weft %s" % tuple(
                "/".join("%+.2f" % j["error_%s_at_%d_gf_cm_pct" % (dd, l)] for l in (5, 20, 100))
                for dd in ("warp", "weft"))
        elif t == "bias":
            v = "G %.1f N/m (%+.2f %%)" % (j["shear_rigidity_n_m"], j["error_pct"])
        else:
            nodes = j.get("nodes")
            v = "DC %.1f %% (%s nodes)" % (j["drape_coefficient_pct"], "/".join(
                map(str, nodes)) if isinstance(nodes, list) else nodes)
        rows.append([f, t, r, v])
    table = md_table(["fabric", "test", "resolution mm", "result"], rows)
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(5, 4.5))
    for res in sorted({c[1] for c in cant}):
        pts = [c for c in cant if c[1] == res]
        ax.plot([p[2] for p in pts], [p[3] for p in pts], "o", label="%d mm" % res)
    if cant:
        lo, hi = min(c[2] for c in cant) * 0.9, max(c[2] for c in cant) * 1.1
        ax.plot([lo, hi], [lo, hi], "k-", lw=0.8)
        ax.fill_between([lo, hi], [lo * 0.95, hi * 0.95], [lo * 1.05, hi * 1.05], alpha=0.15,
                        label="±5 %")
    ax.set_xlabel("target bending length, mm")
    ax.set_ylabel("simulated (warp), mm")
    ax.set_title("Peirce cantilever")
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "claim.png"), dpi=110)
    plt.close(fig)
    return dict(table=table, plot="claim.png", verdict="holds" if miss == 0 else "does not hold",
                figure="%d of %d cantilever/tensile/bias figures outside tolerance at the "
                       "finest resolution run" % (miss, total),
                notes="`tapeline fabric test` for %d fabric(s); tolerances: cantilever 5 %%, "
                      "tensile 5 %%, bias 10 %%, each test judged at the finest resolution run; "
                      "Cusick drape coefficients have no target. The "
                      "tables of `fabric_table.py` (with the Cusick spreads) are in "
                      "[fabric.md](results/fabric/fabric.md)." % len(names),
                links=[("fabric tables", "fabric.md")])


def part_wrinkles(ctx, d):
    """The wrinkle wavelength law on the cloth solver: `wrinkles buckling --test foundation` over
    the mode's bending rigidities (run_wrinkles.sh's strip at the mode's resolution)."""
    w = ctx.size["wrinkles"]
    report = os.path.join(d, "foundation.json")
    say("wrinkles: strip on a foundation, B = %s uN m at %g mm" % (
        ",".join("%g" % b for b in w["bending"]), w["resolution"]))
    run([ctx.tool, "wrinkles", "buckling", "--test", "foundation", "--bending",
         ",".join("%g" % b for b in w["bending"]), "--resolution", w["resolution"],
         "--threads", THREADS, "--report", report], os.devnull)
    j = json.load(open(report))
    pts = j["points"]
    rows = [["%g" % p["bending_un_m"], "%.2f" % p["predicted_wavelength_mm"],
             "%.2f" % p["measured_wavelength_mm"], "%+.1f" % p["error_percent"],
             "%.2f" % p["peak_share"], p["pattern"]] for p in pts]
    table = md_table(["B µN·m", "predicted λ mm", "measured λ mm", "error %", "peak share",
                      "pattern"], rows)
    worst = max(abs(p["error_percent"]) for p in pts)
    holds = abs(j["slope"] - 0.25) <= 0.03 and worst <= 20
    plt = pyplot()
    fig, ax = plt.subplots(figsize=(5, 4))
    bs = [p["bending_un_m"] for p in pts]
    ax.loglog(bs, [p["predicted_wavelength_mm"] for p in pts], "k-", label="2π(B/K)^¼")
    ax.loglog(bs, [p["measured_wavelength_mm"] for p in pts], "o",
              label="measured, slope %.3f" % j["slope"])
    ax.set_xlabel("bending rigidity B, µN·m")
    ax.set_ylabel("wavelength, mm")
    ax.set_title("Strip on a foundation (K = %g N/m³)" % j["foundation_n_m3"])
    ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "claim.png"), dpi=110)
    plt.close(fig)
    return dict(table=table, plot="claim.png", verdict="holds" if holds else "does not hold",
                figure="log-log slope %.3f (rule 0.25 ± 0.03), largest wavelength error %.1f %% "
                       "(rule ≤ 20 %%)" % (j["slope"], worst),
                notes="`tapeline wrinkles buckling --test foundation`: a %g × %g mm strip of %s "
                      "at %g mm edges on a Winkler foundation of %g N/m³, compressed %g %% in "
                      "stages and relaxed by the solver's Newton solve; the dominant wavelength "
                      "of its centre line against 2π(B/K)^¼. The tube under axial compression "
                      "(docs/wrinkles/scaling.md, about 17 minutes) is left out: it collapses "
                      "into one dent, not the law's axisymmetric wrinkles. The experiments are "
                      "described in docs/wrinkles/scaling.md." % (
                          j["length_mm"], j["width_mm"], j["fabric"], j["resolution_mm"],
                          j["foundation_n_m3"], 100 * j["strain"]),
                links=[("the run's report (JSON)", "foundation.json")])


# Peers: geometry-central's methods, built from the checkout --peers names (never downloaded),
# by the driver of benchmarks/peers/ in a build folder of its own outside the project's build.
# (peer method, what it computes, our counterpart in `bench geodesic`)
PEER_METHODS = [("gc-mmp", "MMP (exact polyhedral)", "exact-mmp"),
                ("gc-heat", "heat method", "heat"),
                ("gc-fmm", "fast marching", "fmm"),
                ("gc-flipout", "FlipOut (edge flips)", "exact-mmp path"),
                ("gc-pc-heat", "point-cloud heat", "gcf-points")]
# Our surface methods beside the peers: their counterparts, and the rest of the time/error front.
PEER_OURS_SURFACE = "exact-mmp,heat,heat-idt,dijkstra,fmm,gcf-window:8,gcf-window:8/faces"
PEER_EXACT_RULE = 1e-12  # gc-mmp against exact-mmp: mean relative difference at most this
PEER_SRC = os.path.join(ROOT, "benchmarks", "peers")


def peer_build_dir(peers):
    """The build folder of the driver against checkout `peers`: one per checkout and per copy of
    this repository (CMake ties a build folder to its source folder)."""
    cache = os.environ.get("XDG_CACHE_HOME") or os.path.join(os.path.expanduser("~"), ".cache")
    key = os.path.abspath(peers) + "\n" + os.path.abspath(PEER_SRC)
    return os.path.join(cache, "tapeline", "peers", "gc-" + hashlib.sha1(
        key.encode()).hexdigest()[:10])


def check_peers_dir(peers):
    """The checks of --peers DIR made before anything runs (UsageError: exit 2)."""
    if not os.path.isdir(peers):
        raise UsageError("--peers %s: no such folder" % peers)
    if not os.path.isdir(os.path.join(peers, "include", "geometrycentral")) or \
            not os.path.isfile(os.path.join(peers, "CMakeLists.txt")):
        raise UsageError("--peers %s: not a geometry-central checkout (no "
                         "include/geometrycentral or CMakeLists.txt)" % peers)
    if not os.path.isfile(os.path.join(peers, "deps", "happly", "happly.h")):
        raise UsageError("--peers %s: deps/happly is empty (run `git submodule update --init` "
                         "in the checkout)" % peers)
    if shutil.which("cmake") is None:
        raise UsageError("--peers %s: cmake not found (needed to build the peer)" % peers)


def build_peer(ctx):
    """Configure and build benchmarks/peers/ against the checkout (Release with the tool's own
    optimisation flags, -j1), in a cache folder kept between runs; the driver is copied into the
    run's work folder. A checkout that does not build is a bad --peers DIR: UsageError."""
    build = peer_build_dir(ctx.peers)
    flags = ctx.meta.get("flags", "none")
    flags_arg = [] if flags in ("none", "unknown") else ["-DCMAKE_CXX_FLAGS_RELEASE=" + flags]
    os.makedirs(build, exist_ok=True)
    log = os.path.join(build, "build.log")
    say("peers: building geometry-central from %s in %s (log: %s)" % (ctx.peers, build, log))
    with open(log, "w") as lf:
        for step in (["cmake", "-S", PEER_SRC, "-B", build, "-DCMAKE_BUILD_TYPE=Release",
                      "-DGC_DIR=" + ctx.peers] + flags_arg,
                     ["cmake", "--build", build, "--target", "gc_peer", "-j1"]):
            lf.write("$ %s\n" % " ".join(step))
            lf.flush()
            p = subprocess.Popen(step, stdout=subprocess.PIPE, stderr=subprocess.STDOUT,
                                 text=True)
            tail = []
            for line in p.stdout:
                lf.write(line)
                tail = (tail + [line.rstrip()])[-20:]
                if re.match(r"^\[\s*\d+%\]", line):
                    sys.stderr.write("peers: " + line)
            if p.wait() != 0:
                err = next((t for t in tail if "error" in t.lower()), None) or \
                    next((t for t in reversed(tail) if t.strip()), "no message")
                raise UsageError("--peers %s: geometry-central does not build (%s; log: %s)" % (
                    ctx.peers, err.strip()[:200], log))
    exe = os.path.join(build, "gc_peer")
    if not os.access(exe, os.X_OK):
        raise UsageError("--peers %s: the build made no gc_peer (log: %s)" % (ctx.peers, log))
    ctx.peer_tool = os.path.join(ctx.work, "gc_peer")
    shutil.copy2(exe, ctx.peer_tool)
    try:
        rev = subprocess.run(["git", "-C", ctx.peers, "rev-parse", "--short=12", "HEAD"],
                             capture_output=True, text=True, check=True).stdout.strip()
        dirty = subprocess.run(["git", "-C", ctx.peers, "status", "--porcelain",
                                "--untracked-files=no"], capture_output=True,
                               text=True).stdout.strip()
        ctx.peer_git = rev + ("-dirty" if dirty else "")
    except (OSError, subprocess.CalledProcessError):
        ctx.peer_git = "unknown (not a git checkout)"


def run_peer(ctx, obj, method, source, target=None, out=None):
    cmd = [ctx.peer_tool, obj, "--method", method, "--source", source]
    if target is not None:
        cmd += ["--target", target]
    if out:
        cmd += ["--out", out]
    text = run(cmd)
    line = next((t for t in reversed(text.splitlines()) if t.startswith("{")), None)
    if line is None:
        raise PartError("gc_peer %s wrote no result line" % method)
    return json.loads(line)


def rel_errors(values, reference, excluded):
    """Mean and max relative error, reachability mismatches: the formula of the bench lines'
    mean_rel_error (benchmarks/harness/src/error_stats.cpp), the source and its one-ring
    excluded."""
    total, mx, n, mismatch = 0.0, 0.0, 0, 0
    for i, (v, r) in enumerate(zip(values, reference)):
        if i in excluded:
            continue
        if math.isfinite(v) != math.isfinite(r):
            mismatch += 1
            continue
        if not math.isfinite(r) or r <= 0:
            continue
        e = abs(v - r) / r
        total += e
        mx = max(mx, e)
        n += 1
    return (total / n if n else None), (mx if n else None), mismatch


def peer_mesh(ctx, name, cache):
    """The OBJ of a benchmark mesh (an analytic spec through `mesh generate` with the bench's
    seed, or the file), its points and triangles."""
    if name in cache:
        return cache[name]
    arg = ctx.mesh_arg(name)
    if arg is None:
        cache[name] = None
        return None
    obj = os.path.join(ctx.work, "peer_%s.obj" % re.sub(r"[^A-Za-z0-9]+", "_", name))
    if arg[0] == "--surface":
        run([ctx.tool, "--quiet", "mesh", "generate", name, "--seed", SEED, "--out", obj])
    elif arg[1].endswith(".obj"):
        shutil.copy(arg[1], obj)
    else:
        cache[name] = None
        return None
    pts, tris = read_obj(obj)
    cache[name] = (obj, pts, tris)
    return cache[name]


def part_peers(ctx, d):
    """geometry-central beside our methods on the meshes and sources of parts mmp and d."""
    if ctx.peers is None:
        table = md_table(["peer", "method", "status"],
                         [["geometry-central", m, "peer not built (no --peers DIR)"]
                          for _, m, _ in PEER_METHODS])
        return dict(table=table, plot=None, verdict="not run", figure="peer not built",
                    notes="With `--peers DIR` (a local geometry-central checkout with its "
                          "submodules, never downloaded or committed) the driver of "
                          "benchmarks/peers/ is built against it and geometry-central's MMP, "
                          "heat method, fast marching, FlipOut and point-cloud heat method run "
                          "on the meshes and sources of parts mmp and (d), beside ours.",
                    links=[])
    s = ctx.size
    rep = s["mmp_repeat"]
    cache, runs, rows, plotdata, missing = {}, [], [], {}, []
    ours_all = []
    sets = [("surface", s["mmp_surfaces"], s["mmp_sources"], rep,
             PEER_OURS_SURFACE, ["gc-mmp", "gc-heat", "gc-fmm", "gc-flipout"]),
            ("points", s["d_meshes"], s["d_sources"], 1, "exact-mmp,gcf-points",
             ["gc-pc-heat"])]
    for kind, names, nsources, repeat, ours_methods, peer_methods in sets:
        for name in names:
            m = peer_mesh(ctx, name, cache)
            if m is None:
                missing.append(name)
                continue
            obj, pts, tris = m
            nv = len(pts)
            say("peers: %s (%d vertices): ours %s" % (name, nv, ours_methods))
            ours = ctx.bench(["--mesh", obj, "--methods", ours_methods, "--reference",
                              "exact-mmp", "--sources", nsources, "--repeat", repeat],
                             os.path.join(ctx.work, "peer_ours.jsonl"))
            for r in ours:
                r["mesh"], r["peer_set"] = name, kind
                r["mesh_file"] = os.path.basename(obj)  # a path relative to the run
                if r.get("vertices") != nv:
                    raise PartError("%s: the tool loaded %s vertices, the OBJ has %d" % (
                        name, r.get("vertices"), nv))
            ours_all += ours
            sources = []
            for r in ours:
                if r["source"] not in sources:
                    sources.append(r["source"])
            for src in sources:
                ref_f = os.path.join(ctx.work, "peer_ref.txt")
                run([ctx.tool, "--quiet", "geodesic", "distances", obj, "--source", src,
                     "--method", "exact-mmp", "--out", ref_f])
                ref = read_distances(ref_f)
                excluded = {src} | {v for t in tris if src in t for v in t}
                target = max((i for i in range(nv) if math.isfinite(ref[i])),
                             key=lambda i: ref[i])
                for method in peer_methods:
                    say("peers: %s source %d: %s" % (name, src, method))
                    if method == "gc-flipout":
                        ours_path = []
                        for _ in range(repeat):
                            pj = os.path.join(ctx.work, "peer_path.json")
                            run([ctx.tool, "--quiet", "geodesic", "path", obj, "--from", src,
                                 "--to", target, "--out", pj])
                            ours_path.append(json.load(open(pj)))
                    for k in range(repeat):
                        dist_f = os.path.join(ctx.work, "peer_dist.txt")
                        line = run_peer(ctx, obj, method, src,
                                        target if method == "gc-flipout" else None,
                                        None if method == "gc-flipout" else dist_f)
                        line.update(mesh=name, vertices=nv, source=src, repetition=k)
                        if method == "gc-flipout":
                            line["exact_length"] = ref[target]
                            line["ours_path_length"] = ours_path[0]["length"]
                            line["ours_path_seconds"] = statistics.median(
                                p["seconds"] for p in ours_path)
                            e = abs(line["length"] - ref[target]) / ref[target]
                            line.update(mean_rel_error=e, max_rel_error=e,
                                        reachability_mismatches=0)
                        elif k == 0:
                            mean, mx, mism = rel_errors(read_distances(dist_f), ref, excluded)
                            line.update(mean_rel_error=mean, max_rel_error=mx,
                                        reachability_mismatches=mism)
                        runs.append(line)
    if not runs:
        raise PartError("no mesh available (missing: %s)" % ", ".join(missing))
    write_jsonl(os.path.join(d, "peers.jsonl"), runs)
    write_jsonl(os.path.join(d, "ours.jsonl"), ours_all)
    # The time/error front on each surface mesh: our methods and the peers' distance fields.
    front_lines = [r for r in ours_all if r.get("peer_set") == "surface"]
    family = {r["mesh"]: r.get("family") for r in front_lines}
    for r in runs:
        if r["method"] in ("gc-mmp", "gc-heat", "gc-fmm"):
            front_lines.append(dict(
                method=r["method"], mesh=r["mesh"], family=family.get(r["mesh"]),
                vertices=r["vertices"], status="ok",
                reference="exact-mmp", source=r["source"], repetition=r["repetition"],
                pre_seconds=r["pre_seconds"], query_seconds=r["query_seconds"],
                mean_rel_error=r.get("mean_rel_error"), max_rel_error=r.get("max_rel_error"),
                compiler_flags=r.get("compiler_flags")))
    write_jsonl(os.path.join(d, "front.jsonl"), front_lines)
    bench_report([os.path.join(d, "front.jsonl")], os.path.join(d, "front"),
                 "Ours and geometry-central's: time against error")
    median = statistics.median
    exact_worst = None
    for peer, what, counterpart in PEER_METHODS:
        for name in dict.fromkeys(r["mesh"] for r in runs if r["method"] == peer):
            pr = [r for r in runs if r["method"] == peer and r["mesh"] == name]
            errs = [r for r in pr if r.get("mean_rel_error") is not None]
            mean = statistics.mean(r["mean_rel_error"] for r in errs) if errs else None
            mx = max(r["max_rel_error"] for r in errs) if errs else None
            mism = sum(r.get("reachability_mismatches", 0) for r in pr)
            t_peer = median(r["pre_seconds"] + r["query_seconds"] for r in pr)
            q_peer = median(r["query_seconds"] for r in pr)
            kind = "points" if peer == "gc-pc-heat" else "surface"
            if peer == "gc-flipout":
                t_ours = median(r["ours_path_seconds"] for r in pr)
                q_ours, our_err = None, "path length %.3g" % median(
                    abs(r["ours_path_length"] - r["exact_length"]) / r["exact_length"]
                    for r in pr)
            else:
                ok = [r for r in ours_all if r["mesh"] == name and r["method"] == counterpart
                      and r["peer_set"] == kind and r["status"] == "ok"]
                if not ok:
                    rows.append([peer, what, name, pr[0]["vertices"], fmt(mean, "%.2e"),
                                 fmt(mx, "%.2e"), counterpart, "not ok", "%.3g" % t_peer, "–",
                                 "–", "–"])
                    continue
                t_ours = median(r["pre_seconds"] + r["query_seconds"] for r in ok)
                q_ours = median(r["query_seconds"] for r in ok)
                oe = [r["mean_rel_error"] for r in ok if r.get("mean_rel_error") is not None]
                our_err = "reference" if counterpart == "exact-mmp" else fmt(
                    statistics.mean(oe) if oe else None, "%.2e")
            if peer == "gc-mmp" and mean is not None:
                exact_worst = max(exact_worst or 0.0, mean)
            ratio = t_peer / t_ours if t_ours > 0 else None
            qratio = q_peer / q_ours if q_ours else None
            rows.append([peer, what, name, pr[0]["vertices"], fmt(mean, "%.2e"),
                         fmt(mx, "%.2e") + ("" if not mism else " (%d unreachable)" % mism),
                         counterpart, our_err, "%.3g" % t_peer, "%.3g" % t_ours,
                         fmt(ratio, "%.3g"), fmt(qratio, "%.3g")])
            if ratio is not None:
                plotdata.setdefault(peer, []).append((pr[0]["vertices"], ratio, mean))
    table = md_table(["peer method", "what", "mesh", "|V|", "mean rel err vs our exact-mmp",
                      "max rel err vs our exact-mmp", "our counterpart",
                      "our counterpart's mean rel err", "peer time s", "our time s",
                      "time ratio peer / ours", "query-only time ratio"], rows)
    plt = pyplot()
    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(10, 4.2))
    for (peer, pts), mk in zip(sorted(plotdata.items()), "osD^v"):
        ax1.loglog([p[0] for p in pts], [p[1] for p in pts], mk, alpha=0.8, label=peer)
        ax2.loglog([p[0] for p in pts], [max(p[2] or 0, 1e-17) for p in pts], mk, alpha=0.8,
                   label=peer)
    ax1.axhline(1.0, color="k", lw=0.8)
    ax1.set_xlabel("|V|")
    ax1.set_ylabel("time ratio geometry-central / ours")
    ax1.set_title("time (pre + query), median, one point per mesh")
    ax2.set_xlabel("|V|")
    ax2.set_ylabel("mean relative error against our exact-mmp")
    ax2.set_title("error (drawn at ≥ 1e-17)")
    for ax in (ax1, ax2):
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(os.path.join(d, "claim.png"), dpi=110)
    plt.close(fig)
    if exact_worst is None:
        verdict, figure = "undecided", "gc-mmp did not run"
    else:
        verdict = "holds" if exact_worst <= PEER_EXACT_RULE else "does not hold"
        figure = ("exact against exact: gc-mmp's mean relative difference from exact-mmp at "
                  "most %.1e (rule: ≤ %.0e)" % (exact_worst, PEER_EXACT_RULE))
    ratios = {}
    for r in rows:
        if r[10] != "–":
            ratios.setdefault(r[0], []).append(float(r[10]))
    timing = "; ".join("%s / %s %s" % (p, c, ("%.2g to %.2g" % (min(ratios[p]), max(ratios[p])))
                                       if len(ratios[p]) > 1 else "%.2g" % ratios[p][0])
                       for p, _, c in PEER_METHODS if p in ratios)
    flags = " ".join(runs[0].get("compiler_flags", "unknown").split())
    notes = (
        "geometry-central git %s (%s), built by `benchmarks/peers/` (Release with the tool's "
        "optimisation flags; compiler and flags `%s`; SuiteSparse %s) into %s; one process per "
        "run. Surface methods on the meshes and sources of part mmp (%d repetition(s), median), "
        "the point-cloud heat method on those of part (d) (the vertices as a point cloud, 1 "
        "repetition). Both sides read the same OBJ (analytic surfaces written by `tapeline mesh "
        "generate SPEC --seed %d`); ours are `bench geodesic` lines on that file. Errors: mean "
        "over sources of the mean relative difference from `geodesic distances --method "
        "exact-mmp`, the source and its one-ring excluded (the formula of the bench lines' "
        "mean_rel_error). Times are pre + query seconds inside each program (loading excluded); "
        "gc-heat's pre is the solver set-up, gc-pc-heat's the first solve minus a second; the "
        "query-only ratio compares the query seconds alone. gc-fmm is set against our fmm "
        "(both first-order fast marching; ours splits obtuse corners by unfolding, so on meshes "
        "with obtuse faces its error is the lower). gc-flipout shortens a Dijkstra edge path "
        "from the source to the vertex farthest from it (near the cut locus, where geodesics of other "
        "classes are almost as short) into a locally shortest geodesic; its error is the "
        "relative difference of that path's length from the exact distance, its time is set "
        "against `geodesic path` (exact-mmp, the JSON's seconds). Verdict rule: holds when "
        "gc-mmp agrees with exact-mmp to a mean relative difference of at most %.0e.%s" % (
            ctx.peer_git, ctx.peers, flags, "yes" if runs[0].get("suitesparse") else "no",
            peer_build_dir(ctx.peers), rep, SEED, PEER_EXACT_RULE,
            "" if not missing else " Not available: %s." % ", ".join(missing)))
    return dict(table=table, plot="claim.png", verdict=verdict, figure=figure,
                timing_figure="time ratio " + timing if timing else None, notes=notes,
                links=[("peer runs (JSON lines)", "peers.jsonl"),
                       ("our runs (JSON lines)", "ours.jsonl"),
                       ("time against error, ours and the peers' (one panel per mesh)",
                        "front/time_vs_error.png"),
                       ("the front's table", "front/table.md")])


PARTS = [
    ("a", "a_linear_time", "(a) Algorithm 2 (gcf-window) runs in linear time", part_a),
    ("b", "b_window_error", "(b) Algorithm 2's error is bounded by O(εm)", part_b),
    ("c", "c_smooth_surface",
     "(c) Algorithm 1 (gcf-exact) is closer to the smooth surface than exact polyhedral "
     "geodesics", part_c),
    ("d", "d_point_clouds", "(d) Algorithm 3 (gcf-points) works on point clouds", part_d),
    ("mmp", "exact_mmp", "Exact MMP against CGAL: time, memory, agreement", part_mmp),
    ("measure", "measurement", "Measurement: exact girths of the synthetic body, same girths on "
     "the same surface; population self-checks", part_measure),
    ("grading", "grading", "Grading against FreeSewing's own drafts", part_grading),
    ("drape", "drape", "Drape gates and time", part_drape),
    ("fabric", "fabric", "Fabric tests", part_fabric),
    ("wrinkles", "wrinkles", "Wrinkle figures", part_wrinkles),
    ("peers", "peers", "Peers side by side", part_peers),
]


# --------------------------------------------------------------------------------------------
# results.md


def render_results(ctx, results, wall):
    L = ["# Reproduced results", "",
         "Generated by `benchmarks/reproduce.sh %s` in %.0f s; do not edit by hand. Every figure "
         "below comes from this one run; each section has its table, its plot, the rule its "
         "verdict follows and the provenance of the run. Timings come from a machine that may be "
         "shared: exponents and ratios hold better than seconds." % (
             " ".join(ctx.argv) or "--%s" % ctx.mode, wall), "",
         ctx.provenance_line(), "", "## Summary", ""]
    rows = []
    for key, folder, title, _ in PARTS:
        r = results[key]
        rows.append([title, r["verdict"], r["figure"], r.get("timing_figure") or "–"])
    L += [md_table(["claim", "verdict", "figure", "timing figure"], rows), "",
          ctx.provenance_line(), ""]
    for key, folder, title, _ in PARTS:
        r = results[key]
        fig = "; ".join(x for x in (r["figure"], r.get("timing_figure")) if x and x != "–")
        L += ["## %s" % title, "", "**Verdict: %s** — %s" % (r["verdict"], fig), ""]
        if r.get("error"):
            L += ["**Part failed:** %s" % r["error"].replace("\n", " "), ""]
        # A part's table, or its list of tables: each followed by the provenance line.
        tables = r.get("table") or []
        for table in [tables] if isinstance(tables, str) else tables:
            L += [table, "", ctx.provenance_line(), ""]
        if r.get("plot"):
            L += ["![%s](results/%s/%s)" % (title, folder, r["plot"]), ""]
        if r.get("notes"):
            L += [r["notes"], ""]
        if r.get("links"):
            L += ["More: " + ", ".join("[%s](results/%s/%s)" % (lab, folder, f)
                                      for lab, f in r["links"]), ""]
    return "\n".join(L)


# --------------------------------------------------------------------------------------------
# Options and main


class Parser(argparse.ArgumentParser):
    def error(self, message):
        raise UsageError(message + " (see --help)")


def parse_args(argv):
    p = Parser(prog=PROG, description="Regenerate docs/results.md: a table and a plot for each "
               "claim, at the sizes of one mode.")
    g = p.add_mutually_exclusive_group()
    g.add_argument("--quick", dest="mode", action="store_const", const="quick",
                   help="reduced sizes, at most 30 min on 2 cores (default)")
    g.add_argument("--full", dest="mode", action="store_const", const="full",
                   help="the complete figures (hours)")
    g.add_argument("--smoke", dest="mode", action="store_const", const="smoke",
                   help="tiny sizes (about a minute): checks that the command runs")
    p.add_argument("--out", default=os.path.join(ROOT, "docs"),
                   help="folder for results.md and results/ (default: docs/ of the repository)")
    p.add_argument("--tool", default=os.path.join(ROOT, "build", "apps", "tapeline"),
                   help="the tapeline executable (default: build/apps/tapeline)")
    p.add_argument("--data", default=os.path.join(os.path.dirname(ROOT), "shared", "data"),
                   help="shared data folder (default: ../shared/data); parts without it are "
                        "skipped")
    p.add_argument("--peers", metavar="DIR",
                   help="a local geometry-central checkout to run beside (never downloaded)")
    p.add_argument("--only", metavar="PARTS",
                   help="comma-separated parts to run (%s); the others are marked not run" %
                        ",".join(k for k, *_ in PARTS))
    a = p.parse_args(argv)
    a.mode = a.mode or "quick"
    a.argv = argv
    if not (os.path.isfile(a.tool) and os.access(a.tool, os.X_OK)):
        raise UsageError("--tool %s: not an executable file" % a.tool)
    if a.peers:
        check_peers_dir(os.path.abspath(a.peers))
    keys = [k for k, *_ in PARTS]
    if a.only:
        a.only = a.only.split(",")
        bad = [k for k in a.only if k not in keys]
        if bad:
            raise UsageError("--only: unknown part '%s' (one of %s)" % (bad[0], ",".join(keys)))
    parent = os.path.dirname(os.path.abspath(a.out)) or "/"
    if os.path.exists(a.out) and not os.path.isdir(a.out):
        raise UsageError("--out %s: exists and is not a folder" % a.out)
    if not os.path.isdir(a.out) and not os.path.isdir(parent):
        raise UsageError("--out %s: its parent folder does not exist" % a.out)
    return a


def install(ctx):
    """Move results.md and results/ from the staging folder into --out."""
    os.makedirs(ctx.out, exist_ok=True)
    final_dir = os.path.join(ctx.out, "results")
    old = None
    if os.path.exists(final_dir):
        old = os.path.join(ctx.out, ".results.old.%d" % os.getpid())
        os.replace(final_dir, old)
    os.replace(os.path.join(ctx.stage, "results"), final_dir)
    os.replace(os.path.join(ctx.stage, "results.md"), os.path.join(ctx.out, "results.md"))
    if old:
        shutil.rmtree(old, ignore_errors=True)


def main(argv):
    try:
        args = parse_args(argv)
        ctx = Context(args)
        work = tempfile.mkdtemp(prefix="reproduce_")
        try:
            probe_tool(ctx, work)
            if ctx.peers and (not ctx.only or "peers" in ctx.only):
                ctx.work = work
                build_peer(ctx)
        except UsageError:
            shutil.rmtree(work, ignore_errors=True)
            raise
    except UsageError as e:
        print("%s: error: %s" % (PROG, e), file=sys.stderr)
        return 2
    ctx.work = work
    start = time.monotonic()
    failed = []
    try:
        os.makedirs(ctx.out, exist_ok=True)
        ctx.stage = tempfile.mkdtemp(prefix=".results.tmp.", dir=ctx.out)
        os.makedirs(os.path.join(ctx.stage, "results"))
        results = {}
        for i, (key, folder, title, fn) in enumerate(PARTS):
            if ctx.only and key not in ctx.only:
                results[key] = dict(verdict="not run", figure="not selected (--only)", table=None)
                continue
            say("[%d/%d] %s" % (i + 1, len(PARTS), title))
            t0 = time.monotonic()
            d = ctx.part_dir(folder)
            try:
                results[key] = fn(ctx, d)
            except Exception as e:  # a part's failure is a result: reported, then exit 1
                msg = str(e) if isinstance(e, PartError) else "%s: %s" % (type(e).__name__, e)
                say("%s FAILED: %s" % (title, msg))
                results[key] = dict(verdict="failed", figure="the part failed", error=msg,
                                    table=None)
                failed.append(key)
            say("[%d/%d] %s: %s (%.0f s)" % (i + 1, len(PARTS), title, results[key]["verdict"],
                                             time.monotonic() - t0))
        wall = time.monotonic() - start
        with open(os.path.join(ctx.stage, "results.md"), "w") as f:
            f.write(render_results(ctx, results, wall) + "\n")
        install(ctx)
        say("wrote %s and %s/ in %.0f s%s" % (
            os.path.join(ctx.out, "results.md"), os.path.join(ctx.out, "results"), wall,
            "" if not failed else "; failed parts: " + ", ".join(failed)))
    except KeyboardInterrupt:
        say("interrupted; nothing written")
        return 130
    finally:
        shutil.rmtree(work, ignore_errors=True)
        if ctx.stage and os.path.isdir(ctx.stage):
            shutil.rmtree(ctx.stage, ignore_errors=True)
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
