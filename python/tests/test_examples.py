"""The example of the README and the demo runs and prints what it says."""
import os
import subprocess
import sys

from conftest import DATA

EXAMPLE = os.path.join(os.path.dirname(__file__), "..", "examples", "quickstart.py")


def test_quickstart_runs():
    done = subprocess.run([sys.executable, EXAMPLE, DATA], capture_output=True, text=True,
                          timeout=300)
    assert done.returncode == 0, done.stderr
    assert "spot.obj: 2930 vertices, 5856 triangles" in done.stdout
    assert "waist_girth" in done.stdout and "ISO 8559-1" in done.stdout
    assert "shirt on it: " in done.stdout and "quality gates" in done.stdout
