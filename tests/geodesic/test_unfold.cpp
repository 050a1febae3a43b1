// Unfolding of path strips (unfold.h) and its SVG picture (unfold_svg.h).
//
// Oracles (DESIGN.md §6):
// - analytic: on a flat grid the unfolding is a rigid motion of the grid itself, so every vertex
//   has one position in the plane whatever face it is reached through, and every unfolded length
//   equals the 3D one (1e-12 relative: a few rounding steps per face).
// - invariants: every unfolded face keeps its three edge lengths (1e-12, the mesh's unit on unit
//   spheres) and consecutive faces share their hinge edge exactly (same corner positions); the
//   unfolded polyline has the traced length (an isometry, 1e-12 relative).
// - independent exact method: an exact polyhedral geodesic (our MMP) that passes no vertex is
//   straight in its unfolding (Mitchell, Mount, Papadimitriou 1987): its length equals the distance
//   between the unfolded end points to 1e-9 relative (MMP's own trace is exact to ~1e-12; the
//   margin covers the accumulated rotation of the strip over a few hundred faces).
#include <tapeline/core/errors.h>
#include <tapeline_test/gcf.h>
#include <tapeline_test/mmp.h>
#include <tapeline_test/unfold.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace tg = tapeline_test::geodesic;

namespace {

double dist2(const std::array<double, 2>& a, const std::array<double, 2>& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1]);
}

/// Edge lengths kept per face, hinges shared exactly, unfolded length = traced length.
void expect_isometric_strip(const tg::Soup& soup, const tg::UnfoldedPath& u, const char* what) {
    ASSERT_FALSE(u.faces.empty()) << what;
    double worst = 0;
    for (std::size_t i = 0; i < u.faces.size(); ++i) {
        const auto& f = u.faces[i];
        for (int k = 0; k < 3; ++k) {
            const double d3 =
                tg::euclidean(soup.points[f.vertices[k]], soup.points[f.vertices[(k + 1) % 3]]);
            const double d2 = dist2(f.corners[k], f.corners[(k + 1) % 3]);
            worst = std::max(worst, std::abs(d3 - d2));
        }
        if (i == 0)
            continue;
        const auto& g = u.faces[i - 1];
        int shared = 0;
        for (int a = 0; a < 3; ++a)
            for (int b = 0; b < 3; ++b)
                if (g.vertices[a] == f.vertices[b]) {
                    ++shared;
                    EXPECT_EQ(g.corners[a], f.corners[b]) << what << " hinge " << i;
                }
        EXPECT_EQ(shared, 2) << what << ": faces " << i - 1 << " and " << i
                             << " do not share an edge";
    }
    EXPECT_LE(worst, 1e-12) << what;
    EXPECT_NEAR(u.unfolded_length, u.traced_length, 1e-12 * u.traced_length) << what;
    ASSERT_EQ(u.points.size(), u.point_face.size());
    EXPECT_EQ(u.points.front()[0], 0.0);
    EXPECT_EQ(u.points.front()[1], 0.0);
    EXPECT_NEAR(u.points.back()[1], 0.0, 1e-12 * u.straight_length);
}

}  // namespace

TEST(Unfold, FlatGridIsARigidMotionOfTheGrid) {
    const tg::Soup soup = tg::flat_grid(20, 1.0);
    // An exact path and a curvature-flow path between face points, so the strip is a real one
    // (a straight segment through face interiors) and a zigzag polyline on the faces.
    const auto from = tg::SurfacePoint::face(3, {0.2, 0.3, 0.5});
    const auto to = tg::SurfacePoint::face(700, {0.6, 0.3, 0.1});
    const tg::PathResult exact = tg::mmp_path(soup, from, to);
    tg::CurvatureFlowOptions o;
    o.tolerance = 1e-12;  // the flow is linear on a plane and converges to the segment
    const tg::GcfResult flow = tg::gcf_path(soup, from, to, o);
    for (const auto* path : {&exact.points, &flow.on_mesh.points}) {
        const tg::UnfoldedPath u = tg::unfold(soup, *path);
        expect_isometric_strip(soup, u, "flat grid");
        // One plane position per vertex, and every pairwise distance the 3D one: a rigid motion.
        std::map<std::size_t, std::array<double, 2>> at;
        for (const auto& f : u.faces)
            for (int k = 0; k < 3; ++k) {
                const auto [it, fresh] = at.emplace(f.vertices[k], f.corners[k]);
                if (!fresh)
                    EXPECT_NEAR(dist2(it->second, f.corners[k]), 0.0, 1e-12);
            }
        double worst = 0;
        for (const auto& [v, p] : at)
            for (const auto& [w, q] : at)
                worst = std::max(
                    worst, std::abs(dist2(p, q) - tg::euclidean(soup.points[v], soup.points[w])));
        EXPECT_LE(worst, 1e-12);
        const double d = tg::euclidean(tg::position(soup, from), tg::position(soup, to));
        EXPECT_NEAR(u.straight_length, d, 1e-12 * d);
        EXPECT_TRUE(u.straight_inside);
        // Both paths are straight on a plane (the flow converges to the segment).
        EXPECT_NEAR(u.unfolded_length, u.straight_length, 1e-9 * d);
    }
}

TEST(Unfold, IcosphereStripsAreIsometricAndExactPathsStraight) {
    for (int level : {4, 5}) {
        const std::string spec = "icosphere:" + std::to_string(level);
        const tg::Soup soup = tg::surface(spec);
        for (double degrees : {20.0, 60.0, 110.0, 170.0}) {
            const std::size_t b = vertex_at_angle(soup, 0, degrees);
            // Face-point ends: a geodesic between generic points passes no vertex.
            const auto from = tg::SurfacePoint::face(7, {0.3, 0.3, 0.4});
            const auto to = tg::SurfacePoint::face(b % soup.faces.size(), {0.5, 0.2, 0.3});
            const tg::PathResult exact = tg::mmp_path(soup, from, to);
            const tg::UnfoldedPath u = tg::unfold(soup, exact.points);
            expect_isometric_strip(soup, u, spec.c_str());
            const double gap = (u.unfolded_length - u.straight_length) / u.straight_length;
            std::printf(
                "[ unfold   ] %s exact MMP path %.0f deg: %zu faces, %zu at vertices, traced "
                "%.12f straight %.12f (rel %+.1e), inside %d\n",
                spec.c_str(), degrees, u.faces.size(), u.vertex_points, u.traced_length,
                u.straight_length, gap, u.straight_inside);
            EXPECT_NEAR(u.traced_length, exact.length, 1e-12 * exact.length);
            if (u.vertex_points == 0) {
                EXPECT_LE(std::abs(gap), 1e-9) << spec << " " << degrees;
                EXPECT_TRUE(u.straight_inside);
            }
            // The curvature-flow path between the same points: isometric strip too, and its
            // unfolded straight segment is never longer than the traced path.
            const tg::GcfResult flow = tg::gcf_path(soup, from, to);
            const tg::UnfoldedPath v = tg::unfold(soup, flow.on_mesh.points);
            expect_isometric_strip(soup, v, "gcf");
            EXPECT_LE(v.straight_length, v.traced_length * (1 + 1e-12));
            std::printf(
                "[ unfold   ]   gcf on-mesh path: %zu faces, traced %.12f straight %.12f (traced "
                "- straight %.1e rel), exact %.12f, inside %d\n",
                v.faces.size(), v.traced_length, v.straight_length,
                (v.traced_length - v.straight_length) / v.straight_length, exact.length,
                v.straight_inside);
        }
    }
}

TEST(Unfold, ExactPathsOnSpotAreStraightAwayFromVertices) {
    const tg::Soup soup = tg::spot();
    const std::size_t n = soup.faces.size();
    std::size_t checked = 0;
    for (std::size_t k = 1; k <= 16; ++k) {
        const auto from = tg::SurfacePoint::face((k * 131) % n, {0.25, 0.35, 0.4});
        const auto to = tg::SurfacePoint::face((k * 2417 + 999) % n, {0.45, 0.25, 0.3});
        const tg::PathResult exact = tg::mmp_path(soup, from, to);
        const tg::UnfoldedPath u = tg::unfold(soup, exact.points);
        expect_isometric_strip(soup, u, "spot");
        const double gap = (u.unfolded_length - u.straight_length) / u.straight_length;
        std::printf("[ unfold   ] spot exact path %zu: %zu faces, %zu at vertices, rel %+.1e\n", k,
                    u.faces.size(), u.vertex_points, gap);
        if (u.vertex_points == 0) {
            ++checked;
            EXPECT_LE(std::abs(gap), 1e-9) << k;
        } else {
            // Through a vertex the exact path bends (a saddle); it is still no shorter than the
            // straight segment in any unfolding.
            EXPECT_GE(gap, -1e-9) << k;
        }
    }
    // spot has many saddle vertices: measured 7 of these 16 pairs pass none.
    EXPECT_GE(checked, 5u);
}

TEST(Unfold, PolyhedronGivesTheSameStrip) {
    const tg::Soup soup = tg::surface("icosphere:3");
    const auto from = tg::SurfacePoint::face(2, {0.3, 0.3, 0.4});
    const auto to = tg::SurfacePoint::face(500, {0.5, 0.2, 0.3});
    const tg::PathResult exact = tg::mmp_path(soup, from, to);
    const auto a = tg::unfold(soup, exact.points);
    const auto b = tg::unfold(soup, exact.points, {}, tg::MeshKind::polyhedron);
    ASSERT_EQ(a.faces.size(), b.faces.size());
    for (std::size_t i = 0; i < a.faces.size(); ++i)
        EXPECT_EQ(a.faces[i].face, b.faces[i].face);
    // Polyhedron_3 starts its faces at another corner: the same strip up to rounding.
    EXPECT_NEAR(a.straight_length, b.straight_length, 1e-12 * a.straight_length);
}

TEST(Unfold, SvgHasTheStripAndTheLengths) {
    const tg::Soup soup = tg::surface("icosphere:3");
    const tg::PathResult exact = tg::mmp_path(soup, tg::SurfacePoint::face(2, {0.3, 0.3, 0.4}),
                                              tg::SurfacePoint::face(500, {0.5, 0.2, 0.3}));
    const auto u = tg::unfold(soup, exact.points);
    const std::string svg = tg::unfold_svg(u, "a <test> & title");
    EXPECT_EQ(svg.rfind("<?xml", 0), 0u);
    EXPECT_NE(svg.find("</svg>"), std::string::npos);
    EXPECT_NE(svg.find("a &lt;test&gt; &amp; title"), std::string::npos);
    EXPECT_NE(svg.find("traced length"), std::string::npos);
    std::size_t polygons = 0;
    for (std::size_t p = svg.find("<polygon"); p != std::string::npos;
         p = svg.find("<polygon", p + 1))
        ++polygons;
    EXPECT_EQ(polygons, u.faces.size());
}

TEST(Unfold, RejectsPathsOffTheFaces) {
    const tg::Soup soup = tg::surface("icosphere:2");
    auto expect_invalid = [](const std::function<void()>& f, const std::string& fragment) {
        try {
            f();
            ADD_FAILURE() << "no exception; expected one mentioning \"" << fragment << "\"";
        } catch (const tapeline::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find(fragment), std::string::npos) << e.what();
        }
    };
    const tg::Vec3 a = soup.points[0];
    expect_invalid([&] { tg::unfold(soup, {a}); }, "two distinct points");
    expect_invalid([&] { tg::unfold(soup, {a, a}); }, "two distinct points");
    expect_invalid([&] { tg::unfold(soup, {a, {0, 0, 0}}); }, "point #1");
    expect_invalid([&] { tg::unfold(soup, {a, {0, 0, std::nan("")}}); }, "not finite");
    expect_invalid([&] { tg::unfold(soup, {a, soup.points[1]}, {0.0}); }, "tolerance");
    // A chord across the sphere: its far end is on a face, but not next to the start's faces.
    const tg::Vec3 far = soup.points[vertex_at_angle(soup, 0, 180.0)];
    expect_invalid([&] { tg::unfold(soup, {a, far}); }, "not on a face next to");
}
