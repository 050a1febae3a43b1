#!/usr/bin/python3
"""Compare two result folders of benchmarks/reproduce.sh, ignoring what depends on timings.

usage: compare_results.py A B [--show N]
  A, B: folders holding results.md and results/ (the --out of reproduce.sh), or results/ itself.

Compared: the set of files; every Markdown table of every .md file, cell by cell, except the
columns whose heading names a timing or memory quantity (time, timing, seconds, s, wall, RSS, MB, KB,
ms/..., and the exponents fitted to times: k query, R² query, k pre+query); every .json and .jsonl file, value by value, except keys naming timings, memory or dates
(*seconds*, timings*, wall*, *rss*, timestamp, ms_per*, date) and the revision a line was made by
(git: two revisions can be compared). Text outside tables (provenance, dates, wall time) and the pixels of the plots are not compared; a PNG must exist in both.
Prints every difference (the first N, default 20) and exits 0 when there is none, 1 when there
are some, 2 on a usage error (one line on stderr).
"""
import argparse
import json
import os
import re
import sys

PROG = "compare_results.py"
# bench_report.py's scaling table: "k query", "R² query", "k pre+query" are fitted to timings.
VOLATILE_COLUMN = re.compile(r"time|timing|seconds|\bs\b|wall|rss|\bmb\b|\bkb\b|ms/|date|timestamp|"
                             r"^k query|^k pre|^r² query", re.IGNORECASE)
VOLATILE_KEY = re.compile(r"seconds|^timings|^wall|rss|timestamp|^ms_per|^date$|^time$|^git$",
                          re.IGNORECASE)


def split_row(line):
    """Cells of a Markdown table row; '\\|' is a literal bar."""
    body = line.strip()
    if body.startswith("|"):
        body = body[1:]
    if body.endswith("|") and not body.endswith("\\|"):
        body = body[:-1]
    cells, cur, i = [], "", 0
    while i < len(body):
        if body[i] == "\\" and i + 1 < len(body):
            cur += body[i:i + 2]
            i += 2
            continue
        if body[i] == "|":
            cells.append(cur.strip())
            cur = ""
        else:
            cur += body[i]
        i += 1
    cells.append(cur.strip())
    return cells


def tables(path):
    """Every table of a Markdown file: (line number, header, rows)."""
    with open(path, encoding="utf-8") as f:
        lines = f.read().split("\n")
    out = []
    i = 0
    while i < len(lines):
        if (lines[i].lstrip().startswith("|") and i + 1 < len(lines)
                and re.match(r"^\s*\|?\s*:?-+:?\s*(\||$)", lines[i + 1])):
            header = split_row(lines[i])
            rows, j = [], i + 2
            while j < len(lines) and lines[j].lstrip().startswith("|"):
                rows.append((j + 1, split_row(lines[j])))
                j += 1
            out.append((i + 1, header, rows))
            i = j
        else:
            i += 1
    return out


def compare_md(rel, a, b, diffs):
    ta, tb = tables(a), tables(b)
    if len(ta) != len(tb):
        diffs.append("%s: %d tables against %d" % (rel, len(ta), len(tb)))
    for (la, ha, ra), (lb, hb, rb) in zip(ta, tb):
        if ha != hb:
            diffs.append("%s:%d: table headings differ: %s | %s" % (rel, la, ha, hb))
            continue
        keep = [k for k, h in enumerate(ha) if not VOLATILE_COLUMN.search(h)]
        if len(ra) != len(rb):
            diffs.append("%s:%d: %d rows against %d" % (rel, la, len(ra), len(rb)))
        for (na, ca), (nb, cb) in zip(ra, rb):
            for k in keep:
                va = ca[k] if k < len(ca) else "<missing>"
                vb = cb[k] if k < len(cb) else "<missing>"
                if va != vb:
                    diffs.append("%s:%d: column '%s': %s | %s" % (rel, na, ha[k], va, vb))


def strip(v):
    if isinstance(v, dict):
        return {k: strip(x) for k, x in v.items() if not VOLATILE_KEY.search(k)}
    if isinstance(v, list):
        return [strip(x) for x in v]
    return v


def walk(a, b, where, diffs):
    if isinstance(a, dict) and isinstance(b, dict):
        for k in sorted(set(a) | set(b)):
            if k not in a or k not in b:
                diffs.append("%s: key '%s' only in %s" % (where, k, "A" if k in a else "B"))
            else:
                walk(a[k], b[k], "%s.%s" % (where, k), diffs)
    elif isinstance(a, list) and isinstance(b, list):
        if len(a) != len(b):
            diffs.append("%s: %d items against %d" % (where, len(a), len(b)))
        for i, (x, y) in enumerate(zip(a, b)):
            walk(x, y, "%s[%d]" % (where, i), diffs)
    elif a != b:
        diffs.append("%s: %s | %s" % (where, json.dumps(a)[:80], json.dumps(b)[:80]))


def load_json(path):
    with open(path, encoding="utf-8") as f:
        text = f.read()
    if path.endswith(".jsonl"):
        return [json.loads(line) for line in text.split("\n") if line.strip()]
    return json.loads(text)


def files(root):
    out = set()
    for d, _, fs in os.walk(root):
        for f in fs:
            if not f.startswith("."):
                out.add(os.path.relpath(os.path.join(d, f), root))
    return out


def base_of(folder):
    if os.path.isfile(os.path.join(folder, "results.md")):
        return folder, ["results.md"], os.path.join(folder, "results")
    if os.path.isdir(folder):
        return os.path.dirname(os.path.abspath(folder)), [], folder
    raise ValueError("%s: no such folder" % folder)


def compare(a, b):
    diffs = []
    (ba, top_a, ra), (bb, top_b, rb) = base_of(a), base_of(b)
    fa = {os.path.join("results", f) for f in files(ra)} | set(top_a)
    fb = {os.path.join("results", f) for f in files(rb)} | set(top_b)
    for f in sorted(fa ^ fb):
        diffs.append("%s: only in %s" % (f, "A" if f in fa else "B"))
    for rel in sorted(fa & fb):
        pa, pb = os.path.join(ba, rel), os.path.join(bb, rel)
        if rel.endswith(".md"):
            compare_md(rel, pa, pb, diffs)
        elif rel.endswith(".json") or rel.endswith(".jsonl"):
            try:
                walk(strip(load_json(pa)), strip(load_json(pb)), rel, diffs)
            except ValueError as e:
                diffs.append("%s: not valid JSON (%s)" % (rel, e))
    return diffs


class Parser(argparse.ArgumentParser):
    def error(self, message):
        print("%s: error: %s" % (PROG, message), file=sys.stderr)
        sys.exit(2)


def main(argv):
    p = Parser(prog=PROG, description="Compare two reproduce.sh result folders, ignoring "
               "timings.")
    p.add_argument("a")
    p.add_argument("b")
    p.add_argument("--show", type=int, default=20, help="differences printed (default 20)")
    args = p.parse_args(argv)
    try:
        diffs = compare(args.a, args.b)
    except (ValueError, OSError) as e:
        print("%s: error: %s" % (PROG, e), file=sys.stderr)
        return 2
    for d in diffs[:args.show]:
        print(d)
    if len(diffs) > args.show:
        print("... and %d more" % (len(diffs) - args.show))
    print("%s: %s" % (PROG, "identical apart from timings" if not diffs else
                      "%d difference(s)" % len(diffs)), file=sys.stderr)
    return 1 if diffs else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1:]))
