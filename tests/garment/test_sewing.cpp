// Sewing along geodesic strings, welding, the quality figures and the fabric catalogue, against
// analytic truth: a seam whose sides start on the front and the back of a cylinder closes around
// it and never through it; strings on a cylinder are as long as the unrolled (helical) geodesic;
// stretches of affine maps are their singular values; a tube has two boundary loops.
#include <tapeline/garment/drape_solver.h>
#include <tapeline/garment/fabric.h>
#include <tapeline/garment/openings.h>
#include <tapeline/garment/quality.h>
#include <tapeline/garment/stitching.h>
#include <tapeline_test/garment_shapes.h>
#include <tapeline_test/temp_dir.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <optional>
#include <string>

namespace tg = tapeline::garment;
using tapeline_test::capped_cylinder;
using tapeline_test::cloth_grid;
using tapeline_test::grid_vertex;

namespace {

tg::Vec3 v3(double x, double y, double z) {
    return {x, y, z};
}

/// A capsule along z: a cylinder of radius r between z = −h and z = h closed by hemispheres,
/// outward oriented; `slices` around, `rings` per hemisphere, `along` rings on the cylinder.
tapeline_test::GarmentTriMesh capsule(double r, double h, int slices, int rings, int along) {
    tapeline_test::GarmentTriMesh m;
    std::vector<std::pair<double, double>> profile;  // (radius, z) from the bottom pole up
    for (int i = 1; i <= rings; ++i) {
        const double a = -M_PI / 2 + (M_PI / 2) * i / rings;
        profile.push_back({r * std::cos(a), -h + r * std::sin(a)});
    }
    for (int i = 1; i <= along; ++i) {
        profile.push_back({r, -h + 2 * h * i / along});
    }
    for (int i = 1; i < rings; ++i) {
        const double a = (M_PI / 2) * i / rings;
        profile.push_back({r * std::cos(a), h + r * std::sin(a)});
    }
    m.points.push_back({0, 0, -h - r});
    for (const auto& [rad, z] : profile) {
        for (int j = 0; j < slices; ++j) {
            const double phi = 2 * M_PI * j / slices;
            m.points.push_back({rad * std::cos(phi), rad * std::sin(phi), z});
        }
    }
    const auto top = std::uint32_t(m.points.size());
    m.points.push_back({0, 0, h + r});
    const int n = int(profile.size());
    const auto at = [&](int i, int j) { return std::uint32_t(1 + i * slices + (j % slices)); };
    for (int j = 0; j < slices; ++j) {
        m.triangles.push_back({0, at(0, j + 1), at(0, j)});
        m.triangles.push_back({top, at(n - 1, j), at(n - 1, j + 1)});
    }
    for (int i = 0; i + 1 < n; ++i) {
        for (int j = 0; j < slices; ++j) {
            m.triangles.push_back({at(i, j), at(i, j + 1), at(i + 1, j + 1)});
            m.triangles.push_back({at(i, j), at(i + 1, j + 1), at(i + 1, j)});
        }
    }
    return m;
}

/// Exact signed distance to that capsule.
double capsule_distance(double r, double h, const tg::Vec3& p) {
    const double z = std::clamp(p[2], -h, h);
    return std::sqrt(p[0] * p[0] + p[1] * p[1] + (p[2] - z) * (p[2] - z)) - r;
}

}  // namespace

TEST(GarmentStretch, SingularValuesOfAnAffineMap) {
    // Pattern triangle (0,0),(10,0),(0,10) mapped by F = diag(1.1, 0.9) then rotated in 3D:
    // the largest principal stretch is 1.1 whatever the rotation.
    const std::vector<std::array<tg::UV, 3>> uv = {{tg::UV{0, 0}, tg::UV{10, 0}, tg::UV{0, 10}}};
    const double c = std::cos(0.7), s = std::sin(0.7);
    const auto rot = [&](double x, double y) { return v3(c * x, y, s * x); };
    const std::vector<tg::Vec3> x = {rot(0, 0), rot(11, 0), rot(0, 9)};
    const auto st = tg::triangle_stretch(x, {{0, 1, 2}}, uv);
    ASSERT_EQ(st.size(), 1u);
    EXPECT_NEAR(st[0], 1.1, 1e-12);
    // A shear x' = x + 0.5 y: singular values of [[1, .5],[0, 1]] are (1 ± ...): the larger is
    // (0.5 + sqrt(4.25)) / 2 · ... computed in closed form: sqrt((2.25 + sqrt(2.25² − 4)) / 2).
    const std::vector<tg::Vec3> y = {v3(0, 0, 0), v3(10, 0, 0), v3(5, 10, 0)};
    const double expected = std::sqrt((2.25 + std::sqrt(2.25 * 2.25 - 4)) / 2);
    EXPECT_NEAR(tg::triangle_stretch(y, {{0, 1, 2}}, uv)[0], expected, 1e-12);
}

TEST(GarmentWeld, UnionOfPairsAndBoundaryLoops) {
    // A 4 × 2 grid rolled into a tube by stitching its left and right columns.
    const int nx = 4, ny = 2;
    tg::ClothModel c = cloth_grid(nx, ny, 10, v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0));
    std::vector<tg::Stitch> pairs;
    for (int j = 0; j <= ny; ++j) {
        pairs.push_back({grid_vertex(nx, 0, j), grid_vertex(nx, nx, j), 0, 0});
    }
    const tg::Welding w = tg::weld_pairs(c.positions.size(), pairs);
    EXPECT_EQ(w.count, c.positions.size() - std::size_t(ny + 1));
    for (const auto& p : pairs) {
        EXPECT_EQ(w.weld_map[p.a], w.weld_map[p.b]);
    }
    std::vector<tg::Tri> welded;
    for (const auto& t : c.triangles) {
        welded.push_back({w.weld_map[t[0]], w.weld_map[t[1]], w.weld_map[t[2]]});
    }
    EXPECT_EQ(tg::boundary_loop_vertices(welded).size(), 2u);       // the tube's two rims
    EXPECT_EQ(tg::boundary_loop_vertices(c.triangles).size(), 1u);  // flat sheet
}

TEST(GarmentStrings, PointsAlongAndSewingTargets) {
    tg::StringPath s;
    s.points = {v3(0, 0, 0), v3(10, 0, 0), v3(10, 30, 0)};
    s.arc = {0, 10, 40};
    EXPECT_DOUBLE_EQ(s.length(), 40);
    const auto p = s.at(25);
    EXPECT_NEAR(p[0], 10, 1e-12);
    EXPECT_NEAR(p[1], 15, 1e-12);
    tg::SewingPlan plan;
    plan.pairs = {{7, 9, 0, 0}};
    plan.strings = {s};
    const auto t0 = tg::sewing_targets(plan, 0.0, 0.0);
    ASSERT_EQ(t0.size(), 2u);
    EXPECT_EQ(t0[0].vertex, 7u);  // in vertex order
    EXPECT_EQ(t0[0].target, v3(0, 0, 0));
    EXPECT_EQ(t0[1].target, v3(10, 30, 0));
    const auto t1 = tg::sewing_targets(plan, 1.0, 0.0);
    EXPECT_NEAR(t1[0].target[1], 10, 1e-12);  // both at the middle, arc 20
    EXPECT_NEAR(t1[1].target[1], 10, 1e-12);
}

// A corner vertex sewn in two pairs is pulled to the mean of its two string points; where that
// mean lies inside the body it is lifted out. A box 600 × 100 × 300 mm (x, y, z): one point 5 mm
// off its side face (0, 0, 155), the other 5 mm over its top (0, 55, z2), z2 swept from 140 to
// 60 mm. The mean (0, 27.5, (155 + z2)/2) lies inside, nearest the side while z2 > 100 and the
// top after: lifted along the nearest skin's normal, frame by frame, the target jumps 39 mm at
// z2 = 100. Given the state of the frames before, it moves with the mean instead: the same
// targets up to the jump, then none moves more than 1 mm a step (the mean moves 0.5 mm), and
// every one lies outside at least half the offset.
TEST(GarmentStrings, CornerTargetsMoveWithTheirMeanWithoutJumps) {
    tapeline_test::GarmentTriMesh box;
    for (int k = 0; k < 8; ++k) {
        box.points.push_back(v3(k & 1 ? 300 : -300, k & 2 ? 50 : -50, k & 4 ? 150 : -150));
    }
    box.triangles = {{0, 2, 3}, {0, 3, 1}, {4, 5, 7}, {4, 7, 6}, {0, 1, 5}, {0, 5, 4},
                     {2, 6, 7}, {2, 7, 3}, {0, 4, 6}, {0, 6, 2}, {1, 3, 7}, {1, 7, 5}};
    ASSERT_GT(tapeline_test::signed_volume(box), 0);
    const tg::SignedDistanceGrid sdf(box.points, box.triangles);
    const double offset = 5;
    const auto string_to = [](const tg::Vec3& p) {  // a string whose middle is p
        tg::StringPath s;
        s.points = {tapeline::vec3::sub(p, v3(1, 0, 0)), tapeline::vec3::add(p, v3(1, 0, 0))};
        s.arc = {0, 2};
        return s;
    };
    tg::SewingTargetState state;
    std::optional<tg::Vec3> last, last_alone;
    double largest_move = 0, largest_move_alone = 0;
    for (double z2 = 140; z2 >= 60; z2 -= 1) {
        tg::SewingPlan plan;
        plan.pairs = {{0, 1, 0, 0}, {0, 2, 0, 0}};
        plan.strings = {string_to(v3(0, 0, 155)), string_to(v3(0, 55, z2))};
        const auto alone = tg::sewing_targets(plan, 1.0, 0.0, &sdf, offset);
        const auto kept = tg::sewing_targets(plan, 1.0, 0.0, &sdf, offset, &state);
        ASSERT_EQ(kept.size(), 3u);
        ASSERT_EQ(kept[0].vertex, 0u);
        const tg::Vec3 t = kept[0].target, a = alone[0].target;
        if (z2 > 100) {
            EXPECT_EQ(t, a) << z2;
        }
        const double d = sdf.exact_signed_distance(t, nullptr);
        EXPECT_GE(d, 0.5 * offset - 1e-9) << z2;
        EXPECT_LE(d, offset + 1e-9) << z2;
        if (last) {
            largest_move =
                std::max(largest_move, tapeline::vec3::norm(tapeline::vec3::sub(t, *last)));
            largest_move_alone = std::max(
                largest_move_alone, tapeline::vec3::norm(tapeline::vec3::sub(a, *last_alone)));
        }
        last = t;
        last_alone = a;
    }
    EXPECT_GT(largest_move_alone, 35.0);  // the jump, frame by frame
    EXPECT_LT(largest_move, 1.0);
}

// A capsule along z (radius 100 mm, its cylinder from z = −100 to 100, hemispheres beyond) with
// two flat sheets, one in front of it (y = +120) and one behind (y = −120), whose top edges
// (z = 160) are sewn together: the chord between a front and a back seam vertex runs through the
// capsule (as the chord of a shoulder seam runs through the shoulder). The strings must go over
// the top instead, and sewing must close the seam around the capsule with no cloth edge crossing
// it at any frame.
TEST(GarmentSewing, SeamAroundACylinderClosesAroundItNeverThroughIt) {
    const double R = 100, H = 100, y0 = 120, z_top = 160, off = 8;
    const auto body = capsule(R, H, 64, 16, 20);
    tg::ColliderOptions co;
    co.cell_mm = 4;
    const tg::SignedDistanceGrid sdf(body.points, body.triangles, co);
    const int nx = 12, nz = 18;
    const double cell = 15;  // sheets 180 mm wide (x), 270 mm tall (z up to z_top)
    tg::ClothModel cloth;
    for (int side = 0; side < 2; ++side) {
        const double y = side == 0 ? y0 : -y0;
        const tg::ClothModel g =
            cloth_grid(nx, nz, cell, v3(-90, y, z_top - nz * cell), v3(1, 0, 0), v3(0, 0, 1));
        const std::uint32_t base = std::uint32_t(cloth.positions.size());
        cloth.positions.insert(cloth.positions.end(), g.positions.begin(), g.positions.end());
        for (std::size_t f = 0; f < g.triangles.size(); ++f) {
            const auto& t = g.triangles[f];
            cloth.triangles.push_back({base + t[0], base + t[1], base + t[2]});
            cloth.rest_uv.push_back(g.rest_uv[f]);
            cloth.grain.push_back(g.grain[f]);
        }
    }
    const std::uint32_t n0 = std::uint32_t((nx + 1) * (nz + 1));
    tg::SewingPlan plan;
    for (int i = 0; i <= nx; ++i) {
        plan.pairs.push_back({grid_vertex(nx, i, nz), n0 + grid_vertex(nx, i, nz), 0, 0});
        plan.seam_of_pair.push_back(0);
    }
    // The test means something only if the chords do go through the capsule.
    const auto mid = tapeline::vec3::scale(
        tapeline::vec3::add(cloth.positions[plan.pairs[6].a], cloth.positions[plan.pairs[6].b]),
        0.5);
    ASSERT_LT(capsule_distance(R, H, mid), -10);
    tg::compute_strings(plan, cloth.positions, body.points, body.triangles, sdf, off);
    for (std::size_t k = 0; k < plan.strings.size(); ++k) {
        const tg::StringPath& s = plan.strings[k];
        for (std::size_t i = 1; i + 1 < s.points.size(); ++i) {
            EXPECT_NEAR(capsule_distance(R, H, s.points[i]), off, 1.0)
                << "string " << k << " point " << i << " is not lifted " << off << " mm";
        }
    }
    // The centre pair's string (plane x = 0): from the cloth vertex down to the lifted skin
    // nearest to it (towards the hemisphere's centre), then over the top at radius R + off, an
    // arc from the angle a above the horizontal on one side to the same angle on the other.
    const double a = std::atan2(z_top - H, y0);
    const double drop = std::hypot(y0, z_top - H) - (R + off);
    const double centre = 2 * drop + (R + off) * (M_PI - 2 * a);
    EXPECT_NEAR(plan.strings[6].length(), centre, 0.03 * centre);
    tg::FabricParams fabric;
    fabric.bending_un_m = 1;
    // The thickness must exceed the sagitta of a cloth edge over the body: edges of this sheet,
    // stretched up to 27 mm over the top, dip 27²/(8·108) ≈ 0.85 mm between their ends.
    fabric.thickness_mm = 2;
    tg::DrapeOptions opt;
    opt.gravity = {0, 0, 0};
    opt.self_collision = false;
    opt.substeps = 40;
    tg::DrapeSolver solver(cloth, fabric, opt, &sdf);
    tg::GarmentMesh g;
    g.triangles = cloth.triangles;
    g.uv = cloth.rest_uv;
    g.triangle_piece.assign(cloth.triangles.size(), 0);
    const int frames = 45;
    for (int f = 0; f < frames + 15; ++f) {
        const double sigma = std::min(1.0, double(f + 1) / frames);
        solver.set_attachments(tg::sewing_targets(plan, sigma, 1e-4));
        solver.step();
        g.positions = solver.positions();
        const auto q = tg::garment_quality(body.points, body.triangles, g, 0, 0);
        ASSERT_EQ(q.edges_crossing_body, 0u) << "frame " << f;
        ASSERT_EQ(q.vertices_inside_body, 0u) << "frame " << f;
    }
    double gap_max = 0;
    for (const auto& p : plan.pairs) {
        gap_max = std::max(gap_max, tapeline::vec3::norm(tapeline::vec3::sub(
                                        solver.positions()[p.a], solver.positions()[p.b])));
        // The seam lies over the top now (above the cylinder's end).
        EXPECT_GT(solver.positions()[p.a][2], H + 0.5 * R);
    }
    EXPECT_LT(gap_max, 1.0) << "the seam did not close";
}

TEST(GarmentQuality, CountsEdgesCrossingABodyAndVerticesInside) {
    const double R = 50, L = 200;
    const auto body = capped_cylinder(v3(0, 0, 0), R, L, 48, 8);
    // A 2-cell strip along x through the cylinder: its vertices at x = −80, −40... one of them at
    // x = 0 is inside (depth R = 50 from the surface... the nearest face is at distance ≈ R).
    tg::GarmentMesh g;
    g.positions = {v3(-80, 0, 0),  v3(0, 0, 0),  v3(80, 0, 0),
                   v3(-80, 0, 10), v3(0, 0, 10), v3(80, 0, 10)};
    g.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}, {1, 5, 4}};
    g.uv.assign(4, {tg::UV{0, 0}, tg::UV{1, 0}, tg::UV{0, 1}});
    g.triangle_piece.assign(4, 0);
    const auto q = tg::garment_quality(body.points, body.triangles, g, 0, 0);
    EXPECT_EQ(q.vertices_inside_body, 2u);
    EXPECT_NEAR(q.max_depth_mm, R, 0.01 * R);  // the faces' sagitta is 0.1 % of R at 48 slices
    // Edges crossing the cylinder's side: the four edges from x = ±80 to x = 0 (two per row and
    // the diagonals 0–4 and 1–5), each crossing once; the vertical edges 1–4 lie inside.
    EXPECT_EQ(q.edges_crossing_body, 6u);
    EXPECT_EQ(q.self_intersections, 0u);
}

// Two pieces crossing: piece "a" a 20 mm square in the plane y = 0 (split along x = z), piece
// "b" one triangle in the plane x = 2 standing through it. Two of b's edges pierce a's triangle
// on the side z > x, at (2, 0, 3) and (2, 0, 4.5); b's trace on y = 0 (z from 3 to 4.5 at x = 2)
// meets none of a's edges. Far from any body.
TEST(GarmentQuality, CountsAndLocatesSelfIntersectionsByPieces) {
    const auto body = capped_cylinder(v3(0, 0, 1000), 50, 100, 24, 4);
    tg::GarmentMesh g;
    g.positions = {v3(-10, 0, -10), v3(10, 0, -10), v3(10, 0, 10), v3(-10, 0, 10),
                   v3(2, -5, 3),    v3(2, 5, 3),    v3(2, 5, 6)};
    g.triangles = {{0, 1, 2}, {0, 2, 3}, {4, 5, 6}};
    g.uv.assign(3, {tg::UV{0, 0}, tg::UV{1, 0}, tg::UV{0, 1}});
    g.triangle_piece = {0, 0, 1};
    g.piece_names = {"a", "b"};
    const auto q = tg::garment_quality(body.points, body.triangles, g, 0, 0);
    EXPECT_EQ(q.edges_crossing_body, 0u);
    EXPECT_EQ(q.self_intersections, 2u);
    ASSERT_EQ(q.self_crossings_by_pieces.size(), 1u);
    EXPECT_EQ(q.self_crossings_by_pieces[0].first, "a / b");
    EXPECT_EQ(q.self_crossings_by_pieces[0].second, 2u);
    // The midpoints of the two crossing edges, (2, 0, 3) and (2, 0, 4.5), in either order.
    ASSERT_EQ(q.self_crossing_points.size(), 2u);
    double z_sum = 0;
    for (const auto& p : q.self_crossing_points) {
        EXPECT_NEAR(p[0], 2, 1e-12);
        EXPECT_NEAR(p[1], 0, 1e-12);
        z_sum += p[2];
    }
    EXPECT_NEAR(z_sum, 7.5, 1e-12);
    // Moved 1 mm beside a (x = 11), b crosses nothing.
    for (std::size_t i = 4; i < 7; ++i) {
        g.positions[i][0] = 11;
    }
    const auto apart = tg::garment_quality(body.points, body.triangles, g, 0, 0);
    EXPECT_EQ(apart.self_intersections, 0u);
    EXPECT_TRUE(apart.self_crossings_by_pieces.empty());
}

// A seam pulled shut across a triangle welds two of its corners: the triangle collapses to a
// segment. The crossing test never reports one: CGAL's segment–triangle test is undefined for it,
// and compiled without its checks it reported an edge 2 mm from the collapsed triangle (0, 0, 1)
// as crossing it (two such on a draped pencil dress failed its self-intersection gate). A
// triangle of three distinct collinear corners crosses nothing either (before: both edges of
// 8-9-10 that pass beside the line 5-7); real crossings beside them still count.
TEST(GarmentQuality, CollapsedTrianglesCrossNothing) {
    const auto body = capped_cylinder(v3(0, 0, -5000), 50, 100, 24, 4);
    tg::GarmentMesh g;
    g.positions = {
        v3(0, 0, 200),    v3(10, 10, 210),                    // 0, 1: collapsed
        v3(2, 8, 203),    v3(8, 2, 203),   v3(5, 5, 180),     // 2-4: 2 mm from its line
        v3(0, 0, 100),    v3(10, 0, 100),  v3(20, 0, 100),    // 5-7: collinear
        v3(10, -5, 95),   v3(10, 5, 95),   v3(10, 0, 105),    // 8-10: x = 10, round (10, 0, 100)
        v3(-10, 0, -210), v3(30, 0, -210), v3(-10, 0, -170),  // 11-13: y = 0
        v3(0, -5, -205),  v3(0, 5, -205),  v3(0, 5, -195)};   // 14-16: x = 0
    g.triangles = {{0, 0, 1}, {2, 3, 4}, {5, 6, 7}, {8, 9, 10}, {11, 12, 13}, {14, 15, 16}};
    g.uv.assign(g.triangles.size(), {tg::UV{0, 0}, tg::UV{1, 0}, tg::UV{0, 1}});
    g.triangle_piece.assign(g.triangles.size(), 0);
    // Counted: the collinear triangle's three edges on 8-10 (5-7 through (10, 0, 100), 5-6 and
    // 6-7 touching it there); 14-15 through (0, 0, -205) and 14-16 through (0, 0, -200), both
    // inside 11-13. Not counted: anything on the collapsed or the collinear triangle.
    std::vector<std::size_t> crossed;
    tg::internal::for_each_edge_triangle_crossing(
        g.positions, g.triangles,
        [&](std::uint32_t, std::uint32_t, std::size_t t) { crossed.push_back(t); });
    EXPECT_EQ(crossed, (std::vector<std::size_t>{3, 3, 3, 4, 4}));
    const auto q = tg::garment_quality(body.points, body.triangles, g, 0, 0);
    EXPECT_EQ(q.self_intersections, 5u);
}

// Flat cloth is the common case of a drape (a back panel, a skirt) and the hard case for the
// crossing test: every edge lies in the plane of its neighbours' triangles. A 60 × 60 grid of
// 20 mm cells in a tilted plane far from the origin, and the same grid folded along a line into
// a 90° dihedral (two flat halves): no edge crosses a triangle.
TEST(GarmentQuality, FlatAndFoldedClothHasNoSelfIntersection) {
    const auto body = capped_cylinder(v3(0, 0, -5000), 50, 100, 24, 4);
    const double c1 = std::cos(0.3), s1 = std::sin(0.3), c2 = std::cos(1.1), s2 = std::sin(1.1);
    const tg::Vec3 u = v3(c1, s1 * s2, s1 * c2);  // two orthonormal directions of a tilted plane
    const tg::Vec3 w = v3(0, c2, -s2);
    for (const bool folded : {false, true}) {
        const int n = 60;
        const tg::ClothModel grid = cloth_grid(n, n, 20, v3(0, 0, 0), v3(1, 0, 0), v3(0, 1, 0));
        tg::GarmentMesh g;
        const tg::Vec3 normal = tapeline::vec3::cross(u, w);
        for (const tg::Vec3& p : grid.positions) {
            // Folded: the half beyond x = 600 turns up along the plane's normal.
            const double a = folded && p[0] > 600 ? 600 : p[0];
            const double up = folded && p[0] > 600 ? p[0] - 600 : 0;
            g.positions.push_back(v3(313.7 + a * u[0] + p[1] * w[0] + up * normal[0],
                                     1103.3 + a * u[1] + p[1] * w[1] + up * normal[1],
                                     151.9 + a * u[2] + p[1] * w[2] + up * normal[2]));
        }
        g.triangles = grid.triangles;
        g.uv = grid.rest_uv;
        g.triangle_piece.assign(g.triangles.size(), 0);
        const auto q = tg::garment_quality(body.points, body.triangles, g, 0, 0);
        EXPECT_EQ(q.self_intersections, 0u) << (folded ? "folded" : "flat");
    }
}

// The stretch split between triangles on the body and off it. Cylinder of radius R along z;
// separate right triangles in planes y = const parallel to its side: those at y = R + 2 (about
// 2 mm off the skin) are stretched 1.2 along x against their pattern, those at y = R + 40 are
// not. With a 5 mm band the on-body p95 is exactly 1.2, the off-body one 1; a band below 2 mm
// puts every triangle off the body, and no band leaves the split out.
TEST(GarmentQuality, SplitsStretchOnAndOffTheBody) {
    const double R = 50, L = 400;
    const auto body = capped_cylinder(v3(0, 0, 0), R, L, 96, 8);
    tg::GarmentMesh g;
    const int on_count = 6, off_count = 14;
    for (int i = 0; i < on_count + off_count; ++i) {
        const bool on = i < on_count;
        const double y = on ? R + 2 : R + 40, z0 = -150 + 15 * i, s = on ? 1.2 : 1.0;
        const std::uint32_t b = std::uint32_t(g.positions.size());
        // A 10 × 10 mm right triangle in the plane y = const, its pattern 10/s wide along x.
        g.positions.push_back(v3(-5, y, z0));
        g.positions.push_back(v3(5, y, z0));
        g.positions.push_back(v3(-5, y, z0 + 10));
        g.triangles.push_back({b, b + 1, b + 2});
        g.uv.push_back({tg::UV{0, 0}, tg::UV{10 / s, 0}, tg::UV{0, 10}});
        g.triangle_piece.push_back(0);
    }
    const auto q = tg::garment_quality(body.points, body.triangles, g, 0, 0, 5.0);
    EXPECT_NEAR(q.triangles_on_body_percent, 100.0 * on_count / (on_count + off_count), 1e-9);
    EXPECT_NEAR(q.stretch_p95_on_body, 1.2, 1e-12);
    EXPECT_NEAR(q.stretch_p95_off_body, 1.0, 1e-12);
    EXPECT_NEAR(q.stretch_max, 1.2, 1e-12);
    const auto tight = tg::garment_quality(body.points, body.triangles, g, 0, 0, 1.5);
    EXPECT_EQ(tight.triangles_on_body_percent, 0.0);
    EXPECT_NEAR(tight.stretch_p95_off_body, 1.2, 1e-12);  // 6 of 20 above the 95th percentile
    const auto none = tg::garment_quality(body.points, body.triangles, g, 0, 0);
    EXPECT_EQ(none.triangles_on_body_percent, 0.0);
    EXPECT_EQ(none.stretch_p95_on_body, 1.0);
    EXPECT_EQ(none.stretch_p95_off_body, 1.0);
}

// set_damping acts from the next step: a free triangle falling under gravity reaches the discrete
// terminal velocity of v <- v·exp(-k·h) + g·h, i.e. g·h / (1 - exp(-k·h)), and a bad rate is
// refused.
TEST(GarmentDamping, RaisedDampingReachesTheDiscreteTerminalVelocity) {
    tg::ClothModel m;
    m.positions = {v3(0, 0, 0), v3(10, 0, 0), v3(0, 0, 10)};
    m.triangles = {{0, 1, 2}};
    m.rest_uv = {{tg::UV{0, 0}, tg::UV{10, 0}, tg::UV{0, 10}}};
    m.grain = {tg::UV{0, 1}};
    tg::DrapeOptions o;
    o.damping_per_second = 0;
    o.threads = 1;
    tg::DrapeSolver solver(m, tg::FabricParams{}, o);
    for (int f = 0; f < 5; ++f) {
        solver.step();
    }
    const double k = 6;
    solver.set_damping(k);
    for (int f = 0; f < 90; ++f) {  // 3 s: exp(-18) of the start is left
        solver.step();
    }
    const double h = o.frame_seconds / o.substeps;
    const double terminal = -9810 * h / (1 - std::exp(-k * h));
    for (const tg::Vec3& v : solver.velocities()) {
        EXPECT_NEAR(v[1], terminal, 1e-6 * std::abs(terminal));
        EXPECT_NEAR(v[0], 0, 1e-9);
    }
    EXPECT_THROW(solver.set_damping(-1), tapeline::InvalidInput);
    EXPECT_THROW(solver.set_damping(std::nan("")), tapeline::InvalidInput);
}

namespace {
// The exact signed distance of a sphere.
struct SphereCollider : tg::Collider {
    double r;
    explicit SphereCollider(double radius) : r(radius) {}
    double signed_distance(const tg::Vec3& p, tg::Vec3* gradient) const override {
        const double n = std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        if (gradient) {
            *gradient = n > 0 ? tg::Vec3{p[0] / n, p[1] / n, p[2] / n} : tg::Vec3{0, 1, 0};
        }
        return n - r;
    }
};
}  // namespace

// The cloth keeps DrapeOptions::body_clearance_mm from the collider (by default the fabric's
// thickness): a square dropped on an exact sphere rests with its closest vertex at the clearance.
TEST(GarmentClearance, ClothRestsAtTheClearanceFromTheCollider) {
    const SphereCollider sphere(60);
    for (const double clearance : {0.0, 3.0}) {
        tg::ClothModel m =
            tapeline_test::cloth_grid(12, 12, 10, v3(-60, 75, -60), v3(1, 0, 0), v3(0, 0, 1));
        tg::DrapeOptions o;
        o.body_clearance_mm = clearance;
        o.self_collision = false;
        tg::FabricParams f;
        f.thickness_mm = 1;
        tg::DrapeSolver solver(m, f, o, &sphere);
        for (int k = 0; k < 45; ++k) {
            solver.step();
        }
        double closest = 1e300;
        for (const tg::Vec3& p : solver.positions()) {
            closest = std::min(closest, sphere.signed_distance(p, nullptr));
        }
        const double expected = clearance > 0 ? clearance : f.thickness_mm;
        EXPECT_NEAR(closest, expected, 0.05) << "clearance option " << clearance;
    }
    tg::DrapeOptions bad;
    bad.body_clearance_mm = -1;
    EXPECT_THROW(
        tg::DrapeSolver(tapeline_test::cloth_grid(2, 2, 10, v3(0, 0, 0), v3(1, 0, 0), v3(0, 0, 1)),
                        tg::FabricParams{}, bad),
        tapeline::InvalidInput);
}

TEST(GarmentFabric, CatalogueAndFileRefusals) {
    EXPECT_EQ(tg::fabric_from("denim").name, "denim");
    try {
        tg::fabric_from("tweed");
        FAIL() << "an unknown fabric was accepted";
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("unknown fabric 'tweed'"), std::string::npos);
    }
    const tapeline_test::TempDir tmp;
    const std::string path = tmp.file("fabric_bad.json");
    { std::ofstream(path) << R"({"density_g_m2": -3})"; }
    try {
        tg::fabric_from(path);
        FAIL() << "a negative density was accepted";
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("\"density_g_m2\" must be a positive"),
                  std::string::npos);
    }
    { std::ofstream(path) << R"({"name": "mine", "bending_un_m": 3, "colour": 1})"; }
    try {
        tg::fabric_from(path);
        FAIL() << "an unknown field was accepted";
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("unknown field \"colour\""), std::string::npos);
    }
    { std::ofstream(path) << R"({"name": "mine", "bending_un_m": 3})"; }
    const tg::FabricParams f = tg::fabric_from(path);
    EXPECT_EQ(f.name, "mine");
    EXPECT_EQ(f.bending_un_m, 3);
}
