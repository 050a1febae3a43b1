// Fast marching (fast_marching.h): analytic truth on flat and spherical meshes, the exact
// polyhedral distance and Dijkstra's edge paths as bounds, the obtuse-corner unfolding.
#include <tapeline_test/fast_marching.h>
#include <tapeline_test/geodesic.h>
#include <tapeline_test/mmp.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>
#include <vector>

namespace tg = tapeline_test::geodesic;

namespace {

/// The flat grid with every interior vertex moved by up to `jitter` cells in x and y (seeded):
/// a planar mesh with obtuse faces.
tg::Soup jittered_grid(std::size_t n, double jitter, unsigned seed) {
    tg::Soup soup = tg::flat_grid(n, 1.0);
    std::mt19937 rng(seed);
    std::uniform_real_distribution<double> u(-jitter / n, jitter / n);
    for (std::size_t j = 1; j < n; ++j)
        for (std::size_t i = 1; i < n; ++i) {
            auto& p = soup.points[j * (n + 1) + i];
            p[0] += u(rng);
            p[1] += u(rng);
        }
    return soup;
}

double mean_abs_error(const std::vector<double>& d, const std::vector<double>& truth) {
    double sum = 0;
    for (std::size_t v = 0; v < d.size(); ++v)
        sum += std::abs(d[v] - truth[v]);
    return sum / d.size();
}

}  // namespace

// A plane wave is what the update assumes: with the sources on the line x = 0 the distance is x,
// a linear field, and every face update that the wave passes through reproduces it to round-off.
// On a grid of right triangles every vertex has such a face; on the jittered grid (559 obtuse
// corners) the obtuse corners need their virtual edges for it: without them 525 of the 625
// vertices are off, by up to 1.7e-2 (measured).
TEST(FastMarching, LinearFieldIsExactOnFlatMeshes) {
    // The heat test's sheared grid: every cell cut along its long diagonal after x += 2y, corners
    // of 153 degrees; sources on the bottom edge [0, 1] x {0}. A vertex above that edge (x <= 1)
    // is at distance y, and the vertex straight below it lies at exactly 90 degrees to one edge of
    // its obtuse corner: the section must be closed (up to the unfolding's rounding) to find it.
    // (Beyond x = 1 the distance is to the corner (1, 0): a point source, not checked here.)
    {
        const std::size_t n = 24;
        const tg::Soup soup = tg::sheared_grid(n);
        tg::Sources row;
        for (std::size_t i = 0; i <= n; ++i)
            row.points.push_back(tg::SurfacePoint::vertex(i));
        const tg::FastMarchingField f = tg::fast_marching(soup, row);
        double worst = 0;
        std::size_t above = 0;
        for (std::size_t v = 0; v < soup.points.size(); ++v)
            if (soup.points[v][0] <= 1 + 1e-12) {
                worst = std::max(worst, std::abs(f.d[v] - soup.points[v][1]));
                ++above;
            }
        EXPECT_LT(worst, 1e-12) << "sheared grid";
        EXPECT_EQ(above, 169u);  // i + 2j <= 24
        EXPECT_EQ(f.report.obtuse_corners, 2 * n * n);
    }
    for (const double jitter : {0.0, 0.35}) {
        const std::size_t n = 24;
        const tg::Soup soup = jitter > 0 ? jittered_grid(n, jitter, 7) : tg::flat_grid(n, 1.0);
        tg::Sources line;
        for (std::size_t j = 0; j <= n; ++j)
            line.points.push_back(tg::SurfacePoint::vertex(j * (n + 1)));
        for (const bool unfold : {true, false}) {
            tg::FastMarchingOptions o;
            o.unfold_obtuse = unfold;
            const tg::FastMarchingField f = tg::fast_marching(soup, line, o);
            double worst = 0;
            for (std::size_t v = 0; v < soup.points.size(); ++v)
                worst = std::max(worst, std::abs(f.d[v] - soup.points[v][0]));
            if (jitter == 0 || unfold)
                EXPECT_LT(worst, 1e-12) << "jitter " << jitter << " unfold " << unfold;
            else
                EXPECT_GT(worst, 1e-3) << "the jittered grid needs its virtual edges";
            EXPECT_EQ(f.report.obtuse_corners == 0, jitter == 0);
            EXPECT_EQ(f.report.virtual_edges, unfold ? f.report.obtuse_corners : 0u);
        }
    }
}

// A point source: the error against the Euclidean distance falls under refinement on the flat
// grid, a little slower than the edge length (the plane wave cannot follow the front's curvature
// near the source; measured mean absolute error 5.6e-3, 3.8e-3, 2.4e-3 at 16, 32, 64 cells: ratios
// 1.49, 1.58). Dijkstra's error would not fall at all (the diagonals' zig-zag stays).
TEST(FastMarching, PointSourceErrorIsFirstOrder) {
    std::vector<double> errors;
    for (const std::size_t n : {16u, 32u, 64u}) {
        const tg::Soup soup = tg::flat_grid(n, 1.0);
        const std::size_t centre = (n / 2) * (n + 1) + n / 2;
        const tg::FastMarchingField f = tg::fast_marching(soup, tg::Sources::vertex(centre));
        std::vector<double> truth;
        for (const auto& p : soup.points)
            truth.push_back(tg::euclidean(p, soup.points[centre]));
        errors.push_back(mean_abs_error(f.d, truth));
    }
    for (std::size_t i = 1; i < errors.size(); ++i)
        EXPECT_GT(errors[i - 1] / errors[i], 1.35) << i;
}

// On the unit sphere against the great-circle distance: the mean relative error falls under
// refinement (measured 2.0e-2, 1.5e-2, 9.6e-3 at icosphere levels 3, 4, 5: ratios 1.40, 1.51) and
// is a fraction of Dijkstra's, which does not fall (8.3e-2, 8.5e-2, 8.6e-2).
TEST(FastMarching, SphereConvergesToTheGreatCircleDistance) {
    std::vector<double> errors;
    for (const char* spec : {"icosphere:3", "icosphere:4", "icosphere:5"}) {
        const tg::Soup soup = tg::surface(spec);
        const std::vector<double> truth = tg::analytic_distances(spec, soup, 0);
        const tg::FastMarchingField f = tg::fast_marching(soup, tg::Sources::vertex(0));
        const tg::Field dij = tg::distances(soup, tg::Method::dijkstra, tg::Sources::vertex(0));
        const tg::ErrorStats e = tg::compare(f.d, truth);
        const tg::ErrorStats ed = tg::compare(dij.d, truth);
        errors.push_back(e.mean_rel);
        EXPECT_LT(e.mean_rel, ed.mean_rel / 4) << spec;
    }
    for (std::size_t i = 1; i < errors.size(); ++i)
        EXPECT_GT(errors[i - 1] / errors[i], 1.3) << i;
}

// Every vertex's value is at most its smallest neighbour's plus the edge (the one-vertex updates
// are always among the candidates, and a neighbour accepted later is no smaller), so by induction
// over Dijkstra's order the fast marching never exceeds Dijkstra's edge-path distance. It is
// not a bound the other way: on the torus's saddles it falls below the exact polyhedral distance
// (by up to 1.1e-2, 1 % of the torus's radius, measured). Its mean error against the exact
// distance is well under Dijkstra's (measured 3.0-3.4 % here).
TEST(FastMarching, NeverAboveDijkstra) {
    for (const char* spec : {"icosphere:3", "ellipsoid:1,0.6,0.3:4:0.25", "torus:1,0.4:40,16"}) {
        const tg::Soup soup = tg::surface(spec);
        tg::Sources sources;
        sources.points = {tg::SurfacePoint::vertex(3), tg::SurfacePoint::face(30, {0.2, 0.5, 0.3})};
        const tg::FastMarchingField f = tg::fast_marching(soup, sources);
        const tg::Field dij = tg::distances(soup, tg::Method::dijkstra, sources);
        const tg::MmpField exact = tg::mmp_distances(soup, sources);
        for (std::size_t v = 0; v < soup.points.size(); ++v)
            ASSERT_LE(f.d[v], dij.d[v] * (1 + 1e-12)) << spec << " vertex " << v;
        const tg::ErrorStats e = tg::compare(f.d, exact.d);
        EXPECT_LT(e.mean_rel, tg::compare(dij.d, exact.d).mean_rel / 2) << spec;
    }
}

// Obtuse corners: the jittered ellipsoid has them (10,488 of 61,440 corners); their virtual edges
// halve the mean error against the exact polyhedral distance (measured 1.6e-2 against 3.1e-2).
TEST(FastMarching, UnfoldingObtuseCornersLowersTheError) {
    const tg::Soup soup = tg::surface("ellipsoid:1,0.6,0.3:5:0.25");
    const tg::MmpField exact = tg::mmp_distances(soup, tg::Sources::vertex(10));
    tg::FastMarchingOptions off;
    off.unfold_obtuse = false;
    const tg::FastMarchingField with = tg::fast_marching(soup, tg::Sources::vertex(10));
    const tg::FastMarchingField without = tg::fast_marching(soup, tg::Sources::vertex(10), off);
    const tg::ErrorStats a = tg::compare(with.d, exact.d), b = tg::compare(without.d, exact.d);
    EXPECT_GT(with.report.obtuse_corners, 1000u);
    EXPECT_EQ(with.report.virtual_edges + with.report.unsplit_obtuse, with.report.obtuse_corners);
    EXPECT_EQ(without.report.virtual_edges, 0u);
    EXPECT_LT(a.mean_rel, 0.75 * b.mean_rel);
}

// The heat test's sheared grid (every corner of 153 degrees split by a virtual edge, point source
// at the centre, Euclidean truth): measured mean relative error over the vertices beyond a tenth
// of the largest distance 1.9e-2 with the virtual edges
// (the plane waves through them and the edges themselves as paths), 0.53 without, as bad as
// Dijkstra's; the heat method with the intrinsic Delaunay Laplacian measured 2.3e-2 here.
TEST(FastMarching, ShearedGridNeedsTheVirtualEdges) {
    const tg::Soup soup = tg::sheared_grid(24);
    const std::size_t source = 312;  // the centre vertex (12, 12)
    std::vector<double> truth(soup.points.size());
    for (std::size_t v = 0; v < truth.size(); ++v)
        truth[v] = tg::euclidean(soup.points[v], soup.points[source]);
    tg::FastMarchingOptions off;
    off.unfold_obtuse = false;
    const auto with = tg::compare(tg::fast_marching(soup, tg::Sources::vertex(source)).d, truth);
    const auto without =
        tg::compare(tg::fast_marching(soup, tg::Sources::vertex(source), off).d, truth);
    EXPECT_LT(with.mean_rel, 0.03);
    EXPECT_GT(without.mean_rel, 0.3);
}

// A solver prepared once answers every query as the one-shot function does; a face location on a
// corner is that vertex; a face location seeds its corners with their straight-line distance.
TEST(FastMarching, SolverQueriesAndFaceLocations) {
    const tg::Soup soup = tg::surface("icosphere:3");
    const std::size_t f = 40;
    const std::vector<tg::Sources> queries = {
        tg::Sources::vertex(5), tg::Sources{{tg::SurfacePoint::face(f, {0.2, 0.3, 0.5})}},
        tg::Sources{{tg::SurfacePoint::face(f, {0, 1, 0})}}, tg::Sources::vertex(soup.faces[f][1])};
    const auto fields = tg::fast_marching_queries(soup, queries);
    ASSERT_EQ(fields.size(), queries.size());
    for (std::size_t q = 0; q < queries.size(); ++q)
        EXPECT_EQ(fields[q].d, tg::fast_marching(soup, queries[q]).d) << q;
    const tg::Vec3 x = tg::position(soup, tg::SurfacePoint::face(f, {0.2, 0.3, 0.5}));
    for (auto v : soup.faces[f])
        EXPECT_NEAR(fields[1].d[v], tg::euclidean(x, soup.points[v]), 1e-15);
    EXPECT_EQ(fields[2].d, fields[3].d);
    EXPECT_EQ(fields[0].report.method, "fast_marching");
    EXPECT_GT(fields[0].report.face_updates, soup.points.size() / 2);
    EXPECT_EQ(fields[0].report.face_updates + fields[0].report.edge_updates + 1,
              soup.points.size());
}
