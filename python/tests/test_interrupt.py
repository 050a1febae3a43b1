"""Ctrl-C during a long call stops it at the library's next progress point."""
import os
import signal
import subprocess
import sys
import time

CHILD = r"""
import sys, time
import numpy as np
from tapeline import geodesic as g
n = int(sys.argv[1])
xs = np.linspace(0.0, 1.0, n)
X, Y = np.meshgrid(xs, xs)
rng = np.random.default_rng(1)
Z = 0.002 * rng.standard_normal(X.shape)
V = np.column_stack([X.ravel(), Y.ravel(), Z.ravel()])
i, j = np.meshgrid(np.arange(n - 1), np.arange(n - 1))
a = (j * n + i).ravel(); b = a + 1; c = a + n; d = c + 1
F = np.vstack([np.column_stack([a, b, d]), np.column_stack([a, d, c])])
print("ready", flush=True)
t0 = time.perf_counter()
try:
    g.distances(V, F, 0, method="exact-mmp")
    print("finished %.2f" % (time.perf_counter() - t0), flush=True)
except KeyboardInterrupt as e:
    print("interrupted %.2f %s" % (time.perf_counter() - t0, e), flush=True)
"""


def interrupted_after(script, arg, sleep_s, timeout_s=300):
    """Runs `script` in a child, sends it Ctrl-C `sleep_s` after it says "ready"; returns its
    output and how long it went on after the signal."""
    child = subprocess.Popen([sys.executable, "-c", script, arg], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=os.environ.copy())
    assert child.stdout.readline().strip() == "ready"
    time.sleep(sleep_s)
    sent = time.perf_counter()
    child.send_signal(signal.SIGINT)
    out, err = child.communicate(timeout=timeout_s)
    return out, err, time.perf_counter() - sent


def test_ctrl_c_interrupts_exact_distances():
    out, err, waited = interrupted_after(CHILD, "700", 2.0, 120)
    assert out.startswith("interrupted"), (out, err)
    assert waited < 10, f"the call went on {waited:.1f} s after Ctrl-C"


DRESS_CHILD = r"""
import os, sys, time
import tapeline
from tapeline import pattern
data = sys.argv[1]
V, F, _ = tapeline.read_mesh(os.path.join(data, "bodies", "mh_female_average.obj"))
shirt = pattern.read(os.path.join(data, "patterns", "shirt_mean_specification.json"))
print("ready", flush=True)
t0 = time.perf_counter()
try:
    tapeline.dress(V, F, shirt, units="dm")  # 10 mm cloth: about a minute of frames
    print("finished %.2f" % (time.perf_counter() - t0), flush=True)
except KeyboardInterrupt as e:
    print("interrupted %.2f %s" % (time.perf_counter() - t0, e), flush=True)
"""


def test_ctrl_c_interrupts_a_drape():
    from conftest import DATA
    out, err, waited = interrupted_after(DRESS_CHILD, DATA, 5.0)
    assert out.startswith("interrupted"), (out, err)
    # The body's distance grid and the placement have no progress point: a machine busy with
    # other tests may still be in them; the drape itself lasts a minute and more.
    assert waited < 30, f"the drape went on {waited:.1f} s after Ctrl-C"
