#!/usr/bin/python3
"""Tests for benchmarks/scripts/bench_report.py (JSON lines -> Markdown tables and PNG plots).

Run from the repository root:
    /usr/bin/python3 -m unittest discover -s tests/scripts -v
    /usr/bin/python3 tests/scripts/test_bench_report.py

The script is driven as a user drives it (subprocess: exit codes, stderr, files written) and, for
checks finer than the table's printed precision, imported as a module.
"""

import importlib.util
import json
import os
import re
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "benchmarks" / "scripts" / "bench_report.py"
DASH = "\u2013"
PLOTS = ("query_time_vs_vertices.png", "error_vs_vertices.png", "memory_vs_vertices.png",
         "window_sweep.png", "time_vs_error.png")


def load_module():
    spec = importlib.util.spec_from_file_location("bench_report", SCRIPT)
    module = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(module)
    return module


def have_matplotlib():
    return importlib.util.find_spec("matplotlib") is not None


def line(method, mesh, vertices, status="ok", **kw):
    rec = {
        "method": method, "mesh": mesh, "family": mesh.split(":")[0], "mesh_file": None,
        "vertices": vertices, "faces": 2 * vertices - 4, "mean_edge_length": 0.1, "source": 0,
        "repetition": 0, "options": {}, "pre_seconds": 0.0, "query_seconds": 0.0,
        "peak_rss_bytes": 30e6 + 500 * vertices, "base_rss_bytes": 30e6, "reference": "ref",
        "mean_rel_error": 0.0, "max_rel_error": 0.0, "truth": None,
        "mean_rel_error_truth": None, "max_rel_error_truth": None, "status": status,
        "message": "", "git": "3e439db", "compiler_flags": "GNU 12.2.0 -O3 -DNDEBUG",
        "threads": 1, "timestamp": "2026-11-21T04:00:00Z",
    }
    rec.update(kw)
    return rec


SIZES = (100, 400, 1600, 6400)
C_SLOW, C_FAST = 1e-4, 1e-3  # query = C_SLOW * V^1.5 and C_FAST * V; both 0.1 s at V = 100
SLOW_SPREAD = (0.5, 1.0, 4.0)  # odd number of repetitions: the median is the middle one
FAST_SPREAD = (0.5, 0.9, 1.1, 4.0)  # even number: the median is the mean of 0.9 and 1.1
REF_PRE, REF_QUERY = 0.3, 0.1


def scaling_lines():
    """Exact power laws: pre = 2 query, so pre+query has the same exponent as query."""
    out = []
    for v in SIZES:
        mesh = f"sphere:{v}"
        for rep in range(3):
            out.append(line("ref", mesh, v, repetition=rep, pre_seconds=REF_PRE,
                            query_seconds=REF_QUERY))
        q = C_SLOW * v ** 1.5
        for rep, f in enumerate(SLOW_SPREAD):
            out.append(line("slow", mesh, v, repetition=rep, pre_seconds=2 * q * f,
                            query_seconds=q * f, mean_rel_error=1e-3 * (rep + 1),
                            max_rel_error=1e-2 * (rep + 1), truth="great circle",
                            mean_rel_error_truth=2e-3, max_rel_error_truth=5e-3))
        q = C_FAST * v
        for rep, f in enumerate(FAST_SPREAD):
            out.append(line("fast", mesh, v, repetition=rep, pre_seconds=2 * q * f,
                            query_seconds=q * f, mean_rel_error=4e-2, max_rel_error=9e-2))
    # Runs that did not finish: counted, listed, and their (bogus) timings never enter a median.
    out.append(line("fast", "sphere:6400", 6400, status="timeout", repetition=4,
                    pre_seconds=None, query_seconds=None, message="budget of 60 s exceeded"))
    out.append(line("slow", "sphere:100", 100, status="crash", repetition=3,
                    pre_seconds=1e6, query_seconds=1e6, message="signal 11"))
    out.append(line("slow", "sphere:100", 100, status="crash", repetition=4,
                    pre_seconds=1e6, query_seconds=1e6, message="second crash, not listed"))
    return out


def write_jsonl(path, records, extra_text=""):
    with open(path, "w", encoding="utf-8") as f:
        for rec in records:
            f.write(json.dumps(rec) + "\n")
        f.write(extra_text)


def split_row(text):
    cells = re.split(r"(?<!\\)\|", text.strip())[1:-1]
    return [c.strip().replace("\\|", "|") for c in cells]


def parse_tables(markdown):
    """Every Markdown table in the text, as a list of {header: cell} dicts."""
    tables, lines, i = [], markdown.splitlines(), 0
    while i < len(lines):
        if lines[i].startswith("|") and i + 1 < len(lines) and lines[i + 1].startswith("|:-"):
            header = split_row(lines[i])
            i += 2
            rows = []
            while i < len(lines) and lines[i].startswith("|"):
                rows.append(dict(zip(header, split_row(lines[i]))))
                i += 1
            tables.append(rows)
        else:
            i += 1
    return tables


class ScriptTestCase(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="bench_report_test_")
        self.tmp = Path(self._tmp.name)
        self.out = self.tmp / "out"

    def tearDown(self):
        self._tmp.cleanup()

    def run_script(self, *args, env_extra=None):
        env = dict(os.environ)
        env["MPLCONFIGDIR"] = str(self.tmp / "mplconfig")  # no writes to $HOME, no cache warnings
        env.update(env_extra or {})
        return subprocess.run([sys.executable, str(SCRIPT), *map(str, args)], env=env,
                              capture_output=True, text=True, timeout=120)

    def report_ok(self, records, *extra_args):
        src = self.tmp / "results.jsonl"
        write_jsonl(src, records)
        proc = self.run_script(src, "--out-dir", self.out, *extra_args)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        text = (self.out / "table.md").read_text(encoding="utf-8")
        return proc, text

    def assert_fails(self, proc, *fragments):
        self.assertNotEqual(proc.returncode, 0)
        err = proc.stderr.strip()
        self.assertEqual(len(err.splitlines()), 1, f"expected one line on stderr, got:\n{err}")
        self.assertTrue(err.startswith("bench_report: error: "), err)
        for fragment in fragments:
            self.assertIn(fragment, err)
        self.assertFalse(self.out.exists() and any(self.out.iterdir()),
                         "nothing may be written on error")


class TableTest(ScriptTestCase):
    def setUp(self):
        super().setUp()
        self.proc, self.text = self.report_ok(scaling_lines(), "--no-plots", "--title", "Synthetic")
        self.main, self.scaling, self.front = parse_tables(self.text)

    def row(self, method, vertices):
        matches = [r for r in self.main if r["method"] == method and r["|V|"] == str(vertices)]
        self.assertEqual(len(matches), 1, self.text)
        return matches[0]

    def test_fitted_exponents_in_scaling_table(self):
        fits = {r["method"]: r for r in self.scaling}
        self.assertEqual(set(fits), {"ref", "slow", "fast"})
        for method, k in (("slow", 1.5), ("fast", 1.0), ("ref", 0.0)):
            self.assertEqual(fits[method]["family"], "sphere")
            self.assertEqual(fits[method]["meshes"], "4")
            self.assertEqual(fits[method]["V range"], f"100{DASH}6400")
            for column in ("k query", "k pre+query"):
                self.assertAlmostEqual(float(fits[method][column]), k, delta=5e-4)
                self.assertEqual(fits[method][column], f"{k:.3f}")

    def test_fitted_exponents_to_1e_6(self):
        # The table prints 3 decimals; the values behind it must be exact to 1e-6.
        module = load_module()
        src = self.tmp / "results.jsonl"
        report = module.build_report(module.read_records([str(src)]))
        for method, k in (("slow", 1.5), ("fast", 1.0)):
            fit = report.scaling_for("sphere", method)
            self.assertAlmostEqual(fit.k_query, k, delta=1e-6)
            self.assertAlmostEqual(fit.k_total, k, delta=1e-6)
            self.assertAlmostEqual(fit.query_fit[1], 1.0, delta=1e-9)  # R^2 of an exact law

    def test_fit_exponent_function(self):
        module = load_module()
        k, r2, pts = module.fit_exponent([(10, 3.0 * 10 ** 2.25), (1000, 3.0 * 1000 ** 2.25),
                                          (50, 0.0), (70, None)])
        self.assertAlmostEqual(k, 2.25, delta=1e-12)
        self.assertEqual(len(pts), 2)  # zero and missing times are left out
        self.assertIsNone(module.fit_exponent([(10, 1.0), (10, 2.0)]))  # one distinct V only

    def test_medians_over_repetitions(self):
        # Odd repetitions (slow): median is the middle value; even (fast): mean of the two middle.
        # The crash lines' 1e6 s must not count.
        self.assertEqual(self.row("slow", 100)["query s (median)"], "0.100")
        self.assertEqual(self.row("slow", 100)["pre s (median)"], "0.200")
        self.assertEqual(self.row("fast", 400)["query s (median)"], "0.400")
        self.assertEqual(self.row("fast", 400)["pre s (median)"], "0.800")

    def test_even_median_is_mean_of_middle_pair(self):
        recs = [line("m", "box:8", 8, repetition=i, pre_seconds=p, query_seconds=q)
                for i, (p, q) in enumerate(((1.0, 1.0), (2.0, 4.0), (3.0, 5.0), (10.0, 9.0)))]
        recs += [line("n", "box:8", 8, repetition=i, pre_seconds=p)
                 for i, p in enumerate((1.0, 2.0, 10.0))]
        _, text = self.report_ok(recs, "--no-plots")
        rows = {r["method"]: r for r in parse_tables(text)[0]}
        self.assertEqual(rows["m"]["pre s (median)"], "2.50")
        self.assertEqual(rows["m"]["query s (median)"], "4.50")
        self.assertEqual(rows["n"]["pre s (median)"], "2.00")

    def test_ratio_against_reference(self):
        # ref: pre+query = 0.4 s everywhere; slow and fast: pre+query = 3 query.
        self.assertEqual(self.row("ref", 100)["time ratio vs ref"], "1.00")
        self.assertEqual(self.row("slow", 100)["time ratio vs ref"], "0.750")
        self.assertEqual(self.row("fast", 100)["time ratio vs ref"], "0.750")
        self.assertEqual(self.row("slow", 400)["time ratio vs ref"], "6.00")
        self.assertEqual(self.row("fast", 400)["time ratio vs ref"], "3.00")
        self.assertEqual(self.row("slow", 1600)["time ratio vs ref"], "48.0")

    def test_reference_override(self):
        _, text = self.report_ok(scaling_lines(), "--no-plots", "--reference", "fast")
        rows = [r for r in parse_tables(text)[0] if r["|V|"] == "400"]
        self.assertEqual([r["method"] for r in rows], ["fast", "ref", "slow"])  # reference first
        ratio = {r["method"]: r["time ratio vs ref"] for r in rows}
        self.assertEqual(ratio, {"fast": "1.00", "ref": "0.333", "slow": "2.00"})

    def test_no_reference_lines_gives_dash(self):
        recs = [line("heat", "box:8", 8, pre_seconds=1.0, query_seconds=1.0)]
        _, text = self.report_ok(recs, "--no-plots")
        self.assertEqual(parse_tables(text)[0][0]["time ratio vs ref"], DASH)

    def test_errors_and_null_truth(self):
        slow = self.row("slow", 1600)
        self.assertEqual(slow["mean rel err vs ref"], "2.00e-03")  # mean of 1e-3, 2e-3, 3e-3
        self.assertEqual(slow["max rel err vs ref"], "3.00e-02")
        self.assertEqual(slow["mean rel err vs truth"], "2.00e-03")
        self.assertEqual(slow["max rel err vs truth"], "5.00e-03")
        fast = self.row("fast", 1600)
        self.assertEqual(fast["mean rel err vs truth"], DASH)
        self.assertEqual(fast["max rel err vs truth"], DASH)
        self.assertEqual(self.row("ref", 1600)["mean rel err vs ref"], "0")

    def test_memory_columns(self):
        r = self.row("fast", 1600)  # peak RSS = 30e6 + 500 * 1600 bytes
        self.assertEqual(r["peak RSS MB (median)"], "30.8")
        self.assertEqual(r["KB/vertex"], "19.2")

    def test_rows_grouped_by_family_vertices_method(self):
        extra = [line("heat", "ball:1", 50), line("heat", "ball:2", 200)]
        _, text = self.report_ok(scaling_lines() + extra, "--no-plots")
        order = [(r["family"], int(r["|V|"]), r["method"]) for r in parse_tables(text)[0]]
        self.assertEqual(order[:2], [("ball", 50, "heat"), ("ball", 200, "heat")])
        self.assertEqual(order[2:5], [("sphere", 100, "ref"), ("sphere", 100, "fast"),
                                      ("sphere", 100, "slow")])
        self.assertEqual([v for _, v, _ in order], sorted(v for _, v, _ in order[:2])
                         + sorted(v for _, v, _ in order[2:]))

    def test_non_ok_runs_counted_and_listed(self):
        self.assertEqual(self.row("fast", 6400)["runs ok/total"], "4/5")
        self.assertEqual(self.row("slow", 100)["runs ok/total"], "3/5")
        self.assertEqual(self.row("slow", 400)["runs ok/total"], "3/3")
        n_lines = len(scaling_lines())
        self.assertIn(f"Runs not ok: 3 of {n_lines}.", self.text)
        listed = [ln for ln in self.text.splitlines() if ln.startswith("- `")]
        self.assertEqual(len(listed), 2, self.text)
        self.assertIn("`fast` on `sphere:6400`: timeout \u00d71", self.text)
        self.assertIn("budget of 60 s exceeded", self.text)
        self.assertIn("`slow` on `sphere:100`: crash \u00d72", self.text)
        self.assertIn("signal 11", self.text)  # first occurrence only
        self.assertNotIn("second crash", self.text)

    def test_time_error_front(self):
        # ref: exact, slow; fast: quick and rough; mid: in between on both; worse: slower and
        # rougher than mid (dominated); tie: as fast as fast but rougher (dominated).
        lines = [line("ref", "m:1", 100, pre_seconds=0.0, query_seconds=1.0),
                 line("fast", "m:1", 100, query_seconds=0.01, mean_rel_error=0.1),
                 line("mid", "m:1", 100, query_seconds=0.1, mean_rel_error=0.01),
                 line("worse", "m:1", 100, query_seconds=0.2, mean_rel_error=0.02),
                 line("tie", "m:1", 100, query_seconds=0.01, mean_rel_error=0.2),
                 line("noerr", "m:1", 100, query_seconds=0.05, mean_rel_error=None)]
        module = load_module()
        src = self.tmp / "results.jsonl"
        write_jsonl(src, lines)
        fr = module.front(module.build_report(module.read_records([str(src)])))
        self.assertEqual(list(fr), ["m:1"])
        got = {m: (e, t, on) for m, e, t, on in fr["m:1"]}
        self.assertEqual(set(got), {"ref", "fast", "mid", "worse", "tie"})
        self.assertEqual([m for m, _, _, on in fr["m:1"] if on], ["fast", "mid", "ref"])
        self.assertEqual(got["ref"], (0.0, 1.0, True))
        self.assertFalse(got["worse"][2])
        self.assertFalse(got["tie"][2])
        _, table = self.report_ok(lines, "--no-plots")
        self.assertIn("## Time/error front", table)
        self.assertRegex(table, r"\| m:1 \| mid \| 0\.100 \| 1\.00e-02 \| front \|")
        self.assertRegex(table, r"\| m:1 \| worse \| 0\.200 \| 2\.00e-02 \| +\|")

    def test_stdout_lists_files_and_no_temporaries_left(self):
        self.assertEqual(self.proc.stdout.split(), [str(self.out / "table.md")])
        self.assertEqual(sorted(os.listdir(self.out)), ["table.md"])
        self.assertTrue(self.text.startswith("# Synthetic\n"))
        self.assertIn("Generated by: `", self.text)


class InputErrorTest(ScriptTestCase):
    def test_malformed_json_names_file_and_line(self):
        src = self.tmp / "bad.jsonl"
        write_jsonl(src, [line("heat", "box:8", 8)], extra_text='\n{"method": "heat", "mesh":\n')
        proc = self.run_script(src, "--out-dir", self.out, "--no-plots")
        self.assert_fails(proc, f"{src}:3:", "not valid JSON")

    def test_missing_required_key(self):
        for key in ("method", "mesh", "vertices", "status"):
            with self.subTest(key=key):
                rec = line("heat", "box:8", 8)
                del rec[key]
                src = self.tmp / f"no_{key}.jsonl"
                write_jsonl(src, [line("heat", "box:8", 8), rec])
                proc = self.run_script(src, "--out-dir", self.out, "--no-plots")
                self.assert_fails(proc, f"{src}:2:", f"missing required key '{key}'")

    def test_missing_file(self):
        proc = self.run_script(self.tmp / "absent.jsonl", "--out-dir", self.out, "--no-plots")
        self.assert_fails(proc, "absent.jsonl", "no such file")

    def test_empty_input(self):
        src = self.tmp / "empty.jsonl"
        src.write_text("\n  \n", encoding="utf-8")
        proc = self.run_script(src, "--out-dir", self.out, "--no-plots")
        self.assert_fails(proc, "empty input")

    def test_bad_value_types(self):
        cases = (({"status": "exploded"}, "status 'exploded'"),
                 ({"query_seconds": "0.1"}, "'query_seconds' must be a number"),
                 ({"vertices": 0}, "'vertices' must be a positive integer"),
                 ({"vertices": 12.5}, "'vertices' must be a positive integer"),
                 ({"method": None}, "'method' must be a non-empty string"))
        for change, fragment in cases:
            with self.subTest(change=change):
                src = self.tmp / "typed.jsonl"
                rec = line("heat", "box:8", 8)
                rec.update(change)
                write_jsonl(src, [rec])
                proc = self.run_script(src, "--out-dir", self.out, "--no-plots")
                self.assert_fails(proc, f"{src}:1:", fragment)

    def test_error_in_second_file_writes_nothing(self):
        good, bad = self.tmp / "good.jsonl", self.tmp / "bad.jsonl"
        write_jsonl(good, scaling_lines())
        bad.write_text("not json\n", encoding="utf-8")
        proc = self.run_script(good, bad, "--out-dir", self.out, "--no-plots")
        self.assert_fails(proc, f"{bad}:1:")


class PlotTest(ScriptTestCase):
    @unittest.skipUnless(have_matplotlib(), "matplotlib not installed (python3-matplotlib)")
    def test_pngs_written(self):
        proc, _ = self.report_ok(scaling_lines())
        written = proc.stdout.split()
        self.assertEqual(written, [str(self.out / n) for n in ("table.md",) + PLOTS])
        for name in PLOTS:
            data = (self.out / name).read_bytes()
            self.assertGreater(len(data), 1000, name)
            self.assertEqual(data[:8], b"\x89PNG\r\n\x1a\n", name)
        self.assertEqual(sorted(os.listdir(self.out)), sorted(("table.md",) + PLOTS))

    def test_window_series_groups_windowed_runs_by_mesh(self):
        module = load_module()
        lines = [line("ref", "m1", 100, query_seconds=1.0)]
        for w, err, q in ((16, 1e-3, 4.0), (4, 4e-3, 1.0), (8, 2e-3, 2.0)):
            lines.append(line(f"gcf-window:{w}", "m1", 100, query_seconds=q, mean_rel_error=err,
                              options={"window": w, "anchor": "field"}))
        lines.append(line("gcf-window:8", "m2", 50, query_seconds=1.0,
                          options={"window": 8, "anchor": "field"}))  # one window: no curve
        src = self.tmp / "w.jsonl"
        write_jsonl(src, lines)
        report = module.build_report(module.read_records([str(src)]))
        series = module.window_series(report)
        self.assertEqual(list(series.keys()), [("m1", "field")])
        self.assertEqual(series[("m1", "field")],
                         [(4, 4e-3, 1.0), (8, 2e-3, 2.0), (16, 1e-3, 4.0)])

    @unittest.skipUnless(have_matplotlib(), "matplotlib not installed (python3-matplotlib)")
    def test_legend_shows_fitted_exponent(self):
        module = load_module()
        import matplotlib
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        src = self.tmp / "results.jsonl"
        write_jsonl(src, scaling_lines())
        report = module.build_report(module.read_records([str(src)]))
        labels = []
        real_plot = plt.Axes.plot

        def spy(ax, *args, **kw):
            labels.append(kw.get("label"))
            return real_plot(ax, *args, **kw)
        plt.Axes.plot = spy
        try:
            paths = [str(self.tmp / n) for n in PLOTS]
            module.render_plots(report, "T", plt, paths)
        finally:
            plt.Axes.plot = real_plot
        self.assertIn("slow (sphere) k=1.50", labels)
        self.assertIn("fast (sphere) k=1.00", labels)

    def test_table_only_without_matplotlib(self):
        # A matplotlib that cannot be imported stands in for a Python without the package.
        fake = self.tmp / "fake_site"
        (fake / "matplotlib").mkdir(parents=True)
        (fake / "matplotlib" / "__init__.py").write_text("raise ImportError('hidden by test')\n")
        env = {"PYTHONPATH": str(fake)}
        src = self.tmp / "results.jsonl"
        write_jsonl(src, scaling_lines())
        proc = self.run_script(src, "--out-dir", self.out, env_extra=env)
        self.assert_fails(proc, "python3-matplotlib", "--no-plots")
        proc = self.run_script(src, "--out-dir", self.out, "--no-plots", env_extra=env)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        self.assertEqual(sorted(os.listdir(self.out)), ["table.md"])


if __name__ == "__main__":
    unittest.main(verbosity=2)
