"""tapeline.dress against `tapeline dress` on the same body and pattern; the stretch it reports
recomputed from the arrays it returns; its options, refusals and the fabric library."""
import json
import os

import numpy as np
import pytest

import tapeline
from tapeline import garment, pattern

from conftest import DATA, read_obj

SHIRT = os.path.join(DATA, "patterns", "shirt_mean_specification.json")
AARON = os.path.join(DATA, "patterns", "aaron_cisFemaleAdult36.json")
BASE = os.path.join(DATA, "patterns", "aaron_cisFemaleAdult36_measurements.json")
BINDINGS = ["aaron.armBinding", "aaron.neckBinding"]

# A short sewing phase at a coarse cloth, on one thread: the same computation on both sides.
SHORT_CLI = ["--resolution", "30", "--sew-seconds", "0.2", "--settle-seconds", "0", "--threads",
             "1"]


def short_options():
    o = garment.DressOptions(resolution_mm=30)
    o.sewing.sew_seconds = 0.2
    o.sewing.settle_seconds = 0
    o.sewing.max_extra_seconds = 0  # what the tool does with --settle-seconds 0
    o.drape.threads = 1
    return o


def placement_only(**fields):
    return garment.DressOptions(
        resolution_mm=30,
        sewing=garment.SewingOptions(sew_seconds=0, settle_seconds=0, max_extra_seconds=0),
        **fields)


@pytest.fixture(scope="module")
def short_dress(body):
    """The shirt dressed on the body by tapeline.dress with short_options() (one run, shared)."""
    _, V, F = body
    return tapeline.dress(V, F, pattern.read(SHIRT), units="dm", options=short_options())


def test_dress_equals_the_command_line(cli, body, short_dress, tmp_path):
    path, V, F = body
    out, rep = tmp_path / "g.obj", tmp_path / "r.json"
    cli("dress", path, "--units", "dm", SHIRT, "--out", str(out), "--report", str(rep), *SHORT_CLI)
    shirt = pattern.read(SHIRT)
    d = short_dress
    GV, GF = read_obj(str(out))
    assert d["V"].shape == GV.shape and d["V"].dtype == np.float64
    np.testing.assert_allclose(d["V"], GV, rtol=1e-8, atol=1e-12)  # the OBJ has 9 digits
    assert np.array_equal(d["F"], GF)
    expected = json.loads(rep.read_text())
    got = d["report"]
    assert got["units"] == expected["units"] == "dm"
    assert got["pattern"] == shirt["name"] and got["body"] == "body"  # the tool names the files
    for key in expected:
        if key not in ("body", "pattern", "timings_seconds", "simulation"):
            assert got[key] == expected[key], key
    assert got["simulation"]["frames"] == expected["simulation"]["frames"] > 0


def test_the_reported_stretch_is_that_of_the_returned_arrays(short_dress):
    d = short_dress
    X = d["V"] * 100.0  # dm -> mm, the unit of the pattern coordinates
    tri, uv = d["F"], d["uv"]
    m = len(tri)
    assert uv.shape == (m, 3, 2) and d["stretch"].shape == (m,) and d["piece"].shape == (m,)
    # Largest singular value of the map from each pattern triangle to its 3D triangle.
    E = np.stack([X[tri[:, 1]] - X[tri[:, 0]], X[tri[:, 2]] - X[tri[:, 0]]], axis=2)  # (m, 3, 2)
    U = np.stack([uv[:, 1] - uv[:, 0], uv[:, 2] - uv[:, 0]], axis=2)  # (m, 2, 2)
    J = E @ np.linalg.inv(U)
    sigma = np.linalg.svd(J, compute_uv=False)[:, 0]
    np.testing.assert_allclose(d["stretch"], sigma, rtol=1e-9)
    q = d["report"]["quality"]
    assert np.percentile(sigma, 50) == pytest.approx(q["stretch_median"], rel=0.02)
    assert set(np.unique(d["piece"])) == set(range(len(d["piece_names"])))


def test_placement_only_matches_the_report(body):
    _, V, F = body
    p = pattern.read(SHIRT)
    d = tapeline.dress(V, F, p, units="dm", options=placement_only())
    r = d["report"]
    assert r["placement"]["vertices_inside_body"] == 0
    assert len(d["V"]) == r["mesh"]["garment_vertices"] == r["mesh"]["cloth_vertices"]
    assert len(d["F"]) == r["mesh"]["cloth_triangles"]
    # Unsewn: one opening per piece; every piece placed, in the pattern's order.
    assert r["mesh"]["boundary_loops"] == len(p["pieces"]) == len(d["piece_names"])
    assert d["piece_names"] == [q["name"] for q in p["pieces"]]
    # The garment lies around the body: its box within the body's grown by 10 cm (1 dm).
    lo, hi = V.min(axis=0) - 1.0, V.max(axis=0) + 1.0
    assert (d["V"] >= lo).all() and (d["V"] <= hi).all()


def test_options_reach_the_solver(body):
    _, V, F = body
    o = placement_only(without_pieces=["left_ftorso"])
    o.placement.gap_mm = 25
    d = tapeline.dress(V, F, pattern.read(SHIRT), units="dm", options=o, sdf_cell_mm=6)
    opts = d["report"]["options"]
    assert opts["gap_mm"] == 25 and opts["sdf_cell_mm"] == 6 and opts["resolution_mm"] == 30
    assert opts["without"] == ["left_ftorso"]
    assert "left_ftorso" not in d["piece_names"]


def test_static_solve_options_equal_the_command_line(cli, body, tmp_path):
    # The static solves' and the flattening's options set from Python give the run the tool's
    # flags give: the same garment, the same report.
    path, V, F = body
    out, rep = tmp_path / "g.obj", tmp_path / "r.json"
    cli("dress", path, "--units", "dm", SHIRT, "--out", str(out), "--report", str(rep), *SHORT_CLI,
        "--relax-iterations", "7", "--relax-settle", "2", "--relax-again-friction", "3",
        "--relax-again-releases", "4", "--fold-cycles", "2", "--relax-tolerance", "0.2",
        "--relax-settle-fraction", "0.01", "--fold-rounds", "3", "--fold-rings", "2",
        "--fold-sweeps", "4")
    o = short_options()
    o.relax_options.max_iterations = 7  # nested options are edited in place or replaced
    o.relax_options.settle_iterations = 2
    o.relax_options.tolerance_mm = 0.2
    o.relax_options.settle_fraction = 0.01
    o.relax_again_options = garment.RelaxOptions(
        max_iterations=7, settle_iterations=2, friction_from_iteration=3, release_until_iteration=4,
        tolerance_mm=0.2, settle_fraction=0.01)
    o.fold_options = garment.FoldOptions(max_rounds=3, rings=2, sweeps=4)
    d = tapeline.dress(V, F, pattern.read(SHIRT), units="dm", options=o, fold_cycles=2)
    np.testing.assert_allclose(d["V"], read_obj(str(out))[0], rtol=1e-8, atol=1e-12)
    expected, got = json.loads(rep.read_text()), d["report"]
    for key in expected:
        if key not in ("body", "pattern", "timings_seconds", "simulation"):
            assert got[key] == expected[key], key
    opts = got["options"]
    assert (opts["static_solve_iterations"], opts["static_solve_settle"]) == (7, 2)
    assert (opts["static_solve_again_friction_from"], opts["static_solve_again_releases"]) == (3, 4)
    assert opts["fold_cycles"] == 2
    sim = got["simulation"]
    assert sim["static_solve"]["ran"] and 1 <= sim["static_solves"] <= 2
    assert [s["iterations"] for s in sim["static_solve_each"]] == \
        [s["iterations"] for s in expected["simulation"]["static_solve_each"]]
    assert all(1 <= s["iterations"] <= 7 for s in sim["static_solve_each"])
    assert all(f["rounds"] <= 3 for f in sim["fold_smoothing"])


def test_the_static_solve_and_the_flattening_can_be_turned_off(body):
    _, V, F = body
    d = tapeline.dress(V, F, pattern.read(SHIRT), units="dm", options=short_options(), relax=False,
                       smooth_folds=False, body_points=False)
    opts, sim = d["report"]["options"], d["report"]["simulation"]
    assert not opts["static_solve"] and not opts["fold_smoothing"] and not opts["body_points"]
    assert not sim["static_solve"]["ran"] and sim["static_solves"] == 0
    assert sim["static_solve_each"] == [] and sim["fold_smoothing"] == []


def test_option_objects():
    assert garment.DressOptions().drape.substeps == 40  # dress's default, not the solver's
    assert garment.DrapeOptions().substeps == 10
    o = garment.DressOptions(resolution_mm=20)
    o.sewing.sew_seconds = 0.3  # nested options are edited in place
    assert o.resolution_mm == 20 and o.sewing.sew_seconds == 0.3
    assert garment.DrapeOptions(gravity=[0, 0, -9810]).gravity == [0, 0, -9810]
    with pytest.raises(TypeError, match="unexpected keyword argument 'resolution'"):
        garment.DressOptions(resolution=20)
    with pytest.raises(TypeError, match="substeps"):
        garment.DrapeOptions(substeps="many")
    # dress's static solves stop once settled and run a shorter schedule after a flattening; the
    # solver's own default never stops early.
    d = garment.DressOptions()
    assert d.relax and d.body_points and d.smooth_folds and d.fold_cycles == 4
    assert d.waistband and d.waistband_sag_mm == 20
    assert not garment.DressOptions(waistband=False).waistband
    assert garment.RelaxOptions().settle_iterations == 0 and d.relax_options.settle_iterations == 5
    assert (d.relax_options.friction_from_iteration, d.relax_options.release_until_iteration) == \
        (30, 45)
    assert (d.relax_again_options.friction_from_iteration,
            d.relax_again_options.release_until_iteration) == (10, 20)
    assert garment.FoldOptions(sweeps=3).sweeps == 3 and d.fold_options.max_rounds == 20
    with pytest.raises(TypeError, match="unexpected keyword argument 'iterations'"):
        garment.RelaxOptions(iterations=3)


@pytest.mark.skipif(not hasattr(tapeline, "grade"), reason="built without grading")
def test_dress_grades_to_the_body_first(body):
    _, V, F = body
    p = pattern.read(AARON)
    plain = tapeline.dress(V, F, p, units="dm", options=placement_only(without_pieces=BINDINGS))
    graded = tapeline.dress(V, F, p, units="dm", base=BASE, seed=3,
                            options=placement_only(without_pieces=BINDINGS))
    assert not plain["grading_notes"]
    assert graded["grading_notes"][-1].startswith("graded ")
    # The bundled body's bust (845 mm) is far below the base set's chest (979 mm).
    width = lambda d: np.ptp(d["V"][:, 0])
    assert width(graded) < 0.95 * width(plain)


def test_bindings_found_on_the_body_equal_the_command_line(cli, body, tmp_path):
    # tapeline.bindings_from_body gives the bindings `tapeline grade --base-body` writes, and the
    # body's measurements as the base set; grading with them reaches target + scaled ease.
    path, V, F = body
    shirt = pattern.read(SHIRT)
    found, base, notes = tapeline.bindings_from_body(V, F, shirt, units="dm")
    assert [b["measurement"] for b in found["bindings"]] == [
        "bust_girth", "underbust_girth", "waist_girth", "high_hip_girth", "upper_arm_girth",
        "elbow_girth"] + ["hps_to_waist_back"] * 2 + ["waist_to_armpit"] * 4 + \
        ["waist_to_high_hip"] * 4
    assert any(n.startswith("hip_girth: not bound") for n in notes)
    target = {k: v * 1.05 for k, v in base.items()}
    json.dump(target, open(tmp_path / "t.json", "w"))
    cli("grade", SHIRT, "--base-body", path, "--base-units", "dm", "--to", str(tmp_path / "t.json"),
        "--out", str(tmp_path / "g.json"), "--bindings-out", str(tmp_path / "b.json"),
        "--generations", "0")
    written = json.load(open(tmp_path / "b.json"))
    assert [(b["measurement"], b["ease"]) for b in written["bindings"]] == [
        (b["measurement"], b["ease"]) for b in found["bindings"]]
    for b in found["bindings"]:
        piece_points = {p["name"]: p["points"] for p in found["pieces"]}
        for f in b["features"]:
            assert written["points"][f["piece"]][f["from_point"]] == \
                list(piece_points[f["piece"]][f["from_point"]])
    graded, report = tapeline.grade(found, base, target, generations=0)
    assert report["within_tolerance"], report["fit"]
    with pytest.raises(tapeline.InvalidInput, match="no binding was found"):
        sleeves = dict(found, pieces=[p for p in found["pieces"] if "sleeve" in p["name"]],
                       seams=[], bindings=[])
        tapeline.bindings_from_body(V, F, sleeves, units="dm")


def test_refusals(body):
    _, V, F = body
    p = pattern.read(SHIRT)
    with pytest.raises(tapeline.InvalidInput, match="unknown fabric 'tweed'"):
        tapeline.dress(V, F, p, units="dm", fabric="tweed")
    with pytest.raises(tapeline.InvalidInput, match="no piece 'collar'"):
        tapeline.dress(V, F, p, units="dm", without_pieces=["collar"])
    with pytest.raises(tapeline.InvalidInput, match="resolution"):
        tapeline.dress(V, F, p, units="dm", resolution_mm=0.5)
    # The options of the solves after the drape are refused before the drape runs.
    with pytest.raises(tapeline.InvalidInput,
                       match="dress: relax_options: friction_from_iteration and "
                             "release_until_iteration must be >= 0, got -1 and 45"):
        tapeline.dress(V, F, p, units="dm",
                       relax_options=garment.RelaxOptions(friction_from_iteration=-1))
    with pytest.raises(tapeline.InvalidInput, match="dress: relax_again_options: tolerance_mm"):
        tapeline.dress(V, F, p, units="dm",
                       relax_again_options=garment.RelaxOptions(tolerance_mm=float("nan")))
    with pytest.raises(tapeline.InvalidInput, match="dress: fold_options: .*sweeps >= 1"):
        tapeline.dress(V, F, p, units="dm", fold_options=garment.FoldOptions(sweeps=0))
    with pytest.raises(tapeline.InvalidInput, match="fold_cycles must be >= 1, got 0"):
        tapeline.dress(V, F, p, units="dm", fold_cycles=0)
    with pytest.raises(TypeError, match="dress\\(\\) got an unexpected keyword argument 'gap'"):
        tapeline.dress(V, F, p, units="dm", gap=3)
    with pytest.raises(TypeError):
        tapeline.dress(V, F, p, units="dm", options="fast")
    with pytest.raises(ValueError, match="base"):
        tapeline.dress(V, F, p, units="dm", base=3)
    with pytest.raises(ValueError, match="V"):
        tapeline.dress(V[:, :2], F, p, units="dm")
    with pytest.raises(tapeline.InvalidInput, match="units"):
        tapeline.dress(V, F, p, units="furlong")
    bad = dict(p, pieces=[])
    with pytest.raises(tapeline.InvalidInput):
        tapeline.dress(V, F, bad, units="dm")
    # An unsewn placement fails the gates: strict raises, naming them.
    with pytest.raises(tapeline.SolverFailure, match="quality gates"):
        tapeline.dress(V, F, p, units="dm", strict=True, options=placement_only())


def test_fabric_library_equals_the_command_line(cli):
    names = [f["name"] for f in garment.fabrics()]
    listed = [l.split()[0] for l in cli("fabric", "list").stdout.splitlines()[1:] if l.strip()]
    assert names == listed
    assert garment.fabric("denim") == json.loads(cli("fabric", "show", "denim").stdout)
    # A fabric dict reads back to itself; a bad value is refused naming the field.
    denim = garment.fabric("denim")
    assert garment.fabric(denim) == denim
    with pytest.raises(tapeline.InvalidInput, match="density"):
        garment.fabric(dict(denim, density_g_m2=-1))
    with pytest.raises(ValueError, match="fabric"):
        garment.fabric(3)
