#!/usr/bin/python3
"""Turn `tapeline bench geodesic` JSON lines into a Markdown table and PNG plots.

    benchmarks/scripts/bench_report.py results.jsonl [more.jsonl ...] --out-dir docs/bench
                                       [--title T] [--reference METHOD] [--no-plots]

Writes DIR/table.md (per-mesh table, "Scaling" and "Time/error front" tables) and, unless
--no-plots, DIR/query_time_vs_vertices.png, DIR/error_vs_vertices.png,
DIR/memory_vs_vertices.png, DIR/window_sweep.png and DIR/time_vs_error.png (the front: one panel
per mesh, time against mean error for every method).
Every output is rendered to a temporary name first and renamed only once all of them succeeded,
so a failure never leaves a half-written file behind (DESIGN.md §4). See benchmarks/README.md.

Standard library only; matplotlib (Debian: python3-matplotlib, seen by /usr/bin/python3) is
imported only when plots are requested.
"""

import argparse
import json
import math
import os
import shlex
import statistics
import sys
import tempfile
from collections import Counter, OrderedDict

PROG = "bench_report"
REQUIRED_KEYS = ("method", "mesh", "vertices", "status")
STATUSES = ("ok", "invalid_input", "solver_failed", "timeout", "crash")
NUMERIC_KEYS = (
    "vertices", "faces", "mean_edge_length", "source", "repetition", "pre_seconds",
    "query_seconds", "peak_rss_bytes", "base_rss_bytes", "mean_rel_error", "max_rel_error",
    "mean_rel_error_truth", "max_rel_error_truth", "threads",
)
DASH = "\u2013"  # shown for a value that is missing (null, no ok run, no reference)
TABLE_NAME = "table.md"
PLOT_NAMES = ("query_time_vs_vertices.png", "error_vs_vertices.png", "memory_vs_vertices.png",
              "window_sweep.png", "time_vs_error.png")


class ReportError(Exception):
    """An input or output problem reported as one line on stderr with a non-zero exit."""


# --------------------------------------------------------------------------------------------
# Reading


class Record:
    """One JSON line plus where it came from (for messages)."""

    __slots__ = ("data", "where")

    def __init__(self, data, where):
        self.data = data
        self.where = where

    def get(self, key):
        return self.data.get(key)

    def num(self, key):
        """The value of a numeric key as a float, or None when null, missing or not finite."""
        v = self.data.get(key)
        if v is None:
            return None
        v = float(v)
        return v if math.isfinite(v) else None


def _is_number(v):
    return isinstance(v, (int, float)) and not isinstance(v, bool)


def _validate(obj, where):
    if not isinstance(obj, dict):
        raise ReportError(f"{where}: expected a JSON object, got {type(obj).__name__}")
    for key in REQUIRED_KEYS:
        if key not in obj:
            raise ReportError(f"{where}: missing required key '{key}'")
    for key in ("method", "mesh", "status"):
        if not isinstance(obj[key], str) or not obj[key]:
            raise ReportError(f"{where}: key '{key}' must be a non-empty string")
    if obj["status"] not in STATUSES:
        raise ReportError(f"{where}: status '{obj['status']}' is not one of {', '.join(STATUSES)}")
    for key in NUMERIC_KEYS:
        v = obj.get(key)
        if v is not None and not _is_number(v):
            raise ReportError(f"{where}: key '{key}' must be a number or null, "
                              f"got {json.dumps(v)[:40]}")
    v = obj["vertices"]
    if v is not None and (not math.isfinite(v) or v != int(v) or v <= 0):
        raise ReportError(f"{where}: 'vertices' must be a positive integer or null, got {v}")
    for key in ("family", "reference", "message", "truth"):
        v = obj.get(key)
        if v is not None and not isinstance(v, str):
            raise ReportError(f"{where}: key '{key}' must be a string or null")


def read_records(paths):
    """Parse and validate every line of every file; raises ReportError on the first problem."""
    records = []
    for path in paths:
        try:
            with open(path, "rb") as f:
                raw_lines = f.read().split(b"\n")
        except FileNotFoundError:
            raise ReportError(f"{path}: no such file") from None
        except IsADirectoryError:
            raise ReportError(f"{path}: is a directory, expected a .jsonl file") from None
        except OSError as e:
            raise ReportError(f"{path}: cannot read: {e.strerror}") from None
        for lineno, raw in enumerate(raw_lines, start=1):
            where = f"{path}:{lineno}"
            try:
                text = raw.decode("utf-8")
            except UnicodeDecodeError:
                raise ReportError(f"{where}: not valid UTF-8") from None
            if not text.strip():
                continue
            try:
                obj = json.loads(text)
            except json.JSONDecodeError as e:
                raise ReportError(
                    f"{where}: not valid JSON ({e.msg} at column {e.colno})") from None
            _validate(obj, where)
            records.append(Record(obj, where))
    if not records:
        raise ReportError(f"empty input: no benchmark lines in {', '.join(paths)}")
    return records


# --------------------------------------------------------------------------------------------
# Aggregation


def family_of(rec):
    fam = rec.get("family")
    if fam:
        return fam
    # Older lines without `family`: "icosphere:4" -> "icosphere", "data/bunny.off" -> "bunny".
    mesh = rec.get("mesh")
    base = os.path.basename(mesh.split(":", 1)[0]) or mesh
    return os.path.splitext(base)[0] or base


def median_or_none(values):
    values = [v for v in values if v is not None]
    return statistics.median(values) if values else None


def mean_or_none(values):
    values = [v for v in values if v is not None]
    return math.fsum(values) / len(values) if values else None


def max_or_none(values):
    values = [v for v in values if v is not None]
    return max(values) if values else None


def total_seconds(rec):
    """pre + query of one run; None when either is missing (not measured is not zero)."""
    pre, query = rec.num("pre_seconds"), rec.num("query_seconds")
    return pre + query if pre is not None and query is not None else None


def fit_exponent(points):
    """Least-squares slope k and R^2 of log(y) = k log(V) + b over points (V, y).

    Points with a non-positive or missing value are dropped. Returns None when fewer than two
    distinct V remain (the slope is undefined), else (k, r2, used_points).
    """
    pts = [(v, y) for v, y in points if v is not None and y is not None and v > 0 and y > 0]
    if len({v for v, _ in pts}) < 2:
        return None
    xs = [math.log(v) for v, _ in pts]
    ys = [math.log(y) for _, y in pts]
    n = len(pts)
    mx, my = math.fsum(xs) / n, math.fsum(ys) / n
    sxx = math.fsum((x - mx) ** 2 for x in xs)
    sxy = math.fsum((x - mx) * (y - my) for x, y in zip(xs, ys))
    syy = math.fsum((y - my) ** 2 for y in ys)
    k = sxy / sxx
    ss_res = math.fsum((y - (my + k * (x - mx))) ** 2 for x, y in zip(xs, ys))
    r2 = 1.0 - ss_res / syy if syy > 0 else 1.0
    return k, r2, pts


class MeshInfo:
    def __init__(self, family, mesh):
        self.family = family
        self.mesh = mesh
        self.vertices = None
        self.reference = None


class Row:
    """Aggregate of one (mesh, method): what one line of the main table shows."""

    def __init__(self, mesh_info, method, records):
        self.mesh_info = mesh_info
        self.method = method
        self.records = records
        ok = [r for r in records if r.get("status") == "ok"]
        self.ok = len(ok)
        self.total = len(records)
        self.pre = median_or_none(r.num("pre_seconds") for r in ok)
        self.query = median_or_none(r.num("query_seconds") for r in ok)
        self.pre_query = median_or_none(total_seconds(r) for r in ok)
        self.peak_rss = median_or_none(r.num("peak_rss_bytes") for r in ok)
        v = mesh_info.vertices
        self.kb_per_vertex = self.peak_rss / v / 1e3 if self.peak_rss is not None and v else None
        self.mean_err = mean_or_none(r.num("mean_rel_error") for r in ok)
        self.max_err = max_or_none(r.num("max_rel_error") for r in ok)
        self.mean_err_truth = mean_or_none(r.num("mean_rel_error_truth") for r in ok)
        self.max_err_truth = max_or_none(r.num("max_rel_error_truth") for r in ok)
        self.ratio = None  # filled once the reference row of the mesh is known
        self.window, self.anchor = None, None
        options = records[0].get("options") if records else None
        if isinstance(options, dict) and _is_number(options.get("window")):
            self.window = options["window"]
            self.anchor = options.get("anchor")

    @property
    def family(self):
        return self.mesh_info.family

    @property
    def vertices(self):
        return self.mesh_info.vertices


class ScalingRow:
    def __init__(self, family, method, query_fit, total_fit):
        self.family = family
        self.method = method
        self.query_fit = query_fit
        self.total_fit = total_fit

    @property
    def k_query(self):
        return self.query_fit[0] if self.query_fit else None

    @property
    def k_total(self):
        return self.total_fit[0] if self.total_fit else None


class Report:
    def __init__(self, rows, scaling, failures, records, notes):
        self.rows = rows
        self.scaling = scaling
        self.failures = failures
        self.records = records
        self.notes = notes

    def scaling_for(self, family, method):
        for s in self.scaling:
            if s.family == family and s.method == method:
                return s
        return None


def _most_common(values):
    values = [v for v in values if v is not None]
    return Counter(values).most_common(1)[0][0] if values else None


def build_report(records, reference_override=None):
    notes = []
    # Group by mesh (keeping its family), then by method.
    meshes = OrderedDict()
    by_mesh_method = OrderedDict()
    for rec in records:
        key = (family_of(rec), rec.get("mesh"))
        meshes.setdefault(key, []).append(rec)
        by_mesh_method.setdefault(key, OrderedDict()).setdefault(rec.get("method"), []).append(rec)

    mesh_infos = {}
    for key, recs in meshes.items():
        info = MeshInfo(*key)
        counts = Counter(int(r.get("vertices")) for r in recs if r.get("vertices") is not None)
        if counts:
            info.vertices = counts.most_common(1)[0][0]
            if len(counts) > 1:
                notes.append(f"mesh `{info.mesh}` reports several vertex counts "
                             f"({', '.join(str(v) for v in sorted(counts))}); "
                             f"using {info.vertices}.")
        refs = Counter(r.get("reference") for r in recs if r.get("reference"))
        info.reference = reference_override or (refs.most_common(1)[0][0] if refs else None)
        if not reference_override and len(refs) > 1:
            notes.append(f"mesh `{info.mesh}` names several reference methods "
                         f"({', '.join(sorted(refs))}); ratios use `{info.reference}`.")
        mesh_infos[key] = info

    rows = []
    for key, methods in by_mesh_method.items():
        info = mesh_infos[key]
        mesh_rows = {m: Row(info, m, recs) for m, recs in methods.items()}
        ref_row = mesh_rows.get(info.reference)
        ref_time = ref_row.pre_query if ref_row else None
        for row in mesh_rows.values():
            if ref_time and row.pre_query is not None:
                row.ratio = row.pre_query / ref_time
        rows.extend(mesh_rows.values())

    def row_key(row):
        v = row.vertices
        return (row.family, v is None, v or 0, row.mesh_info.mesh,
                row.method != row.mesh_info.reference, row.method)
    rows.sort(key=row_key)

    # Scaling: per (family, method), one point per mesh (the per-mesh medians).
    groups = OrderedDict()
    for row in rows:
        groups.setdefault((row.family, row.method), []).append(row)
    scaling = []
    for (family, method), grows in groups.items():
        if len({r.vertices for r in grows if r.vertices is not None}) < 2:
            continue
        query_fit = fit_exponent([(r.vertices, r.query) for r in grows])
        total_fit = fit_exponent([(r.vertices, r.pre_query) for r in grows])
        if query_fit is None and total_fit is None:
            continue
        scaling.append(ScalingRow(family, method, query_fit, total_fit))

    failures = OrderedDict()  # (mesh, method, status) -> [count, first record]
    for row in rows:
        for rec in row.records:
            status = rec.get("status")
            if status == "ok":
                continue
            entry = failures.setdefault((row.mesh_info.mesh, row.method, status), [0, rec])
            entry[0] += 1

    gits = {r.get("git") for r in records if r.get("git")}
    if len(gits) > 1:
        notes.append(f"input mixes {len(gits)} git revisions ({', '.join(sorted(gits))}): "
                     "time ratios are only meaningful between runs measured side by side.")
    return Report(rows, scaling, failures, records, notes)


def front(report):
    """{mesh: [(method, mean error vs reference, median pre+query s, on the front), ...]} sorted by
    time. The reference method has error 0. A method is on the front (Pareto optimal) when no other
    method on the mesh is at least as fast and at least as accurate while better in one of them;
    methods without a time or an error are left out."""
    out = OrderedDict()
    for r in report.rows:
        if r.pre_query is None:
            continue
        is_ref = r.method == r.mesh_info.reference
        err = 0.0 if is_ref else r.mean_err
        if err is None:
            continue
        out.setdefault(r.mesh_info.mesh, []).append((r.method, err, r.pre_query))
    result = OrderedDict()
    for mesh, pts in out.items():
        rows = []
        for m, e, t in sorted(pts, key=lambda p: (p[2], p[1], p[0])):
            dominated = any((t2 <= t and e2 <= e) and (t2 < t or e2 < e)
                            for m2, e2, t2 in pts if m2 != m)
            rows.append((m, e, t, not dominated))
        result[mesh] = rows
    return result


# --------------------------------------------------------------------------------------------
# Formatting


def fmt_num(x, sig=3):
    """3 significant digits: plain for 1e-3 <= |x| < 1e3, rounded integer above, else e-notation."""
    if x is None:
        return DASH
    if x == 0:
        return "0"
    ax = abs(x)
    if ax >= 10 ** sig:
        digits = int(math.floor(math.log10(ax))) + 1
        return f"{round(x, sig - digits):.0f}"
    if ax >= 1e-3:
        s = f"{x:#.{sig}g}"
        if "e" in s:  # rounding carried into the next decade, e.g. 999.7 -> 1.00e+03
            return f"{x:.0f}"
        return s.rstrip(".")
    return f"{x:.{sig - 1}e}"


def fmt_err(x):
    """Relative errors in scientific notation, 3 significant digits."""
    if x is None:
        return DASH
    if x == 0:
        return "0"
    return f"{x:.2e}"


def fmt_k(x):
    return DASH if x is None else f"{x:.3f}"


def md_cell(text):
    return str(text).replace("\\", "\\\\").replace("|", "\\|").replace("\r", " ").replace("\n", " ")


def md_table(header, align, rows):
    """align: one character per column, "l" (text) or "r" (numbers)."""
    lines = ["| " + " | ".join(header) + " |",
             "|" + "|".join(":--" if a == "l" else "--:" for a in align) + "|"]
    for r in rows:
        lines.append("| " + " | ".join(r) + " |")
    return lines


MAIN_HEADER = (
    "family", "mesh", "\\|V\\|", "method", "runs ok/total", "pre s (median)", "query s (median)",
    "peak RSS MB (median)", "KB/vertex", "mean rel err vs ref", "max rel err vs ref",
    "mean rel err vs truth", "max rel err vs truth", "time ratio vs ref",
)
MAIN_ALIGN = "llrl" + "r" * 10
SCALING_HEADER = ("family", "method", "meshes", "V range", "k query", "R\u00b2 query",
                  "k pre+query")
SCALING_ALIGN = "llrrrrr"


def render_table(report, title, command, inputs):
    out = [f"# {md_cell(title)}", ""]
    refs = sorted({r.mesh_info.reference for r in report.rows if r.mesh_info.reference})
    ref_text = ", ".join(f"`{r}`" for r in refs) if refs else "none named in the input"
    out += [
        f"Reference method: {ref_text}. Times are medians over the `ok` runs of a (mesh, method); "
        "\"time ratio vs ref\" is median(pre+query) of the method divided by the same for the "
        "reference method on the same mesh (below 1 = faster than the reference). Errors are "
        "relative, in scientific notation: \"mean\" is the mean over sources and repetitions, "
        "\"max\" the maximum. MB = 10\u2076 bytes, KB = 10\u00b3 bytes; KB/vertex is the median "
        f"peak RSS divided by \\|V\\|. {DASH} = not available.",
        "",
    ]
    rows = []
    for r in report.rows:
        v = r.vertices
        rows.append([
            md_cell(r.family), md_cell(r.mesh_info.mesh), DASH if v is None else str(v),
            md_cell(r.method), f"{r.ok}/{r.total}", fmt_num(r.pre), fmt_num(r.query),
            fmt_num(None if r.peak_rss is None else r.peak_rss / 1e6), fmt_num(r.kb_per_vertex),
            fmt_err(r.mean_err), fmt_err(r.max_err), fmt_err(r.mean_err_truth),
            fmt_err(r.max_err_truth), fmt_num(r.ratio),
        ])
    out += md_table(MAIN_HEADER, MAIN_ALIGN, rows)

    n_bad = sum(c for c, _ in report.failures.values())
    out += ["", f"Runs not ok: {n_bad} of {len(report.records)}."]
    if report.failures:
        out.append("")
        for (mesh, method, status), (count, rec) in report.failures.items():
            msg = (rec.get("message") or "").strip()
            msg_text = f": \"{md_cell(msg)}\"" if msg else " (no message)"
            out.append(f"- `{md_cell(method)}` on `{md_cell(mesh)}`: {status} \u00d7{count}; "
                       f"first at {md_cell(rec.where)}{msg_text}")

    out += ["", "## Scaling", ""]
    if report.scaling:
        out += [
            "Exponent k of time \u221d V^k: least-squares slope of log(time) against log(\\|V\\|) "
            "over the per-mesh medians of one family, meshes with a missing or zero time left "
            "out. R\u00b2 near 1 means a single power law describes the data.",
            "",
        ]
        srows = []
        for s in report.scaling:
            fit = s.query_fit or s.total_fit
            vs = [v for v, _ in fit[2]]
            srows.append([md_cell(s.family), md_cell(s.method), str(len(fit[2])),
                          f"{min(vs)}\u2013{max(vs)}", fmt_k(s.k_query),
                          DASH if s.query_fit is None else f"{s.query_fit[1]:.4f}",
                          fmt_k(s.k_total)])
        out += md_table(SCALING_HEADER, SCALING_ALIGN, srows)
    else:
        out.append("No (family, method) with timings on at least two distinct vertex counts.")

    out += ["", "## Time/error front", ""]
    fr = front(report)
    if fr:
        out += [
            "Per mesh, the methods by median pre+query time, with their mean relative error "
            "against the reference (0 for the reference itself); \"front\" marks the methods no "
            "other method beats on both (Pareto optimal). time_vs_error.png draws the same.",
            "",
        ]
        frows = []
        for mesh, pts in fr.items():
            for m, e, t, on in pts:
                frows.append([md_cell(mesh), md_cell(m), fmt_num(t), fmt_err(e),
                              "front" if on else ""])
        out += md_table(["mesh", "method", "pre+query s", "mean rel. error", "front"],
                        ["l", "l", "r", "r", "l"], frows)
    else:
        out.append("No mesh with a time and an error for its methods.")

    out += ["", "## Provenance", ""]
    out.append("- inputs: " + ", ".join(f"`{md_cell(p)}` ({n} lines)" for p, n in inputs))
    for key, label in (("git", "git"), ("compiler_flags", "compiler flags"),
                       ("threads", "threads")):
        vals = sorted({str(r.get(key)) for r in report.records if r.get(key) is not None})
        out.append(f"- {label}: " + (", ".join(f"`{md_cell(v)}`" for v in vals) if vals else DASH))
    stamps = sorted(r.get("timestamp") for r in report.records
                    if isinstance(r.get("timestamp"), str))
    if not stamps:
        out.append(f"- timestamps: {DASH}")
    elif stamps[0] == stamps[-1]:
        out.append(f"- timestamp: {stamps[0]}")
    else:
        out.append(f"- timestamps: {stamps[0]} \u2013 {stamps[-1]}")
    for note in report.notes:
        out.append(f"- note: {note}")
    out += ["", f"Generated by: `{command}`", ""]
    return "\n".join(out)


# --------------------------------------------------------------------------------------------
# Plots


def import_pyplot():
    try:
        import matplotlib
    except ImportError:
        raise ReportError(f"matplotlib is not available to {sys.executable}; install "
                          "python3-matplotlib (apt-get install python3-matplotlib) and run "
                          "with /usr/bin/python3, or pass --no-plots") from None
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    return plt


MARKERS = ("o", "s", "^", "D", "v", "P", "X", "*", "<", ">")


def _series(report, value):
    """{(family, method): [(V, y), ...]} with positive V and y, sorted by V."""
    out = OrderedDict()
    for r in report.rows:
        y = value(r)
        if r.vertices is None or y is None or y <= 0:
            continue
        out.setdefault((r.family, r.method), []).append((r.vertices, y))
    for pts in out.values():
        pts.sort()
    return out


def _styles(report):
    methods, families = [], []
    for r in report.rows:
        if r.method not in methods:
            methods.append(r.method)
        if r.family not in families:
            families.append(r.family)
    colors = {m: f"C{i % 10}" for i, m in enumerate(methods)}
    markers = {f: MARKERS[i % len(MARKERS)] for i, f in enumerate(families)}
    return colors, markers


def _draw(ax, series, colors, markers, label_extra=None, linestyle="-"):
    for (family, method), pts in series.items():
        label = f"{method} ({family})"
        if label_extra:
            label += label_extra(family, method)
        ax.plot([v for v, _ in pts], [y for _, y in pts], linestyle=linestyle,
                marker=markers[family], color=colors[method], label=label)
    if series:
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.grid(True, which="both", alpha=0.3)
        ax.legend(fontsize="small")
    else:
        ax.text(0.5, 0.5, "no positive values to plot", ha="center", va="center",
                transform=ax.transAxes)
    ax.set_xlabel("vertices |V|")


def window_series(report):
    """{(mesh, anchor): [(window, mean error vs reference, query s), ...]} for the runs that
    carry options.window (the windowed curvature flow), sorted by window; only meshes with at
    least two windows."""
    out = OrderedDict()
    for r in report.rows:
        if r.window is None or r.query is None:
            continue
        out.setdefault((r.mesh_info.mesh, r.anchor), []).append((r.window, r.mean_err, r.query))
    # Sorted by window only: the error is None when the runs had no reference.
    return OrderedDict((k, sorted(v, key=lambda t: t[0])) for k, v in out.items() if len(v) >= 2)


def render_plots(report, title, plt, paths):
    colors, markers = _styles(report)
    query_path, error_path, memory_path, window_path, front_path = paths

    def k_label(family, method):
        s = report.scaling_for(family, method)
        return f" k={s.k_query:.2f}" if s is not None and s.k_query is not None else ""

    fig, ax = plt.subplots(figsize=(8, 5.5))
    _draw(ax, _series(report, lambda r: r.query), colors, markers, k_label)
    ax.set_ylabel("query time, median [s]")
    ax.set_title(f"{title}: query time (k: fitted exponent, time \u221d V^k)")
    fig.tight_layout()
    fig.savefig(query_path, format="png", dpi=120)
    plt.close(fig)

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5.5))
    _draw(ax1, _series(report, lambda r: r.mean_err), colors, markers)
    ax1.set_ylabel("mean relative error")
    ax1.set_title("vs reference method")
    _draw(ax2, _series(report, lambda r: r.mean_err_truth), colors, markers, linestyle="--")
    ax2.set_ylabel("mean relative error")
    ax2.set_title("vs analytic truth")
    fig.suptitle(f"{title}: mean relative error")
    fig.tight_layout()
    fig.savefig(error_path, format="png", dpi=120)
    plt.close(fig)

    fig, ax = plt.subplots(figsize=(8, 5.5))
    _draw(ax, _series(report, lambda r: None if r.peak_rss is None else r.peak_rss / 1e6),
          colors, markers)
    ax.set_ylabel("peak RSS, median [MB]")
    ax.set_title(f"{title}: peak memory")
    fig.tight_layout()
    fig.savefig(memory_path, format="png", dpi=120)
    plt.close(fig)

    fig, (ax1, ax2) = plt.subplots(1, 2, figsize=(13, 5.5))
    series = window_series(report)
    for i, ((mesh, anchor), pts) in enumerate(series.items()):
        label = mesh + (f" ({anchor})" if anchor else "")
        style = dict(marker=MARKERS[i % len(MARKERS)], color=f"C{i % 10}", label=label)
        err = [(w, e) for w, e, _ in pts if e is not None and e > 0]
        ax1.plot([w for w, _ in err], [e for _, e in err], **style)
        ax2.plot([w for w, _, _ in pts], [q for _, _, q in pts], **style)
    for ax, ylabel in ((ax1, "mean relative error vs reference"), (ax2, "query time, median [s]")):
        ax.set_xlabel("window W [samples]")
        ax.set_ylabel(ylabel)
        if series:
            ax.set_xscale("log", base=2)
            ax.set_yscale("log")
            ax.grid(True, which="both", alpha=0.3)
            ax.legend(fontsize="small")
        else:
            ax.text(0.5, 0.5, "no runs with options.window", ha="center", va="center",
                    transform=ax.transAxes)
    fig.suptitle(f"{title}: error and time against the window")
    fig.tight_layout()
    fig.savefig(window_path, format="png", dpi=120)
    plt.close(fig)

    render_front(report, title, plt, front_path, colors)


def render_front(report, title, plt, path, colors):
    """One panel per mesh: median pre+query time against mean error, every method a point, the
    front joined by a line; the reference (error 0) drawn at the panel's left edge."""
    fr = front(report)
    n = max(1, len(fr))
    cols = min(3, n)
    rows = (n + cols - 1) // cols
    fig, axes = plt.subplots(rows, cols, figsize=(5.2 * cols, 4.4 * rows), squeeze=False)
    for ax, (mesh, pts) in zip([a for row in axes for a in row], fr.items()):
        errors = [e for _, e, _, _ in pts if e > 0]
        floor = min(errors) / 10 if errors else 1e-16
        for m, e, t, on in pts:
            x = e if e > 0 else floor
            ax.plot([x], [t], marker="o" if on else "x", linestyle="none",
                    color=colors.get(m, "k"), label=m + (" (reference)" if e == 0 else ""))
            ax.annotate(m, (x, t), textcoords="offset points", xytext=(4, 3), fontsize=7)
        line = sorted((e if e > 0 else floor, t) for _, e, t, on in pts if on)
        ax.plot([x for x, _ in line], [t for _, t in line], color="0.6", linewidth=1, zorder=0)
        ax.set_xscale("log")
        ax.set_yscale("log")
        ax.grid(True, which="both", alpha=0.3)
        ax.set_title(mesh, fontsize=9)
        ax.set_xlabel("mean relative error vs reference")
        ax.set_ylabel("pre+query time, median [s]")
    for ax in [a for row in axes for a in row][len(fr):]:
        ax.axis("off")
    if not fr:
        axes[0][0].text(0.5, 0.5, "no mesh with times and errors", ha="center", va="center",
                        transform=axes[0][0].transAxes)
    fig.suptitle(f"{title} (o: on the front, x: dominated)")
    fig.tight_layout()
    fig.savefig(path, format="png", dpi=110)
    plt.close(fig)


# --------------------------------------------------------------------------------------------
# Output


def _umask():
    mask = os.umask(0)
    os.umask(mask)
    return mask


def write_outputs(out_dir, names, render):
    """Render every output to a temporary name in out_dir, then rename them all.

    render(tmp_paths) receives {name: temporary path}. If anything fails, the temporaries are
    removed and no final file is touched.
    """
    try:
        os.makedirs(out_dir, exist_ok=True)
    except OSError as e:
        raise ReportError(f"{out_dir}: cannot create output directory: {e.strerror}") from None
    tmps = OrderedDict()
    try:
        for name in names:
            fd, tmps[name] = tempfile.mkstemp(prefix=f".{name}.", suffix=".tmp", dir=out_dir)
            os.close(fd)
            os.chmod(tmps[name], 0o666 & ~_umask())  # mkstemp makes 0600; outputs are shared
        render(tmps)
        finals = []
        for name, tmp in tmps.items():
            final = os.path.join(out_dir, name)
            os.replace(tmp, final)
            finals.append(final)
        return finals
    except OSError as e:
        raise ReportError(f"{out_dir}: cannot write output: {e}") from None
    finally:
        for tmp in tmps.values():
            if os.path.exists(tmp):
                os.unlink(tmp)


def command_line(argv):
    script = os.path.abspath(__file__)
    rel = os.path.relpath(script)
    script = script if rel.startswith("..") else rel
    return shlex.join([script] + list(argv))


def parse_args(argv):
    p = argparse.ArgumentParser(
        prog="bench_report.py",
        description="Turn `tapeline bench geodesic` JSON lines into Markdown tables and PNG plots.")
    p.add_argument("inputs", nargs="+", metavar="FILE.jsonl", help="benchmark JSON lines")
    p.add_argument("--out-dir", required=True, help="directory for table.md and the PNG plots")
    p.add_argument("--title", default="Geodesic benchmark", help="heading of table and plots")
    p.add_argument("--reference", metavar="METHOD",
                   help="method the time ratio divides by (default: the lines' `reference`)")
    p.add_argument("--no-plots", action="store_true", help="write table.md only (no matplotlib)")
    return p.parse_args(argv)


def main(argv=None):
    argv = sys.argv[1:] if argv is None else list(argv)
    args = parse_args(argv)
    try:
        plt = None if args.no_plots else import_pyplot()  # fail before any work is written
        records = read_records(args.inputs)
        report = build_report(records, args.reference)
        line_counts = Counter(r.where.rsplit(":", 1)[0] for r in records)
        inputs = [(p, line_counts.get(p, 0)) for p in args.inputs]
        text = render_table(report, args.title, command_line(argv), inputs)

        names = [TABLE_NAME] + ([] if plt is None else list(PLOT_NAMES))

        def render(tmps):
            with open(tmps[TABLE_NAME], "w", encoding="utf-8") as f:
                f.write(text)
            if plt is not None:
                render_plots(report, args.title, plt, [tmps[n] for n in PLOT_NAMES])
        for path in write_outputs(args.out_dir, names, render):
            print(path)
    except ReportError as e:
        print(f"{PROG}: error: {e}", file=sys.stderr)
        return 1
    return 0


if __name__ == "__main__":
    sys.exit(main())
