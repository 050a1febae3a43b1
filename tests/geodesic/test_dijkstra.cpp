// Dijkstra on the edge graph (Boost.Graph behind dijkstra.h).
#include <tapeline_test/geodesic.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace tg = tapeline_test::geodesic;

// An edge path is a polyhedral path, so Dijkstra >= exact at every vertex (round-off only).
// Measured overestimate (mean / max rel): icosphere:4 8.6e-2 / 0.235, spot 7.1e-2 / 0.349,
// ellipsoid:1,1,0.5:4:0.3 9.5e-2 / 0.244 -- it does not converge under refinement.
TEST(Dijkstra, NeverBelowExact) {
    for (const char* name :
         {"icosphere:3", "spot", "ellipsoid:1,1,0.5:4:0.3", "cylinder:1,2:32,8"}) {
        const tg::Soup soup = std::string(name) == "spot" ? tg::spot() : tg::surface(name);
        const tg::Field exact = tg::distances(soup, tg::Method::exact, tg::Sources::vertex(11));
        const tg::Field dij = tg::distances(soup, tg::Method::dijkstra, tg::Sources::vertex(11));
        for (std::size_t v = 0; v < soup.points.size(); ++v) {
            ASSERT_GE(dij.d[v], exact.d[v] * (1 - 1e-12)) << name << " vertex " << v;
            ASSERT_GE(dij.d[v], tg::euclidean(soup.points[v], soup.points[11]) * (1 - 1e-12));
        }
        EXPECT_EQ(dij.report.method, "dijkstra");
        EXPECT_EQ(dij.report.prepare_seconds, 0.0);
    }
}

// On the flat grid, a vertex on the source's row is reached along grid edges: the Euclidean
// distance exactly; the diagonal corner of a square cell is at sqrt(2) * cell.
TEST(Dijkstra, ExactAlongGridLines) {
    const tg::Soup soup = tg::flat_grid(8, 1.0);
    const tg::Field f = tg::distances(soup, tg::Method::dijkstra, tg::Sources::vertex(0));
    for (std::size_t i = 0; i <= 8; ++i) {
        EXPECT_NEAR(f.d[i], i / 8.0, 1e-15);      // bottom row
        EXPECT_NEAR(f.d[i * 9], i / 8.0, 1e-15);  // left column
    }
    EXPECT_NEAR(f.d[10], std::sqrt(2.0) / 8, 1e-15);  // face 0 = (0, 1, 10): diagonal edge
}

// A face-location source seeds the three corners with their straight-line distance, exact within
// the face; on a corner it is the vertex source.
TEST(Dijkstra, FaceLocationSeedsTheCorners) {
    const tg::Soup soup = tg::surface("icosphere:3");
    const std::size_t f = 40;
    const tg::SurfacePoint p = tg::SurfacePoint::face(f, {0.2, 0.3, 0.5});
    const tg::Field field = tg::distances(soup, tg::Method::dijkstra, tg::Sources{{p}});
    const tg::Vec3 x = tg::position(soup, p);
    for (auto v : soup.faces[f])
        EXPECT_NEAR(field.d[v], tg::euclidean(x, soup.points[v]), 1e-15);
    const tg::Field corner = tg::distances(soup, tg::Method::dijkstra,
                                           tg::Sources{{tg::SurfacePoint::face(f, {0, 1, 0})}});
    const tg::Field vertex =
        tg::distances(soup, tg::Method::dijkstra, tg::Sources::vertex(soup.faces[f][1]));
    EXPECT_EQ(corner.d, vertex.d);
}

// Several sources = the pointwise minimum of the single-source fields, exactly.
TEST(Dijkstra, MultipleSourcesAreTheMinimumOfSingleSources) {
    const tg::Soup soup = tg::spot();
    tg::Sources all;
    for (std::size_t s : {5u, 700u, 2100u})
        all.points.push_back(tg::SurfacePoint::vertex(s));
    all.points.push_back(tg::SurfacePoint::face(100, {0.6, 0.2, 0.2}));
    const tg::Field joint = tg::distances(soup, tg::Method::dijkstra, all);
    std::vector<double> best(soup.points.size(), std::numeric_limits<double>::infinity());
    for (const auto& p : all.points) {
        const tg::Field f = tg::distances(soup, tg::Method::dijkstra, tg::Sources{{p}});
        for (std::size_t v = 0; v < best.size(); ++v)
            best[v] = std::min(best[v], f.d[v]);
    }
    EXPECT_EQ(joint.d, best);
}
