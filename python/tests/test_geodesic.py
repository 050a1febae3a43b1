"""tapeline.geodesic against analytic truth (a flat grid), the command-line tool on the same
input (bit for bit: the same code on the same mesh), and each other."""
import math
import os
import threading

import numpy as np
import pytest

import tapeline
from tapeline import geodesic as g

from conftest import grid


def test_exact_distances_on_a_plane_are_euclidean(flat):
    V, F = flat
    d = g.distances(V, F, 0)
    assert d.dtype == np.float64 and d.shape == (len(V),)
    np.testing.assert_allclose(d, np.linalg.norm(V - V[0], axis=1), rtol=0, atol=1e-12)


def test_exact_path_on_a_plane_is_the_segment(flat):
    V, F = flat
    solver = g.ExactMmpSolver(V, F)
    target = len(V) - 5
    points, length = solver.path(3, target)
    assert points.shape[1] == 3
    np.testing.assert_allclose(points[0], V[3], atol=1e-12)
    np.testing.assert_allclose(points[-1], V[target], atol=1e-12)
    assert length == pytest.approx(np.linalg.norm(V[target] - V[3]), abs=1e-12)
    assert solver.distance(3, target) == pytest.approx(length, abs=1e-12)
    # Every point on the segment from V[3] to the target.
    u = (V[target] - V[3]) / length
    off = (points - V[3]) - np.outer((points - V[3]) @ u, u)
    assert np.abs(off).max() < 1e-12


def test_curvature_flow_path_on_a_plane(flat):
    V, F = flat
    points, length = g.CurvatureFlowPathSolver(V, F).path(0, len(V) - 1)
    assert length == pytest.approx(math.sqrt(8.0), rel=1e-6)
    np.testing.assert_allclose(points[-1], V[-1], atol=1e-9)


@pytest.mark.parametrize("method", ["exact-mmp", "heat", "heat-idt", "dijkstra", "fmm", "gcf-window:8"])
def test_distances_equal_the_command_line(spot, cli, tmp_path, method):
    path, V, F = spot
    out = tmp_path / "d.txt"
    sources = [17] if method.startswith("gcf") else [17, 900]  # gcf: one vertex source
    args = [a for s in sources for a in ("--source", str(s))]
    cli("geodesic", "distances", path, *args, "--method", method, "-o", str(out))
    expected = np.array([float(x) for x in out.read_text().split()])
    d = g.distances(V, F, sources, method=method)
    np.testing.assert_array_equal(d, expected)


def test_exact_path_equals_the_command_line(spot, cli, tmp_path):
    import json
    path, V, F = spot
    out = tmp_path / "p.json"
    cli("geodesic", "path", path, "--from", "5", "--to", "2000", "-o", str(out))
    expected = json.loads(out.read_text())
    points, length = g.ExactMmpSolver(V, F).path(5, 2000)
    assert length == expected["length"]
    np.testing.assert_array_equal(points, np.array(expected["points"]))


def test_distance_matrix_rows_are_the_fields_and_symmetric(spot):
    _, V, F = spot
    src = [0, 100, 700, 2100]
    m1 = g.distance_matrix(V, F, src, threads=1)
    m2 = g.distance_matrix(V, F, src, threads=2)
    assert m1.shape == (4, len(V)) and m1.dtype == np.float64
    np.testing.assert_array_equal(m1, m2)
    for r, s in enumerate(src):
        np.testing.assert_allclose(m1[r], g.distances(V, F, s), rtol=1e-12, atol=0)
    sub = m1[:, src]
    np.testing.assert_allclose(sub, sub.T, rtol=1e-12, atol=0)
    assert (np.diag(sub) == 0).all()
    np.testing.assert_array_equal(g.distance_matrix(V, F, np.int64(100)), m1[1:2])
    np.testing.assert_array_equal(g.distance_matrix(V, F, np.array(src[:2])), m1[:2])
    with pytest.raises(ValueError, match="a row needs a vertex index"):
        g.distance_matrix(V, F, [(3, (0.2, 0.3, 0.5))])
    with pytest.raises(ValueError, match="no source given"):
        g.distance_matrix(V, F, [])


def test_solvers_equal_the_one_shot_call(spot):
    _, V, F = spot
    np.testing.assert_array_equal(g.ExactMmpSolver(V, F).distances(11), g.distances(V, F, 11))
    heat = g.HeatSolver(V, F, intrinsic_delaunay=True)
    np.testing.assert_array_equal(heat.distances([11, 12]),
                                  g.distances(V, F, [11, 12], method="heat-idt"))
    assert heat.options["intrinsic_delaunay"] is True
    assert heat.report["sources"] == 2


def test_exact_is_below_every_approximation(spot):
    _, V, F = spot
    exact = g.distances(V, F, 100)
    assert exact[100] == 0
    dijkstra = g.distances(V, F, 100, method="dijkstra")
    assert np.all(exact <= dijkstra + 1e-12)
    assert np.all(exact < np.inf)
    heat = g.distances(V, F, 100, method="heat")
    assert np.abs(heat - exact).mean() / exact.mean() < 0.05


def test_flow_path_is_not_shorter_than_the_exact_one(spot):
    _, V, F = spot
    exact = g.ExactMmpSolver(V, F).distance(40, 2500)
    flow = g.CurvatureFlowPathSolver(V, F)
    _, on_mesh = flow.path(40, 2500)
    assert exact - 1e-9 <= on_mesh <= 1.02 * exact
    assert flow.report["iterations"] > 0 and flow.report["samples"] > 2


def test_face_point_sources_follow_the_input_corners(spot):
    _, V, F = spot
    f = 123
    solver = g.ExactMmpSolver(V, F)
    for k in range(3):
        b = [0.0, 0.0, 0.0]
        b[k] = 1.0
        np.testing.assert_allclose(solver.distances([(f, b)]), g.distances(V, F, int(F[f, k])),
                                   atol=1e-12)
    # The centroid is at the same distance from the three corners' fields' mean within the face.
    centre = solver.distances([(f, (1 / 3, 1 / 3, 1 / 3))])
    assert np.argmin(centre) in F[f]


def test_reoriented_faces_keep_their_barycentric_coordinates(flat):
    V, F = flat
    G = F.copy()
    f = 50
    G[f] = G[f, ::-1]  # the loader turns it back to agree with its neighbours
    report = tapeline.check_mesh(V, G)
    assert report["faces_reoriented"] == 1
    b = (0.2, 0.3, 0.5)
    p = b[0] * V[G[f, 0]] + b[1] * V[G[f, 1]] + b[2] * V[G[f, 2]]
    d = g.distances(V, G, [(f, b)])
    np.testing.assert_allclose(d, np.linalg.norm(V - p, axis=1), atol=1e-12)


def test_results_are_in_the_input_vertex_order(flat):
    V, F = flat
    # An unused vertex in front: every index shifts by one, the unused vertex is unreachable.
    V2 = np.vstack([[9.0, 9.0, 9.0], V])
    d = g.distances(V2, F + 1, 1)
    assert d[0] == np.inf
    np.testing.assert_array_equal(d[1:], g.distances(V, F, 0))


def test_inputs_of_other_layouts_are_read_alike(flat):
    V, F = flat
    ref = g.distances(V, F, 0)
    np.testing.assert_array_equal(g.distances(V.astype(np.float32).astype(np.float64), F, 0), ref)
    np.testing.assert_array_equal(g.distances(np.asfortranarray(V), F.astype(np.int32), 0), ref)
    np.testing.assert_array_equal(g.distances(V.tolist(), F.tolist(), 0), ref)


def test_point_cloud_on_a_sphere():
    # Fibonacci sphere: the distance to the antipode is pi.
    n = 3000
    i = np.arange(n) + 0.5
    phi = np.arccos(1 - 2 * i / n)
    theta = math.pi * (1 + 5 ** 0.5) * i
    P = np.column_stack([np.cos(theta) * np.sin(phi), np.sin(theta) * np.sin(phi), np.cos(phi)])
    solver = g.PointCloudSolver(P)
    d = solver.distances(0)
    assert d[0] == 0
    assert d[-1] == pytest.approx(math.pi, rel=0.03)
    great_circle = np.arccos(np.clip(P @ P[0], -1, 1))
    assert np.abs(d - great_circle).max() < 0.05 * math.pi


def test_point_cloud_in_five_dimensions():
    # A flat square sampled on a grid and rotated into R^5: distances are Euclidean.
    rng = np.random.default_rng(3)
    xs = np.linspace(0, 1, 30)
    flat2 = np.array([[x, y] for y in xs for x in xs])
    Q, _ = np.linalg.qr(rng.normal(size=(5, 5)))
    P = np.hstack([flat2, np.zeros((len(flat2), 3))]) @ Q.T
    solver = g.PointCloudSolver(P, projection="plane")
    assert solver.dimension == 5
    d = solver.distances(0)
    np.testing.assert_allclose(d, np.linalg.norm(flat2 - flat2[0], axis=1), atol=0.02)
    samples, length = solver.path(0, len(P) - 1)
    assert samples.shape[1] == 5
    assert length == pytest.approx(math.sqrt(2), rel=0.01)


def test_calls_run_in_parallel_threads(spot):
    _, V, F = spot
    ref = g.distances(V, F, 7)
    out = [None] * 4

    def work(k):
        out[k] = g.distances(V, F, 7)

    threads = [threading.Thread(target=work, args=(k,)) for k in range(4)]
    for t in threads:
        t.start()
    for t in threads:
        t.join()
    for d in out:
        np.testing.assert_array_equal(d, ref)


def test_report_and_options_of_a_named_method(flat):
    V, F = flat
    d, report = g.distances(V, F, 0, method="gcf-window:4", with_report=True)
    assert report["vertices"] == len(V) and report["sources"] == 1
    assert report["options"]["window"] == 4
    assert set(g.methods()) >= {"exact-mmp", "heat", "heat-idt", "dijkstra", "gcf-window"}


# --- refusals ------------------------------------------------------------------------------------

def test_wrong_dtype_and_shape_are_refused(flat):
    V, F = flat
    with pytest.raises(ValueError, match=r"V: expected a float array of shape \(n, 3\), got int64"):
        g.distances(V.astype(np.int64), F, 0)
    with pytest.raises(ValueError, match=r"V: .*shape \(81, 2\)"):
        g.distances(V[:, :2], F, 0)
    with pytest.raises(ValueError, match=r"F: expected an integer array of shape \(m, 3\), got float64"):
        g.distances(V, F.astype(np.float64), 0)
    with pytest.raises(ValueError, match=r"F: face 0 has a negative vertex index"):
        g.distances(V, -F, 0)
    with pytest.raises(ValueError, match=r"P: expected a float array"):
        g.PointCloudSolver(np.zeros((10,)))


def test_library_errors_map_to_python_types(flat):
    V, F = flat
    assert issubclass(tapeline.InvalidInput, ValueError)
    assert issubclass(tapeline.TopologyError, ValueError)
    assert issubclass(tapeline.SolverFailure, RuntimeError)
    with pytest.raises(tapeline.InvalidInput, match="face 128 references vertex 500"):
        g.distances(V, np.vstack([F, [[0, 1, 500]]]), 0)
    bad = V.copy()
    bad[4, 1] = np.nan
    with pytest.raises(tapeline.InvalidInput, match="vertex 4"):
        g.distances(bad, F, 0)
    with pytest.raises(tapeline.InvalidInput, match="unknown method 'nope'"):
        g.distances(V, F, 0, method="nope")
    with pytest.raises(tapeline.InvalidInput, match="mesh.obj: cannot open file"):
        tapeline.read_mesh("/nonexistent/mesh.obj")
    with pytest.raises(tapeline.TopologyError):
        G = np.vstack([F, F[:1]])  # a duplicate face, refused in strict mode
        tapeline.check_mesh(V, G, strict=True)


def test_bad_sources_are_refused(flat):
    V, F = flat
    with pytest.raises(tapeline.InvalidInput, match="vertex 500 does not exist"):
        g.distances(V, F, 500)
    with pytest.raises(ValueError, match="vertex -1: vertex indices start at 0"):
        g.distances(V, F, -1)
    with pytest.raises(ValueError, match="barycentric coordinates must be >= 0 and sum to 1"):
        g.distances(V, F, [(0, (0.5, 0.6, 0.0))])
    with pytest.raises(ValueError, match="face 999 does not exist"):
        g.distances(V, F, [(999, (1, 0, 0))])
    with pytest.raises(ValueError, match="no source given"):
        g.distances(V, F, [])
    with pytest.raises(ValueError, match="expected a vertex index"):
        g.distances(V, F, "0")
    with pytest.raises(TypeError, match="unexpected keyword argument 'windows'"):
        g.ExactMmpSolver(V, F, windows=3)
    with pytest.raises(ValueError, match="projection='cube': expected one of mls, plane"):
        g.PointCloudSolver(V, projection="cube")


def test_read_mesh_reports_repairs(spot, tmp_path):
    path, V, F = spot
    V2, F2, report = tapeline.read_mesh(path)
    assert report["vertices"] == len(V) and report["faces"] == len(F)
    np.testing.assert_array_equal(V2, V)
    np.testing.assert_array_equal(F2, F)
    # A quad and a duplicate vertex: triangulated and merged.
    p = tmp_path / "quad.off"
    p.write_text("OFF\n6 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n1 0 0\n2 0 0\n"
                 "4 0 1 2 3\n3 4 5 2\n")
    V3, F3, r3 = tapeline.read_mesh(str(p))
    assert r3["polygons_triangulated"] == 1 and r3["duplicate_vertices_merged"] == 1
    assert V3.shape == (5, 3) and F3.shape == (3, 3)
