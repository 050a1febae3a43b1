// Geodesics on point sets by geodesic curvature flow (point_cloud.h, the thesis' Algorithm 3)
// against analytic truth (DESIGN.md §6): great circles on the unit sphere, in R^3 and embedded
// isometrically in R^5; GeographicLib on an ellipsoid of revolution; the unrolled plane of a
// Swiss roll; and the exact polyhedral distance (our MMP) on the mesh whose vertices are the
// points. Timings are printed, not asserted.
//
// Errors are relative, over the points farther than three cells from the source: nearer, the
// distance is a few cells and its relative error says more about the interpolation inside the
// source's cells than about the propagation (the mesh tests leave out the source's 1-ring for the
// same reason). Bounds are the target (mean <= 1 % on clean samples) where it is the
// point, else the measured value (printed) with a stated margin; the propagation is
// deterministic (batches are committed in queue order), so margins only absorb library
// differences.
#include <tapeline/core/errors.h>
#include <tapeline_test/geodesic.h>
#include <tapeline_test/mmp.h>
#include <tapeline_test/point_cloud.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace tg = tapeline_test::geodesic;

namespace {

struct Errors {
    double mean = 0, max = 0;
    std::size_t count = 0, unreached = 0;
};

Errors relative_errors(const std::vector<double>& d, const std::vector<double>& truth,
                       double exclude_below) {
    Errors e;
    double sum = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        if (!(truth[i] > exclude_below))
            continue;
        if (!std::isfinite(d[i])) {
            ++e.unreached;
            continue;
        }
        const double r = std::abs(d[i] - truth[i]) / truth[i];
        sum += r;
        e.max = std::max(e.max, r);
        ++e.count;
    }
    e.mean = e.count ? sum / static_cast<double>(e.count) : 0.0;
    return e;
}

/// Great-circle distances from point `src` of a cloud on the unit sphere (3 coordinates used).
std::vector<double> great_circle(const tg::Cloud& c3, std::size_t src) {
    std::vector<double> out(c3.size());
    const double* s = c3.at(src);
    for (std::size_t i = 0; i < c3.size(); ++i) {
        const double* p = c3.at(i);
        const double cx = s[1] * p[2] - s[2] * p[1], cy = s[2] * p[0] - s[0] * p[2],
                     cz = s[0] * p[1] - s[1] * p[0];
        out[i] = std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz),
                            s[0] * p[0] + s[1] * p[1] + s[2] * p[2]);
    }
    return out;
}

void print(const std::string& what, const tg::CloudField& f, const Errors& e) {
    const auto& r = f.report;
    std::printf(
        "[ gcf-pts  ] %-44s n %6zu D %zu k %zu%s cell %.4f nodes %5zu | mean %.2e max %.2e "
        "(%zu pts) | prep %.0f ms (knn %s %.0f) prop %.0f ms interp %.0f ms | %zu flows %zu it "
        "%zu charts %s\n",
        what.c_str(), r.points, r.dimension, r.manifold_dimension,
        r.manifold_dimension_estimated ? "(est)" : "", r.cell_size, r.nodes, e.mean, e.max, e.count,
        1e3 * r.prepare_seconds, r.knn.c_str(), 1e3 * r.knn_seconds, 1e3 * r.propagate_seconds,
        1e3 * r.interpolate_seconds, r.flows, r.iterations, r.charts, r.status.c_str());
}

void expect_basic(const tg::CloudField& f, std::size_t src, const std::string& what) {
    EXPECT_EQ(f.d[src], 0.0) << what;
    EXPECT_EQ(f.report.unreachable, 0u) << what;
    EXPECT_EQ(f.report.solver_failures, 0u) << what;
    for (double x : f.d)
        ASSERT_TRUE(std::isfinite(x) && x >= 0) << what;
}

}  // namespace

// Noisy clouds are compared with the truth at the clean points (the figure) and, to
// separate the method from the noise itself, with the great circle between the noisy points
// projected radially onto the sphere: a point moved tangentially by the noise really is at
// another distance, a floor of about 0.74 sigma / distance on the mean that no method can beat
// (E|tangential component| = 0.8 sigma, mean of 1 / distance over the sphere 0.93).
TEST(PointCloud, SphereAgainstGreatCircleCleanAndNoisy) {
    const tg::Cloud clean = tg::random_sphere(10000, 1);
    const std::size_t src = 0;
    const auto truth = great_circle(clean, src);
    for (const auto projection : {tg::PointCloudProjection::mls, tg::PointCloudProjection::plane}) {
        for (const double noise : {0.0, 0.001, 0.005}) {
            const tg::Cloud c = noise > 0 ? tg::with_noise(clean, noise, 7) : clean;
            tg::Cloud radial = c;
            for (std::size_t i = 0; i < radial.size(); ++i) {
                double* p = radial.xyz.data() + 3 * i;
                const double len = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
                for (int j = 0; j < 3; ++j)
                    p[j] /= len;
            }
            const auto truth_noisy = great_circle(radial, src);
            tg::PointCloudDistanceOptions o;
            o.projection = projection;
            if (noise >= 0.005)
                o.neighbours = 32;  // smoother local surfaces under heavy noise
            const tg::CloudField f = tg::cloud_distances(c, src, o);
            const Errors e = relative_errors(f.d, truth, 3 * f.report.cell_size);
            const Errors en = relative_errors(f.d, truth_noisy, 3 * f.report.cell_size);
            char what[96];
            std::snprintf(what, sizeof what, "sphere, %s, noise %.1f %%%s",
                          projection == tg::PointCloudProjection::mls ? "mls" : "plane",
                          100 * noise, noise >= 0.005 ? ", d 32" : "");
            print(what, f, e);
            if (noise > 0)
                std::printf(
                    "[ gcf-pts  ]   vs the noisy points' own great circles: mean %.2e "
                    "max %.2e\n",
                    en.mean, en.max);
            expect_basic(f, src, what);
            EXPECT_EQ(f.report.manifold_dimension, 2u) << what;
            // Bounds: about 3x the measured mean error (the propagation is deterministic; the
            // margin absorbs library differences), far inside the 1 % target.
            const bool mls = projection == tg::PointCloudProjection::mls;
            if (noise == 0) {
                EXPECT_LE(e.mean, mls ? 6e-4 : 4.5e-3) << what;  // measured 1.9e-4, 1.5e-3
            } else {
                // Against the clean truth the noise floor (0.26 %, 1.3 %) dominates: measured
                // 3.5e-3 and 1.6e-2, bounded at 1.5x (3x the margin above the floor). Against
                // the noisy points' own great circles, what is left is the method's: measured
                // 1.1e-3 / 1.2e-3 (0.1 %, mls / plane) and 3.8e-3 / 2.1e-3 (0.5 %), about 3x.
                EXPECT_LE(e.mean, noise < 0.002 ? 5e-3 : 2.4e-2) << what;
                EXPECT_LE(en.mean, noise < 0.002 ? 3.5e-3 : 1.2e-2) << what;
            }
        }
    }
}

TEST(PointCloud, EllipsoidOfRevolutionAgainstGeographicLib) {
    const std::string spec = "ellipsoid:1,1,0.5:5:0.3";
    const tg::Soup soup = tg::surface(spec);
    const tg::Cloud c = tg::cloud_of(soup.points);
    const std::size_t src = 0;
    const auto truth = tg::analytic_distances(spec, soup, src);
    ASSERT_FALSE(truth.empty());
    const tg::CloudField f = tg::cloud_distances(c, src);
    const Errors e = relative_errors(f.d, truth, 3 * f.report.cell_size);
    print("ellipsoid 1,1,0.5 (jittered icosphere:5 vertices)", f, e);
    expect_basic(f, src, spec);
    EXPECT_LE(e.mean, 1e-2);
}

TEST(PointCloud, SphereInR5AgainstGreatCircle) {
    const tg::Cloud c3 = tg::random_sphere(6000, 3);
    const tg::Cloud c5 = tg::embed(c3, 5, 11);
    const std::size_t src = 5;
    const auto truth = great_circle(c3, src);
    for (const auto input : {tg::CloudInput::point_d, tg::CloudInput::array_pairs}) {
        const tg::CloudField f = tg::cloud_distances(c5, src, {}, input);
        const Errors e = relative_errors(f.d, truth, 3 * f.report.cell_size);
        const std::string what = input == tg::CloudInput::point_d
                                     ? "S^2 in R^5 (Epick_d Point_d)"
                                     : "S^2 in R^5 (vector<double>, First_of_pair)";
        print(what, f, e);
        expect_basic(f, src, what);
        EXPECT_EQ(f.report.dimension, 5u);
        EXPECT_EQ(f.report.manifold_dimension, 2u);
        EXPECT_TRUE(f.report.manifold_dimension_estimated);
        EXPECT_LE(e.mean, 1e-2) << what;
    }
    // The same points in R^3 give the same field up to rounding (the method is invariant under
    // isometries of the ambient space, grids aside: cells differ, so only statistics agree).
    const tg::CloudField f3 = tg::cloud_distances(c3, src);
    const Errors e3 = relative_errors(f3.d, truth, 3 * f3.report.cell_size);
    print("the same sphere in R^3", f3, e3);
    expect_basic(f3, src, "R^3");
    const tg::CloudField f5 = tg::cloud_distances(c5, src);
    const Errors e35 = relative_errors(f5.d, f3.d, 3 * f3.report.cell_size);
    std::printf("[ gcf-pts  ] R^5 against R^3, point by point: mean %.2e max %.2e\n", e35.mean,
                e35.max);
    // Both are within the method's error of the same truth (R^3 measured 2.4e-4 mean, as R^5),
    // and of each other point by point (measured 1.2e-4 mean): the embedding changes the grid,
    // not the surface. About 3x each.
    EXPECT_LE(e3.mean, 7e-4);
    EXPECT_LE(e35.mean, 4e-4);
}

TEST(PointCloud, SwissRollAgainstUnrolledPlane) {
    std::vector<double> plane;
    const tg::Cloud c = tg::swiss_roll(20000, 21.0, 5, plane);
    const std::size_t src = 17;
    std::vector<double> truth(c.size());
    for (std::size_t i = 0; i < c.size(); ++i)
        truth[i] = std::hypot(plane[2 * i] - plane[2 * src], plane[2 * i + 1] - plane[2 * src + 1]);
    const tg::CloudField f = tg::cloud_distances(c, src);
    const Errors e = relative_errors(f.d, truth, 3 * f.report.cell_size);
    print("Swiss roll (t in [1.5 pi, 4.5 pi], h in [0, 21])", f, e);
    expect_basic(f, src, "Swiss roll");
    EXPECT_EQ(f.report.manifold_dimension, 2u);
    EXPECT_LE(e.mean, 1e-2);
    // The layers are 2 pi apart: a cell graph that jumped between them would give distances far
    // below the unrolled truth somewhere.
    EXPECT_LE(e.max, 0.1);
}

TEST(PointCloud, MeshVerticesAgainstExactPolyhedral) {
    const tg::Soup soup = tg::spot();
    const tg::Cloud c = tg::cloud_of(soup.points);
    const std::size_t src = 0;
    const tg::MmpField exact = tg::mmp_distances(soup, tg::Sources::vertex(src));
    tg::PointCloudDistanceOptions o;
    o.neighbours = 12;
    const tg::CloudField f = tg::cloud_distances(c, src, o);
    const Errors e = relative_errors(f.d, exact.d, 3 * f.report.cell_size);
    print("spot vertices vs exact polyhedral (MMP)", f, e);
    expect_basic(f, src, "spot");
    // The points sample a smooth surface the polyhedron only approximates (2930 vertices, sharp
    // ears and horns): measured mean 4.0e-3; 3x that.
    EXPECT_LE(e.mean, 1.2e-2);
}

TEST(PointCloud, PathsAgainstGreatCircle) {
    const tg::Cloud c = tg::random_sphere(8000, 2);
    const auto truth = great_circle(c, 0);
    for (std::size_t to : {10u, 200u, 3000u}) {
        const tg::CloudPath ab = tg::cloud_path(c, 0, to);
        const tg::CloudPath ba = tg::cloud_path(c, to, 0);
        const double rel = std::abs(ab.length - truth[to]) / truth[to];
        std::printf(
            "[ gcf-pts  ] path 0-%zu: great circle %.6f, flowed %.6f (rel %.1e), back %.6f, "
            "%zu samples, %zu it, %s\n",
            to, truth[to], ab.length, rel, ba.length, ab.xyz.size() / 3, ab.report.iterations,
            ab.status.c_str());
        ASSERT_GE(ab.xyz.size(), 6u);
        for (int j = 0; j < 3; ++j)  // the endpoints: the points projected onto their surfaces
            EXPECT_NEAR(ab.xyz[j], c.at(0)[j], 1e-4);
        EXPECT_LE(rel, 5e-3);
        EXPECT_NEAR(ab.length, ba.length, 5e-3 * truth[to]);  // symmetry
        for (std::size_t i = 0; i < ab.xyz.size(); i += 3) {  // on the sphere
            const double r = std::sqrt(ab.xyz[i] * ab.xyz[i] + ab.xyz[i + 1] * ab.xyz[i + 1] +
                                       ab.xyz[i + 2] * ab.xyz[i + 2]);
            EXPECT_NEAR(r, 1.0, 2e-3);
        }
    }
}

// Both neighbour searches build the same kNN graph: the distances agree up to ties between
// equidistant points (1e-9; measured 0). Which one is faster is the benchmark's to say.
TEST(PointCloud, KnnBackendsAgree) {
    const std::size_t n = 10000;
    const tg::Cloud c = tg::random_sphere(n, 4);
    tg::CloudField f[2];
    int b = 0;
    for (const auto backend : {tg::PointCloudKnn::cgal, tg::PointCloudKnn::nanoflann}) {
        tg::PointCloudDistanceOptions o;
        o.knn = backend;
        f[b++] = tg::cloud_distances(c, 0, o);
    }
    double diff = 0;
    for (std::size_t i = 0; i < n; ++i)
        diff = std::max(diff, std::abs(f[0].d[i] - f[1].d[i]));
    EXPECT_EQ(f[0].report.knn, "cgal");
    EXPECT_EQ(f[1].report.knn, "nanoflann");
    expect_basic(f[0], 0, "cgal kNN");
    EXPECT_LE(diff, 1e-9);
}

TEST(PointCloud, NormalMapAndSolverReuse) {
    const tg::Cloud c = tg::random_sphere(6000, 6);
    const auto truth = great_circle(c, 0);
    const tg::CloudField f = tg::cloud_distances_with_normals(c, c.xyz, 0);
    const Errors e = relative_errors(f.d, truth, 3 * f.report.cell_size);
    print("sphere with exact normals (normal_map)", f, e);
    expect_basic(f, 0, "normal_map");
    EXPECT_LE(e.mean, 1e-2);

    double prep = 0;
    const std::vector<std::size_t> sources{0, 100, 2000};
    const auto fields = tg::cloud_distances_many(c, sources, {}, &prep);
    std::printf("[ gcf-pts  ] solver reused: prepare %.1f ms, queries", 1e3 * prep);
    for (const auto& q : fields)
        std::printf(" %.1f ms", 1e3 * q.report.seconds);
    std::printf("\n");
    // Symmetry d(a, b) = d(b, a) up to the method's error.
    for (std::size_t a = 0; a < sources.size(); ++a)
        for (std::size_t b = a + 1; b < sources.size(); ++b) {
            const double ab = fields[a].d[sources[b]], ba = fields[b].d[sources[a]];
            EXPECT_NEAR(ab, ba, 5e-3 * ab) << sources[a] << "-" << sources[b];
        }
    EXPECT_EQ(fields[0].d, tg::cloud_distances(c, 0).d);  // same as the one-shot call
}

TEST(PointCloud, DisconnectedCloudLeavesInfinity) {
    tg::Cloud a = tg::random_sphere(3000, 8);
    const tg::Cloud b = tg::random_sphere(2000, 9);
    for (std::size_t i = 0; i < b.size(); ++i)
        a.xyz.insert(a.xyz.end(), {b.at(i)[0] + 5, b.at(i)[1], b.at(i)[2]});
    const tg::CloudField f = tg::cloud_distances(a, 0);
    EXPECT_EQ(f.report.reached, 3000u);
    EXPECT_EQ(f.report.unreachable, 2000u);
    for (std::size_t i = 0; i < a.size(); ++i)
        EXPECT_EQ(std::isfinite(f.d[i]), i < 3000) << i;
    const tg::CloudPath p = tg::cloud_path(a, 0, 4000);
    EXPECT_EQ(p.status, "unreachable");
    EXPECT_TRUE(p.xyz.empty());
    EXPECT_FALSE(std::isfinite(p.length));
}

namespace {

template <class F>
void expect_invalid(F&& f, const std::string& needle) {
    try {
        f();
        ADD_FAILURE() << "no InvalidInput; expected a message with: " << needle;
    } catch (const tapeline::InvalidInput& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find(needle), std::string::npos) << m;
        EXPECT_EQ(m.find('\n'), std::string::npos) << "one line: " << m;
        EXPECT_EQ(m.rfind("gcf_point_cloud: ", 0), 0u) << m;
    }
}

}  // namespace

TEST(PointCloud, RejectsBadInputWithItsMessage) {
    const tg::Cloud c = tg::random_sphere(500, 10);
    tg::Cloud few = c;
    few.xyz.resize(3 * 10);
    expect_invalid([&] { tg::cloud_distances(few, 0); },
                   "10 points, fewer than neighbours + 1 = 17");
    tg::Cloud dup = c;
    dup.xyz.insert(dup.xyz.end(), c.at(42), c.at(42) + 3);
    expect_invalid([&] { tg::cloud_distances(dup, 0); },
                   "points #42 and #500 coincide (duplicate points)");
    tg::Cloud nan = c;
    nan.xyz[3 * 77 + 1] = std::numeric_limits<double>::quiet_NaN();
    expect_invalid([&] { tg::cloud_distances(nan, 0); }, "point #77 has a non-finite coordinate");
    expect_invalid([&] { tg::cloud_distances(c, 500); },
                   "source point #500 out of range (500 points)");
    expect_invalid([&] { tg::cloud_path(c, 3, 3); }, "path from a point to itself");
    tg::PointCloudDistanceOptions o;
    o.cell_size = -1;
    expect_invalid([&] { tg::cloud_distances(c, 0, o); }, "cell_size must be finite and >= 0");
    o = {};
    o.neighbours = 2;
    expect_invalid([&] { tg::cloud_distances(c, 0, o); }, "neighbours must be at least 3");
    o = {};
    o.neighbours = 7;
    expect_invalid([&] { tg::cloud_distances(c, 0, o); },
                   "the mls projection of a 2-manifold needs at least 8 neighbours (given 7)");
    o = {};
    o.manifold_dimension = 3;
    expect_invalid([&] { tg::cloud_distances(c, 0, o); },
                   "manifold_dimension 3 must be below the ambient dimension 3");
    o = {};
    o.flow.solver = tapeline::geodesic::CurvatureFlowSolver::ceres;
    expect_invalid([&] { tg::cloud_distances(c, 0, o); }, "the ceres flow solver is for meshes");
    o = {};
    o.cell_size = 1e-300;
    expect_invalid([&] { tg::cloud_distances(c, 0, o); }, "is too small for the extent");
}

// The error at several sizes (the default cell shrinks with the spacing) and against the cell
// size and the window at a fixed cloud; time against the number of points is the benchmark's
// (benchmarks/run_points.sh, part 3).
TEST(PointCloud, ScalingAndParameters) {
    for (const std::size_t n : {2500u, 10000u}) {
        const tg::Cloud c = tg::random_sphere(n, 12);
        const auto truth = great_circle(c, 0);
        const tg::CloudField f = tg::cloud_distances(c, 0);
        const Errors e = relative_errors(f.d, truth, 3 * f.report.cell_size);
        print("sphere, " + std::to_string(n) + " points", f, e);
        expect_basic(f, 0, std::to_string(n) + " points");
        EXPECT_LE(e.mean, 1e-2);
    }
    const tg::Cloud c = tg::random_sphere(10000, 13);
    const auto truth = great_circle(c, 0);
    for (const double cell : {0.05, 0.08, 0.12, 0.2}) {
        for (const std::size_t window : {4u, 8u, 16u}) {
            tg::PointCloudDistanceOptions o;
            o.cell_size = cell;
            o.window = window;
            const tg::CloudField f = tg::cloud_distances(c, 0, o);
            const Errors e = relative_errors(f.d, truth, 0.3);
            char what[64];
            std::snprintf(what, sizeof what, "sphere, cell %.2f, window %zu", cell, window);
            print(what, f, e);
            EXPECT_LE(e.mean, 2e-2) << what;
        }
    }
}
