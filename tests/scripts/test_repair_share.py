#!/usr/bin/python3
"""Tests for benchmarks/scripts/repair_share.py (gcf JSON lines -> where the flow's time goes).

    /usr/bin/python3 tests/scripts/test_repair_share.py
"""

import json
import subprocess
import sys
import tempfile
import unittest
from pathlib import Path

ROOT = Path(__file__).resolve().parents[2]
SCRIPT = ROOT / "benchmarks" / "scripts" / "repair_share.py"


def line(method, mesh, vertices, query, repair, flows, steps, err, status="ok"):
    return {"method": method, "mesh": mesh, "vertices": vertices, "query_seconds": query,
            "repair_seconds": repair, "flows": flows, "flow_iterations": steps,
            "mean_rel_error": err, "status": status}


class RepairShareTest(unittest.TestCase):
    def setUp(self):
        self._tmp = tempfile.TemporaryDirectory(prefix="repair_share_test_")
        self.tmp = Path(self._tmp.name)

    def tearDown(self):
        self._tmp.cleanup()

    def run_script(self, lines):
        src = self.tmp / "in.jsonl"
        src.write_text("".join(json.dumps(r) + "\n" if isinstance(r, dict) else r
                               for r in lines))
        out = self.tmp / "out.md"
        proc = subprocess.run([sys.executable, str(SCRIPT), str(src), str(out)],
                              capture_output=True, text=True, timeout=60)
        return proc, out

    def test_medians_shares_and_per_vertex_counts(self):
        rows = [line("gcf-window:8/faces", "a/b/m.off", 100, q, r, 400, 5000, 1e-4)
                for q, r in ((2.0, 0.5), (4.0, 1.0), (3.0, 3.0))]
        rows.append(line("exact-mmp", "a/b/m.off", 100, 1.0, None, None, None, 0.0))
        rows.append(line("gcf-window:8/faces", "a/b/m.off", 100, 99.0, 99.0, 1, 1, 1.0,
                         status="timeout"))
        proc, out = self.run_script(rows)
        self.assertEqual(proc.returncode, 0, proc.stderr)
        text = out.read_text()
        # median query 3.0, median repair 1.0 -> 33 %; 400 / 100 and 5000 / 100 per vertex.
        self.assertIn("| m.off | gcf-window:8/faces | 100 | 3 | 1 | 33 % | 4.00 | 50.0 | "
                      "1.00e-04 |", text)
        self.assertNotIn("exact-mmp |", text)

    def test_bad_input_one_line_nothing_written(self):
        for lines, fragment in (([], "no ok gcf-* line"), (["{not json\n"], "in.jsonl:1")):
            proc, out = self.run_script(lines)
            self.assertNotEqual(proc.returncode, 0)
            self.assertEqual(len(proc.stderr.strip().splitlines()), 1, proc.stderr)
            self.assertIn(fragment, proc.stderr)
            self.assertFalse(out.exists())


if __name__ == "__main__":
    unittest.main(verbosity=2)
