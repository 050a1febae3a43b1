// DrapeSolver against analytic truth (free fall, catenary), contact with analytic solids (sphere,
// thin cylinder at a large step), stitches and attachments, determinism across thread counts,
// blow-up detection and the refusals of bad input.
#include <tapeline/draw/mesh_render.h>
#include <tapeline/garment/collider.h>
#include <tapeline/garment/crossings.h>
#include <tapeline/garment/drape_solver.h>
#include <tapeline/garment/waistband.h>

#include <tapeline_test/expect.h>

#include <gtest/gtest.h>
#include <tapeline_test/garment_shapes.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <cmath>
#include <functional>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace {

using tapeline_test::message_of;

using tapeline::garment::Attachment;
using tapeline::garment::ClothModel;
using tapeline::garment::ColliderOptions;
using tapeline::garment::DrapeOptions;
using tapeline::garment::DrapeSolver;
using tapeline::garment::FabricParams;
using tapeline::garment::SignedDistanceGrid;
using tapeline::garment::StepReport;
using tapeline::garment::Stitch;
using tapeline::garment::Vec3;
using tapeline_test::cloth_grid;
using tapeline_test::grid_vertex;

double distance(const Vec3& a, const Vec3& b) {
    return std::sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                     (a[2] - b[2]) * (a[2] - b[2]));
}

// A horizontal square cloth (in the x–z plane) centred on (cx, y, cz).
ClothModel horizontal_square(int cells, double cell, double cx, double y, double cz) {
    const double half = cells * cell / 2;
    return cloth_grid(cells, cells, cell, {cx - half, y, cz - half}, {1, 0, 0}, {0, 0, 1});
}

// Appends cloth b to cloth a (two separate pieces in one model).
ClothModel join(ClothModel a, const ClothModel& b) {
    const auto offset = static_cast<std::uint32_t>(a.positions.size());
    a.positions.insert(a.positions.end(), b.positions.begin(), b.positions.end());
    for (auto t : b.triangles) {
        a.triangles.push_back({t[0] + offset, t[1] + offset, t[2] + offset});
    }
    a.rest_uv.insert(a.rest_uv.end(), b.rest_uv.begin(), b.rest_uv.end());
    a.grain.insert(a.grain.end(), b.grain.begin(), b.grain.end());
    return a;
}

// A strip of nx × ny cells along x, laid as a V of the given length between two supports `span`
// apart (each half straight, so every triangle is at rest), its end columns pinned.
ClothModel v_strip(double length, double span, double cell, int nx, int ny) {
    ClothModel strip = cloth_grid(nx, ny, cell, {0, 0, -cell}, {1, 0, 0}, {0, 0, 1});
    const double drop = std::sqrt((length / 2) * (length / 2) - (span / 2) * (span / 2));
    for (Vec3& p : strip.positions) {
        const double s = p[0];
        const double along = s <= length / 2 ? s : length - s;
        p[0] = s <= length / 2 ? along * span / length : span - along * span / length;
        p[1] = -along * 2 * drop / length;
    }
    strip.pinned.assign(strip.positions.size(), 0);
    for (int j = 0; j <= ny; ++j) {
        strip.pinned[grid_vertex(nx, 0, j)] = 1;
        strip.pinned[grid_vertex(nx, nx, j)] = 1;
    }
    return strip;
}

// A stiff fabric without bending: the strip hangs as a chain.
FabricParams chain_fabric() {
    FabricParams fabric;
    fabric.stretch_warp_n_m = fabric.stretch_weft_n_m = 1e5;
    fabric.bending_un_m = 0;
    return fabric;
}

// A soft fabric without bending (20 N/m stretch, 5 N/m shear): hanging sheets stretch visibly.
FabricParams soft_fabric() {
    FabricParams fabric;
    fabric.stretch_warp_n_m = fabric.stretch_weft_n_m = 20;
    fabric.shear_n_m = 5;
    fabric.bending_un_m = 0;
    return fabric;
}

// How far the centre line (row 1) of a v_strip hangs below its supports, mm.
double centre_sag(const std::vector<Vec3>& x, int nx) {
    double lowest = 0;
    for (int i = 0; i <= nx; ++i) {
        lowest = std::min(lowest, x[grid_vertex(nx, i, 1)][1]);
    }
    return -lowest;
}

// The catenary's a from L = 2a·sinh(D/2a), by bisection (the right side decreases in a).
double catenary_parameter(double length, double span) {
    double lo = 1, hi = 1e5;
    for (int k = 0; k < 200; ++k) {
        const double a = 0.5 * (lo + hi);
        (2 * a * std::sinh(span / (2 * a)) > length ? lo : hi) = a;
    }
    return 0.5 * (lo + hi);
}

// Free fall under symplectic Euler sub-steps: after N sub-steps of h from rest the drop is
// g·h²·N(N+1)/2 = g·t²/2 + g·t·h/2 exactly (the O(h) term is the scheme's known bias). The cloth
// is unstrained, so its constraints move nothing beyond rounding (1e-9 mm).
TEST(GarmentDrapeSolver, FreeFallMatchesTheDiscreteParabola) {
    DrapeOptions options;
    options.damping_per_second = 0;
    options.self_collision = false;
    DrapeSolver solver(horizontal_square(10, 10, 0, 0, 0), FabricParams{}, options);
    const double g = 9810, h = options.frame_seconds / options.substeps;
    StepReport report;
    for (int f = 0; f < 15; ++f) {
        report = solver.step();
    }
    const double n = 15.0 * options.substeps, t = 15 * options.frame_seconds;
    const double expected = g * h * h * n * (n + 1) / 2;
    EXPECT_NEAR(expected - g * t * t / 2, g * t * h / 2, 1e-9);
    for (std::size_t i = 0; i < solver.positions().size(); ++i) {
        const Vec3& p = solver.positions()[i];
        const Vec3& p0 = solver.model().positions[i];
        ASSERT_NEAR(p0[1] - p[1], expected, 1e-9) << "vertex " << i;
        ASSERT_NEAR(p[0], p0[0], 1e-9);
        ASSERT_NEAR(p[2], p0[2], 1e-9);
        ASSERT_NEAR(solver.velocities()[i][1], -g * t, 1e-6);
    }
    EXPECT_EQ(report.frame, 15u);
    EXPECT_NEAR(report.simulated_seconds, t, 1e-12);
    EXPECT_DOUBLE_EQ(report.moving_fraction, 1.0);
    EXPECT_EQ(report.contacts, 0u);
    // Kinetic energy: ½·M·(g·t)², M = area × density.
    const double mass = 0.1 * 0.1 * 0.180;  // kg
    EXPECT_NEAR(report.kinetic_energy_j, 0.5 * mass * (g * t * 1e-3) * (g * t * 1e-3), 1e-9);
}

// Catenary: a narrow, nearly inextensible strip without bending stiffness hung from both ends
// settles to y = a·cosh(x/a) with L = 2a·sinh(D/2a). The sag is measured on the strip's centre
// line. XPBD with one pass per sub-step leaves a hanging chain of N elements stretched by about
// g·h²·N²/2 (each hard constraint acts like a spring of stiffness m/h²): with N = 30 and 60
// sub-steps per frame that is 0.3 mm, 0.1 % of the length, i.e. about 0.15 % of the sag (the sag
// moves 1.5 times as much as the length relative to the slack); 1 % leaves room for the strip's
// 20 mm width.
TEST(GarmentDrapeSolver, HangingStripSettlesToTheCatenary) {
    const double length = 300, span = 200, cell = 10;
    const int nx = 30, ny = 2;
    ClothModel strip = v_strip(length, span, cell, nx, ny);
    const FabricParams fabric = chain_fabric();
    DrapeOptions options;
    options.self_collision = false;
    options.damping_per_second = 4;  // the rest shape does not depend on damping
    options.substeps = 60;
    DrapeSolver solver(strip, fabric, options);
    StepReport report;
    for (int f = 0; f < 240; ++f) {
        report = solver.step();
    }
    EXPECT_LT(report.max_move_mm, 0.01);
    const double a = catenary_parameter(length, span);
    const double sag = a * (std::cosh(span / (2 * a)) - 1);
    const double hang = centre_sag(solver.positions(), nx);
    EXPECT_NEAR(hang, sag, 0.01 * sag) << "catenary parameter a = " << a;
    RecordProperty("sag_mm", std::to_string(hang));
    RecordProperty("catenary_sag_mm", std::to_string(sag));
}

// A square dropped on a sphere: no vertex inside (the contact pass runs last, leaving every
// vertex at least the thickness (1 mm) from the mesh by the grid's measure; the mesh is inside
// the sphere by its sagitta ≤ 0.24 mm and the grid errs by ≤ 0.08 mm, so the analytic distance
// stays above 1 − 0.32 mm; we require ≥ 0.5 mm) and it comes to rest.
TEST(GarmentDrapeSolver, SquareDroppedOnASphereRestsOutsideIt) {
    const double radius = 100;
    const auto sphere = tapeline_test::uv_sphere({0, 0, 0}, radius, 64, 32);
    const SignedDistanceGrid body(sphere.points, sphere.triangles, ColliderOptions{5});
    DrapeSolver solver(horizontal_square(30, 10, 0, radius + 20, 0), FabricParams{}, DrapeOptions{},
                       &body);
    StepReport report;
    int still = 0;
    for (int f = 0; f < 300 && still < 10; ++f) {
        report = solver.step();
        still = report.moving_fraction == 0 ? still + 1 : 0;
    }
    EXPECT_EQ(still, 10) << "still moving after " << report.frame << " frames: fraction "
                         << report.moving_fraction;
    EXPECT_GT(report.contacts, 50u);
    double closest = 1e300;
    for (const Vec3& p : solver.positions()) {
        closest = std::min(closest, distance(p, {0, 0, 0}) - radius);
    }
    EXPECT_GE(closest, 0.5);
    RecordProperty("frames_to_rest", std::to_string(report.frame));
}

// A cloth falling 500 mm onto a horizontal cylinder of radius 20 mm, with five times the usual
// frame step: at impact each sub-step moves it more than the cylinder's diameter, so only the
// swept test keeps it from tunnelling. Through the impact frame and the next, no vertex may be
// inside (grid error ≤ 25/8·2/20 ≈ 0.3 mm and sagitta 0.2 mm, against a 1 mm thickness), and at
// the impact frame the column that fell onto the axis must lie on top of the cylinder. (Later
// the cloth may slide off sideways: at h = 1/60 s one pass per sub-step makes it very stretchy,
// see the catenary test; that is not tunnelling.)
TEST(GarmentDrapeSolver, ThinCylinderAtFiveTimesTheFrameStepIsNotTunnelled) {
    const double radius = 20, length = 400, height = 500;
    const auto cylinder = tapeline_test::capped_cylinder({0, 0, 0}, radius, length, 32, 8);
    const SignedDistanceGrid body(cylinder.points, cylinder.triangles, ColliderOptions{5});
    DrapeOptions options;
    options.frame_seconds *= 5;
    const double h = options.frame_seconds / options.substeps;
    ASSERT_GT(std::sqrt(2 * 9810 * (height - radius - 1)) * h, 2 * radius);
    const int nx = 16, nz = 40;
    const ClothModel cloth = cloth_grid(nx, nz, 5, {-40, height, -100}, {1, 0, 0}, {0, 0, 1});
    DrapeSolver solver(cloth, FabricParams{}, options, &body);
    int impact = 0;
    for (int f = 1; f <= 12 && (impact == 0 || f <= impact + 1); ++f) {
        const StepReport report = solver.step();
        if (impact == 0 && report.contacts > 0) {
            impact = f;
            for (int j = 0; j <= nz; ++j) {
                const Vec3& p = solver.positions()[grid_vertex(nx, nx / 2, j)];
                ASSERT_GT(p[1], radius) << "the centre column went through the cylinder";
            }
        }
        for (std::size_t i = 0; i < solver.positions().size(); ++i) {
            const Vec3& p = solver.positions()[i];
            ASSERT_GE(tapeline_test::cylinder_signed_distance({0, 0, 0}, radius, length, p), 0.4)
                << "vertex " << i << " inside the cylinder after frame " << f;
        }
    }
    EXPECT_EQ(impact, 2);  // 500 mm takes 0.32 s: the second frame
}

// Same run with 1 and 2 threads: every position bit-identical.
// Two strips crossing at right angles, the lower one held, the upper one falling onto it. Their
// vertices are placed so that none lies over the other strip: only edges meet, like an X, where
// they cross. Vertex–triangle pairs alone let the upper strip fall through; with the edge–edge
// pairs it rests on the lower one.
TEST(GarmentDrapeSolver, EdgesCrossingLikeAnXDoNotPassThrough) {
    // Lower: x from -90 to 90 (nodes at ±30, ±90), z from -20 to 20, held at y = 0.
    ClothModel lower = cloth_grid(3, 1, 60, {-90, 0, -20}, {1, 0, 0}, {0, 0, 1});
    for (Vec3& p : lower.positions) {
        p[2] = p[2] < 0 ? p[2] : 20;  // the second row at z = 20 (cells 60 × 40)
    }
    for (auto& uv : lower.rest_uv) {
        for (auto& c : uv) {
            c[1] = c[1] > 0 ? 40 : 0;
        }
    }
    // Upper: z from -90 to 90 (nodes at ±30, ±90), x from -20 to 20, 5 mm above.
    ClothModel upper = cloth_grid(3, 1, 60, {-20, 5, -90}, {0, 0, 1}, {1, 0, 0});
    for (Vec3& p : upper.positions) {
        p[0] = p[0] < 0 ? p[0] : 20;
    }
    for (auto& uv : upper.rest_uv) {
        for (auto& c : uv) {
            c[1] = c[1] > 0 ? 40 : 0;
        }
    }
    ClothModel both = join(lower, upper);
    both.pinned.assign(both.positions.size(), 0);
    for (std::size_t i = 0; i < lower.positions.size(); ++i) {
        both.pinned[i] = 1;
    }
    const std::size_t offset = lower.positions.size();
    for (std::size_t i = 0; i < both.positions.size(); ++i) {
        const Vec3& p = both.positions[i];
        const bool over_the_other =
            i < offset ? std::abs(p[0]) < 20 : std::abs(p[2]) < 20;  // inside the other's span
        ASSERT_FALSE(over_the_other) << "vertex " << i;
    }
    // The upper strip's four inner vertices (z = ±30), after a second.
    auto lowest_inner = [&](bool edge_edge) {
        DrapeOptions options;
        options.edge_edge_collision = edge_edge;
        // The pairs alone: with 60 mm cells against 1 mm of thickness a few edges still end a
        // frame through the other strip's triangles (4-8 from the sixth frame on), and the
        // untangling, which rests the contacts of the vertices on crossings for a frame, then
        // lets this strip fall through (garment/README.md, limits).
        options.untangle = false;
        DrapeSolver solver(both, FabricParams{}, options);
        for (int f = 0; f < 30; ++f) {
            solver.step();
        }
        double lowest = 1e9;
        for (std::size_t i = offset; i < both.positions.size(); ++i) {
            if (std::abs(both.positions[i][2]) < 40) {
                lowest = std::min(lowest, solver.positions()[i][1]);
            }
        }
        return lowest;
    };
    EXPECT_LT(lowest_inner(false), -1000);  // fell through (free fall: 4.9 m in a second)
    const double thickness = FabricParams{}.thickness_mm;
    EXPECT_GT(lowest_inner(true), 0.0);              // held above the lower strip...
    EXPECT_LT(lowest_inner(true), 5.0 + thickness);  // ...and resting on it
}

// Cloth cut through cloth: a sheet with a round bump that pokes 7.5 mm through a flat sheet above
// it (the two meet along a closed curve of radius 15 mm). The bump is the sheet's rest shape (each
// triangle's rest triangle is its own 3D triangle; no bending), so nothing but the untangling can
// take it back through: the vertex–triangle contacts keep every vertex on the side it starts on.
// Untangling must move the bump down against the flat sheet (a move the other way fails the
// test). Crossings are counted independently of the solver (CGAL's exact predicates), and the
// solver's own count at the first frame's start must equal that count.
std::size_t exact_crossings(const std::vector<Vec3>& x,
                            const std::vector<tapeline::garment::Tri>& t) {
    std::size_t n = 0;
    tapeline::garment::internal::for_each_edge_triangle_crossing(
        x, t, [&](std::uint32_t, std::uint32_t, std::size_t) { ++n; });
    return n;
}

ClothModel bump_through_sheet() {
    ClothModel flat = horizontal_square(12, 10, 0, 2.5, 0);
    ClothModel bump = horizontal_square(8, 10, 3, -5, 2);  // off-centre: no symmetric ties
    for (Vec3& p : bump.positions) {
        const double r = std::hypot(p[0] - 3, p[2] - 2);
        p[1] += 15 * std::max(0.0, 1 - r / 30);
    }
    // The bump at rest: each rest triangle congruent to its 3D triangle, with the grid's
    // orientation.
    for (std::size_t t = 0; t < bump.triangles.size(); ++t) {
        const auto& tv = bump.triangles[t];
        Vec3 e1, e2;
        for (int k = 0; k < 3; ++k) {
            e1[k] = bump.positions[tv[1]][k] - bump.positions[tv[0]][k];
            e2[k] = bump.positions[tv[2]][k] - bump.positions[tv[0]][k];
        }
        const double l1 = std::sqrt(e1[0] * e1[0] + e1[1] * e1[1] + e1[2] * e1[2]);
        const double along = (e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2]) / l1;
        const double l2sq = e2[0] * e2[0] + e2[1] * e2[1] + e2[2] * e2[2];
        const auto& uv = bump.rest_uv[t];
        const double side = (uv[1][0] - uv[0][0]) * (uv[2][1] - uv[0][1]) -
                                        (uv[1][1] - uv[0][1]) * (uv[2][0] - uv[0][0]) >
                                    0
                                ? 1.0
                                : -1.0;
        bump.rest_uv[t] = {{{0, 0}, {l1, 0}, {along, side * std::sqrt(l2sq - along * along)}}};
    }
    return join(flat, bump);
}

TEST(GarmentDrapeSolver, UntanglingPullsABumpBackThroughTheSheetItCut) {
    const ClothModel cloth = bump_through_sheet();
    const std::size_t at_start = exact_crossings(cloth.positions, cloth.triangles);
    ASSERT_GT(at_start, 8u);
    FabricParams fabric;
    fabric.bending_un_m = 0;
    auto run = [&](bool untangle, int threads, std::size_t* first_count) {
        DrapeOptions options;
        options.gravity = {0, 0, 0};
        options.untangle = untangle;
        options.threads = threads;
        DrapeSolver solver(cloth, fabric, options);
        for (int f = 0; f < 60; ++f) {
            const StepReport r = solver.step();
            if (f == 0 && first_count) {
                *first_count = r.cloth_crossings;
            }
        }
        return solver.positions();
    };
    std::size_t first = 0;
    const auto untangled = run(true, 1, &first);
    EXPECT_EQ(first, at_start);  // the solver's search finds exactly what the exact count finds
    EXPECT_EQ(exact_crossings(untangled, cloth.triangles), 0u);
    const auto kept = run(false, 1, nullptr);
    EXPECT_GT(exact_crossings(kept, cloth.triangles), at_start / 2);  // contacts alone keep the cut
    // Deterministic whatever the thread count.
    const auto two = run(true, 2, nullptr);
    for (std::size_t i = 0; i < untangled.size(); ++i) {
        ASSERT_EQ(untangled[i], two[i]) << "vertex " << i;
    }
}

TEST(GarmentDrapeSolver, BitIdenticalForAnyThreadCount) {
    const auto sphere = tapeline_test::uv_sphere({0, 0, 0}, 80, 48, 24);
    const SignedDistanceGrid body(sphere.points, sphere.triangles, ColliderOptions{5});
    std::vector<std::vector<Vec3>> results;
    std::vector<std::size_t> self_contacts;
    for (int threads : {1, 2}) {
        DrapeOptions options;
        options.threads = threads;
        // 3721 vertices, 7200 triangles: every parallel path runs in several blocks.
        DrapeSolver solver(horizontal_square(60, 4, 0, 90, 0), FabricParams{}, options, &body);
        std::size_t most_self = 0;
        for (int f = 0; f < 12; ++f) {
            most_self = std::max(most_self, solver.step().self_contacts);
        }
        results.push_back(solver.positions());
        self_contacts.push_back(most_self);
    }
    ASSERT_EQ(results[0].size(), results[1].size());
    for (std::size_t i = 0; i < results[0].size(); ++i) {
        ASSERT_EQ(results[0][i], results[1][i]) << "vertex " << i;
    }
    EXPECT_EQ(self_contacts[0], self_contacts[1]);
    EXPECT_GT(self_contacts[0], 0u);  // the self-collision path ran too
}

// Tethers against the softness of XPBD: a 400 mm strip of 40 elements hangs from its pinned top
// row with 10 sub-steps per frame. Without tethers it stretches by about g·h²·N²/2 (87 mm at
// h = 1/300 s) — more than 5 % end to end. With tether_stretch 1.02 every vertex in row i stays
// within 1.02·i·cell of the top vertex of its column (its nearest anchor over the rest edges,
// straight up the column); the tether acts last in the pass here (no collider), so the bound
// holds to rounding. Hanging under gravity the strip is still stretched, not compressed.
TEST(GarmentDrapeSolver, TethersBoundTheStretchOfHangingCloth) {
    const int nx = 40, ny = 3;
    const double cell = 10;
    ClothModel strip = cloth_grid(nx, ny, cell, {0, 0, 0}, {0, -1, 0}, {0, 0, 1});
    strip.pinned.assign(strip.positions.size(), 0);
    for (int j = 0; j <= ny; ++j) {
        strip.pinned[grid_vertex(nx, 0, j)] = 1;
    }
    FabricParams fabric;
    fabric.bending_un_m = 0;
    double end_to_end[2] = {0, 0};
    for (const double tether : {0.0, 1.02}) {
        DrapeOptions options;
        options.self_collision = false;
        options.damping_per_second = 4;
        options.tether_stretch = tether;
        DrapeSolver solver(strip, fabric, options);
        StepReport report;
        for (int f = 0; f < 90; ++f) {
            report = solver.step();
        }
        const auto& x = solver.positions();
        double longest = 0;
        for (int j = 0; j <= ny; ++j) {
            const Vec3& top = x[grid_vertex(nx, 0, j)];
            for (int i = 1; i <= nx; ++i) {
                const double d = distance(x[grid_vertex(nx, i, j)], top);
                if (tether > 0) {
                    ASSERT_LE(d, tether * i * cell * (1 + 1e-12)) << "row " << i << " column " << j;
                }
            }
            longest = std::max(longest, distance(x[grid_vertex(nx, nx, j)], top) / (nx * cell));
        }
        end_to_end[tether > 0] = longest;
        EXPECT_EQ(report.tether_anchors, tether > 0 ? std::size_t(ny + 1) : 0u);
    }
    EXPECT_GT(end_to_end[0], 1.05) << "the solver alone is expected to be soft here";
    EXPECT_LE(end_to_end[1], 1.02 * (1 + 1e-12));
    EXPECT_GT(end_to_end[1], 1.0);
}

// reset() brings back the initial state, and the rerun reproduces the first run exactly.
TEST(GarmentDrapeSolver, ResetReplaysTheSameRun) {
    DrapeSolver solver(horizontal_square(8, 10, 0, 0, 0), FabricParams{}, DrapeOptions{});
    for (int f = 0; f < 5; ++f) {
        solver.step();
    }
    const std::vector<Vec3> first = solver.positions();
    solver.reset();
    EXPECT_EQ(solver.positions(), solver.model().positions);
    for (const Vec3& v : solver.velocities()) {
        EXPECT_EQ(v, (Vec3{0, 0, 0}));
    }
    StepReport report;
    for (int f = 0; f < 5; ++f) {
        report = solver.step();
    }
    EXPECT_EQ(report.frame, 5u);
    EXPECT_EQ(solver.positions(), first);
}

TEST(GarmentDrapeSolver, BlowUpThrowsNamingTheFrame) {
    {  // a speed limit every falling cloth exceeds within the first frame
        DrapeOptions options;
        options.max_speed_mm_s = 100;
        DrapeSolver solver(horizontal_square(4, 10, 0, 0, 0), FabricParams{}, options);
        EXPECT_THROW(solver.step(), tapeline::SolverFailure);
        solver.reset();
        const std::string message = message_of([&] { solver.step(); });
        EXPECT_EQ(message.rfind("frame 1: ", 0), 0u) << message;
        EXPECT_NE(message.find("max_speed_mm_s"), std::string::npos) << message;
        // The state is unusable until reset().
        EXPECT_NE(message_of([&] { solver.step(); }).find("reset()"), std::string::npos);
    }
    {  // hard stitches yanking two squares 5 m apart together within one sub-step
        ClothModel two =
            join(horizontal_square(4, 10, 0, 0, 0), horizontal_square(4, 10, 5000, 0, 0));
        DrapeOptions options;
        options.substeps = 1;
        DrapeSolver solver(two, FabricParams{}, options);
        solver.step();
        solver.step();
        solver.set_stitches({Stitch{grid_vertex(4, 4, 2), 25 + grid_vertex(4, 0, 2), 0, 0}});
        const std::string message = message_of([&] { solver.step(); });
        EXPECT_EQ(message.rfind("frame 3: ", 0), 0u) << message;
    }
}

// Two squares 40 mm apart: a hard attachment holds a corner of the first where it is, a hard
// stitch of rest 0 joins the facing edge midpoints. Gravity pulls both down; after settling the
// stitched vertices coincide within 0.1 mm and the attached corner is on its target within
// 0.1 mm (each sub-step ends with those constraints projected, up to the contact passes after).
TEST(GarmentDrapeSolver, StitchPullsTwoPiecesTogetherAndAttachmentHolds) {
    const int cells = 10;
    const ClothModel a = horizontal_square(cells, 10, 0, 0, 0);
    const ClothModel b = horizontal_square(cells, 10, 140, 0, 0);
    const ClothModel two = join(a, b);
    const auto offset = static_cast<std::uint32_t>(a.positions.size());
    DrapeOptions options;
    options.damping_per_second = 3;
    DrapeSolver solver(two, FabricParams{}, options);
    const std::uint32_t corner = grid_vertex(cells, 0, 0);
    const std::uint32_t sa = grid_vertex(cells, cells, cells / 2);
    const std::uint32_t sb = offset + grid_vertex(cells, 0, cells / 2);
    ASSERT_NEAR(distance(two.positions[sa], two.positions[sb]), 40, 1e-9);
    solver.set_attachments({Attachment{corner, two.positions[corner], 0}});
    solver.set_stitches({Stitch{sa, sb, 0, 0}});
    for (int f = 0; f < 150; ++f) {
        solver.step();
    }
    EXPECT_LT(distance(solver.positions()[sa], solver.positions()[sb]), 0.1);
    EXPECT_LT(distance(solver.positions()[corner], two.positions[corner]), 0.1);
    // It hangs: the far corner of the second square is well below the attachment.
    EXPECT_LT(solver.positions()[offset + grid_vertex(cells, cells, cells)][1], -100);
}

// An attachment along an axis holds the vertex in a plane, nothing else: every vertex of a
// square held along y under gravity with a sideways part does not fall at all, and slides
// sideways as in free fall (the same discrete parabola as FreeFallMatchesTheDiscreteParabola).
TEST(GarmentDrapeSolver, AxisAttachmentHoldsTheHeightAndLetsTheClothSlide) {
    DrapeOptions options;
    options.damping_per_second = 0;
    options.self_collision = false;
    const double gx = 2000, gz = -1000;
    options.gravity = {gx, -9810, gz};
    const ClothModel square = horizontal_square(10, 10, 0, 0, 0);
    DrapeSolver solver(square, FabricParams{}, options);
    std::vector<Attachment> held;
    for (std::uint32_t v = 0; v < square.positions.size(); ++v) {
        held.push_back(Attachment{v, square.positions[v], 0, {0, 1, 0}});
    }
    solver.set_attachments(held);
    for (int f = 0; f < 15; ++f) {
        solver.step();
    }
    const double h = options.frame_seconds / options.substeps, n = 15.0 * options.substeps;
    for (std::size_t i = 0; i < solver.positions().size(); ++i) {
        const Vec3& p = solver.positions()[i];
        const Vec3& p0 = square.positions[i];
        ASSERT_NEAR(p[1], p0[1], 1e-9) << "vertex " << i;
        ASSERT_NEAR(p[0] - p0[0], gx * h * h * n * (n + 1) / 2, 1e-9) << "vertex " << i;
        ASSERT_NEAR(p[2] - p0[2], gz * h * h * n * (n + 1) / 2, 1e-9) << "vertex " << i;
    }
}

// The static solve with axis attachments: a sheet hung from its top row, held along y there and
// pinned at one corner only, rests where the same sheet pinned along its whole top row rests
// (the row cannot move down, and nothing pulls it sideways).
TEST(GarmentDrapeSolver, RelaxWithTheTopRowHeldAlongTheVerticalMatchesItPinned) {
    const int nx = 20, ny = 8;
    ClothModel sheet = cloth_grid(nx, ny, 10, {0, 0, 0}, {0, -1, 0}, {0, 0, 1});
    const FabricParams fabric = soft_fabric();
    DrapeOptions options;
    options.self_collision = false;
    ClothModel pinned = sheet;
    pinned.pinned.assign(sheet.positions.size(), 0);
    for (int j = 0; j <= ny; ++j) {
        pinned.pinned[grid_vertex(nx, 0, j)] = 1;
    }
    ClothModel held = sheet;
    held.pinned.assign(sheet.positions.size(), 0);
    held.pinned[grid_vertex(nx, 0, 0)] = 1;
    DrapeSolver a(pinned, fabric, options), b(held, fabric, options);
    std::vector<Attachment> row;
    for (int j = 1; j <= ny; ++j) {
        const std::uint32_t v = grid_vertex(nx, 0, j);
        row.push_back(Attachment{v, sheet.positions[v], 0, {0, 1, 0}});
    }
    b.set_attachments(row);
    for (int f = 0; f < 10; ++f) {
        a.step();
        b.step();
    }
    const auto ra = a.relax(), rb = b.relax();
    ASSERT_TRUE(ra.converged);
    EXPECT_TRUE(rb.converged) << rb.iterations << " iterations, stop " << rb.stop;
    EXPECT_LT(rb.max_residual_of_weight, 1e-3);
    double worst = 0;
    for (std::size_t v = 0; v < sheet.positions.size(); ++v) {
        worst = std::max(worst, distance(a.positions()[v], b.positions()[v]));
    }
    EXPECT_LT(worst, 0.05) << "largest difference, mm";
    for (const Attachment& at : row) {
        EXPECT_NEAR(b.positions()[at.vertex][1], at.target[1], 1e-3) << "vertex " << at.vertex;
    }
    // It does hang: the bottom row is well below the top.
    EXPECT_LT(b.positions()[grid_vertex(nx, nx, ny / 2)][1], -nx * 10 - 1);
}

// The waistband's spring (waistband.h): a sheet hung from its top row, held there along x and z
// hard and along y by the waistband's compliance for a 20 mm sag, comes to rest with its top row
// 20 mm lower on average — the whole weight on the springs, by the balance of vertical forces.
TEST(GarmentDrapeSolver, WaistbandSpringsCarryTheWeightAtTheirSag) {
    const int nx = 12, ny = 10;
    const ClothModel sheet = cloth_grid(nx, ny, 10, {0, 0, 0}, {0, -1, 0}, {0, 0, 1});
    FabricParams fabric;
    fabric.bending_un_m = 0;
    DrapeOptions options;
    options.self_collision = false;
    DrapeSolver solver(sheet, fabric, options);
    std::vector<std::uint32_t> top;
    for (int j = 0; j <= ny; ++j) {
        top.push_back(grid_vertex(nx, 0, j));
    }
    const double sag = 20;
    const double c =
        tapeline::garment::waistband_compliance(solver.total_mass_kg() * 9.81, top.size(), sag);
    // 120 × 100 mm of 180 g/m²: 0.0216 N, over 11 vertices.
    EXPECT_NEAR(c, 11 * sag / (0.012 * 0.180 * 9.81), 1e-9 * c);
    std::vector<Attachment> held =
        tapeline::garment::waistband_attachments(sheet.positions, top, c);
    for (std::uint32_t v : top) {
        held.push_back(Attachment{v, sheet.positions[v], 0, {1, 0, 0}});
        held.push_back(Attachment{v, sheet.positions[v], 0, {0, 0, 1}});
    }
    solver.set_attachments(held);
    for (int f = 0; f < 20; ++f) {
        solver.step();
    }
    const auto rep = solver.relax();
    EXPECT_TRUE(rep.converged) << rep.iterations << " iterations, stop " << rep.stop;
    EXPECT_LT(rep.total_residual_of_weight, 1e-4);
    double sink = 0;
    for (std::uint32_t v : top) {
        sink += (sheet.positions[v][1] - solver.positions()[v][1]) / double(top.size());
        EXPECT_NEAR(solver.positions()[v][0], sheet.positions[v][0], 1e-3);
        EXPECT_NEAR(solver.positions()[v][2], sheet.positions[v][2], 1e-3);
    }
    EXPECT_NEAR(sink, sag, 0.01 * sag);
}

TEST(GarmentDrapeSolver, RefusesBadInputNamingTheElement) {
    const ClothModel good = horizontal_square(4, 10, 0, 0, 0);
    auto refuse = [&](ClothModel cloth, DrapeOptions options, FabricParams fabric,
                      const std::string& expected) {
        const std::string message = message_of([&] { DrapeSolver(cloth, fabric, options); });
        EXPECT_NE(message.find(expected), std::string::npos)
            << "expected '" << expected << "' in: " << message;
        EXPECT_THROW(DrapeSolver(cloth, fabric, options), tapeline::InvalidInput);
    };
    {
        ClothModel c = good;
        c.rest_uv.pop_back();
        refuse(c, {}, {}, "rest_uv has 31 entries for 32 triangles");
    }
    {
        DrapeOptions o;
        o.tether_stretch = 0.5;
        refuse(good, o, {}, "options.tether_stretch must be 0 (no tethers) or >= 1, got 0.5");
    }
    {
        ClothModel c = good;
        c.grain.pop_back();
        refuse(c, {}, {}, "grain has 31 entries");
    }
    {
        ClothModel c = good;
        c.triangles[3][1] = 999;
        refuse(c, {}, {}, "triangle 3 has vertex index 999 out of range");
    }
    {
        ClothModel c = good;
        c.rest_uv[5][2] = c.rest_uv[5][0];
        refuse(c, {}, {}, "triangle 5: degenerate rest triangle");
    }
    {
        ClothModel c = good;
        c.positions[7][2] = std::nan("");
        refuse(c, {}, {}, "vertex 7 has a non-finite position");
    }
    {
        ClothModel c = good;
        c.pinned.assign(3, 1);
        refuse(c, {}, {}, "pinned has 3 entries for 25 vertices");
    }
    {
        ClothModel c = good;
        c.grain[2] = {0, 0};
        refuse(c, {}, {}, "triangle 2: grain direction is zero");
    }
    {
        DrapeOptions o;
        o.substeps = 0;
        refuse(good, o, {}, "options.substeps must be >= 1, got 0");
    }
    {
        DrapeOptions o;
        o.frame_seconds = -1;
        refuse(good, o, {}, "options.frame_seconds");
    }
    {
        FabricParams f;
        f.stretch_weft_n_m = -3;
        refuse(good, {}, f, "fabric.stretch_weft_n_m");
    }
    refuse(ClothModel{}, {}, {}, "empty cloth");

    DrapeSolver solver(good, FabricParams{}, DrapeOptions{});
    EXPECT_THROW(solver.set_attachments({Attachment{25, {0, 0, 0}, 0}}), tapeline::InvalidInput);
    EXPECT_NE(message_of([&] {
                  solver.set_attachments({Attachment{25, {0, 0, 0}, 0}});
              }).find("attachment 0: vertex 25 out of range"),
              std::string::npos);
    EXPECT_NE(message_of([&] {
                  solver.set_attachments(
                      {Attachment{0, {0, 0, 0}, 0}, Attachment{1, {0, 0, 0}, 0, {0, 0.5, 0}}});
              }).find("attachment 1: axis must be zero or a unit vector, its length is 0.5"),
              std::string::npos);
    EXPECT_NE(message_of([&] {
                  solver.set_stitches({Stitch{1, 2, 0, 0}, Stitch{3, 3, 0, 0}});
              }).find("stitch 1 joins vertex 3 to itself"),
              std::string::npos);
    EXPECT_NE(message_of([&] {
                  solver.set_stitches({Stitch{1, 2, -1, 0}});
              }).find("rest_mm"),
              std::string::npos);
}

// ---- relax(): the static equilibrium by a direct solve

// The warp strain of the triangle (a, b, c) against its rest shape, |F·e_warp| − 1, computed from
// positions and pattern coordinates (independently of the solver).
double warp_strain(const ClothModel& m, std::size_t t, const std::vector<Vec3>& x) {
    const auto& uv = m.rest_uv[t];
    const auto& tri = m.triangles[t];
    const double m00 = uv[1][0] - uv[0][0], m10 = uv[1][1] - uv[0][1];
    const double m01 = uv[2][0] - uv[0][0], m11 = uv[2][1] - uv[0][1];
    const double det = m00 * m11 - m01 * m10;
    // Column 0 of F = [x1 − x0, x2 − x0]·Dm⁻¹; the grain is the pattern's first axis.
    const double i00 = m11 / det, i10 = -m10 / det;
    Vec3 f;
    for (int a = 0; a < 3; ++a) {
        f[a] = (x[tri[1]][a] - x[tri[0]][a]) * i00 + (x[tri[2]][a] - x[tri[0]][a]) * i10;
    }
    return std::sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]) - 1;
}

// A sheet hanging from its pinned top row: each row of elements carries the weight of the cloth
// below it, so its warp strain is ρ·g·(H − s)/k at the depth s of its middle (ρ the areal
// density, k the warp stiffness; the lumped masses make that exact for the rows of a uniform grid,
// and without a Poisson coupling in the model the width stays). The sub-stepped solver leaves the
// top of such a sheet far softer than the fabric (see the solver's header); relax() must give the
// analytic strain in every row, and a balance of forces (residual) near zero.
TEST(GarmentDrapeSolver, RelaxedHangingSheetCarriesTheWeightBelowEachRow) {
    const int nx = 30, ny = 10;
    const double cell = 10, k = 20, density = 180, g = 9.81;
    ClothModel sheet = cloth_grid(nx, ny, cell, {0, 0, 0}, {0, -1, 0}, {0, 0, 1});
    sheet.pinned.assign(sheet.positions.size(), 0);
    for (int j = 0; j <= ny; ++j) {
        sheet.pinned[grid_vertex(nx, 0, j)] = 1;
    }
    FabricParams fabric;
    fabric.stretch_warp_n_m = fabric.stretch_weft_n_m = k;
    fabric.shear_n_m = 5;
    fabric.bending_un_m = 0;
    fabric.density_g_m2 = density;
    DrapeOptions options;
    options.self_collision = false;
    DrapeSolver solver(sheet, fabric, options);
    for (int f = 0; f < 10; ++f) {
        solver.step();
    }
    const auto rep = solver.relax();
    EXPECT_TRUE(rep.converged) << rep.iterations << " iterations, last move "
                               << rep.last_max_move_mm;
    EXPECT_LT(rep.energy_after_j, rep.energy_before_j);
    EXPECT_LT(rep.max_residual_of_weight, 1e-3);
    // Per row of elements the mean strain is the analytic one within 1 % of the top row's strain;
    // single triangles within 5 % of it (the alternating diagonals give the vertices 4 or 8
    // triangles, hence unequal lumped masses across a row).
    const double top = density * 1e-3 * g * (nx - 0.5) * cell * 1e-3 / k;
    std::vector<double> sum(nx, 0.0);
    std::vector<int> count(nx, 0);
    for (std::size_t t = 0; t < sheet.triangles.size(); ++t) {
        // Row of elements: the smaller i of the triangle's corners (i = index mod (nx + 1)).
        int row = nx;
        for (auto v : sheet.triangles[t]) {
            row = std::min(row, int(v % (nx + 1)));
        }
        const double got = warp_strain(sheet, t, solver.positions());
        sum[row] += got;
        ++count[row];
        const double depth_m = (row + 0.5) * cell * 1e-3, height_m = nx * cell * 1e-3;
        const double expected = density * 1e-3 * g * (height_m - depth_m) / k;
        ASSERT_NEAR(got, expected, 0.05 * top) << "triangle " << t << " row " << row;
    }
    double worst = 0;
    for (int row = 0; row < nx; ++row) {
        const double depth_m = (row + 0.5) * cell * 1e-3, height_m = nx * cell * 1e-3;
        const double expected = density * 1e-3 * g * (height_m - depth_m) / k;
        const double mean = sum[row] / count[row];
        worst = std::max(worst, std::abs(mean - expected) / top);
        EXPECT_NEAR(mean, expected, 0.01 * top) << "row " << row;
    }
    RecordProperty("worst_row_relative_error", std::to_string(worst));
    for (const Vec3& v : solver.velocities()) {
        ASSERT_EQ(v, (Vec3{0, 0, 0}));
    }
}

// The catenary again, from the V of the right length straight to the static solve (no
// dynamics): the sag within 0.5 % (a stiff strip, no bending). Newton needs about 130
// iterations here (the strip's sideways modes are soft), hence the options.
TEST(GarmentDrapeSolver, RelaxFromAVFindsTheCatenary) {
    const double length = 300, span = 200, cell = 10;
    const int nx = 30, ny = 2;
    ClothModel strip = v_strip(length, span, cell, nx, ny);
    const FabricParams fabric = chain_fabric();
    DrapeOptions options;
    options.self_collision = false;
    DrapeSolver solver(strip, fabric, options);
    tapeline::garment::RelaxOptions ro;
    ro.max_iterations = 300;
    ro.tolerance_mm = 1e-4;
    const auto rep = solver.relax(ro);
    RecordProperty("iterations", std::to_string(rep.iterations));
    EXPECT_TRUE(rep.converged) << rep.iterations << " iterations, last move "
                               << rep.last_max_move_mm;
    const double a = catenary_parameter(length, span);
    const double sag = a * (std::cosh(span / (2 * a)) - 1);
    const double hang = centre_sag(solver.positions(), nx);
    EXPECT_NEAR(hang, sag, 0.005 * sag);
}

// A sheet hanging from its pinned top row over a sphere that bulges 15 mm through its plane from
// behind, gravity tilted by 0.5 rad so that the sheet leans back onto it: settled by the
// sub-stepped solver, then relaxed. No vertex inside the sphere (the analytic distance at least 0.5
// mm, as for the sub-stepped solver), the cloth balanced (net force on the free vertices, the
// sphere's push taken out, below a hundredth of their weight: the solve stops at moves of 0.1 mm),
// the stretch back to the fabric's (the sub-stepped solver leaves the top rows far softer), and
// the same result for one and two threads, all with the solve's default options. (A square lying
// on a sphere slides off it: the solve's friction acts only from its 30th iteration, so the test
// hangs the cloth where it cannot slide away.)
TEST(GarmentDrapeSolver, RelaxedSheetOverASphereStaysOutsideAndBalances) {
    const double radius = 60;
    const Vec3 centre{100, -150, -(radius - 15)};
    const auto sphere = tapeline_test::uv_sphere(centre, radius, 64, 32);
    const SignedDistanceGrid body(sphere.points, sphere.triangles, ColliderOptions{2});
    const int nx = 30, ny = 20;
    ClothModel sheet = cloth_grid(nx, ny, 10, {0, 0, 0}, {0, -1, 0}, {1, 0, 0});
    sheet.pinned.assign(sheet.positions.size(), 0);
    for (int j = 0; j <= ny; ++j) {
        sheet.pinned[grid_vertex(nx, 0, j)] = 1;
    }
    // Start in front of the sphere: the plane moved forward by the bulge plus the clearance.
    for (Vec3& p : sheet.positions) {
        p[2] = 17;
    }
    std::vector<Vec3> result[2];
    for (int threads : {1, 2}) {
        DrapeOptions options;
        options.threads = threads;
        options.self_collision = false;
        options.damping_per_second = 4;
        options.gravity = {0, -9810 * std::cos(0.5), -9810 * std::sin(0.5)};  // leans back
        DrapeSolver solver(sheet, FabricParams{}, options, &body);
        for (int f = 0; f < 60; ++f) {
            solver.step();
        }
        const auto rep = solver.relax();  // the default options: they must converge here
        EXPECT_TRUE(rep.converged)
            << rep.iterations << " iterations, last move " << rep.last_max_move_mm;
        EXPECT_GT(rep.contacts, 5u);
        EXPECT_LT(rep.total_residual_of_weight, 1e-2);
        EXPECT_LT(rep.energy_after_j, rep.energy_before_j);
        double closest = 1e300;
        for (const Vec3& p : solver.positions()) {
            closest = std::min(closest, distance(p, centre) - radius);
        }
        EXPECT_GE(closest, 0.5);
        double top = 0;
        for (int j = 0; j < ny; ++j) {  // the first row of elements, where the load is largest
            for (std::size_t t = 0; t < sheet.triangles.size(); ++t) {
                const auto& tri = sheet.triangles[t];
                if (tri[0] % (nx + 1) == 0 || tri[1] % (nx + 1) == 0 || tri[2] % (nx + 1) == 0) {
                    top = std::max(top, warp_strain(sheet, t, solver.positions()));
                }
            }
        }
        EXPECT_LT(top, 0.01);  // cotton jersey under 300 mm of itself: about 0.04 %
        result[threads - 1] = solver.positions();
        RecordProperty("iterations_" + std::to_string(threads), std::to_string(rep.iterations));
    }
    EXPECT_EQ(result[0], result[1]);
}

// A closed slab, `depth` thick, whose top (y = 0) is a grid of n × n cells of `cell` mm centred
// on the origin, with the top vertices `spikes` (grid i, j) raised by `height`: bumps two cells
// wide at their base on a flat body. Oriented outward (each face away from the centre while flat).
tapeline_test::GarmentTriMesh spiked_slab(int n, double cell, double depth,
                                          const std::vector<std::pair<int, int>>& spikes,
                                          double height) {
    using namespace tapeline::vec3;
    tapeline_test::GarmentTriMesh m;
    const double half = n * cell / 2;
    const auto top = [&](int i, int j) { return std::uint32_t(i * (n + 1) + j); };
    const auto bottom = [&](int i, int j) { return std::uint32_t((n + 1) * (n + 1)) + top(i, j); };
    for (const double y : {0.0, -depth}) {
        for (int i = 0; i <= n; ++i) {
            for (int j = 0; j <= n; ++j) {
                m.points.push_back({-half + i * cell, y, -half + j * cell});
            }
        }
    }
    const auto quad = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c, std::uint32_t d) {
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
    };
    for (int i = 0; i < n; ++i) {
        for (int j = 0; j < n; ++j) {
            quad(top(i, j), top(i + 1, j), top(i + 1, j + 1), top(i, j + 1));
            quad(bottom(i, j), bottom(i + 1, j), bottom(i + 1, j + 1), bottom(i, j + 1));
        }
        quad(top(i, 0), top(i + 1, 0), bottom(i + 1, 0), bottom(i, 0));
        quad(top(i, n), top(i + 1, n), bottom(i + 1, n), bottom(i, n));
        quad(top(0, i), top(0, i + 1), bottom(0, i + 1), bottom(0, i));
        quad(top(n, i), top(n, i + 1), bottom(n, i + 1), bottom(n, i));
    }
    const Vec3 centre{0, -depth / 2, 0};
    for (auto& t : m.triangles) {
        const Vec3 &a = m.points[t[0]], &b = m.points[t[1]], &c = m.points[t[2]];
        const Vec3 mid = scale(add(add(a, b), c), 1.0 / 3);
        if (dot(cross(sub(b, a), sub(c, a)), sub(mid, centre)) < 0) {
            std::swap(t[1], t[2]);
        }
    }
    for (const auto& [i, j] : spikes) {
        m.points[top(i, j)][1] += height;
    }
    return m;
}

// Cloth edges crossing the body's triangles (CGAL's exact predicates, as the quality gate).
std::size_t edges_through(const tapeline_test::GarmentTriMesh& body, const ClothModel& cloth,
                          const std::vector<Vec3>& x) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<K::Triangle_3> tris;
    const auto pt = [](const Vec3& p) { return K::Point_3(p[0], p[1], p[2]); };
    for (const auto& t : body.triangles) {
        tris.emplace_back(pt(body.points[t[0]]), pt(body.points[t[1]]), pt(body.points[t[2]]));
    }
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<
        K, CGAL::AABB_triangle_primitive<K, std::vector<K::Triangle_3>::const_iterator>>>;
    const Tree tree(tris.cbegin(), tris.cend());
    std::size_t through = 0;
    for (const auto& [a, b] : tapeline::garment::internal::unique_edges(cloth.triangles)) {
        through += tree.do_intersect(K::Segment_3(pt(x[a]), pt(x[b]))) ? 1 : 0;
    }
    return through;
}

// A square of 10 mm cells dropped on a flat slab with sixteen spikes 6 mm high and 8 mm wide at
// their base, as a nipple is to cloth at 10 mm (the grid, of 5 mm cells, rounds them off), then
// relaxed. Without the body's points the static solve keeps the cloth's vertices and edge
// midpoints at their clearance from the grid's surface, and spikes poke through triangles between
// them: cloth edges cross the slab (the case the test is for; it fails if the scene stops showing
// it). With them (every slab vertex, its area-weighted normal, reach one grid cell) no cloth edge
// crosses the slab, the cloth over each spike's tip (along its normal) lies at least 0.45 of the
// clearance above it (the contact holds half the clearance by a stiff penalty), and the solve
// converges.
TEST(GarmentDrapeSolver, RelaxKeepsNarrowBumpsOfTheBodyUnderTheCloth) {
    std::vector<std::pair<int, int>> spikes;
    for (int i : {11, 17, 24, 29}) {
        for (int j : {12, 18, 23, 28}) {
            spikes.emplace_back(i, j);
        }
    }
    const double height = 6, cell = 4;
    const int n = 40;
    const auto slab = spiked_slab(n, cell, 20, spikes, height);
    ASSERT_GT(tapeline_test::signed_volume(slab), 0);
    const SignedDistanceGrid body(slab.points, slab.triangles, ColliderOptions{5});
    const ClothModel sheet = horizontal_square(12, 10, 3, height + 4, 3);
    const double clearance = FabricParams{}.thickness_mm;
    for (const bool with_points : {false, true}) {
        DrapeSolver solver(sheet, FabricParams{}, DrapeOptions{}, &body);
        for (int f = 0; f < 40; ++f) {
            solver.step();
        }
        if (with_points) {
            solver.set_body_points(slab.points,
                                   tapeline::draw::vertex_normals(slab.points, slab.triangles), 5);
        }
        const auto rep = solver.relax();
        const std::size_t through = edges_through(slab, sheet, solver.positions());
        RecordProperty(with_points ? "edges_through_with" : "edges_through_without",
                       std::to_string(through));
        if (!with_points) {
            EXPECT_GT(through, 0u) << "the spikes no longer poke through without the body points";
            EXPECT_EQ(rep.body_point_contacts, 0u);
            continue;
        }
        EXPECT_TRUE(rep.converged)
            << rep.iterations << " iterations, last move " << rep.last_max_move_mm;
        EXPECT_EQ(through, 0u);
        EXPECT_GT(rep.body_point_contacts, 0u);  // tips the cloth rests on (others hold it up)
        // The cloth over each tip: a vertical line through it against every cloth triangle.
        const auto& x = solver.positions();
        for (std::size_t s = 0; s < spikes.size(); ++s) {
            const Vec3& tip =
                slab.points[std::size_t(spikes[s].first * (n + 1) + spikes[s].second)];
            double above = std::numeric_limits<double>::max();
            for (const auto& t : sheet.triangles) {
                const Vec3 &a = x[t[0]], &b = x[t[1]], &c = x[t[2]];
                // Barycentric coordinates of the tip's (x, z) in the triangle's (x, z).
                const double det = (b[0] - a[0]) * (c[2] - a[2]) - (c[0] - a[0]) * (b[2] - a[2]);
                if (std::abs(det) < 1e-9) {
                    continue;
                }
                const double u =
                    ((tip[0] - a[0]) * (c[2] - a[2]) - (c[0] - a[0]) * (tip[2] - a[2])) / det;
                const double v =
                    ((b[0] - a[0]) * (tip[2] - a[2]) - (tip[0] - a[0]) * (b[2] - a[2])) / det;
                if (u < -1e-9 || v < -1e-9 || u + v > 1 + 1e-9) {
                    continue;
                }
                above = std::min(above, (1 - u - v) * a[1] + u * b[1] + v * c[1] - tip[1]);
            }
            ASSERT_LT(above, std::numeric_limits<double>::max()) << "no cloth over spike " << s;
            EXPECT_GE(above, 0.45 * clearance) << "spike " << s;
        }
    }
}

// Fold-overs (smooth_fold_overs). A sheet of 10 mm cells folded over itself across rows j0..j1:
// columns i0+1, i0+2, i0+3 moved by (+15, -3), (-5, +3) and (0, -8) mm in (x, y), so that the
// profile crosses itself (the edge from column i0+2 to i0+3 passes through the triangles between
// columns i0 and i0+1): a fold-over one edge wide, as compressed cloth makes. The crossings are
// counted independently (CGAL's exact predicates).
void crumple(ClothModel& sheet, int nx, int i0, int j0, int j1) {
    const double dx[3] = {15, -5, 0}, dy[3] = {-3, 3, -8};
    for (int j = j0; j <= j1; ++j) {
        for (int k = 0; k < 3; ++k) {
            Vec3& p = sheet.positions[grid_vertex(nx, i0 + 1 + k, j)];
            p[0] += dx[k];
            p[1] += dy[k];
        }
    }
}

ClothModel crumpled_sheet() {
    ClothModel sheet = horizontal_square(24, 10, 0, 0, 0);
    crumple(sheet, 24, 10, 10, 14);
    return sheet;
}

// The fold is flattened: no crossing left (by the exact count, and as reported), the report's
// count before equals the exact count, and nothing moves beyond the patch: the folded block
// (columns 10..14, rows 10..14), the ring around its crossings and the rings added in later
// rounds (one every five), so every vertex more than 1 + max_rounds/5 rings from the block keeps
// its position bit for bit, the sheet's border included. The same result for one and two
// threads.
TEST(GarmentDrapeSolver, FoldOverSmoothingFlattensACrumpleAndNothingElse) {
    const ClothModel sheet = crumpled_sheet();
    const std::size_t before = exact_crossings(sheet.positions, sheet.triangles);
    ASSERT_GT(before, 10u);
    std::vector<Vec3> result[2];
    for (int threads : {1, 2}) {
        DrapeOptions options;
        options.threads = threads;
        DrapeSolver solver(sheet, FabricParams{}, options);
        const tapeline::garment::FoldReport r = solver.smooth_fold_overs();
        EXPECT_EQ(r.crossings_before, before);
        EXPECT_EQ(r.crossings_after, 0u);
        EXPECT_EQ(exact_crossings(solver.positions(), sheet.triangles), 0u);
        EXPECT_GE(r.rounds, 1);
        EXPECT_GT(r.vertices_moved, 0u);
        const int reach = 1 + tapeline::garment::FoldOptions{}.max_rounds / 5 + 1;
        for (int j = 0; j <= 24; ++j) {
            for (int i = 0; i <= 24; ++i) {
                if (std::max(std::max(10 - i, i - 14), std::max(10 - j, j - 14)) > reach) {
                    const std::uint32_t v = grid_vertex(24, i, j);
                    ASSERT_EQ(solver.positions()[v], sheet.positions[v]) << i << ", " << j;
                }
            }
        }
        for (const Vec3& v : solver.velocities()) {
            ASSERT_EQ(v, (Vec3{0, 0, 0}));
        }
        result[threads - 1] = solver.positions();
    }
    EXPECT_EQ(result[0], result[1]);
}

// Cloth without crossings is left as it is.
TEST(GarmentDrapeSolver, FoldOverSmoothingLeavesUncrossedClothAlone) {
    const ClothModel flat = horizontal_square(12, 10, 0, 0, 0);
    DrapeSolver solver(flat, FabricParams{}, DrapeOptions{});
    const tapeline::garment::FoldReport r = solver.smooth_fold_overs();
    EXPECT_EQ(r.crossings_before, 0u);
    EXPECT_EQ(r.rounds, 0);
    EXPECT_EQ(r.vertices_moved, 0u);
    EXPECT_EQ(solver.positions(), flat.positions);
}

// Two sheets 3 mm apart along x, their facing columns stitched (zero rest length, still apart),
// folds on both sides of the seam: every stitched pair keeps its gap exactly (both ends move by the
// mean of their moves), so the smoothing opens no seam; pinned vertices stay put.
TEST(GarmentDrapeSolver, FoldOverSmoothingKeepsStitchedPairsTogetherAndPinsInPlace) {
    // Two 12 × 24 sheets, x from -120 to 0 and from 3 to 123, each folded over itself beside the
    // seam.
    ClothModel left = cloth_grid(12, 24, 10, {-120, 0, -120}, {1, 0, 0}, {0, 0, 1});
    ClothModel right = cloth_grid(12, 24, 10, {3, 0, -120}, {1, 0, 0}, {0, 0, 1});
    crumple(left, 12, 8, 10, 14);   // columns 9, 10, 11 of the left sheet
    crumple(right, 12, 0, 10, 14);  // columns 1, 2, 3 of the right one
    for (int j = 10; j <= 14;
         ++j) {  // the seam's vertices unevenly spaced: the smoothing moves them
        left.positions[grid_vertex(12, 12, j)][2] += j % 2 ? 4 : -4;
        right.positions[grid_vertex(12, 0, j)][2] += j % 2 ? 4 : -4;
    }
    ClothModel both = join(left, right);
    both.pinned.assign(both.positions.size(), 0);
    const std::uint32_t pin = grid_vertex(12, 10, 12);  // inside the left crumple
    both.pinned[pin] = 1;
    const auto offset = static_cast<std::uint32_t>(left.positions.size());
    std::vector<Stitch> stitches;
    for (int j = 0; j <= 24; ++j) {
        stitches.push_back({grid_vertex(12, 12, j), offset + grid_vertex(12, 0, j), 0.0, 0.0});
    }
    ASSERT_GT(exact_crossings(both.positions, both.triangles), 10u);
    DrapeSolver solver(both, FabricParams{}, DrapeOptions{});
    solver.set_stitches(stitches);
    const tapeline::garment::FoldReport r = solver.smooth_fold_overs();
    EXPECT_GT(r.vertices_moved, 0u);
    EXPECT_EQ(solver.positions()[pin], both.positions[pin]);
    double seam_moved = 0;
    for (const Stitch& st : stitches) {
        seam_moved = std::max(seam_moved, distance(solver.positions()[st.a], both.positions[st.a]));
    }
    EXPECT_GT(seam_moved, 0.5);  // the seam moved, its gaps did not change:
    for (const Stitch& st : stitches) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(solver.positions()[st.b][k] - solver.positions()[st.a][k],
                        both.positions[st.b][k] - both.positions[st.a][k], 1e-9)
                << "stitch " << st.a << "-" << st.b;
        }
    }
}

// A folded cap lying on a sphere at the clearance: smoothing a curved patch pulls it towards
// the centre, the push keeps it outside (within the grid's error, 0.3 mm at 2 mm cells).
TEST(GarmentDrapeSolver, FoldOverSmoothingKeepsTheClothOutsideTheBody) {
    const double radius = 120, clearance = 2;
    const auto sphere = tapeline_test::uv_sphere({0, 0, 0}, radius, 96, 48);
    const SignedDistanceGrid body(sphere.points, sphere.triangles, ColliderOptions{2});
    ClothModel cap = crumpled_sheet();
    for (Vec3& p : cap.positions) {  // wrapped over the top of the sphere, crumple included
        const double r = std::hypot(p[0], p[2]);
        const double theta = r / (radius + clearance);
        const double lift = p[1];
        const double scale = r > 0 ? std::sin(theta) / r * (radius + clearance + lift) : 0;
        p = {p[0] * scale, std::cos(theta) * (radius + clearance + lift), p[2] * scale};
    }
    ASSERT_GT(exact_crossings(cap.positions, cap.triangles), 10u);
    DrapeOptions options;
    options.body_clearance_mm = clearance;
    DrapeSolver solver(cap, FabricParams{}, options, &body);
    const tapeline::garment::FoldReport r = solver.smooth_fold_overs();
    EXPECT_EQ(r.crossings_after, 0u);
    double closest = 1e300;
    for (const Vec3& p : solver.positions()) {
        closest = std::min(closest, distance(p, {0, 0, 0}) - radius);
    }
    EXPECT_GE(closest, clearance - 0.3);
}

TEST(GarmentDrapeSolver, FoldOverSmoothingRefusesBadOptions) {
    DrapeSolver solver(horizontal_square(4, 10, 0, 0, 0), FabricParams{}, DrapeOptions{});
    tapeline::garment::FoldOptions fo;
    fo.sweeps = 0;
    EXPECT_NE(message_of([&] { solver.smooth_fold_overs(fo); }).find("sweeps >= 1"),
              std::string::npos);
    fo = {};
    fo.rings = -1;
    EXPECT_NE(message_of([&] { solver.smooth_fold_overs(fo); }).find("rings >= 0"),
              std::string::npos);
    fo = {};
    fo.max_rounds = -2;
    EXPECT_NE(message_of([&] { solver.smooth_fold_overs(fo); }).find("max_rounds >= 0"),
              std::string::npos);
}

TEST(GarmentDrapeSolver, RelaxRefusesBadOptions) {
    using tapeline::garment::RelaxOptions;
    DrapeSolver solver(horizontal_square(4, 10, 0, 0, 0), FabricParams{}, DrapeOptions{});
    // The message of relax() with the default options changed by `set`.
    const auto message_for = [&](auto set) {
        RelaxOptions ro;
        set(ro);
        return message_of([&] { solver.relax(ro); });
    };
    const std::vector<std::pair<std::function<void(RelaxOptions&)>, std::string>> cases = {
        {[](RelaxOptions& r) { r.max_iterations = 0; }, "max_iterations must be >= 1"},
        {[](RelaxOptions& r) { r.tolerance_mm = -1; }, "tolerance_mm"},
        {[](RelaxOptions& r) { r.initial_step_seconds = std::nan(""); }, "initial_step_seconds"},
        {[](RelaxOptions& r) { r.friction_from_iteration = -1; }, "friction_from_iteration"},
        {[](RelaxOptions& r) { r.release_until_iteration = -3; }, "got 30 and -3"},
        {[](RelaxOptions& r) { r.settle_fraction = 1.5; }, "settle_fraction in [0, 1]"},
        {[](RelaxOptions& r) { r.settle_iterations = -1; }, "got -1, 4 and"},
        {[](RelaxOptions& r) { r.stall_rejections = -2; }, "got 0, -2 and"}};
    for (const auto& [set, text] : cases) {
        EXPECT_NE(message_for(set).find(text), std::string::npos) << text;
    }
}

// The settle rule counts from the end of the releases: with every step counting as settled
// (settle_fraction 1) a solve that has not converged stops after exactly release_until_iteration +
// settle_iterations iterations; counting only steps that moved no vertex more than 0.3 mm
// (settle_fraction 0), it stops either converged or with its last step moving none.
TEST(GarmentDrapeSolver, RelaxStopsOnceSettledAfterTheReleases) {
    const int nx = 30, ny = 10;
    // Horizontal, held along one edge: it swings down to hang.
    ClothModel sheet = cloth_grid(nx, ny, 10, {0, 0, 0}, {1, 0, 0}, {0, 0, 1});
    sheet.pinned.assign(sheet.positions.size(), 0);
    for (int j = 0; j <= ny; ++j) {
        sheet.pinned[grid_vertex(nx, 0, j)] = 1;
    }
    DrapeOptions options;
    options.self_collision = false;
    tapeline::garment::RelaxOptions ro;
    ro.release_until_iteration = 6;
    ro.settle_iterations = 3;
    ro.settle_fraction = 1;
    {
        DrapeSolver solver(sheet, FabricParams{}, options);  // from the flat, unstretched sheet
        const auto rep = solver.relax(ro);
        EXPECT_EQ(rep.stop, "settled");
        EXPECT_EQ(rep.iterations, 9);
        EXPECT_FALSE(rep.converged);
    }
    {
        ro.settle_fraction = 0;
        DrapeSolver solver(sheet, FabricParams{}, options);
        const auto rep = solver.relax(ro);
        RecordProperty("iterations", std::to_string(rep.iterations));
        EXPECT_TRUE(rep.stop == "converged" || rep.stop == "settled") << rep.stop;
        EXPECT_EQ(rep.moving_fraction, 0.0);
        EXPECT_GT(rep.iterations, 9);
    }
}

// The hanging sheet of RelaxedHangingSheetCarriesTheWeightBelowEachRow, solved once to 1e-4 mm
// and once to a tolerance below the spacing of doubles at its coordinates (1e-15 mm against
// 5.7e-14 at 300 mm): the second solve cannot converge, and once no step lowers the energy it
// must stop as stalled, after four rejected steps (without the rule it runs on until its damping
// passes 1e-9 s, to the same positions), where the first one ended: the same positions within
// 1e-3 mm and no more energy.
TEST(GarmentDrapeSolver, RelaxStopsAsStalledWhereNoStepLowersTheEnergy) {
    const int nx = 30, ny = 10;
    ClothModel sheet = cloth_grid(nx, ny, 10, {0, 0, 0}, {0, -1, 0}, {0, 0, 1});
    sheet.pinned.assign(sheet.positions.size(), 0);
    for (int j = 0; j <= ny; ++j) {
        sheet.pinned[grid_vertex(nx, 0, j)] = 1;
    }
    const FabricParams fabric = soft_fabric();
    DrapeOptions options;
    options.self_collision = false;
    DrapeSolver solver(sheet, fabric, options), beyond(sheet, fabric, options);
    for (int f = 0; f < 10; ++f) {
        solver.step();
        beyond.step();
    }
    tapeline::garment::RelaxOptions ro;
    ro.max_iterations = 400;
    ro.tolerance_mm = 1e-4;
    const auto met = solver.relax(ro);
    ASSERT_TRUE(met.converged) << met.iterations << " iterations";
    EXPECT_EQ(met.stop, "converged");
    ro.tolerance_mm = 1e-15;
    const auto rep = beyond.relax(ro);
    RecordProperty("iterations", std::to_string(rep.iterations));
    EXPECT_EQ(rep.stop, "stalled") << rep.iterations << " iterations";
    EXPECT_FALSE(rep.converged);
    // Without the rule the solve takes rejected steps until its damping passes 1e-9 s; rejected
    // steps move nothing, so it ends at the very same positions, later.
    DrapeSolver off(sheet, fabric, options);
    for (int f = 0; f < 10; ++f) {
        off.step();
    }
    ro.stall_rejections = 0;
    const auto off_rep = off.relax(ro);
    EXPECT_EQ(off_rep.stop, "damping");
    EXPECT_LT(rep.iterations, off_rep.iterations);
    EXPECT_EQ(beyond.positions(), off.positions());
    EXPECT_LE(rep.energy_after_j, met.energy_after_j + 1e-12);
    double worst = 0;
    for (std::size_t v = 0; v < sheet.positions.size(); ++v) {
        worst = std::max(worst, distance(beyond.positions()[v], solver.positions()[v]));
    }
    EXPECT_LT(worst, 1e-3);
}

// A sheet hanging through a plate 4 mm thick, obliquely (a row of vertices 2 mm above it, the
// next 2 mm below it, the edges between them through it), as a sleeve passes through a hand: the
// triangles through the plate have vertices on both of its sides, and pushing them out along
// one side's normal would pull them into the other. A body point pairs only with a triangle over
// its own side, so the plate's points change nothing here: the solve ends where it ends without
// them, bit for bit.
TEST(GarmentDrapeSolver, BodyPointsLeaveClothThroughAThinPlateAlone) {
    const auto plate = spiked_slab(20, 4, 4, {}, 0);
    const SignedDistanceGrid body(plate.points, plate.triangles, ColliderOptions{2});
    const int nu = 9, nv = 7;
    ClothModel sheet = cloth_grid(nu, nv, 10, {-35, 34, -25}, {0, -0.8, 0.6}, {1, 0, 0});
    sheet.pinned.assign(sheet.positions.size(), 0);
    for (int j = 0; j <= nv; ++j) {
        sheet.pinned[grid_vertex(nu, 0, j)] = 1;
    }
    ASSERT_GT(edges_through(plate, sheet, sheet.positions), 0u);
    std::vector<Vec3> result[2];
    for (const bool with_points : {false, true}) {
        DrapeSolver solver(sheet, FabricParams{}, DrapeOptions{}, &body);
        if (with_points) {
            solver.set_body_points(
                plate.points, tapeline::draw::vertex_normals(plate.points, plate.triangles), 5);
        }
        const auto rep = solver.relax();
        EXPECT_LT(rep.energy_after_j, rep.energy_before_j);
        EXPECT_EQ(rep.body_point_contacts, 0u);
        result[with_points ? 1 : 0] = solver.positions();
    }
    EXPECT_EQ(result[0], result[1]);
}

// set_body_points names what is wrong; good points are taken.
TEST(GarmentDrapeSolver, BodyPointsRefusedNamingThePoint) {
    DrapeSolver solver(horizontal_square(4, 10, 0, 0, 0), FabricParams{}, DrapeOptions{});
    const std::vector<Vec3> p{{0, 0, 0}, {1, 0, 0}}, up{{0, 1, 0}, {0, 1, 0}};
    EXPECT_NE(message_of([&] {
                  solver.set_body_points(p, {{0, 1, 0}}, 5);
              }).find("2 points but 1 normals"),
              std::string::npos);
    EXPECT_NE(message_of([&] {
                  solver.set_body_points(p, {{0, 1, 0}, {0, 2, 0}}, 5);
              }).find("point 1: its normal is not of unit length"),
              std::string::npos);
    EXPECT_NE(message_of([&] {
                  solver.set_body_points({{0, std::nan(""), 0}, {1, 0, 0}}, up, 5);
              }).find("point 0: not finite"),
              std::string::npos);
    EXPECT_NE(message_of([&] { solver.set_body_points(p, up, 0); }).find("reach_mm must be"),
              std::string::npos);
    EXPECT_NE(
        message_of([&] { solver.set_body_points(p, up, std::nan("")); }).find("reach_mm must be"),
        std::string::npos);
    EXPECT_NO_THROW(solver.set_body_points(p, up, 5));
}

// The proportional schedule: friction from the third of the iterations, releases during the
// first half, every other option the default's.
TEST(GarmentDrapeSolver, ProportionalRelaxSchedule) {
    using tapeline::garment::RelaxOptions;
    const RelaxOptions d, p = RelaxOptions::proportional(80), q = RelaxOptions::proportional(7);
    EXPECT_EQ(p.max_iterations, 80);
    EXPECT_EQ(p.friction_from_iteration, 26);
    EXPECT_EQ(p.release_until_iteration, 40);
    EXPECT_EQ(q.friction_from_iteration, 2);
    EXPECT_EQ(q.release_until_iteration, 3);
    EXPECT_EQ(p.tolerance_mm, d.tolerance_mm);
    EXPECT_EQ(p.initial_step_seconds, d.initial_step_seconds);
}

}  // namespace
