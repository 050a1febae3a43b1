// Heat method (CGAL Heat_method_3 behind heat.h), measured against the exact polyhedral
// distance. The heat method approximates the smooth distance with an O(h)-ish error that
// concentrates near the source (where the normalised gradient is least accurate) and on poor
// triangles, so tolerances are relative errors with a ~1.5-2x margin over measured values, and
// "far" errors are over vertices with d > 0.1 max(d).
#include <tapeline/core/errors.h>
#include <tapeline_test/geodesic.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace tg = tapeline_test::geodesic;

namespace {

struct Case {
    const char* name;
    double mean_tol, far_tol, below_euclid_h;
};

tg::Soup load(const std::string& name) {
    return name == "spot" ? tg::spot() : tg::surface(name);
}

}  // namespace

// Measured (source vertex 0, heat / heat_idt):
//   icosphere:4              mean 1.06e-2 / 1.06e-2, far max 3.44e-2 / 3.44e-2, min(d - |pq|) -0.18
//   h spot                     mean 1.69e-2 / 1.69e-2, far max 1.68e-1 / 1.70e-1, min(d - |pq|)
//   -0.70 h ellipsoid:1,1,0.5:4:0.3  mean 1.29e-2 / 1.34e-2, far max 6.08e-2 / 5.91e-2, min(d -
//   |pq|) -0.28 h
// Heat may undershoot the Euclidean lower bound: it is a smoothed distance (the heat step blurs
// the source over ~sqrt(t) = h) and the potential is fixed only up to the value at the source,
// so near the source and across thin parts (spot's legs and ears) it reads short by a fraction
// of an edge.
TEST(Heat, WithinToleranceOfExact) {
    const Case cases[] = {{"icosphere:4", 0.02, 0.06, 0.4},
                          {"spot", 0.03, 0.25, 1.0},
                          {"ellipsoid:1,1,0.5:4:0.3", 0.025, 0.1, 0.5}};
    for (const Case& c : cases) {
        const tg::Soup soup = load(c.name);
        const double h = tg::mean_edge_length(soup);
        const tg::Field exact = tg::distances(soup, tg::Method::exact, tg::Sources::vertex(0));
        for (auto m : {tg::Method::heat, tg::Method::heat_idt}) {
            const tg::Field f = tg::distances(soup, m, tg::Sources::vertex(0));
            const tg::ErrorStats e = tg::compare(f.d, exact.d);
            EXPECT_LT(e.mean_rel, c.mean_tol) << c.name << " " << tg::name(m);
            EXPECT_LT(e.max_rel_far, c.far_tol) << c.name << " " << tg::name(m);
            EXPECT_EQ(f.d[0], 0.0);
            EXPECT_EQ(f.report.method, tg::name(m));
            EXPECT_EQ(f.report.unreachable, 0u);
            for (std::size_t v = 0; v < soup.points.size(); ++v)
                ASSERT_GE(f.d[v],
                          tg::euclidean(soup.points[v], soup.points[0]) - c.below_euclid_h * h)
                    << c.name << " " << tg::name(m) << " vertex " << v;
        }
    }
}

// The intrinsic Delaunay Laplacian is what fixes obtuse triangles. On a flat square grid whose
// every cell is cut along its long diagonal after a shear x += 2 y (a convex parallelogram, so
// the truth is Euclidean), measured mean rel error: heat 0.355, heat_idt 0.023 (15x better).
// On an already Delaunay mesh the two are the same (icosphere:4: 1.060e-2 both). What is NOT
// true: idt is better everywhere -- on uvsphere:32,64 it measured worse (mean 1.2e-3 vs 5.5e-4),
// the pole fans being Delaunay already and the intrinsic edge lengths changing the time step.
TEST(Heat, IntrinsicDelaunayFixesObtuseTriangles) {
    const tg::Soup soup = tg::sheared_grid(24);
    const std::size_t source = 312;  // the centre vertex (12, 12)
    std::vector<double> truth(soup.points.size());
    for (std::size_t v = 0; v < truth.size(); ++v)
        truth[v] = tg::euclidean(soup.points[v], soup.points[source]);
    const auto heat =
        tg::compare(tg::distances(soup, tg::Method::heat, tg::Sources::vertex(source)).d, truth);
    const auto idt = tg::compare(
        tg::distances(soup, tg::Method::heat_idt, tg::Sources::vertex(source)).d, truth);
    EXPECT_GT(heat.mean_rel, 0.2);
    EXPECT_LT(idt.mean_rel, 0.05);
    EXPECT_LT(idt.mean_rel, 0.25 * heat.mean_rel);

    const tg::Soup sphere = tg::surface("icosphere:4");
    const auto a = tg::distances(sphere, tg::Method::heat, tg::Sources::vertex(0)).d;
    const auto b = tg::distances(sphere, tg::Method::heat_idt, tg::Sources::vertex(0)).d;
    const auto ab = tg::compare(a, b);
    EXPECT_LT(ab.max_rel_far, 1e-6) << "an already Delaunay mesh should not change";
}

// Several sources. Default (min_of_single_sources): exactly the minimum of single-source heat
// fields from the same prefactored solver, and within tolerance of the exact multi-source field
// (icosphere:4, 4 sources, measured mean 1.60e-2, far max 6.2e-2). CGAL's joint solve
// (cgal_joint) carries the CGAL#9565 bias: measured mean 2.95e-2, far max 0.150.
TEST(Heat, MultipleSourcesAvoidTheJointNormalisationBias) {
    const tg::Soup soup = tg::surface("icosphere:4");
    const std::vector<std::size_t> src = {0, 100, 500, 1200};
    tg::Sources all;
    std::vector<tg::Sources> queries;
    for (auto s : src) {
        all.points.push_back(tg::SurfacePoint::vertex(s));
        queries.push_back(tg::Sources::vertex(s));
    }
    queries.push_back(all);
    const auto fields = tg::heat_queries(soup, queries);
    ASSERT_EQ(fields.size(), src.size() + 1);
    for (std::size_t v = 0; v < soup.points.size(); ++v) {
        double best = std::numeric_limits<double>::infinity();
        for (std::size_t k = 0; k < src.size(); ++k)
            best = std::min(best, fields[k].d[v]);
        ASSERT_EQ(fields.back().d[v], best) << v;
    }
    const tg::Field exact = tg::distances(soup, tg::Method::exact, all);
    const auto ours = tg::compare(fields.back().d, exact.d);
    EXPECT_LT(ours.mean_rel, 0.03);
    EXPECT_LT(ours.max_rel_far, 0.1);

    // The joint mode is honoured (one joint solve, not the pointwise minimum) and is a distance
    // field within its own measured error (mean 2.95e-2: 2x margin). Whether it beats the default
    // is a benchmark question (geodesic/README.md), not asserted: an improvement must not fail.
    tg::HeatOptions joint;
    joint.multi_source = tg::HeatMultiSource::cgal_joint;
    const auto joint_d =
        tg::distances(soup, tg::Method::heat, all, tg::MeshKind::surface_mesh, joint).d;
    ASSERT_EQ(joint_d.size(), soup.points.size());
    for (std::size_t v = 0; v < joint_d.size(); ++v)
        ASSERT_TRUE(std::isfinite(joint_d[v]) && joint_d[v] >= 0) << v << " " << joint_d[v];
    EXPECT_NE(joint_d, fields.back().d);
    const auto cgal = tg::compare(joint_d, exact.d);
    EXPECT_LT(cgal.mean_rel, 0.06);
}

// One solver, several queries: each query equals the one-shot function, the factorisation time
// is reported once (prepare_seconds identical for every query).
TEST(Heat, PrefactoredSolverMatchesOneShot) {
    const tg::Soup soup = tg::surface("ellipsoid:1,1,0.5:3");
    const auto fields = tg::heat_queries(soup, {tg::Sources::vertex(3), tg::Sources::vertex(300)});
    ASSERT_EQ(fields.size(), 2u);
    EXPECT_EQ(fields[0].d, tg::distances(soup, tg::Method::heat, tg::Sources::vertex(3)).d);
    EXPECT_EQ(fields[1].d, tg::distances(soup, tg::Method::heat, tg::Sources::vertex(300)).d);
    EXPECT_GT(fields[0].report.prepare_seconds, 0.0);
    EXPECT_EQ(fields[0].report.prepare_seconds, fields[1].report.prepare_seconds);
}

// Meshes with boundary: flat square (truth Euclidean; measured mean rel 2.6e-2, max |err| 0.64 h)
// and the open cylinder (against exact; all finite).
TEST(Heat, WorksOnMeshesWithBoundary) {
    const tg::Soup square = tg::flat_grid(24, 1.0);
    std::vector<double> truth(square.points.size());
    for (std::size_t v = 0; v < truth.size(); ++v)
        truth[v] = tg::euclidean(square.points[v], square.points[312]);
    const double h = tg::mean_edge_length(square);
    for (auto m : {tg::Method::heat, tg::Method::heat_idt}) {
        const auto e = tg::compare(tg::distances(square, m, tg::Sources::vertex(312)).d, truth);
        EXPECT_LT(e.mean_rel, 0.05) << tg::name(m);
        EXPECT_LT(e.max_abs, 1.0 * h) << tg::name(m);
    }
    const tg::Soup cylinder = tg::surface("cylinder:1,2:32,8");
    const tg::Field exact = tg::distances(cylinder, tg::Method::exact, tg::Sources::vertex(0));
    const auto e =
        tg::compare(tg::distances(cylinder, tg::Method::heat, tg::Sources::vertex(0)).d, exact.d);
    EXPECT_LT(e.mean_rel, 0.05);
}

// Zero-area faces: both modes reject them with InvalidInput naming the face, before the iDT
// flips can loop (CGAL#5010; if this guard broke, this test would hang, not fail). Plain heat
// without the check does not crash: CGAL computes NaN internally and hands out DBL_MAX for every
// vertex; we turn that into a SolverFailure.
TEST(Heat, ZeroAreaFacesAreRejectedOrReportedAsSolverFailure) {
    tg::Soup soup = tg::flat_grid(4, 1.0);
    // Move the interior vertex 6 onto the segment between the two other corners of the first face
    // that contains it: that face gets zero area, the square stays flat.
    std::size_t f = 0;
    while (std::find(soup.faces[f].begin(), soup.faces[f].end(), 6u) == soup.faces[f].end())
        ++f;
    std::vector<std::size_t> other;
    for (auto v : soup.faces[f])
        if (v != 6)
            other.push_back(v);
    for (int c = 0; c < 3; ++c)
        soup.points[6][c] = 0.5 * (soup.points[other[0]][c] + soup.points[other[1]][c]);
    const std::string face_name = "face #" + std::to_string(f) + " is degenerate";
    for (auto m : {tg::Method::heat, tg::Method::heat_idt}) {
        try {
            tg::distances(soup, m, tg::Sources::vertex(0));
            ADD_FAILURE() << tg::name(m) << ": no exception";
        } catch (const tapeline::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find(face_name), std::string::npos) << e.what();
            EXPECT_NE(std::string(e.what()).find("CGAL#5010"), std::string::npos) << e.what();
        }
    }
    tg::HeatOptions unchecked;
    unchecked.reject_degenerate_faces = false;
    EXPECT_THROW(tg::distances(soup, tg::Method::heat, tg::Sources::vertex(0),
                               tg::MeshKind::surface_mesh, unchecked),
                 tapeline::SolverFailure);
    // The intrinsic Delaunay mode always checks.
    EXPECT_THROW(tg::distances(soup, tg::Method::heat_idt, tg::Sources::vertex(0),
                               tg::MeshKind::surface_mesh, unchecked),
                 tapeline::InvalidInput);
    // Exact and Dijkstra cope with the zero-area face (the square stays flat): d = Euclidean for
    // the exact method at the far corner.
    const tg::Field exact = tg::distances(soup, tg::Method::exact, tg::Sources::vertex(0));
    EXPECT_NEAR(exact.d[24], std::sqrt(2.0), 1e-12);
}

TEST(Heat, FaceLocationSourceIsRejected) {
    const tg::Soup soup = tg::surface("icosphere:2");
    for (auto m : {tg::Method::heat, tg::Method::heat_idt}) {
        try {
            tg::distances(soup, m, tg::Sources{{tg::SurfacePoint::face(3, {0.2, 0.3, 0.5})}});
            ADD_FAILURE() << "no exception";
        } catch (const tapeline::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find("face-location source is not supported"),
                      std::string::npos)
                << e.what();
        }
    }
}
