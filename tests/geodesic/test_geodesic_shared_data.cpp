// Research meshes from TAPELINE_SHARED_DATA_DIR (skipped when absent): a MakeHuman body, the
// meshes the tape-measure work runs on, and a genus-1 mesh.
#include <tapeline_test/geodesic.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

namespace tg = tapeline_test::geodesic;

namespace {

double min_excess_over_euclid(const tg::Soup& soup, const std::vector<double>& d, std::size_t s) {
    double m = 1e300;
    for (std::size_t v = 0; v < soup.points.size(); ++v)
        m = std::min(m, d[v] - tg::euclidean(soup.points[v], soup.points[s]));
    return m;
}

}  // namespace

// MakeHuman body (13,380 vertices, closed, irregular triangles around the face, hands, feet).
// Measured against exact (source vertex 0):
//   heat      mean 6.0e-2, far max 0.134, min(d - |pq|) = -14.9 h  (plain cotan heat breaks down
//             locally on the body's poor triangles)
//   heat_idt  mean 3.4e-2, far max 0.115, min(d - |pq|) = -1.2 h
//   dijkstra  mean 5.4e-2, far max 0.178, never below exact
// So on a body the intrinsic Delaunay Laplacian is the heat variant to use.
TEST(SharedData, BodyMeshHeatIdtBeatsHeatAndBoundsHold) {
    tg::Soup soup;
    if (!tg::shared_mesh("bodies/mh_male_average.obj", soup))
        GTEST_SKIP() << TAPELINE_SHARED_DATA_DIR << "/bodies/mh_male_average.obj absent";
    const double h = tg::mean_edge_length(soup);
    const tg::Field exact = tg::distances(soup, tg::Method::exact, tg::Sources::vertex(0));
    const tg::Field heat = tg::distances(soup, tg::Method::heat, tg::Sources::vertex(0));
    const tg::Field idt = tg::distances(soup, tg::Method::heat_idt, tg::Sources::vertex(0));
    const tg::Field dij = tg::distances(soup, tg::Method::dijkstra, tg::Sources::vertex(0));
    EXPECT_EQ(exact.report.unreachable, 0u);
    EXPECT_GE(min_excess_over_euclid(soup, exact.d, 0), -1e-12);
    for (std::size_t v = 0; v < soup.points.size(); ++v)
        ASSERT_GE(dij.d[v], exact.d[v] * (1 - 1e-12)) << v;
    const auto e_heat = tg::compare(heat.d, exact.d);
    const auto e_idt = tg::compare(idt.d, exact.d);
    EXPECT_LT(e_idt.mean_rel, 0.05);
    EXPECT_LT(e_idt.max_rel_far, 0.2);
    EXPECT_LT(e_idt.mean_rel, 0.75 * e_heat.mean_rel);
    EXPECT_GE(min_excess_over_euclid(soup, idt.d, 0), -2.0 * h);
}

// Genus 1 (bob, 5,344 vertices): measured heat mean 1.9e-2 / far 7.1e-2, heat_idt 1.9e-2 /
// 6.8e-2, min(d - |pq|) -0.42 h; exact and Dijkstra bounds hold.
TEST(SharedData, GenusOneMesh) {
    tg::Soup soup;
    if (!tg::shared_mesh("meshes/bob_tri.obj", soup))
        GTEST_SKIP() << TAPELINE_SHARED_DATA_DIR << "/meshes/bob_tri.obj absent";
    const double h = tg::mean_edge_length(soup);
    const tg::Field exact = tg::distances(soup, tg::Method::exact, tg::Sources::vertex(0));
    EXPECT_GE(min_excess_over_euclid(soup, exact.d, 0), -1e-12);
    for (auto m : {tg::Method::heat, tg::Method::heat_idt}) {
        const tg::Field f = tg::distances(soup, m, tg::Sources::vertex(0));
        const auto e = tg::compare(f.d, exact.d);
        EXPECT_LT(e.mean_rel, 0.035) << tg::name(m);
        EXPECT_LT(e.max_rel_far, 0.12) << tg::name(m);
        EXPECT_GE(min_excess_over_euclid(soup, f.d, 0), -1.0 * h) << tg::name(m);
    }
}
