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


def test_ctrl_c_interrupts_exact_distances():
    child = subprocess.Popen([sys.executable, "-c", CHILD, "700"], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=os.environ.copy())
    assert child.stdout.readline().strip() == "ready"
    time.sleep(2.0)
    sent = time.perf_counter()
    child.send_signal(signal.SIGINT)
    out, err = child.communicate(timeout=120)
    waited = time.perf_counter() - sent
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
    child = subprocess.Popen([sys.executable, "-c", DRESS_CHILD, DATA], stdout=subprocess.PIPE,
                             stderr=subprocess.PIPE, text=True, env=os.environ.copy())
    assert child.stdout.readline().strip() == "ready"
    time.sleep(5.0)
    sent = time.perf_counter()
    child.send_signal(signal.SIGINT)
    out, err = child.communicate(timeout=300)
    waited = time.perf_counter() - sent
    assert out.startswith("interrupted"), (out, err)
    # The body's distance grid and the placement have no progress point: a machine busy with
    # other tests may still be in them; the drape itself lasts a minute and more.
    assert waited < 30, f"the drape went on {waited:.1f} s after Ctrl-C"
