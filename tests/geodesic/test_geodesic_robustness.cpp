// Behaviour shared by the baseline methods: generic mesh types, several components, isolated
// vertices, boundary, and every rejected input with its message (DESIGN.md §4, §6).
#include <tapeline/core/errors.h>
#include <tapeline_test/geodesic.h>

#include <gtest/gtest.h>
#include <tapeline_test/expect.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace tg = tapeline_test::geodesic;

namespace {

const tg::Method kAll[] = {tg::Method::exact, tg::Method::heat, tg::Method::heat_idt,
                           tg::Method::dijkstra, tg::Method::fast_marching};

using tapeline_test::contains;
using tapeline_test::expect_error;

}  // namespace

// The generic API compiles for Surface_mesh and Polyhedron_3 (items with id) and gives the same
// numbers up to round-off: the two meshes start their faces at different halfedges and list
// elements in different orders, so sums are taken in another order (measured max rel difference:
// exact 1.9e-16, dijkstra 5.1e-16, heat 1.8e-14, heat_idt 8.9e-15). Paths to 1e-12.
TEST(GeodesicGeneric, SurfaceMeshAndPolyhedronAgree) {
    auto tol = [](tg::Method m) {
        return m == tg::Method::exact || m == tg::Method::dijkstra || m == tg::Method::fast_marching
                   ? 1e-12
                   : 1e-9;
    };
    const tg::Soup soup = tg::surface("ellipsoid:1,1,0.5:3:0.2");
    tg::Sources sources;
    sources.points = {tg::SurfacePoint::vertex(4), tg::SurfacePoint::vertex(300)};
    tg::Sources with_location = sources;
    with_location.points.push_back(tg::SurfacePoint::face(12, {0.1, 0.6, 0.3}));
    for (auto m : kAll) {
        const tg::Sources& s =
            (m == tg::Method::heat || m == tg::Method::heat_idt) ? sources : with_location;
        const tg::Field a = tg::distances(soup, m, s, tg::MeshKind::surface_mesh);
        const tg::Field b = tg::distances(soup, m, s, tg::MeshKind::polyhedron);
        ASSERT_EQ(a.d.size(), b.d.size());
        double worst = 0;
        for (std::size_t v = 0; v < a.d.size(); ++v)
            worst = std::max(worst, std::abs(a.d[v] - b.d[v]) / std::max(a.d[v], 1e-300));
        EXPECT_LT(worst, tol(m)) << tg::name(m);
        EXPECT_EQ(a.report.unreachable, b.report.unreachable);
        EXPECT_EQ(a.report.faces, b.report.faces);
    }
    const auto pa = tg::exact_path(soup, tg::SurfacePoint::face(12, {0.1, 0.6, 0.3}),
                                   tg::SurfacePoint::vertex(600), tg::MeshKind::surface_mesh);
    const auto pb = tg::exact_path(soup, tg::SurfacePoint::face(12, {0.1, 0.6, 0.3}),
                                   tg::SurfacePoint::vertex(600), tg::MeshKind::polyhedron);
    EXPECT_NEAR(pa.length, pb.length, 1e-12 * pa.length);
    EXPECT_EQ(pa.points.size(), pb.points.size());
}

// Two spheres and an isolated vertex. Vertices away from the source's component get +infinity
// for every method, counted in report.unreachable; the isolated vertex (halfedge(v) null: the
// CGAL#5280 segfault in SMSP) never reaches CGAL; as a source it is at 0 from itself only.
TEST(GeodesicRobustness, ComponentsAndIsolatedVerticesAreUnreachable) {
    const tg::Soup one = tg::surface("icosphere:2");  // 162 vertices
    tg::Soup soup = tg::disjoint_union(one, one, {5, 0, 0});
    soup.points.push_back({10, 10, 10});
    const std::size_t isolated = soup.points.size() - 1;
    const tg::Field exact_one = tg::distances(one, tg::Method::exact, tg::Sources::vertex(0));
    for (auto m : kAll) {
        const tg::Field f = tg::distances(soup, m, tg::Sources::vertex(0));
        EXPECT_EQ(f.report.unreachable, 163u) << tg::name(m);
        EXPECT_EQ(f.report.components, 3u) << tg::name(m);
        for (std::size_t v = 162; v < soup.points.size(); ++v)
            ASSERT_EQ(f.d[v], std::numeric_limits<double>::infinity()) << tg::name(m) << " " << v;
        for (std::size_t v = 0; v < 162; ++v)
            ASSERT_TRUE(std::isfinite(f.d[v])) << tg::name(m) << " " << v;
        if (m == tg::Method::exact)  // the other component changes nothing
            for (std::size_t v = 0; v < 162; ++v)
                ASSERT_EQ(f.d[v], exact_one.d[v]) << v;

        const tg::Field g = tg::distances(soup, m, tg::Sources::vertex(isolated));
        EXPECT_EQ(g.d[isolated], 0.0) << tg::name(m);
        EXPECT_EQ(g.report.unreachable, soup.points.size() - 1) << tg::name(m);

        // One source on each sphere: both components are reached.
        tg::Sources both;
        both.points = {tg::SurfacePoint::vertex(0), tg::SurfacePoint::vertex(162)};
        EXPECT_EQ(tg::distances(soup, m, both).report.unreachable, 1u) << tg::name(m);
    }
    // Paths: to another component there is none (an expected non-result, not an exception).
    const auto none =
        tg::exact_paths(soup, tg::Sources::vertex(0),
                        {tg::SurfacePoint::vertex(200), tg::SurfacePoint::vertex(isolated)});
    for (const auto& p : none) {
        EXPECT_TRUE(p.points.empty());
        EXPECT_EQ(p.length, std::numeric_limits<double>::infinity());
        EXPECT_EQ(p.distance, std::numeric_limits<double>::infinity());
    }
}

// --- rejected inputs ----------------------------------------------------------------------------

TEST(GeodesicErrors, NotATriangleMesh) {
    tg::Soup soup = tg::flat_grid(2, 1.0);
    // Replace the two triangles of the first cell by one quad (0, 1, 4, 3).
    soup.faces.erase(soup.faces.begin(), soup.faces.begin() + 2);
    soup.faces.insert(soup.faces.begin(), {0, 1, 4, 3});
    for (auto m : kAll)
        for (auto kind : {tg::MeshKind::surface_mesh, tg::MeshKind::polyhedron})
            expect_error<tapeline::TopologyError>(
                [&] { tg::distances(soup, m, tg::Sources::vertex(0), kind); },
                {tg::name(m), "face #0 has 4 sides", "not a triangle mesh"}, tg::name(m));
}

TEST(GeodesicErrors, VertexNotInTheMesh) {
    const tg::Soup soup = tg::surface("icosphere:1");  // 42 vertices
    for (auto m : kAll) {
        expect_error<tapeline::InvalidInput>(
            [&] { tg::distances(soup, m, tg::Sources::vertex(1000)); },
            {tg::name(m), "source vertex is not a vertex of the mesh", "index 1000", "42 vertices"},
            tg::name(m));
        expect_error<tapeline::InvalidInput>(
            [&] { tg::distances(soup, m, tg::Sources::vertex(1000), tg::MeshKind::polyhedron); },
            {"source vertex is not a vertex of the mesh (null vertex)"}, tg::name(m));
    }
    expect_error<tapeline::InvalidInput>(
        [&] { tg::exact_path(soup, tg::SurfacePoint::vertex(0), tg::SurfacePoint::vertex(99)); },
        {"target vertex is not a vertex of the mesh", "index 99"}, "path target");
}

TEST(GeodesicErrors, BadFaceLocation) {
    const tg::Soup soup = tg::surface("icosphere:1");  // 80 faces
    const double nan = std::numeric_limits<double>::quiet_NaN();
    for (auto m : {tg::Method::exact, tg::Method::dijkstra, tg::Method::fast_marching}) {
        expect_error<tapeline::InvalidInput>(
            [&] {
                tg::distances(soup, m, tg::Sources{{tg::SurfacePoint::face(500, {1, 0, 0})}});
            },
            {"source face location is not a face of the mesh", "index 500", "80 faces"},
            tg::name(m));
        expect_error<tapeline::InvalidInput>(
            [&] {
                tg::distances(soup, m, tg::Sources{{tg::SurfacePoint::face(500, {1, 0, 0})}},
                              tg::MeshKind::polyhedron);
            },
            {"is not a face of the mesh (null face)"}, tg::name(m));
        expect_error<tapeline::InvalidInput>(
            [&] {
                tg::distances(soup, m, tg::Sources{{tg::SurfacePoint::face(5, {0.5, 0.7, 0.1})}});
            },
            {"on face #5 has barycentric coordinates", "sum to 1"}, tg::name(m));
        expect_error<tapeline::InvalidInput>(
            [&] {
                tg::distances(soup, m, tg::Sources{{tg::SurfacePoint::face(5, {nan, 0.5, 0.5})}});
            },
            {"has barycentric coordinates (", "nan", "must be finite"}, tg::name(m));
        expect_error<tapeline::InvalidInput>(
            [&] {
                tg::distances(soup, m, tg::Sources{{tg::SurfacePoint::face(5, {1.5, -0.5, 0})}});
            },
            {"must be finite, in [0, 1]"}, tg::name(m));
    }
}

TEST(GeodesicErrors, EmptySourceSet) {
    const tg::Soup soup = tg::surface("icosphere:1");
    for (auto m : kAll)
        expect_error<tapeline::InvalidInput>([&] { tg::distances(soup, m, tg::Sources{}); },
                                             {tg::name(m), "the source set is empty"}, tg::name(m));
}

TEST(GeodesicErrors, NonFiniteCoordinate) {
    tg::Soup soup = tg::surface("icosphere:1");
    soup.points[7][1] = std::numeric_limits<double>::quiet_NaN();
    for (auto m : kAll)
        expect_error<tapeline::InvalidInput>(
            [&] { tg::distances(soup, m, tg::Sources::vertex(0)); },
            {tg::name(m), "vertex #7 has a non-finite coordinate"}, tg::name(m));
}

// A Surface_mesh with a removed face but no collect_garbage(): the face indices are no longer
// 0..n-1, which SMSP and the vector-backed maps would index out of bounds.
TEST(GeodesicErrors, IndexMapsMustBeBijections) {
    const tg::Soup soup = tg::surface("icosphere:1");
    for (auto m : kAll)
        expect_error<tapeline::InvalidInput>(
            [&] {
                tg::distances(soup, m, tg::Sources::vertex(0),
                              tg::MeshKind::surface_mesh_with_garbage);
            },
            {"index map is not a bijection"}, tg::name(m));
}
