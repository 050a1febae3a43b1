#!/usr/bin/python3
"""Smoke test of benchmarks/reproduce.sh: bad options are refused with one line and exit 2 and
write nothing; `--smoke` runs to the end and writes results.md with every claim's section, its
verdict, tables that parse, the provenance under every table, and the plots and files it links;
a part that fails is reported in results.md and the command exits 1; compare_results.py finds a
changed figure and ignores a changed timing.

usage: test_reproduce_smoke.py TAPELINE SOURCE_DIR WORK_DIR
"""
import json
import os
import re
import shutil
import stat
import subprocess
import sys
import unittest

TOOL, SRC, WORK = (os.path.abspath(a) for a in sys.argv[1:4])
del sys.argv[1:4]
SCRIPT = os.path.join(SRC, "benchmarks", "reproduce.sh")
COMPARE = os.path.join(SRC, "benchmarks", "scripts", "compare_results.py")
sys.path.insert(0, os.path.join(SRC, "benchmarks", "scripts"))
import compare_results  # noqa: E402  (its Markdown table reader)

# Every section results.md must have: the thesis's four claims and the project's own figures.
SECTIONS = ["(a)", "(b)", "(c)", "(d)", "Exact MMP", "Measurement", "Grading", "Drape", "Fabric",
            "Wrinkle", "Peers"]
VERDICTS = {"holds", "does not hold", "undecided", "figure", "not run"}
PROVENANCE = re.compile(r"^_Provenance: repository git \S+; tool .+ \(git \S+\); compiler \S.*; "
                        r"flags `[^`]*`; threads \d+; machine \S.*, \d+ cores; date "
                        r"\d{4}-\d\d-\d\d \d\d:\d\d UTC; mode \w+, seed \d+\._$")


def run(args, **kw):
    return subprocess.run([SCRIPT] + args, capture_output=True, text=True, timeout=600, **kw)


def sections(text):
    parts = re.split(r"^## ", text, flags=re.M)
    return {p.split("\n", 1)[0]: p for p in parts[1:]}


def edit_table(md, column):
    """Append a digit to the first row's cell of the column whose heading contains COLUMN."""
    with open(md, encoding="utf-8") as f:
        lines = f.read().split("\n")
    lineno, header, rows = compare_results.tables(md)[0]
    k = next(i for i, h in enumerate(header) if column in h)
    n, cells = rows[0]
    cells[k] = cells[k] + "9"
    lines[n - 1] = "| " + " | ".join(cells) + " |"
    with open(md, "w", encoding="utf-8") as f:
        f.write("\n".join(lines))


def edit_jsonl(js, key):
    """Change KEY's value (a string or a number) in the first JSON line that has it."""
    with open(js, encoding="utf-8") as f:
        lines = [json.loads(line) for line in f if line.strip()]
    line = next(x for x in lines if key in x and isinstance(x[key], (str, float)))
    line[key] = line[key] + ("x" if isinstance(line[key], str) else 0.5)
    with open(js, "w", encoding="utf-8") as f:
        f.write("".join(json.dumps(x) + "\n" for x in lines))


class Reproduce(unittest.TestCase):
    smoke = os.path.join(WORK, "smoke")
    result = None

    @classmethod
    def setUpClass(cls):
        shutil.rmtree(WORK, ignore_errors=True)
        os.makedirs(WORK)
        cls.result = run(["--smoke", "--out", cls.smoke, "--tool", TOOL])

    def test_bad_options_write_nothing(self):
        for args in (["--smoke", "--bogus"], ["--smoke", "--quick"],
                     ["--smoke", "--tool", os.path.join(WORK, "no_such_tool")],
                     ["--smoke", "--only", "zz"], ["--smoke", "--peers", os.path.join(WORK, "no")]):
            out = os.path.join(WORK, "bad")
            p = run(args + ["--out", out] + ([] if "--tool" in args else ["--tool", TOOL]))
            with self.subTest(args=args):
                self.assertEqual(p.returncode, 2, p.stderr)
                lines = [line for line in p.stderr.split("\n") if line.strip()]
                self.assertEqual(len(lines), 1, p.stderr)
                self.assertTrue(lines[0].startswith("reproduce.sh: error: "), lines[0])
                self.assertFalse(os.path.exists(out))

    def test_smoke_run(self):
        p = self.result
        self.assertEqual(p.returncode, 0, p.stderr[-3000:])
        self.assertIn("[1/", p.stderr)  # progress on stderr
        md = os.path.join(self.smoke, "results.md")
        with open(md, encoding="utf-8") as f:
            text = f.read()
        secs = sections(text)
        for want in SECTIONS:
            with self.subTest(section=want):
                found = [s for t, s in secs.items() if t.startswith(want)]
                self.assertEqual(len(found), 1, "section %s" % want)
                m = re.search(r"^\*\*Verdict: ([a-z ]+)\*\*", found[0], re.M)
                self.assertIsNotNone(m, "no verdict in %s" % want)
                self.assertIn(m.group(1), VERDICTS)
                self.assertIn("|", found[0], "no table in %s" % want)
        # The synthetic body measured against its exact girths: all 25 within tolerance.
        meas = next(s for t, s in secs.items() if t.startswith("Measurement"))
        self.assertRegex(meas, r"\| body:40,10 \| \d+ \| 25 \| [\d.]+ \(\w+, tolerance [\d.]+\) "
                               r"\| none \|")
        lines = text.split("\n")
        tables = compare_results.tables(md)
        self.assertGreaterEqual(len(tables), len(SECTIONS) + 1)
        for lineno, header, rows in tables:
            with self.subTest(table=lineno):
                self.assertGreater(len(rows), 0)
                for n, cells in rows:
                    self.assertEqual(len(cells), len(header), "line %d" % n)
                end = rows[-1][0]  # the provenance line follows the table
                self.assertRegex(lines[end + 1], PROVENANCE)
        # Every link and image of results.md exists; plots are PNGs.
        links = re.findall(r"\]\((results/[^)]+)\)", text)
        self.assertTrue(any(link.endswith(".png") for link in links))
        for link in links:
            path = os.path.join(self.smoke, link)
            with self.subTest(link=link):
                self.assertTrue(os.path.isfile(path))
                if path.endswith(".png"):
                    with open(path, "rb") as f:
                        self.assertEqual(f.read(8), b"\x89PNG\r\n\x1a\n")
        leftovers = [f for f in os.listdir(self.smoke) if f.startswith(".")]
        self.assertEqual(leftovers, [])

    def test_compare(self):
        self.assertEqual(self.result.returncode, 0)
        same = subprocess.run([COMPARE, self.smoke, self.smoke], capture_output=True, text=True)
        self.assertEqual(same.returncode, 0, same.stdout)
        # A changed timing is ignored, a changed figure is not.
        for column, expect in (("time", 0), ("err", 1)):
            with self.subTest(column=column):
                self.assertEqual(self.compare_edited("table.md", column, edit_table), expect)
        # In the JSON lines: the revision that made a line is ignored, a changed error is not.
        for key, expect in (("git", 0), ("mean_rel_error", 1)):
            with self.subTest(key=key):
                self.assertEqual(self.compare_edited("exact_mmp.jsonl", key, edit_jsonl), expect)

    def compare_edited(self, name, what, edit):
        """compare_results.py's exit code between the smoke run and a copy of it whose
        results/exact_mmp/NAME had WHAT changed by edit(path, what)."""
        copy = os.path.join(WORK, "copy_%s_%s" % (name, what))
        shutil.rmtree(copy, ignore_errors=True)
        shutil.copytree(self.smoke, copy)
        edit(os.path.join(copy, "results", "exact_mmp", name), what)
        p = subprocess.run([COMPARE, self.smoke, copy], capture_output=True, text=True)
        return p.returncode

    def test_failing_part(self):
        # A tool whose `fabric` command fails: that part is reported, the command exits 1.
        fake = os.path.join(WORK, "failing_tool")
        with open(fake, "w") as f:
            f.write('#!/bin/sh\nfor a in "$@"; do [ "$a" = fabric ] && { echo "tapeline: '
                    'error: broken on purpose" >&2; exit 3; }; done\nexec "%s" "$@"\n' % TOOL)
        os.chmod(fake, os.stat(fake).st_mode | stat.S_IXUSR)
        out = os.path.join(WORK, "failing")
        p = run(["--smoke", "--only", "fabric,wrinkles", "--out", out, "--tool", fake])
        self.assertEqual(p.returncode, 1, p.stderr[-2000:])
        with open(os.path.join(out, "results.md"), encoding="utf-8") as f:
            text = f.read()
        fabric = next(s for t, s in sections(text).items() if t.startswith("Fabric"))
        self.assertIn("**Verdict: failed**", fabric)
        self.assertIn("broken on purpose", fabric)


if __name__ == "__main__":
    unittest.main(verbosity=2)
