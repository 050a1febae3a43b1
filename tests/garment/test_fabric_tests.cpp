// The virtual lab tests (fabric_tests.h) at coarse resolution, against analytic truth: the heavy
// elastica (tip chord at 41.5° for an overhang of twice the bending length), the linear strip
// (strain = load/stiffness), the uniaxial bias stress (γ = T/(2G)), a rigid plate on the Cusick
// pedestal (DC = 100 %) and the order of drape coefficients with bending length; and the analytic
// colliders' distances.
#include <tapeline/garment/fabric.h>
#include <tapeline/garment/fabric_tests.h>

#include <gtest/gtest.h>
#include <tapeline_test/fabric_records.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace {

namespace tg = tapeline::garment;

// The pedestal's signed distances at points whose distance is known by construction: a column,
// a flat disc and a plate.
TEST(GarmentFabricTests, AnalyticColliders) {
    tg::Vec3 g;
    const tg::PedestalCollider ped(90, 0);
    EXPECT_DOUBLE_EQ(ped.signed_distance({0, 5, 50}, &g), 5);
    EXPECT_NEAR(ped.signed_distance({60, -100, 80}, &g), 10, 1e-12);  // r = 100
    EXPECT_NEAR(g[0], 0.6, 1e-12);
    EXPECT_NEAR(ped.signed_distance({93, 4, 0}, nullptr), 5, 1e-12);
    EXPECT_NEAR(ped.signed_distance({0, -3, 80}, nullptr), -3, 1e-12);
    // A flat disc (depth 0) and a plate 4 mm thick: below them the distance is to the underside,
    // beside them to the rim.
    const tg::PedestalCollider disc(90, 0, 0), plate(90, 0, 4);
    EXPECT_NEAR(disc.signed_distance({0, -7, 50}, &g), 7, 1e-12);
    EXPECT_NEAR(g[1], -1, 1e-12);
    EXPECT_NEAR(disc.signed_distance({93, -4, 0}, &g), 5, 1e-12);  // the rim's edge, (3, −4) off
    EXPECT_NEAR(g[0], 0.6, 1e-12);
    EXPECT_NEAR(g[1], -0.8, 1e-12);
    EXPECT_NEAR(plate.signed_distance({0, -7, 50}, nullptr), 3, 1e-12);
    EXPECT_NEAR(plate.signed_distance({92, -2, 0}, &g), 2, 1e-12);
    EXPECT_NEAR(g[0], 1, 1e-12);
    EXPECT_NEAR(plate.signed_distance({0, -1, 50}, nullptr), -1, 1e-12);
}

// Peirce cantilever at 10 mm on the Wang et al. denim as measured (anisotropic bending: B 24.25
// µN·m warp, 16 weft, 18.25 bias; shear rigidity 26.5 N/m, stretch 410 and 2028 N/m): the
// simulated bending length must match (B/(W·g))^⅓ within 5 % in both directions, and warp and weft
// must differ as the cube root of their rigidities. The strips have 4 segments: the hinge chain's
// own discretisation costs −2.5 % (a discrete elastica with the same hinges and lumped masses).
TEST(GarmentFabricTests, CantileverGivesTheBendingLength) {
    const tg::FabricParams f = tg::fabric_from("11oz-black-denim");
    tg::FabricTestOptions o;
    o.resolution_mm = 10;
    const tg::CantileverResult warp = tg::cantilever_test(f, false, o);
    const tg::CantileverResult weft = tg::cantilever_test(f, true, o);
    const double cw = std::cbrt(24.25 / (324 * 9.81e-6)), cf = std::cbrt(16.0 / (324 * 9.81e-6));
    EXPECT_NEAR(warp.target_mm, cw, 1e-9);
    EXPECT_NEAR(warp.bending_length_mm, cw, 0.05 * cw);
    EXPECT_NEAR(weft.bending_length_mm, cf, 0.05 * cf);
    EXPECT_NEAR(warp.tip_angle_deg, 41.5, 0.05);
    EXPECT_TRUE(warp.settled && weft.settled);
    EXPECT_NEAR(warp.bending_length_mm / weft.bending_length_mm, cw / cf, 0.02 * cw / cf);
}

// Tip chord angle (degrees) of a cantilever of `n` equal segments under its own weight, small
// deflections, with the solver's hinges: stiffness B·width/dx at the joints and twice that at the
// clamp (half a dual length), masses lumped at the joints (half at the tip). c3 = B/(W·g), mm³.
double discrete_beam_tip_angle(double length, int n, double c3) {
    const double dx = length / n;
    double slope = 0, y = 0;
    for (int k = 0; k < n; ++k) {
        double moment = 0;  // about joint k, per unit width and W·g
        for (int i = k + 1; i <= n; ++i) {
            moment += (i == n ? dx / 2 : dx) * (i - k) * dx;
        }
        slope += moment / ((k == 0 ? 2 : 1) * c3 / dx);
        y += slope * dx;
    }
    return std::atan(y / length) * 180 / 3.14159265358979323846;
}

// A short cantilever (15 mm of the class denim, C = 21.7 mm: a tip 2.4° down) at 2.5 mm bends as
// the beam of its six segments, computed above independently of the solver, within 3 % (it gives
// +2.4 %). On right triangles with alternating diagonals, where only every other vertex of a
// column is loaded by the next column's hinges (fabric_tests.h, lattice_strip_model), the same
// strip sags +17 % beyond the beam.
TEST(GarmentFabricTests, ShortCantileverBendsAsItsBeam) {
    const tg::FabricParams f = tg::fabric_from("denim");
    tg::FabricTestOptions o;
    o.resolution_mm = 2.5;
    const double length = 15;
    bool settled = true;
    const double angle =
        tg::cantilever_tip_angle(f, false, length, o, &settled, nullptr, nullptr, nullptr);
    const double c3 = f.bending_un_m / (f.density_g_m2 * 9.81e-6);
    const double beam = discrete_beam_tip_angle(length, 6, c3);
    const double continuum =
        std::atan(length * length * length / (8 * c3)) * 180 / 3.14159265358979;
    EXPECT_NEAR(beam, continuum, 0.03 * continuum);  // the beam itself: +2.8 % from 6 segments
    EXPECT_NEAR(angle, beam, 0.03 * beam);
    EXPECT_TRUE(settled);
}

// A strip bent across its length does not shear, so its shear rigidity must play no part: the
// Wang et al. denim over twice its bending length at 5 mm comes to the same tip angle with its own
// shear rigidity (26.5 N/m) and with the denim class's (3000 N/m), within 1.5 % (42.7° and 42.4°),
// and near the heavy elastica's 41.5°. On right triangles with alternating diagonals they are
// 6.5 % apart (46.7° against 43.8°): the strip sags through the in-plane zigzag those meshes
// leave unloaded, the more the softer its shear.
TEST(GarmentFabricTests, CantileverDoesNotBendThroughShear) {
    tg::FabricParams soft = tg::fabric_from("11oz-black-denim");
    tg::FabricParams stiff = soft;
    stiff.shear_n_m = 3000;
    tg::FabricTestOptions o;
    o.resolution_mm = 5;
    const double overhang = 2 * std::cbrt(soft.bending_un_m / (soft.density_g_m2 * 9.81e-6));
    bool settled = true;
    const double a_soft =
        tg::cantilever_tip_angle(soft, false, overhang, o, &settled, nullptr, nullptr, nullptr);
    const double a_stiff =
        tg::cantilever_tip_angle(stiff, false, overhang, o, &settled, nullptr, nullptr, nullptr);
    EXPECT_NEAR(a_soft, a_stiff, 0.015 * a_stiff);
    EXPECT_NEAR(a_soft, 41.5, 0.05 * 41.5);
    EXPECT_TRUE(settled);
}

// Over twice its bending length the strip's tip must come to the heavy elastica's 41.49° from
// above as the strip gets more segments, as the discrete elastica does (its error in C is
// negative and shrinks with the segments): cotton jersey (C = 10.4 mm) at 10, 5 and 2.5 mm gives
// 45.1°, 42.9°, 42.0°. With a table under the strip, whose clearance reaches the strip's first
// edge at the clamp, it gives 42.5°, 40.8°, 40.8°: below the elastica and not converging.
TEST(GarmentFabricTests, CantileverConvergesToTheElasticaFromTheDiscreteSide) {
    const tg::FabricParams f = tg::fabric_from("cotton_jersey");
    const double overhang = 2 * std::cbrt(f.bending_un_m / (f.density_g_m2 * 9.81e-6));
    double previous = 90;
    bool settled = true;
    for (double res : {10.0, 5.0, 2.5}) {
        tg::FabricTestOptions o;
        o.resolution_mm = res;
        const double a =
            tg::cantilever_tip_angle(f, false, overhang, o, &settled, nullptr, nullptr, nullptr);
        EXPECT_LT(a, previous) << res << " mm";
        EXPECT_GT(a, 41.49) << res << " mm";
        previous = a;
    }
    EXPECT_LT(previous, 41.49 + 1.0);
    EXPECT_TRUE(settled);
}

using tapeline_test::fast_record;

// Tensile strip at 20 mm: with the secant stiffness of each load the strain is the record's E5,
// E20, E100 within 1 % (the solver's stretch constraint is linear in the stretch, so strain =
// load/k exactly at rest). With the single stiffness (the secant at 5 gf/cm, what drapes use) the
// strain grows linearly: 20× E5 at 100 gf/cm, far from E100 (4.9 %) for this stiffening curve.
TEST(GarmentFabricTests, TensileStripFollowsTheRecord) {
    const tg::Fabric f = tg::fabric_from_fast(fast_record(), "f");
    tg::FabricTestOptions o;
    o.resolution_mm = 20;
    const tg::TensileResult warp = tg::tensile_test(f, false, o);
    ASSERT_EQ(warp.points.size(), 3u);
    EXPECT_TRUE(warp.measured_curve);
    const double e[3] = {0.67, 1.87, 4.9};
    for (int i = 0; i < 3; ++i) {
        EXPECT_NEAR(warp.points[i].simulated_pct, e[i], 0.01 * e[i]) << "load " << i;
    }
    EXPECT_NEAR(warp.points[2].linear_pct, 20 * 0.67, 0.01 * 20 * 0.67);
    EXPECT_GT(std::abs(warp.points[2].linear_error_pct), 100);
    const tg::TensileResult weft = tg::tensile_test(f, true, o);
    EXPECT_NEAR(weft.points[0].simulated_pct, 0.9, 0.009);
}

// Bias extension at 20 mm: under 5 gf/cm along the bias the grain frame carries T/2 of shear, so
// the shear angle is T/(2G): G comes back within 3 % (shirting, G 800 N/m: γ = 0.18°), and for
// the FAST record (G = 123/4.7 = 26.2 N/m, γ = 5.4°) within 5 %.
TEST(GarmentFabricTests, BiasExtensionGivesTheShearRigidity) {
    tg::FabricTestOptions o;
    o.resolution_mm = 20;
    const tg::BiasResult shirting = tg::bias_test(*tg::library_fabric("cotton_shirting"), o);
    EXPECT_NEAR(shirting.simulated_shear_n_m, 800, 0.03 * 800);
    const tg::BiasResult fast = tg::bias_test(tg::fabric_from_fast(fast_record(), "f"), o);
    EXPECT_NEAR(fast.simulated_shear_n_m, 123 / 4.7, 0.05 * 123 / 4.7);
    EXPECT_NEAR(fast.shear_angle_deg, 4.903 / (2 * 123 / 4.7) * 180 / 3.14159265, 0.3);
}

// Cusick at 20 mm: a plate far stiffer than any cloth stays flat on the pedestal (DC within 1 %
// of 100 %); silk drapes more than shirting, which drapes more than the class denim.
TEST(GarmentFabricTests, CusickOrdersFabricsByBendingLength) {
    tg::FabricTestOptions o;
    o.resolution_mm = 20;
    tg::FabricParams plate = tg::fabric_from("denim");
    plate.bending_un_m = 1e6;
    const tg::CusickResult rigid = tg::cusick_test(plate, o);
    EXPECT_NEAR(rigid.drape_coefficient, 1, 0.01);
    const tg::CusickResult silk = tg::cusick_test(tg::fabric_from("silk_charmeuse"), o);
    const tg::CusickResult shirting = tg::cusick_test(tg::fabric_from("cotton_shirting"), o);
    const tg::CusickResult denim = tg::cusick_test(tg::fabric_from("denim"), o);
    EXPECT_LT(silk.drape_coefficient, shirting.drape_coefficient);
    EXPECT_LT(shirting.drape_coefficient, denim.drape_coefficient);
    EXPECT_GT(silk.drape_coefficient, 0);
    EXPECT_GE(shirting.nodes, 3);
    EXPECT_TRUE(shirting.settled);
}

// The Cusick disc is brought to its static equilibrium: denim's DC at 20 and 10 mm agree within
// 3 pp, each solve converged with no vertex's net force above 5 % of its weight. The sub-stepped
// drape's rest alone gives 56 % and 66 %: its folds stop short of the equilibrium, the more so
// the coarser the mesh.
TEST(GarmentFabricTests, CusickDiscRestsAtItsStaticEquilibrium) {
    tg::FabricTestOptions o;
    const tg::FabricParams denim = tg::fabric_from("denim");
    o.resolution_mm = 20;
    const tg::CusickResult coarse = tg::cusick_test(denim, o);
    o.resolution_mm = 10;
    const tg::CusickResult fine = tg::cusick_test(denim, o);
    for (const tg::CusickResult* r : {&coarse, &fine}) {
        EXPECT_TRUE(r->relax.converged) << r->relax.stop;
        EXPECT_LT(r->relax.max_residual_of_weight, 0.05);
        EXPECT_LT(r->relax.energy_after_j, r->relax.energy_before_j);
    }
    EXPECT_NEAR(coarse.drape_coefficient, fine.drape_coefficient, 0.03);
}

// The cloth leaving the Cusick clamp turns down at the clamp's edge whatever the fabric's
// thickness (the solver's clearance to the pedestal): a limp cloth 0.3 and 3 mm thick, the
// first edges out of the clamp descend alike (mean sine of their angle below the horizontal
// within 0.08) and steeply (above 0.6): 0.76 and 0.71. A pedestal rim under the clamp's edge
// fails both: its clearance props up the thick cloth's first edges (0.21 against 0.76).
TEST(GarmentFabricTests, CusickClothTurnsDownAtTheClampsEdge) {
    tg::FabricTestOptions o;
    o.resolution_mm = 20;
    o.max_seconds = 3;
    o.static_solve = false;  // the sub-stepped drape, where the edge contacts act
    auto first_edges_descent = [&](double thickness_mm) {
        tg::FabricParams limp = tg::fabric_from("silk_charmeuse");
        limp.thickness_mm = thickness_mm;
        limp.bending_un_m *= 0.1;
        const tg::CusickResult r = tg::cusick_test(limp, o);
        // Pinned: still at the clamp's height inside the clamp's radius.
        std::vector<char> pinned(r.positions.size(), 0);
        for (std::size_t v = 0; v < r.positions.size(); ++v) {
            const auto& p = r.positions[v];
            pinned[v] = std::abs(p[1] - thickness_mm) < 1e-9 &&
                        std::hypot(p[0], p[2]) <= r.pedestal_radius_mm + 1e-6;
        }
        double sum = 0;
        int edges = 0;
        for (const auto& t : r.triangles) {
            for (int k = 0; k < 3; ++k) {
                std::uint32_t a = t[k], b = t[(k + 1) % 3];
                if (pinned[a] == pinned[b]) {
                    continue;
                }
                if (pinned[b]) {
                    std::swap(a, b);
                }
                const auto& p = r.positions[a];
                const auto& q = r.positions[b];
                sum += (p[1] - q[1]) / std::hypot(q[0] - p[0], q[1] - p[1], q[2] - p[2]);
                ++edges;
            }
        }
        EXPECT_GT(edges, 50);
        return edges > 0 ? sum / edges : 0.0;
    };
    const double thin = first_edges_descent(0.3), thick = first_edges_descent(3);
    EXPECT_GT(thin, 0.6);
    EXPECT_GT(thick, 0.6);
    EXPECT_NEAR(thick, thin, 0.08);
}

TEST(GarmentFabricTests, RefusesBadOptions) {
    tg::FabricTestOptions o;
    o.resolution_mm = 0.2;
    try {
        tg::cantilever_test(tg::fabric_from("denim"), false, o);
        FAIL() << "a resolution of 0.2 mm was accepted";
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("resolution must be within 1 and 50 mm"),
                  std::string::npos);
    }
}

}  // namespace
