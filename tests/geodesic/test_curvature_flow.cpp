// Two-point geodesic paths by geodesic curvature flow (curvature_flow.h) against great circles on
// icospheres (analytic truth), against the exact polyhedral distance (our MMP), against Euclidean
// truth on a flat grid, and its invariants (DESIGN.md §6).
//
// Tolerances (h = mean edge length):
// - convergence: the flow stops when max |kappa_g| * h <= options.tolerance, so the report must
//   say so; that is the definition of a converged discrete geodesic here.
// - on-mesh path >= exact polyhedral distance - 1e-9 relative: it is a path traced on the faces,
//   so only rounding can make it shorter; and <= 3 % longer (the "within a few percent").
// - symmetry 1e-6 relative: both directions converge to the same discrete geodesic up to the
//   convergence tolerance (measured in the printout).
// - flat grid: the flow is linear there and converges to the straight segment; 1e-9 relative.
#include <tapeline/core/errors.h>
#include <tapeline_test/gcf.h>
#include <tapeline_test/mmp.h>
#include <tapeline_test/unfold.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace tg = tapeline_test::geodesic;

namespace {

double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v[v.size() / 2];
}

double rel(double a, double b) {
    return std::abs(a - b) / std::abs(b);
}

}  // namespace

TEST(CurvatureFlow, IcosphereAgainstGreatCircleAndExactPolyhedral) {
    for (int level : {4, 5}) {
        const std::string spec = "icosphere:" + std::to_string(level);
        const tg::Soup soup = tg::surface(spec);
        const std::size_t a = 0;
        const auto truth = tg::analytic_distances(spec, soup, a);
        ASSERT_FALSE(truth.empty());
        const tg::MmpField mmp = tg::mmp_distances(soup, tg::Sources::vertex(a));
        for (double degrees : {30.0, 90.0, 150.0}) {
            const std::size_t b = vertex_at_angle(soup, a, degrees);
            const tg::GcfResult r =
                tg::gcf_path(soup, tg::SurfacePoint::vertex(a), tg::SurfacePoint::vertex(b));
            const double t = truth[b], e = mmp.d[b];
            std::printf(
                "[ gcf      ] %s %3.0f deg: great circle %.6f | exact polyhedral %.6f "
                "(rel err %.2e) | gcf on-mesh %.6f (%.2e, vs exact %+.2e; plane-cut trace "
                "%+.2e, %zu flips, %zu bends) | gcf smooth %.6f (%.2e) | %zu samples, %zu it, "
                "kappa*h %.1e, %s, fallbacks %zu, %.1f ms\n",
                spec.c_str(), degrees, t, e, rel(e, t), r.on_mesh.length, rel(r.on_mesh.length, t),
                (r.on_mesh.length - e) / e, (r.report.traced_length - e) / e,
                r.report.straighten_flips, r.report.straighten_bends, r.smooth.length,
                rel(r.smooth.length, t), r.report.samples, r.report.iterations,
                r.report.scaled_max_geodesic_curvature, r.report.status.c_str(),
                r.report.trace_fallbacks, 1e3 * r.report.seconds);
            EXPECT_EQ(r.report.status, "converged") << spec << " " << degrees;
            EXPECT_LE(r.report.scaled_max_geodesic_curvature, tg::CurvatureFlowOptions{}.tolerance);
            EXPECT_GE(r.on_mesh.length, e * (1 - 1e-9)) << spec << " " << degrees;
            EXPECT_LE(r.on_mesh.length, e * 1.03) << spec << " " << degrees;
            // Measured: on-mesh <= 7e-6 relative above the exact polyhedral distance; 1e-4 keeps
            // a 15x margin and still catches a path that wanders off the geodesic.
            EXPECT_LE(r.on_mesh.length, e * (1 + 1e-4)) << spec << " " << degrees;
            // The thesis' claim, as measured here for the Phong-lifted samples: closer to the
            // great circle than the exact polyhedral distance (measured ratio <= 0.26).
            EXPECT_LE(rel(r.smooth.length, t), 0.5 * rel(e, t)) << spec << " " << degrees;
            EXPECT_EQ(r.report.trace_fallbacks, 0u);
            if (level == 4) {
                // The on-mesh path lies on the faces; the smooth one is nearer the unit sphere
                // (max over all points; the on-mesh max includes its edge crossings).
                double off_faces = 0, on_mesh_radius = 0, smooth_radius = 0;
                for (const auto& p : r.on_mesh.points) {
                    off_faces = std::max(off_faces, tg::distance_to_surface(soup, p));
                    on_mesh_radius =
                        std::max(on_mesh_radius, std::abs(tg::euclidean(p, {0, 0, 0}) - 1));
                }
                for (const auto& p : r.smooth.points)
                    smooth_radius =
                        std::max(smooth_radius, std::abs(tg::euclidean(p, {0, 0, 0}) - 1));
                std::printf(
                    "[ gcf      ]   on-mesh points: max distance to the faces %.1e, max "
                    "||p|-1| %.2e; smooth points: max ||p|-1| %.2e\n",
                    off_faces, on_mesh_radius, smooth_radius);
                EXPECT_LE(off_faces, 1e-12);
                EXPECT_LT(smooth_radius, 0.75 * on_mesh_radius);  // measured ratio <= 0.51
            }
            // Endpoints exact.
            ASSERT_FALSE(r.on_mesh.points.empty());
            EXPECT_EQ(r.on_mesh.points.front(), soup.points[a]);
            EXPECT_EQ(r.on_mesh.points.back(), soup.points[b]);
            EXPECT_EQ(r.smooth.points.front(), soup.points[a]);
            EXPECT_EQ(r.smooth.points.back(), soup.points[b]);
        }
    }
}

TEST(CurvatureFlow, SymmetricAndOnPolyhedron) {
    const tg::Soup soup = tg::surface("icosphere:4");
    const std::size_t a = 3, b = vertex_at_angle(soup, a, 120.0);
    const auto ab = tg::gcf_path(soup, tg::SurfacePoint::vertex(a), tg::SurfacePoint::vertex(b));
    const auto ba = tg::gcf_path(soup, tg::SurfacePoint::vertex(b), tg::SurfacePoint::vertex(a));
    std::printf(
        "[ gcf      ] symmetry: on-mesh %.12f vs %.12f (%.2e), smooth %.12f vs %.12f "
        "(%.2e)\n",
        ab.on_mesh.length, ba.on_mesh.length, rel(ab.on_mesh.length, ba.on_mesh.length),
        ab.smooth.length, ba.smooth.length, rel(ab.smooth.length, ba.smooth.length));
    EXPECT_LE(rel(ab.on_mesh.length, ba.on_mesh.length), 1e-6);
    EXPECT_LE(rel(ab.smooth.length, ba.smooth.length), 1e-6);
    const auto poly = tg::gcf_path(soup, tg::SurfacePoint::vertex(a), tg::SurfacePoint::vertex(b),
                                   {}, tg::MeshKind::polyhedron);
    EXPECT_NEAR(poly.on_mesh.length, ab.on_mesh.length, 1e-12 * ab.on_mesh.length);
    const auto named = tg::gcf_path_with_named_parameters(soup, tg::SurfacePoint::vertex(a),
                                                          tg::SurfacePoint::vertex(b));
    EXPECT_EQ(named.on_mesh.length, ab.on_mesh.length);
    // Face-location endpoints.
    const auto loc = tg::gcf_path(soup, tg::SurfacePoint::face(10, {0.2, 0.3, 0.5}),
                                  tg::SurfacePoint::face(900, {0.6, 0.3, 0.1}));
    EXPECT_EQ(loc.report.status, "converged");
    const tg::Vec3 p0 = tg::position(soup, tg::SurfacePoint::face(10, {0.2, 0.3, 0.5}));
    EXPECT_EQ(loc.on_mesh.points.front(), p0);
    // Sample count and spacing options.
    tg::CurvatureFlowOptions o;
    o.sample_count = 50;
    EXPECT_EQ(tg::gcf_path(soup, tg::SurfacePoint::vertex(a), tg::SurfacePoint::vertex(b), o)
                  .report.samples,
              50u);
    o.sample_count = 0;
    o.sample_spacing = 2 * tg::mean_edge_length(soup);
    const auto coarse =
        tg::gcf_path(soup, tg::SurfacePoint::vertex(a), tg::SurfacePoint::vertex(b), o);
    EXPECT_NEAR(static_cast<double>(coarse.report.samples), ab.report.samples / 2.0, 2.0);
    // A tiny step does not converge within the cap: a status, not an exception.
    o = {};
    o.step = 1e-3;
    o.max_iterations = 5;
    const auto slow =
        tg::gcf_path(soup, tg::SurfacePoint::vertex(a), tg::SurfacePoint::vertex(b), o);
    EXPECT_EQ(slow.report.status, "max_iterations");
    EXPECT_EQ(slow.report.iterations, 5u);
}

TEST(CurvatureFlow, FlatGridGivesTheStraightSegment) {
    const tg::Soup soup = tg::flat_grid(20, 1.0);
    tg::CurvatureFlowOptions o;
    o.tolerance = 1e-12;
    for (auto [a, b] : {std::pair<std::size_t, std::size_t>{0, 440}, {3, 21 * 17 + 20}}) {
        const auto r =
            tg::gcf_path(soup, tg::SurfacePoint::vertex(a), tg::SurfacePoint::vertex(b), o);
        const double d = tg::euclidean(soup.points[a], soup.points[b]);
        std::printf(
            "[ gcf      ] flat %zu-%zu: euclid %.15f on-mesh %.15f smooth %.15f, %zu it, "
            "%s\n",
            a, b, d, r.on_mesh.length, r.smooth.length, r.report.iterations,
            r.report.status.c_str());
        EXPECT_NEAR(r.on_mesh.length, d, 1e-9 * d);
        EXPECT_NEAR(r.smooth.length, d, 1e-9 * d);
    }
}

// The initial path steps across edges as well as along them (face_path). On a grid whose cells are
// all split the same way, edge paths can only go along the axes and one diagonal: towards (2, 1)
// they are 8 % long (1 + sqrt 2 against sqrt 5), a metric of the grid rather than of the surface,
// and on a limb such a path can take the other way round. A step to the vertex opposite an edge,
// straight through the two faces, adds the (2, 1) and (1, 2) directions: within 2.8 % everywhere.
TEST(CurvatureFlow, InitialPathStepsAcrossFacesAndStaysNearTheStraightLine) {
    const std::size_t n = 20;
    const tg::Soup soup = tg::flat_grid(n, 1.0, false);
    tg::CurvatureFlowOptions o;
    o.max_iterations = 1;
    double worst = 0;
    for (std::size_t k = 1; k <= n; ++k) {
        for (const std::size_t b : {k * (n + 1) + n, n * (n + 1) + k}) {  // far column, far row
            const auto r =
                tg::gcf_path(soup, tg::SurfacePoint::vertex(0), tg::SurfacePoint::vertex(b), o);
            const double d = tg::euclidean(soup.points[0], soup.points[b]);
            worst = std::max(worst, r.report.initial_length / d - 1);
            EXPECT_LE(r.report.initial_length, 1.03 * d) << b;
            EXPECT_NEAR(r.on_mesh.length, d, 1e-9 * d) << b;  // straightened: the segment
        }
    }
    std::printf("[ gcf      ] flat grid: initial path at most %.2f %% longer than the segment\n",
                100 * worst);
}

TEST(CurvatureFlow, FromAGivenPolyline) {
    const tg::Soup soup = tg::flat_grid(10, 1.0);
    const std::vector<tg::Vec3> zigzag{{0.1, 0.1, 0}, {0.8, 0.2, 0}, {0.3, 0.6, 0}, {0.9, 0.9, 0}};
    tg::CurvatureFlowOptions o;
    o.tolerance = 1e-12;
    const auto r = tg::gcf_path_from_polyline(soup, zigzag, o);
    const double d = tg::euclidean(zigzag.front(), zigzag.back());
    EXPECT_NEAR(r.on_mesh.length, d, 1e-9 * d);
    EXPECT_EQ(r.on_mesh.points.front(), zigzag.front());
    EXPECT_EQ(r.on_mesh.points.back(), zigzag.back());
}

// The end point of a given polyline is the one given, even where walking towards it from the
// point before stops on the wrong sheet of a fold. A hairpin: two 1 x 1 sheets 0.02 apart (top
// z = 0.02, bottom z = 0) joined along x = 1 by a band. The polyline's last piece crosses the gap
// from the top sheet to a bottom vertex; the nearest-vertex walk along it ends on the top sheet
// right above. The path then must end at the bottom vertex, and (a path on the faces) be at least
// the geodesic distance, 0.8 + 0.02 + 0.7 unfolded. (Found on a coarse mesh, where the end point
// moved by 40 % of the path's length.)
TEST(CurvatureFlow, GivenPolylineEndsWhereItWasGivenAcrossAFold) {
    const std::size_t n = 10;
    const double gap = 0.02;
    tg::Soup soup;
    auto id = [&](std::size_t sheet, std::size_t i, std::size_t j) {
        return sheet * (n + 1) * (n + 1) + j * (n + 1) + i;
    };
    for (std::size_t sheet = 0; sheet < 2; ++sheet)
        for (std::size_t j = 0; j <= n; ++j)
            for (std::size_t i = 0; i <= n; ++i)
                soup.points.push_back({static_cast<double>(i) / n, static_cast<double>(j) / n,
                                       sheet == 0 ? 0.0 : gap});
    for (std::size_t j = 0; j < n; ++j) {
        for (std::size_t i = 0; i < n; ++i) {
            // bottom faces down (-z), top faces up: one consistently oriented surface
            soup.faces.push_back({id(0, i, j), id(0, i, j + 1), id(0, i + 1, j)});
            soup.faces.push_back({id(0, i + 1, j), id(0, i, j + 1), id(0, i + 1, j + 1)});
            soup.faces.push_back({id(1, i, j), id(1, i + 1, j), id(1, i, j + 1)});
            soup.faces.push_back({id(1, i + 1, j), id(1, i + 1, j + 1), id(1, i, j + 1)});
        }
        soup.faces.push_back({id(0, n, j), id(0, n, j + 1), id(1, n, j)});
        soup.faces.push_back({id(1, n, j), id(0, n, j + 1), id(1, n, j + 1)});
    }
    const tg::Vec3 start{0.2, 0.5, gap}, end{0.3, 0.5, 0.0};
    const std::vector<tg::Vec3> polyline{start, {1.0, 0.5, gap}, end};
    const auto r = tg::gcf_path_from_polyline(soup, polyline);
    ASSERT_FALSE(r.on_mesh.points.empty());
    EXPECT_LE(tg::euclidean(r.on_mesh.points.back(), end), 1e-12);
    EXPECT_LE(tg::euclidean(r.on_mesh.points.front(), start), 1e-12);
    const double geodesic = (1.0 - 0.2) + gap + (1.0 - 0.3);
    EXPECT_GE(r.on_mesh.length, geodesic * (1 - 1e-9));
    std::printf("[ gcf      ] hairpin: path from the given polyline %.6f, geodesic %.6f\n",
                r.on_mesh.length, geodesic);
}

namespace {

void expect_invalid(const std::function<void()>& f, const std::string& fragment) {
    try {
        f();
        ADD_FAILURE() << "no exception; expected one mentioning \"" << fragment << "\"";
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
    }
}

}  // namespace

TEST(CurvatureFlow, RejectsBadInput) {
    const tg::Soup soup = tg::surface("icosphere:2");
    const auto v0 = tg::SurfacePoint::vertex(0), v5 = tg::SurfacePoint::vertex(5);
    expect_invalid([&] { tg::gcf_path(soup, v0, v0); }, "coincide");
    auto with = [&](auto edit) {
        tg::CurvatureFlowOptions o;
        edit(o);
        return [&soup, &v0, &v5, o] { tg::gcf_path(soup, v0, v5, o); };
    };
    const double nan = std::numeric_limits<double>::quiet_NaN();
    expect_invalid(with([&](auto& o) { o.step = 0; }), "step");
    expect_invalid(with([&](auto& o) { o.step = -1; }), "step");
    expect_invalid(with([&](auto& o) { o.step = nan; }), "step");
    expect_invalid(with([&](auto& o) { o.tolerance = nan; }), "tolerance");
    expect_invalid(with([&](auto& o) { o.sample_spacing = nan; }), "sample_spacing");
    expect_invalid(with([&](auto& o) { o.sample_count = 2; }), "sample_count");
    expect_invalid(with([&](auto& o) { o.endpoint_weight = 0; }), "endpoint_weight");
    expect_invalid(with([&](auto& o) { o.update_tolerance = -1; }), "update_tolerance");
    expect_invalid([&] { tg::gcf_path(soup, v0, tg::SurfacePoint::vertex(100000)); },
                   "not a vertex of the mesh");
    expect_invalid(
        [&] {
            tg::gcf_path(soup, tg::SurfacePoint::face(0, {0.5, 0.6, 0.1}), v5);
        },
        "barycentric");
    expect_invalid([&] { tg::gcf_path_from_polyline(soup, {{1, 0, 0}}); }, "at least two");
}

TEST(CurvatureFlow, UnreachableIsAValue) {
    const tg::Soup one = tg::surface("icosphere:1");
    const tg::Soup two = tg::disjoint_union(one, one, {5, 0, 0});
    const auto r = tg::gcf_path(two, tg::SurfacePoint::vertex(0),
                                tg::SurfacePoint::vertex(one.points.size() + 1));
    EXPECT_EQ(r.report.status, "unreachable");
    EXPECT_TRUE(std::isinf(r.on_mesh.length));
}

// A reused GeodesicPathSolver answers each query as the one-shot function does, and the three
// Eigen solvers of the flow step reach the same path. Their times are the benchmark's
// (benchmarks/run_gcf.sh), not a unit test's (DESIGN.md §7). Tolerances: the same deterministic
// flow gives the same path, 1e-12 relative (rounding only); sparse QR solves the same
// least-squares step as LDLT (measured: the same length to the last digit, 1e-9); LSCG solves it
// iteratively, takes other steps and stops elsewhere inside the flow's own tolerance (measured
// 26 iterations against 18, length +8.8e-8 relative): 3e-7.
TEST(CurvatureFlow, ReusedSolverAndTheEigenSolversAgreeWithTheOneShotPath) {
    const tg::Soup soup = tg::surface("icosphere:5");
    const std::size_t a = 0;
    std::vector<std::pair<tg::SurfacePoint, tg::SurfacePoint>> pairs;
    for (double deg : {30.0, 90.0, 150.0, 179.0})
        pairs.push_back(
            {tg::SurfacePoint::vertex(a), tg::SurfacePoint::vertex(vertex_at_angle(soup, a, deg))});
    const auto q = tg::gcf_paths(soup, pairs);
    ASSERT_EQ(q.paths.size(), pairs.size());
    for (std::size_t k = 0; k < pairs.size(); ++k) {
        const auto one = tg::gcf_path(soup, pairs[k].first, pairs[k].second);
        EXPECT_EQ(q.paths[k].report.status, "converged") << k;
        EXPECT_EQ(one.report.status, "converged") << k;
        EXPECT_NEAR(q.paths[k].on_mesh.length, one.on_mesh.length, 1e-12 * one.on_mesh.length) << k;
        EXPECT_EQ(q.paths[k].report.iterations, one.report.iterations) << k;
    }
    const std::size_t b = vertex_at_angle(soup, a, 150.0);
    tg::GcfResult ref;
    for (auto s : {tg::CurvatureFlowSolver::eigen_normal_ldlt,
                   tg::CurvatureFlowSolver::eigen_sparse_qr, tg::CurvatureFlowSolver::eigen_lscg}) {
        tg::CurvatureFlowOptions o;
        o.solver = s;
        const auto r =
            tg::gcf_path(soup, tg::SurfacePoint::vertex(a), tg::SurfacePoint::vertex(b), o);
        EXPECT_EQ(r.report.status, "converged") << r.report.solver;
        EXPECT_EQ(r.report.solver, std::string(to_string(s)));
        if (s == tg::CurvatureFlowSolver::eigen_normal_ldlt) {
            ref = r;
            continue;
        }
        std::printf("[ gcf      ] icosphere:5 150 deg solver %-18s %zu it, on-mesh %.12f (%+.1e)\n",
                    r.report.solver.c_str(), r.report.iterations, r.on_mesh.length,
                    rel(r.on_mesh.length, ref.on_mesh.length));
        const double rel_tol = s == tg::CurvatureFlowSolver::eigen_lscg ? 3e-7 : 1e-9;
        EXPECT_NEAR(r.on_mesh.length, ref.on_mesh.length, rel_tol * ref.on_mesh.length)
            << r.report.solver;
    }
}

// Non-convex and open meshes: the on-mesh path is a path on the faces (>= exact polyhedral
// distance) and, converged or not, a few percent from it at most.
TEST(CurvatureFlow, OtherMeshesAgainstExactPolyhedral) {
    struct Case {
        const char* name;
        tg::Soup soup;
    };
    std::vector<Case> cases;
    cases.push_back({"spot", tg::spot()});
    cases.push_back({"cylinder:1,2:32,8", tg::surface("cylinder:1,2:32,8")});
    cases.push_back({"ellipsoid:1,1,0.5:4:0.3", tg::surface("ellipsoid:1,1,0.5:4:0.3")});
    for (const auto& c : cases) {
        const std::size_t n = c.soup.points.size();
        const std::size_t a = 0;
        const tg::MmpField mmp = tg::mmp_distances(c.soup, tg::Sources::vertex(a));
        const tg::MmpField loc_mmp =
            tg::mmp_distances(c.soup, tg::Sources{{tg::SurfacePoint::face(0, {0.2, 0.3, 0.5})}});
        for (std::size_t b : {n / 3, n / 2, n - 1}) {
            const auto r =
                tg::gcf_path(c.soup, tg::SurfacePoint::vertex(a), tg::SurfacePoint::vertex(b));
            const double e = mmp.d[b];
            std::printf(
                "[ gcf      ] %-24s %zu-%zu: exact %.6f on-mesh %.6f (%+.2e; plane-cut %+.2e, "
                "%zu flips, %zu bends) smooth %.6f (%+.2e) | %zu samples, %zu it, kappa*h %.1e, "
                "%s, fallbacks %zu\n",
                c.name, a, b, e, r.on_mesh.length, (r.on_mesh.length - e) / e,
                (r.report.traced_length - e) / e, r.report.straighten_flips,
                r.report.straighten_bends, r.smooth.length, (r.smooth.length - e) / e,
                r.report.samples, r.report.iterations, r.report.scaled_max_geodesic_curvature,
                r.report.status.c_str(), r.report.trace_fallbacks);
            EXPECT_GE(r.on_mesh.length, e * (1 - 1e-9)) << c.name << " " << b;
            EXPECT_LE(r.on_mesh.length, e * 1.03) << c.name << " " << b << " " << r.report.status;
            // A face-location start and a restart from the traced path. Regression: on the
            // jittered ellipsoid these cycled without converging while the projection looked only
            // at the 1-ring of the nearest vertex.
            const auto loc = tg::gcf_path(c.soup, tg::SurfacePoint::face(0, {0.2, 0.3, 0.5}),
                                          tg::SurfacePoint::vertex(b));
            const auto again = tg::gcf_path_from_polyline(c.soup, r.on_mesh.points);
            tg::CurvatureFlowOptions interp;
            interp.interpolate_normals = true;
            const auto loc_i = tg::gcf_path(c.soup, tg::SurfacePoint::face(0, {0.2, 0.3, 0.5}),
                                            tg::SurfacePoint::vertex(b), interp);
            const double e_loc = loc_mmp.d[b];
            std::printf(
                "[ gcf      ]   face-location start: %s (kappa*h %.1e, %+.2e vs exact); "
                "interpolated normals: %s (%.1e, %+.2e); restart from the traced path: %s "
                "(%.1e)\n",
                loc.report.status.c_str(), loc.report.scaled_max_geodesic_curvature,
                (loc.on_mesh.length - e_loc) / e_loc, loc_i.report.status.c_str(),
                loc_i.report.scaled_max_geodesic_curvature, (loc_i.on_mesh.length - e_loc) / e_loc,
                again.report.status.c_str(), again.report.scaled_max_geodesic_curvature);
            // Converged or not (on spot, irregular and non-convex, some runs cycle without
            // reaching the flow's tolerance), the result is a path on the faces from the face
            // location: never below the exact distance, and within the same 3 % of it.
            if (std::string(c.name) != "spot") {
                EXPECT_EQ(loc.report.status, "converged") << c.name << " " << b;
                EXPECT_EQ(again.report.status, "converged") << c.name << " " << b;
            }
            for (const auto* p : {&loc, &loc_i}) {
                EXPECT_GE(p->on_mesh.length, e_loc * (1 - 1e-9)) << c.name << " " << b;
                EXPECT_LE(p->on_mesh.length, e_loc * 1.03) << c.name << " " << b;
            }
            EXPECT_GE(again.on_mesh.length, e * (1 - 1e-9));
            EXPECT_NEAR(again.on_mesh.length, r.on_mesh.length, 1e-3 * r.on_mesh.length);
        }
    }
}

// The interpolated-normal option (not the thesis' rule): same checks as the default on the
// icospheres, numbers printed for comparison.
TEST(CurvatureFlow, InterpolatedNormals) {
    tg::CurvatureFlowOptions o;
    o.interpolate_normals = true;
    for (int level : {4, 5}) {
        const std::string spec = "icosphere:" + std::to_string(level);
        const tg::Soup soup = tg::surface(spec);
        const auto truth = tg::analytic_distances(spec, soup, 0);
        const tg::MmpField mmp = tg::mmp_distances(soup, tg::Sources::vertex(0));
        for (double degrees : {90.0, 150.0}) {
            const std::size_t b = vertex_at_angle(soup, 0, degrees);
            const auto r =
                tg::gcf_path(soup, tg::SurfacePoint::vertex(0), tg::SurfacePoint::vertex(b), o);
            std::printf(
                "[ gcf      ] interpolated normals %s %3.0f deg: on-mesh vs exact %+.2e, "
                "smooth vs great circle %.2e, %zu it, %s\n",
                spec.c_str(), degrees, (r.on_mesh.length - mmp.d[b]) / mmp.d[b],
                rel(r.smooth.length, truth[b]), r.report.iterations, r.report.status.c_str());
            EXPECT_EQ(r.report.status, "converged");
            EXPECT_GE(r.on_mesh.length, mmp.d[b] * (1 - 1e-9));
            EXPECT_LE(r.on_mesh.length, mmp.d[b] * 1.03);
        }
    }
}

// Ceres against the Eigen normal-equation LDLT on the same flow (the time per iteration is the
// benchmark's, DESIGN.md §7). Both minimise the same linear least-squares system per step; they
// differ in how the endpoints are held (Ceres: constant parameter blocks; Eigen: rows of weight
// 1e4, which let the endpoint coordinates move by O(1e-8) inside the solve, though the endpoints
// themselves are never moved) and in rounding. So the iterates agree to far below the flow's own
// tolerance and the flow takes the same number of steps: the final samples must agree to 1e-8
// mean edge lengths (the endpoint rows' effect; measured <= 7e-11) and the lengths to 1e-9
// relative. CGNR solves each step only to its iterative tolerance, so its path is another point
// of the flow's stopping set: converged, and its length within kCgnrRel of the exact steps'.
TEST(CurvatureFlow, CeresSolverMatchesEigen) {
    if (!tg::gcf_ceres_available())
        GTEST_SKIP() << "tapeline::geodesic_ceres not built";
    constexpr double kCgnrRel = 1e-6;
    for (int level : {5, 6}) {
        const std::string spec = "icosphere:" + std::to_string(level);
        const tg::Soup soup = tg::surface(spec);
        const double h = tg::mean_edge_length(soup);
        const std::size_t a = 0, b = vertex_at_angle(soup, a, 150.0);
        for (std::size_t samples : {40, 100, 300}) {
            struct Run {
                const char* name;
                tg::CurvatureFlowSolver solver;
                tg::CeresLinearSolver linear;
            };
            using S = tg::CurvatureFlowSolver;
            using L = tg::CeresLinearSolver;
            std::vector<Run> runs{
                {"eigen_normal_ldlt", S::eigen_normal_ldlt, L{}},
                {"ceres sparse chol (SuiteSparse)", S::ceres, L::sparse_normal_cholesky},
                {"ceres sparse chol (Eigen)", S::ceres, L::sparse_normal_cholesky_eigen}};
            if (samples <= 100)  // slow beyond: 15 ms per iteration at 300 samples
                runs.push_back({"ceres cgnr", S::ceres, L::cgnr});
            if (samples <= 40)  // dense: 3.4 ms per iteration at 100 samples
                runs.push_back({"ceres dense_qr", S::ceres, L::dense_qr});
            tg::GcfResult ref;
            for (const Run& run : runs) {
                tg::CurvatureFlowOptions o;
                o.sample_count = samples;
                o.solver = run.solver;
                o.ceres_linear_solver = run.linear;
                const tg::GcfResult r =
                    tg::gcf_path(soup, tg::SurfacePoint::vertex(a), tg::SurfacePoint::vertex(b), o);
                EXPECT_EQ(r.report.solver, std::string(to_string(run.solver)));
                if (run.solver == S::eigen_normal_ldlt) {
                    ref = r;
                    continue;
                }
                const std::string what = spec + " " + std::to_string(samples) + " " + run.name;
                std::printf("[ gcf      ] %s: %zu it (eigen %zu), %s, on-mesh %+.1e vs eigen\n",
                            what.c_str(), r.report.iterations, ref.report.iterations,
                            r.report.status.c_str(), rel(r.on_mesh.length, ref.on_mesh.length));
                if (run.linear == L::cgnr) {
                    // An iterative inner solve converges in more outer steps (it may stop at the
                    // iteration limit where the direct solve converged): its path length is what
                    // must agree.
                    EXPECT_NEAR(r.on_mesh.length, ref.on_mesh.length, kCgnrRel * ref.on_mesh.length)
                        << what;
                    continue;
                }
                EXPECT_EQ(r.report.status, ref.report.status) << what;
                ASSERT_EQ(r.smooth.points.size(), ref.smooth.points.size());
                double max_dev = 0;
                for (std::size_t i = 0; i < r.smooth.points.size(); ++i)
                    max_dev =
                        std::max(max_dev, tg::euclidean(r.smooth.points[i], ref.smooth.points[i]));
                EXPECT_EQ(r.report.iterations, ref.report.iterations) << what;
                EXPECT_LE(max_dev, 1e-8 * h) << what;
                EXPECT_NEAR(r.on_mesh.length, ref.on_mesh.length, 1e-9 * ref.on_mesh.length)
                    << what;
            }
        }
    }
}

TEST(CurvatureFlow, CeresSolverMissingIsRejected) {
    if (!tg::gcf_ceres_available())
        GTEST_SKIP() << "tapeline::geodesic_ceres not built";
    const tg::Soup soup = tg::surface("icosphere:2");
    tg::CurvatureFlowOptions o;
    o.solver = tg::CurvatureFlowSolver::ceres;
    tg::gcf_ceres_register(false);
    try {
        tg::gcf_path(soup, tg::SurfacePoint::vertex(0), tg::SurfacePoint::vertex(5), o);
        ADD_FAILURE() << "no exception";
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("curvature_flow_ceres.h"), std::string::npos)
            << e.what();
    }
    tg::gcf_ceres_register(true);
    EXPECT_EQ(tg::gcf_path(soup, tg::SurfacePoint::vertex(0), tg::SurfacePoint::vertex(5), o)
                  .report.status,
              "converged");
}

// GeodesicPathSolver::paths runs the queries with tbb::parallel_for on one shared solver (and its
// lazily filled frame cache): every result must be bitwise the one of the sequential queries,
// since each query is deterministic and a frame is the same whichever thread computes it.
TEST(CurvatureFlow, ParallelPathsEqualSequential) {
    struct Case {
        const char* name;
        tg::Soup soup;
    };
    std::vector<Case> cases;
    cases.push_back({"icosphere:5", tg::surface("icosphere:5")});
    cases.push_back({"spot", tg::spot()});
    for (const auto& c : cases) {
        std::vector<std::pair<tg::SurfacePoint, tg::SurfacePoint>> pairs;
        const std::size_t n = c.soup.points.size(), nf = c.soup.faces.size();
        for (std::size_t k = 0; k < 24; ++k) {
            const auto from = k % 3 == 0 ? tg::SurfacePoint::face((k * 977) % nf, {0.2, 0.3, 0.5})
                                         : tg::SurfacePoint::vertex((k * 131) % n);
            pairs.push_back({from, tg::SurfacePoint::vertex((k * 7919 + n / 2) % n)});
        }
        const auto t0 = std::chrono::steady_clock::now();
        const tg::GcfQueries seq = tg::gcf_paths(c.soup, pairs);
        const double seq_s =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count() -
            seq.prepare_seconds;
        double par_s = 0;
        const tg::GcfQueries par = tg::gcf_paths_parallel(c.soup, pairs, {}, &par_s);
        ASSERT_EQ(par.paths.size(), seq.paths.size());
        for (std::size_t k = 0; k < pairs.size(); ++k) {
            const auto& p = par.paths[k];
            const auto& q = seq.paths[k];
            EXPECT_EQ(p.on_mesh.points, q.on_mesh.points) << c.name << " pair " << k;
            EXPECT_EQ(p.smooth.points, q.smooth.points) << c.name << " pair " << k;
            EXPECT_EQ(p.on_mesh.length, q.on_mesh.length) << c.name << " pair " << k;
            EXPECT_EQ(p.report.iterations, q.report.iterations) << c.name << " pair " << k;
            EXPECT_EQ(p.report.status, q.report.status) << c.name << " pair " << k;
        }
        std::printf(
            "[ gcf      ] %s: %zu paths, sequential %.1f ms, GeodesicPathSolver::paths "
            "(parallel) %.1f ms\n",
            c.name, pairs.size(), 1e3 * seq_s, 1e3 * par_s);
    }
    // A bad pair is named before any work.
    const tg::Soup soup = tg::surface("icosphere:2");
    try {
        tg::gcf_paths_parallel(soup, {{tg::SurfacePoint::vertex(0), tg::SurfacePoint::vertex(5)},
                                      {tg::SurfacePoint::vertex(3), tg::SurfacePoint::vertex(3)}});
        ADD_FAILURE() << "no exception";
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("pair #1"), std::string::npos) << e.what();
    }
}

// The straightened on-mesh path (options.straighten, the default) against the exact polyhedral
// distance (our MMP). Started from the exact path itself (the right homotopy class) it must be
// within the 1e-6 relative: the funnel is exact up to rounding in whatever face sequence
// the flow leaves it, but the flow (which follows the smooth surface) may move the path across a
// vertex into a neighbouring class whose geodesic is longer by ~1e-9..1e-7 (measured: up to
// +3.5e-7 on spot, where the path bends at a saddle). From the Dijkstra start the flow can settle
// on a farther locally shortest path: it is then still a polyhedral geodesic, straight in its own
// unfolding where it passes no vertex (1e-9 relative), and never shorter than the exact path.
TEST(CurvatureFlow, StraightenedPathIsTheExactDistanceInItsClass) {
    // From the Dijkstra start the flow may settle on a farther locally shortest path: measured
    // worst +2.4e-7 (icosphere:5), +5.7e-6 (icosphere:6), +3.5e-7 (spot); about 3.5x.
    constexpr double kDijkstraGap = 2e-5;
    struct Case {
        const char* name;
        tg::Soup soup;
        std::size_t pairs;
    };
    std::vector<Case> cases;
    cases.push_back({"icosphere:5", tg::surface("icosphere:5"), 9});
    cases.push_back({"icosphere:6", tg::surface("icosphere:6"), 5});
    cases.push_back({"spot", tg::spot(), 9});
    for (const auto& c : cases) {
        const std::size_t n = c.soup.points.size();
        const std::size_t a = 0;
        std::vector<tg::SurfacePoint> targets;
        for (std::size_t k = 1; k <= c.pairs; ++k)
            targets.push_back(tg::SurfacePoint::vertex((k * n) / (c.pairs + 1) + 7));
        const auto exact = tg::mmp_paths(c.soup, tg::Sources::vertex(a), targets);
        std::size_t exact_count = 0, exact_count_from_exact = 0;
        double worst = 0, worst_from_exact = 0;
        for (std::size_t k = 0; k < targets.size(); ++k) {
            const std::size_t b = targets[k].index;
            const double e = exact[k].length;
            const auto r = tg::gcf_path(c.soup, tg::SurfacePoint::vertex(a), targets[k]);
            const double gap = (r.on_mesh.length - e) / e;
            exact_count += std::abs(gap) <= 1e-9;
            worst = std::max(worst, gap);
            EXPECT_GE(gap, -1e-9) << c.name << " " << b;
            EXPECT_LE(gap, kDijkstraGap) << c.name << " " << b;
            EXPECT_TRUE(r.report.straightened) << c.name << " " << b;
            if (r.report.straighten_bends == 0) {
                const tg::UnfoldedPath u = tg::unfold(c.soup, r.on_mesh.points);
                EXPECT_NEAR(u.unfolded_length, u.straight_length, 1e-9 * u.straight_length)
                    << c.name << " " << b;
            }
            // The exact path as the initial polyline (reversed: MMP traces from the target).
            std::vector<tg::Vec3> init(exact[k].points.rbegin(), exact[k].points.rend());
            const auto from_exact = tg::gcf_path_from_polyline(c.soup, init);
            const double gap_exact = (from_exact.on_mesh.length - e) / e;
            exact_count_from_exact += std::abs(gap_exact) <= 1e-9;
            worst_from_exact = std::max(worst_from_exact, gap_exact);
            std::printf(
                "[ gcf      ] %s 0-%zu: exact %.9f | Dijkstra start: on-mesh %+.1e (plane-cut "
                "%+.1e), %zu flips, %zu bends, %s | exact-path start: on-mesh %+.1e (plane-cut "
                "%+.1e)\n",
                c.name, b, e, gap, (r.report.traced_length - e) / e, r.report.straighten_flips,
                r.report.straighten_bends, r.report.status.c_str(), gap_exact,
                (from_exact.report.traced_length - e) / e);
            EXPECT_GE(gap_exact, -1e-9) << c.name << " " << b;
            EXPECT_LE(gap_exact, 1e-6) << c.name << " " << b;
        }
        std::printf(
            "[ gcf      ] %s: exact to 1e-9: %zu of %zu from Dijkstra (worst %+.1e), %zu of %zu "
            "from the exact path (worst %+.1e)\n",
            c.name, exact_count, targets.size(), worst, exact_count_from_exact, targets.size(),
            worst_from_exact);
    }
}
