"""Shared fixtures: the bundled meshes read as plain arrays, a flat grid, the command-line tool."""
import os
import subprocess

import numpy as np
import pytest

DATA = os.environ.get(
    "TAPELINE_DATA_DIR",
    os.path.join(os.path.dirname(__file__), "..", "..", "data"))


def read_obj(path):
    """The vertices and triangles of an OBJ file exactly as written (no repair), 0-based."""
    V, F = [], []
    with open(path) as f:
        for line in f:
            t = line.split()
            if not t:
                continue
            if t[0] == "v":
                V.append([float(x) for x in t[1:4]])
            elif t[0] == "f":
                F.append([int(c.split("/")[0]) - 1 for c in t[1:]])
    return np.array(V, dtype=np.float64), np.array(F, dtype=np.int64)


@pytest.fixture(scope="session")
def spot():
    path = os.path.join(DATA, "spot.obj")
    V, F = read_obj(path)
    return path, V, F


@pytest.fixture(scope="session")
def body():
    path = os.path.join(DATA, "bodies", "mh_female_average.obj")
    V, F = read_obj(path)
    return path, V, F


def grid(n=9, size=2.0):
    """A flat square of n x n vertices in the plane z = 0, two triangles per cell (diagonals
    alternating), so that exact distances are the Euclidean ones."""
    xs = np.linspace(0.0, size, n)
    V = np.array([[x, y, 0.0] for y in xs for x in xs])
    F = []
    for j in range(n - 1):
        for i in range(n - 1):
            a, b, c, d = j * n + i, j * n + i + 1, (j + 1) * n + i, (j + 1) * n + i + 1
            if (i + j) % 2 == 0:
                F += [[a, b, d], [a, d, c]]
            else:
                F += [[a, b, c], [b, d, c]]
    return V, np.array(F, dtype=np.int64)


@pytest.fixture
def flat():
    return grid()


@pytest.fixture(scope="session")
def cli():
    exe = os.environ.get("TAPELINE_CLI")
    if not exe or not os.path.exists(exe):
        pytest.skip("TAPELINE_CLI (the tapeline tool) not given")

    def run(*args):
        done = subprocess.run([exe, *args], capture_output=True, text=True)
        assert done.returncode == 0, done.stderr
        return done

    return run
