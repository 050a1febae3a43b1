// Single-source distances by geodesic curvature flow (gcf_distances, the thesis' Algorithms 1 and
// 2) against the exact polyhedral distance (our MMP), great circles on icospheres (analytic
// truth) and Euclidean truth on a flat grid (DESIGN.md §6). Timings are printed, not asserted.
//
// Errors are relative, over the vertices outside the source's closed 1-ring (those are straight
// edges by construction). The bounds are the measured values (printed) with a stated margin;
// gcf_distances is deterministic, so the margin only absorbs compiler / library differences:
// - flat grid, window 0: the flow is linear there and converges to the straight segment; 1e-9
//   (measured 4.5e-14). The window version keeps a kinked fixed prefix (see below): printed and
//   bounded, not Euclidean.
// - Algorithm 1 (window 0), Phong-lifted length: it approaches the smooth sphere, not the
//   polyhedron, so against exact polyhedral it differs by the polyhedron's own error (measured
//   mean 3.1e-3 at level 3, 8.0e-4 at level 4); against the great circle its mean error is
//   0.44 / 0.43 of the exact polyhedral distance's (the "at most half" holds at level 4;
//   level 5 is not run here, too slow for a unit test).
// - Algorithm 1 with the on-face length (polyhedral_length: traced and straightened): mean
//   7.4e-6 / 1.1e-6 against exact polyhedral (5.9e-4 / 1.7e-4 with the chords before).
// - Algorithm 2 (window 8), the thesis' straightest-parent rule and prefix anchor: every vertex
//   keeps the prefix of its parent up to the fixed sample, so each generation adds a kink and the
//   kinks add up along the path. Measured mean 1.5e-2 / 2.1e-2, max 9.0e-2 / 1.06e-1: the issue's
//   targets (mean <= 0.1 %, max <= 1 %) are NOT met by the rule as written; its accuracy is a
//   benchmark row (gcf-window-thesis), only its invariants are asserted here. With shortest_parent:
//   mean 4.9e-3 / 2.5e-3, max 1.5e-2 / 7.6e-3.
// - Algorithm 2 with the field anchor (the default; interpolated anchor distance, anchor slid to
//   straighten the kink, cut-locus guard): on-face length against exact polyhedral, like for
//   like, mean 5.6e-4 / 1.6e-4, max 9.7e-4 / 8.4e-4: the targets are met; Phong-lifted against
//   the great circle 0.43 / 0.40 of the exact polyhedral distance's error. With the polyhedral
//   length (issue 4, shared meshes): mean 1.0e-4 / 3.7e-5, max 1.5e-3 / 1.1e-3.
#include <tapeline/core/errors.h>
#include <tapeline_test/gcf.h>
#include <tapeline_test/mmp.h>

#include <gtest/gtest.h>
#include <tbb/global_control.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace tg = tapeline_test::geodesic;

namespace {

struct Errors {
    double mean = 0, max = 0;
    std::size_t count = 0;
};

/// Relative errors of d against ref over the vertices outside the source's closed 1-ring.
Errors relative_errors(const tg::Soup& soup, std::size_t src, const std::vector<double>& d,
                       const std::vector<double>& ref) {
    std::vector<char> ring(soup.points.size(), 0);
    ring[src] = 1;
    for (const auto& f : soup.faces)
        if (std::find(f.begin(), f.end(), src) != f.end())
            for (auto v : f)
                ring[v] = 1;
    Errors e;
    double sum = 0;
    for (std::size_t v = 0; v < d.size(); ++v) {
        if (ring[v])
            continue;
        const double r = std::abs(d[v] - ref[v]) / ref[v];
        sum += r;
        e.max = std::max(e.max, r);
        ++e.count;
    }
    e.mean = e.count ? sum / static_cast<double>(e.count) : 0.0;
    return e;
}

void expect_basic(const tg::Soup& soup, std::size_t src, const tg::GcfField& f,
                  const std::string& what) {
    ASSERT_EQ(f.d.size(), soup.points.size());
    EXPECT_EQ(f.report.reached, soup.points.size()) << what;
    EXPECT_EQ(f.report.unreachable, 0u) << what;
    EXPECT_EQ(f.report.status, "ok") << what;
    EXPECT_EQ(f.d[src], 0.0) << what;
    for (std::size_t v = 0; v < f.d.size(); ++v) {
        ASSERT_TRUE(std::isfinite(f.d[v])) << what << " vertex " << v;
        EXPECT_GE(f.d[v], 0.999 * tg::euclidean(soup.points[src], soup.points[v]))
            << what << " vertex " << v;
    }
}

struct Config {
    std::size_t window;
    bool shortest_parent;
    bool smooth_length;
    const char* name;
    tg::WindowAnchor anchor = tg::WindowAnchor::prefix;  // the thesis' rule
};

}  // namespace

TEST(CurvatureFlowDistances, FlatGridIsEuclidean) {
    const tg::Soup soup = tg::flat_grid(12, 1.0);
    const std::size_t src = 0;
    for (const Config c :
         {Config{0, false, true, "window 0"}, Config{8, false, true, "window 8"},
          Config{8, true, true, "window 8, shortest parent"},
          Config{8, false, true, "window 8, field anchor", tg::WindowAnchor::field}}) {
        tg::CurvatureFlowDistanceOptions o;
        o.window = c.window;
        o.shortest_parent = c.shortest_parent;
        o.anchor = c.anchor;
        o.cut_locus_guard = c.window == 0 || c.anchor == tg::WindowAnchor::field;
        const tg::GcfField f = tg::gcf_distances(soup, src, o);
        const std::string what = std::string("flat grid, ") + c.name;
        expect_basic(soup, src, f, what);
        double max_err = 0;
        for (std::size_t v = 0; v < f.d.size(); ++v)
            max_err = std::max(max_err,
                               std::abs(f.d[v] - tg::euclidean(soup.points[src], soup.points[v])));
        std::printf(
            "[ gcf-dist ] %s: max |d - euclidean| %.2e (grid size 1), %zu flows, %zu it, "
            "%s, %.1f ms\n",
            what.c_str(), max_err, f.report.flows, f.report.iterations, f.report.status.c_str(),
            1e3 * f.report.seconds);
        if (c.window == 0)
            EXPECT_LE(max_err, 1e-9) << what;
        else if (c.anchor == tg::WindowAnchor::field)  // measured 2.3e-5
            EXPECT_LE(max_err, 1e-4) << what;
        else  // measured 6.6e-3 (straightest) and 3.7e-3 (shortest parent)
            EXPECT_LE(max_err, 1e-2) << what;
    }
}

TEST(CurvatureFlowDistances, IcosphereAgainstExactPolyhedralAndGreatCircle) {
    for (int level : {3, 4}) {
        const std::string spec = "icosphere:" + std::to_string(level);
        const tg::Soup soup = tg::surface(spec);
        const std::size_t src = 0;
        const auto truth = tg::analytic_distances(spec, soup, src);
        ASSERT_FALSE(truth.empty());
        const tg::MmpField mmp = tg::mmp_distances(soup, tg::Sources::vertex(src));
        const Errors exact_vs_truth = relative_errors(soup, src, mmp.d, truth);
        std::printf("[ gcf-dist ] %s: exact polyhedral vs great circle: mean %.2e max %.2e\n",
                    spec.c_str(), exact_vs_truth.mean, exact_vs_truth.max);
        for (const Config c :
             {Config{0, false, true, "window 0 (Algorithm 1)"},
              Config{0, false, false, "window 0, on-face length"},
              Config{8, false, true, "window 8 (Algorithm 2)"},
              Config{8, true, true, "window 8, shortest parent"},
              Config{8, false, true, "window 8, field anchor", tg::WindowAnchor::field},
              Config{8, false, false, "window 8, field anchor, on-face length",
                     tg::WindowAnchor::field}}) {
            tg::CurvatureFlowDistanceOptions o;
            o.window = c.window;
            o.shortest_parent = c.shortest_parent;
            o.smooth_length = c.smooth_length;
            o.anchor = c.anchor;
            // The thesis' rule as written for the prefix anchor; the guard for the others.
            o.cut_locus_guard = c.window == 0 || c.anchor == tg::WindowAnchor::field;
            const tg::GcfField f = tg::gcf_distances(soup, src, o);
            const std::string what = spec + ", " + c.name;
            expect_basic(soup, src, f, what);
            const Errors vs_exact = relative_errors(soup, src, f.d, mmp.d);
            const Errors vs_truth = relative_errors(soup, src, f.d, truth);
            const double ratio = vs_truth.mean / exact_vs_truth.mean;
            std::printf(
                "[ gcf-dist ] %s: vs exact polyhedral mean %.2e max %.2e | vs great circle mean "
                "%.2e max %.2e (%.2f x exact polyhedral's mean error) | %zu flows, %zu it, %s, "
                "%zu stored samples, %.1f ms, %.1f us/vertex\n",
                what.c_str(), vs_exact.mean, vs_exact.max, vs_truth.mean, vs_truth.max, ratio,
                f.report.flows, f.report.iterations, f.report.status.c_str(),
                f.report.stored_samples, 1e3 * f.report.seconds,
                1e6 * f.report.seconds / static_cast<double>(f.report.vertices));
            EXPECT_EQ(f.report.converged, f.report.flows) << what;
            if (c.window == 0 && c.smooth_length) {
                // Measured 3.1e-3 / 3.8e-3 (level 3), 8.0e-4 / 9.5e-4 (level 4): 1.3x margin.
                EXPECT_LE(vs_exact.mean, level == 3 ? 4e-3 : 1.05e-3) << what;
                EXPECT_LE(vs_exact.max, level == 3 ? 5e-3 : 1.25e-3) << what;
                // Beats the exact polyhedral distance against the great circle (measured 0.44,
                // 0.43); the "at most half" asserted at level 4.
                EXPECT_LE(ratio, level == 3 ? 0.6 : 0.5) << what;
            } else if (c.window == 0) {
                // Measured 7.4e-6 / 2.9e-4 (level 3), 1.1e-6 / 5.2e-5 (level 4; chords before:
                // 5.9e-4 / 9.9e-4, 1.7e-4 / 2.9e-4).
                EXPECT_LE(vs_exact.mean, level == 3 ? 8e-4 : 2.5e-4) << what;
                EXPECT_LE(vs_exact.max, level == 3 ? 1.3e-3 : 4e-4) << what;
            } else if (c.anchor == tg::WindowAnchor::field && !c.smooth_length) {
                // The targets against exact polyhedral, like for like (on-face lengths):
                // mean <= 0.1 %, max <= 1 %. Measured 1.0e-4 / 1.5e-3 (level 3), 3.7e-5 / 1.1e-3
                // (level 4; chords before: 5.6e-4 / 9.7e-4, 1.5e-4 / 9.3e-4).
                EXPECT_LE(vs_exact.mean, level == 3 ? 1e-3 : 3e-4) << what;
                EXPECT_LE(vs_exact.max, level == 3 ? 2e-3 : 1.5e-3) << what;
            } else if (c.anchor == tg::WindowAnchor::field) {
                // Phong-lifted: against the great circle. Measured: see the printout.
                EXPECT_LE(vs_truth.mean, level == 3 ? 2e-3 : 7e-4) << what;
                EXPECT_LE(vs_truth.max, 1e-2) << what;
            } else if (!c.shortest_parent) {
                // The thesis' prefix rule misses the targets (see the header); its accuracy is a
                // benchmark row (gcf-window-thesis:8 in benchmarks/run_gcf.sh), not a unit-test
                // snapshot: here only expect_basic's properties (every vertex reached, finite,
                // never below the straight line) and convergence of every flow hold it.
            } else {
                // Measured 4.9e-3 / 1.5e-2 (level 3), 2.5e-3 / 7.6e-3 (level 4).
                EXPECT_LE(vs_exact.mean, level == 3 ? 6e-3 : 3.5e-3) << what;
                EXPECT_LE(vs_exact.max, level == 3 ? 2e-2 : 1e-2) << what;
            }
        }
    }
}

TEST(CurvatureFlowDistances, BadOptionsAreRejected) {
    const tg::Soup soup = tg::surface("icosphere:1");
    tg::CurvatureFlowDistanceOptions o;
    o.sample_spacing = -1;
    EXPECT_THROW(tg::gcf_distances(soup, 0, o), tapeline::InvalidInput);
    o = {};
    o.flow.step = 0;
    EXPECT_THROW(tg::gcf_distances(soup, 0, o), tapeline::InvalidInput);
    o = {};
    o.smooth_length = false;
    o.repair_steiner_points = -2;
    EXPECT_THROW(tg::gcf_distances(soup, 0, o), tapeline::InvalidInput);
    for (const double margin : {-0.1, 1.5, std::nan("")}) {
        o = {};
        o.smooth_length = false;
        o.repair_graph_margin = margin;
        try {
            tg::gcf_distances(soup, 0, o);
            ADD_FAILURE() << "margin " << margin << " accepted";
        } catch (const tapeline::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find("repair_graph_margin"), std::string::npos);
        }
    }
}

TEST(CurvatureFlowDistances, PolyhedronGivesTheSameField) {
    const tg::Soup soup = tg::surface("icosphere:2");
    for (std::size_t window : {std::size_t(0), std::size_t(8)}) {
        tg::CurvatureFlowDistanceOptions o;
        o.window = window;
        const tg::GcfField a = tg::gcf_distances(soup, 3, o);
        const tg::GcfField b = tg::gcf_distances(soup, 3, o, tg::MeshKind::polyhedron);
        ASSERT_EQ(a.d.size(), b.d.size());
        // On the symmetric icosphere the cut-locus guard compares parents whose flowed lengths
        // tie to ~1e-11 (flow tolerance 1e-7), and the two mesh types list neighbours in another
        // order, so the kept parent may differ: 1e-10 relative (measured up to 7.5e-12 apart).
        for (std::size_t v = 0; v < a.d.size(); ++v)
            EXPECT_NEAR(a.d[v], b.d[v], 1e-10 * (1 + a.d[v])) << "window " << window << " " << v;
    }
}

TEST(CurvatureFlowDistances, OtherComponentIsUnreachable) {
    tg::Soup soup = tg::surface("icosphere:1");
    const std::size_t n = soup.points.size(), nf = soup.faces.size();
    for (std::size_t i = 0; i < n; ++i)
        soup.points.push_back({soup.points[i][0] + 5, soup.points[i][1], soup.points[i][2]});
    for (std::size_t f = 0; f < nf; ++f) {
        auto face = soup.faces[f];
        for (auto& v : face)
            v += n;
        soup.faces.push_back(face);
    }
    const tg::GcfField f = tg::gcf_distances(soup, 0, {});
    EXPECT_EQ(f.report.reached, n);
    EXPECT_EQ(f.report.unreachable, n);
    for (std::size_t v = 0; v < 2 * n; ++v) {
        if (v < n)
            EXPECT_TRUE(std::isfinite(f.d[v])) << v;
        else
            EXPECT_EQ(f.d[v], std::numeric_limits<double>::infinity()) << v;
    }
}

// The thesis bounds the window's error by O(epsilon m); epsilon and m are defined in
// CurvatureFlowDistanceReport (largest anchor kink excess per mean edge; most faces on one path)
// and error_bound = epsilon * m * mean edge. Tested against the whole-path flow (Algorithm 1) with
// the same settings, so only the window's error counts. Measured: with the thesis' prefix rule
// the bound does NOT hold with constant 1 (max |d2 - d1| / bound = 7.3 at level 3, 9.3 at level
// 4, growing: many small kinks turning the same way make the path drift, a first-order effect
// that a second-order local excess does not see); with field anchors it holds (0.31, 0.74).
TEST(CurvatureFlowDistances, EpsilonMBoundAgainstTheWholePathFlow) {
    for (int level : {3, 4}) {
        const tg::Soup soup = tg::surface("icosphere:" + std::to_string(level));
        tg::CurvatureFlowDistanceOptions whole;
        whole.smooth_length = false;
        whole.repair_tolerance = -1;  // the algorithms' own fields (the bound is the thesis')
        const tg::GcfField d1 = tg::gcf_distances(soup, 0, whole);
        EXPECT_EQ(d1.report.epsilon, 0.0);
        EXPECT_EQ(d1.report.error_bound, 0.0);
        for (const auto anchor : {tg::WindowAnchor::prefix, tg::WindowAnchor::field}) {
            tg::CurvatureFlowDistanceOptions o = whole;
            o.window = 8;
            o.anchor = anchor;
            o.cut_locus_guard = anchor == tg::WindowAnchor::field;
            const tg::GcfField d2 = tg::gcf_distances(soup, 0, o);
            double worst = 0;
            for (std::size_t v = 0; v < d2.d.size(); ++v)
                worst = std::max(worst, std::abs(d2.d[v] - d1.d[v]));
            const bool field = anchor == tg::WindowAnchor::field;
            const double ratio = worst / d2.report.error_bound;
            std::printf(
                "[ gcf-dist ] icosphere:%d, window 8, %s anchor: epsilon %.3e, m %zu, bound "
                "%.3e, max |d_window - d_whole| %.3e (%.2f x bound)\n",
                level, field ? "field" : "prefix", d2.report.epsilon, d2.report.max_faces,
                d2.report.error_bound, worst, ratio);
            EXPECT_GT(d2.report.epsilon, 0.0);
            EXPECT_GT(d2.report.max_faces, 10u);
            // The thesis' prefix rule does not meet the bound (7.3x, 9.3x measured; see above and
            // geodesic/README.md): a property of the rule, recorded, not asserted, so that an
            // improvement does not fail. The field anchor must meet it.
            if (field)
                EXPECT_LE(ratio, 1.0);
        }
    }
}

// The ring batches are flowed in parallel against the same visited set and committed in queue
// order: the field must be bitwise the same with one thread and with several.
TEST(CurvatureFlowDistances, SameFieldWithOneThreadAndWithSeveral) {
    const tg::Soup soup = tg::surface("ellipsoid:1,0.6,0.3:3:0.25");
    tg::CurvatureFlowDistanceOptions o;
    o.window = 6;
    tg::GcfField one, many;
    {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 1);
        one = tg::gcf_distances(soup, 5, o);
    }
    {
        const tbb::global_control limit(tbb::global_control::max_allowed_parallelism, 4);
        many = tg::gcf_distances(soup, 5, o);
    }
    ASSERT_EQ(one.d.size(), many.d.size());
    for (std::size_t v = 0; v < one.d.size(); ++v)
        EXPECT_EQ(one.d[v], many.d[v]) << v;
    EXPECT_EQ(one.report.iterations, many.report.iterations);
}

// Issue 4, shared meshes: with the on-face length the distance used to be the length of the
// chords between the flowed samples, which cut through creases and folds (a 0.84-edge chord across
// fandisk's 90-degree crease is 0.34 edges short). polyhedral_length (default) traces each segment
// on the faces and straightens the path through them. Oracle: a flat grid folded by 90 degrees
// along a grid line, whose geodesic distance is the Euclidean distance in the unfolded grid.
// Measured (window 8, source at a corner, the crease 6 of 12 cells away): chords mean 1.3e-2,
// max 7.7e-2; polyhedral length mean 3.6e-4, max 5.3e-3. Asserted with ~2x margin; the chords'
// failure is kept as a check that the test can fail.
TEST(CurvatureFlowDistances, FoldedGridOnFaceLengthIsTheUnfoldedDistance) {
    const tg::Soup flat = tg::flat_grid(12, 1.0);
    tg::Soup folded = flat;
    for (auto& p : folded.points)
        if (p[0] > 0.5 + 1e-12)
            p = {0.5, p[1], p[0] - 0.5};
    const std::size_t src = 0;
    std::vector<double> truth(flat.points.size());
    for (std::size_t v = 0; v < truth.size(); ++v)
        truth[v] = tg::euclidean(flat.points[src], flat.points[v]);
    for (const bool polyhedral : {true, false}) {
        tg::CurvatureFlowDistanceOptions o;
        o.window = 8;
        o.smooth_length = false;
        o.polyhedral_length = polyhedral;
        // The two length measures themselves (the repair pass mends the chords' field too).
        o.repair_tolerance = -1;
        const tg::GcfField f = tg::gcf_distances(folded, src, o);
        const Errors e = relative_errors(folded, src, f.d, truth);
        std::printf("[ gcf-dist ] grid folded 90 degrees, window 8, %s: mean %.2e max %.2e\n",
                    polyhedral ? "polyhedral length" : "chords", e.mean, e.max);
        if (polyhedral) {
            EXPECT_LE(e.mean, 1e-3);
            EXPECT_LE(e.max, 1e-2);
        } else {
            EXPECT_GT(e.max, 3e-2);
        }
    }
}

// spot (data/spot.obj, coarse and irregular), window 8, on-face length, against exact MMP from
// vertex 0. Before the polyhedral length and the monotone anchor slides: mean 1.5e-3, max 6.9e-2
// (an anchor slide that overshot on a curved region; chords). Measured now: mean 2.6e-4, max
// 5.9e-3: the targets (0.1 %, 1 %) are met for this source (the other benchmark source
// still has one vertex at 1.4 %, see geodesic/README.md).
TEST(CurvatureFlowDistances, SpotOnFaceLengthMeetsTheTargets) {
    const tg::Soup soup = tg::spot();
    const std::size_t src = 0;
    const tg::MmpField mmp = tg::mmp_distances(soup, tg::Sources::vertex(src));
    tg::CurvatureFlowDistanceOptions o;
    o.window = 8;
    o.smooth_length = false;
    const tg::GcfField f = tg::gcf_distances(soup, src, o);
    const Errors e = relative_errors(soup, src, f.d, mmp.d);
    std::printf("[ gcf-dist ] spot, window 8, polyhedral length: mean %.2e max %.2e, %.1f ms\n",
                e.mean, e.max, 1e3 * f.report.seconds);
    EXPECT_LE(e.mean, 5e-4);
    EXPECT_LE(e.max, 1e-2);
}

// On decimated-knight (502 vertices) the exact geodesics from vertex 0 to 481 and from 186 to 181
// run through saddle vertices; every start the repair had before the Steiner graph (fresh search,
// best neighbour's path, descent path) flowed to a locally shortest path beside the saddle, 1.39 %
// long from vertex 0. Started from the graph's path, the flow lands in the geodesic's class. From
// 186 the field without the graph happens to stay within 1 % with the window flows' limit of 20
// steps (0.87 %; 1.25 % when every flow ran to 200): which locally shortest path a flow lands in
// depends on where the flows before it stopped. The graph still lowers it.
TEST(CurvatureFlowDistances, SteinerGraphStartReachesGeodesicsThroughSaddleVertices) {
    tg::Soup knight;
    if (!tg::shared_mesh("meshes/decimated-knight.off", knight))
        GTEST_SKIP() << TAPELINE_SHARED_DATA_DIR << "/meshes/decimated-knight.off absent";
    for (const std::size_t source : {std::size_t{0}, std::size_t{186}}) {
        const tg::MmpField mmp = tg::mmp_distances(knight, tg::Sources::vertex(source));
        tg::CurvatureFlowDistanceOptions o;
        o.window = 8;
        o.smooth_length = false;
        o.repair_steiner_points = 0;
        const tg::GcfField without = tg::gcf_distances(knight, source, o);
        o.repair_steiner_points = 3;
        const tg::GcfField with = tg::gcf_distances(knight, source, o);
        const Errors before = relative_errors(knight, source, without.d, mmp.d);
        const Errors after = relative_errors(knight, source, with.d, mmp.d);
        std::printf(
            "[ gcf-dist ] decimated-knight from %zu, window 8, repaired: without the graph "
            "max %.2e, with it max %.2e (%zu flagged by the graph)\n",
            source, before.max, after.max, with.report.repair_graph_flagged);
        if (source == 0) {
            EXPECT_GT(before.max, 1e-2) << source;
        }
        EXPECT_LE(after.max, 1e-2) << source;
        EXPECT_LE(after.max, before.max) << source;
        EXPECT_LE(after.mean, before.mean) << source;
        EXPECT_EQ(without.report.repair_graph_flagged, 0u);
    }
}

// With a window of 4 on decimated-knight from vertex 0 a run of anchors interpolated low leaves a
// region about 30 % short that agrees with itself, so the neighbour check passes it; far below the
// Steiner-graph distance (an upper bound of the exact one), it is re-solved all the same.
TEST(CurvatureFlowDistances, FieldFarBelowTheGraphDistanceIsReSolved) {
    tg::Soup knight;
    if (!tg::shared_mesh("meshes/decimated-knight.off", knight))
        GTEST_SKIP() << TAPELINE_SHARED_DATA_DIR << "/meshes/decimated-knight.off absent";
    const tg::MmpField mmp = tg::mmp_distances(knight, tg::Sources::vertex(0));
    tg::CurvatureFlowDistanceOptions o;
    o.window = 4;
    o.smooth_length = false;
    o.repair_graph_margin = 1;  // never
    const tg::GcfField without = tg::gcf_distances(knight, 0, o);
    o.repair_graph_margin = 0.03;
    const tg::GcfField with = tg::gcf_distances(knight, 0, o);
    const Errors before = relative_errors(knight, 0, without.d, mmp.d);
    const Errors after = relative_errors(knight, 0, with.d, mmp.d);
    std::printf(
        "[ gcf-dist ] decimated-knight from 0, window 4: max %.2e without the margin rule, "
        "%.2e with it\n",
        before.max, after.max);
    EXPECT_GT(before.max, 0.1);
    EXPECT_LE(after.max, 1e-2);
    // The vertices the rule moved were too short and now hold path lengths: not below exact.
    for (std::size_t v = 0; v < knight.points.size(); ++v)
        if (without.d[v] < mmp.d[v] * 0.9)
            EXPECT_GE(with.d[v], mmp.d[v] * (1 - 1e-9)) << v;
}

// The Steiner graph's paths lie on the faces: its distances are upper bounds of the exact ones,
// with or without the finer points near the source. Near the source a path is a few edges long,
// and what a graph path loses at each crossing (up to a fraction of an edge) is a large part of
// its length: on bunny_decimated from vertex 2966, 8 points per edge leave vertex 3075 (4.9 mean
// edges away) 4.1 % above exact; 32 points within 12 mean edges bring the max to 0.78 %.
TEST(CurvatureFlowDistances, SteinerGraphIsAnUpperBoundAndTightNearTheSource) {
    const tg::Soup sphere = tg::surface("ellipsoid:1,0.6,0.3:3:0.25");
    const tg::MmpField exact = tg::mmp_distances(sphere, tg::Sources::vertex(5));
    for (const unsigned near : {0u, 32u}) {
        const std::vector<double> g = tg::steiner_distances(sphere, 5, 3, near, 12);
        for (std::size_t v = 0; v < g.size(); ++v)
            EXPECT_GE(g[v], exact.d[v] * (1 - 1e-12)) << near << " " << v;
        EXPECT_EQ(g[5], 0.0);
    }
}

TEST(CurvatureFlowDistances, SteinerGraphOnBunnyIsTightWithFinerPointsNearTheSource) {
    tg::Soup bunny;
    if (!tg::shared_mesh("meshes/bunny_decimated.off", bunny))
        GTEST_SKIP() << TAPELINE_SHARED_DATA_DIR << "/meshes/bunny_decimated.off absent";
    const tg::MmpField mmp = tg::mmp_distances(bunny, tg::Sources::vertex(2966));
    const std::vector<double> g8 = tg::steiner_distances(bunny, 2966, 8);
    const std::vector<double> g32 = tg::steiner_distances(bunny, 2966, 8, 32, 12);
    const Errors e8 = relative_errors(bunny, 2966, g8, mmp.d);
    const Errors e32 = relative_errors(bunny, 2966, g32, mmp.d);
    for (std::size_t v = 0; v < g8.size(); ++v) {
        EXPECT_GE(g32[v], mmp.d[v] * (1 - 1e-12)) << v;
        EXPECT_LE(g32[v], g8[v] * (1 + 1e-12)) << v;  // more nodes: never a longer shortest path
    }
    std::printf(
        "[ gcf-dist ] bunny_decimated from 2966, Steiner graph: 8 points per edge max %.2e, "
        "32 near the source max %.2e\n",
        e8.max, e32.max);
    EXPECT_GT(e8.max, 3e-2);
    EXPECT_LT(e32.max, 1e-2);
}

// The default margin (1 % with 8 graph points per edge): on decimated-knight from vertex 420 at
// window 8, vertex 460 and its neighbours are 1.14 % short and agree with each other, so the
// neighbour check passes them; 1.28 % below the graph distance, they are re-solved. From blub's
// vertex 5771 the field at vertex 3945 is exact, 2.3 % below a graph with 8 points (10.7 edges
// from the source), and the re-solved paths all end 1.14 % long beside the saddle vertex the
// geodesic runs through: the finer graph near the source keeps such vertices from being flagged,
// and a vertex flagged all the same takes at most its graph distance.
TEST(CurvatureFlowDistances, DefaultMarginMendsShortRunsAndKeepsExactVertices) {
    struct Case {
        const char* mesh;
        std::size_t source;
    };
    for (const Case c :
         {Case{"meshes/decimated-knight.off", 420}, Case{"meshes/blub_triangulated.obj", 5771}}) {
        tg::Soup soup;
        if (!tg::shared_mesh(c.mesh, soup))
            GTEST_SKIP() << TAPELINE_SHARED_DATA_DIR << "/" << c.mesh << " absent";
        const tg::MmpField mmp = tg::mmp_distances(soup, tg::Sources::vertex(c.source));
        tg::CurvatureFlowDistanceOptions o;
        o.window = 8;
        o.smooth_length = false;
        o.repair_graph_margin = 1;  // never
        const tg::GcfField without = tg::gcf_distances(soup, c.source, o);
        o.repair_graph_margin = -1;  // the default
        const tg::GcfField with = tg::gcf_distances(soup, c.source, o);
        const Errors before = relative_errors(soup, c.source, without.d, mmp.d);
        const Errors after = relative_errors(soup, c.source, with.d, mmp.d);
        std::printf(
            "[ gcf-dist ] %s from %zu, window 8: max %.2e without the margin rule, %.2e "
            "with the default\n",
            c.mesh, c.source, before.max, after.max);
        EXPECT_LE(after.max, 1e-2) << c.mesh;
        if (c.source == 420)
            EXPECT_GT(before.max, 1e-2);
    }
}

// The repair pass (CurvatureFlowDistanceOptions::repair_tolerance), on the benchmark's second
// sources. From spot's vertex 548 the windowed on-face field has a vertex 1.4 % long (its geodesic
// arrives between the directions of its visited neighbours' paths); from the torus' vertex 10088
// one 1.2 % long, where a fresh two-point search takes the other way round the inner side and only
// the field's own descent path starts in the right class. The repaired field must meet the 1 %
// target, and every distance it replaces must be a path length, so not below the exact one (a
// straightened on-mesh path is a path on the faces). From fandisk's vertex 0 a region of vertices
// is ~1 % long together, so each agrees with its neighbours' update; only after its border is
// mended are the next vertices flagged (two rounds left one 1.01 % long). Other sources, six per
// shared mesh, are measured by benchmarks/run_gcf.sh (GCF_SOURCES_ONLY=1; geodesic/README.md).
TEST(CurvatureFlowDistances, RepairPassMeetsOnePercentAndStaysAboveExact) {
    struct Case {
        const char* name;
        tg::Soup soup;
        std::size_t source;
    };
    std::vector<Case> cases{{"spot", tg::spot(), 548},
                            {"torus:1,0.4:160,64", tg::surface("torus:1,0.4:160,64"), 10088}};
    tg::Soup fandisk;
    const bool with_fandisk = tg::shared_mesh("meshes/fandisk.obj", fandisk);
    if (with_fandisk)
        cases.push_back({"fandisk", fandisk, 0});
    for (const auto& c : cases) {
        const tg::MmpField mmp = tg::mmp_distances(c.soup, tg::Sources::vertex(c.source));
        tg::CurvatureFlowDistanceOptions o;
        o.window = 8;
        o.smooth_length = false;
        o.repair_tolerance = -1;
        const tg::GcfField raw = tg::gcf_distances(c.soup, c.source, o);
        o.repair_tolerance = 2e-3;
        const tg::GcfField repaired = tg::gcf_distances(c.soup, c.source, o);
        const Errors before = relative_errors(c.soup, c.source, raw.d, mmp.d);
        const Errors after = relative_errors(c.soup, c.source, repaired.d, mmp.d);
        std::printf(
            "[ gcf-dist ] %s from %zu, window 8, on faces: without repair mean %.2e max %.2e; "
            "with repair mean %.2e max %.2e (%zu re-solved, %zu replaced, %.1f of %.1f ms)\n",
            c.name, c.source, before.mean, before.max, after.mean, after.max,
            repaired.report.repair_checked, repaired.report.repair_improved,
            1e3 * repaired.report.repair_seconds, 1e3 * repaired.report.seconds);
        EXPECT_GT(before.max, 1e-2) << c.name;  // the case the pass is for
        EXPECT_LE(after.max, 1e-2) << c.name;
        EXPECT_LE(after.mean, before.mean) << c.name;
        EXPECT_EQ(raw.report.repair_checked, 0u) << c.name;
        EXPECT_GT(repaired.report.repair_improved, 0u) << c.name;
        std::size_t changed = 0;
        for (std::size_t v = 0; v < c.soup.points.size(); ++v) {
            if (repaired.d[v] != raw.d[v]) {
                ++changed;
                EXPECT_GE(repaired.d[v], mmp.d[v] * (1 - 1e-9)) << c.name << " " << v;
            }
        }
        EXPECT_EQ(changed, repaired.report.repair_improved) << c.name;
    }
    // Spot and the torus ran above (a failure there is reported as such); the fandisk case is the
    // skipped part.
    if (!with_fandisk)
        GTEST_SKIP() << TAPELINE_SHARED_DATA_DIR << "/meshes/fandisk.obj absent";
}
