// Fabric conversions against the published constants and their own inverses; the refusals of bad
// lab records; the hinge stiffness of bending.h against the continuum energy ½·B·κ²·area of a
// cylindrical bend, on right-triangle and equilateral meshes at three edge lengths.
#include <tapeline/garment/bending.h>
#include <tapeline/garment/fabric.h>
#include <tapeline/garment/fabric_lab.h>

#include <tapeline_test/expect.h>

#include <gtest/gtest.h>
#include <tapeline_test/fabric_records.h>
#include <tapeline_test/garment_shapes.h>
#include <tapeline_test/temp_dir.h>

#include <cmath>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {

using tapeline_test::message_of;

namespace tg = tapeline::garment;
using tapeline_test::kPi;
using tg::ClothModel;
using tg::UV;
using tg::Vec3;

// Units: 1 gf = 9.80665e-3 N (standard gravity), so 1 gf·cm²/cm = 9.80665e-3·1e-4/1e-2 N·m and
// 1 gf/(cm·deg) = 0.980665 N/m per (π/180 rad).
TEST(GarmentFabricLab, UnitConversions) {
    EXPECT_NEAR(tg::kKesBendingToNm, 9.807e-5, 1e-8);
    EXPECT_NEAR(tg::kKesBendingToNm, 9.80665e-3 * 1e-4 / 1e-2, 1e-15);
    EXPECT_NEAR(tg::kKesShearToNPerMRad, 56.19, 0.01);
    EXPECT_NEAR(tg::kKesShearToNPerMRad * kPi / 180, 0.980665, 1e-12);
    // The FAST lab-report example (garment_next.md §3.3): W 168 g/m², C 15 mm: B 5.56 µN·m;
    // EB5 4.7 %: G 26.17 N/m.
    EXPECT_NEAR(tg::fast_bending_un_m(168, 15), 5.56, 0.005);
    EXPECT_NEAR(tg::fast_shear_n_m(4.7), 26.17, 0.005);
    // G = (T/2)/γ with γ = 2·EB5/100 at T = 5 gf/cm: the constant 123 from first principles.
    EXPECT_NEAR(5 * 0.980665 / 4 * 100, 123, 0.5);
    // Round trips.
    for (double c : {8.0, 15.0, 31.5}) {
        EXPECT_NEAR(tg::bending_length_mm(tg::fast_bending_un_m(210, c), 210), c, 1e-9 * c);
    }
    EXPECT_NEAR(tg::bias_extension_pct_of(tg::fast_shear_n_m(3.3)), 3.3, 1e-12);
    EXPECT_NEAR(tg::secant_stiffness_n_m(5, 1.0), 490.3325, 1e-9);
}

using tapeline_test::fast_record;

nlohmann::json kes_record() {
    nlohmann::json j = {{"W", 16.8}};
    const std::map<std::string, std::pair<double, double>> v = {
        {"LT", {0.65, 0.7}},   {"EMT", {4.0, 6.0}}, {"RT", {65, 60}},    {"B", {0.09, 0.07}},
        {"2HB", {0.04, 0.03}}, {"G", {0.8, 0.7}},   {"2HG", {0.9, 0.8}}, {"2HG5", {1.9, 1.7}}};
    for (const auto& [k, wv] : v) {
        j[k + "_warp"] = wv.first;
        j[k + "_weft"] = wv.second;
    }
    j["WT_warp"] = 0.65 * 250 * 0.04;
    j["WT_weft"] = 0.7 * 250 * 0.06;
    return j;
}

TEST(GarmentFabricLab, FastRecord) {
    const tg::Fabric f = tg::fabric_from_fast(fast_record(), "f.json");
    EXPECT_DOUBLE_EQ(f.params.density_g_m2, 168);
    EXPECT_NEAR(f.params.bending_un_m, 5.56, 0.005);
    EXPECT_NEAR(tg::bending_length_mm(f.params.bending_un_m, 168), 15, 1e-9);
    EXPECT_NEAR(tg::bending_length_mm(tg::bending_weft_of(f.params), 168), 12, 1e-9);
    EXPECT_NEAR(f.params.shear_n_m, 26.17, 0.005);
    // The secant stiffness gives back E5: strain = load / k.
    EXPECT_NEAR(5 * 0.980665 / f.params.stretch_warp_n_m * 100, 0.67, 1e-12);
    EXPECT_DOUBLE_EQ(f.extension_weft_pct[2], 6.8);
    EXPECT_DOUBLE_EQ(f.params.thickness_mm, 0.62);
    // Formability F = (E20 − E5)·B/14.7 (mm²) of the lab report: 0.45.
    EXPECT_NEAR((f.extension_warp_pct[1] - f.extension_warp_pct[0]) * f.params.bending_un_m / 14.7,
                0.45, 0.005);
}

TEST(GarmentFabricLab, KesRecord) {
    const tg::Fabric f = tg::fabric_from_kes(kes_record(), "k.json");
    EXPECT_DOUBLE_EQ(f.params.density_g_m2, 168);
    EXPECT_NEAR(f.params.bending_un_m, 0.09 * 98.0665, 1e-9);
    EXPECT_NEAR(f.params.shear_n_m, 0.75 * 56.19, 0.01);
    // The power-law curve passes through (EMT, 500 gf/cm) and its energy ∫F dε, integrated here
    // numerically from the strain function, is WT.
    const double emt = 4.0, lt = 0.65;
    EXPECT_NEAR(tg::kes_strain_pct(emt, lt, 500), emt, 1e-12);
    double wt = 0;
    const int n = 20000;
    for (int i = 0; i < n; ++i) {  // ∫F dε = Fm·εm − ∫ε dF (integration by parts)
        const double f0 = 500.0 * i / n, f1 = 500.0 * (i + 1) / n;
        wt += 0.5 * (tg::kes_strain_pct(emt, lt, f0) + tg::kes_strain_pct(emt, lt, f1)) / 100 *
              (f1 - f0);
    }
    wt = 500 * emt / 100 - wt;
    EXPECT_NEAR(wt, 0.65 * 250 * 0.04, 1e-3);
    EXPECT_LT(f.extension_warp_pct[0], f.extension_warp_pct[1]);
    EXPECT_NEAR(5 * 0.980665 / f.params.stretch_warp_n_m * 100, f.extension_warp_pct[0], 1e-12);
}

TEST(GarmentFabricLab, RefusalsNameTheKeys) {
    auto fast = fast_record();
    fast["E50_warp"] = 1;
    EXPECT_NE(message_of<tapeline::InvalidInput>([&] {
                  tg::fabric_from_fast(fast, "f.json");
              }).find("f.json: unknown FAST key(s): E50_warp"),
              std::string::npos);
    fast = fast_record();
    fast.erase("C_weft");
    fast.erase("EB5");
    EXPECT_NE(message_of<tapeline::InvalidInput>([&] {
                  tg::fabric_from_fast(fast, "f.json");
              }).find("f.json: missing FAST key(s): C_weft, EB5"),
              std::string::npos);
    fast = fast_record();
    fast["C_warp"] = -3;
    EXPECT_NE(message_of<tapeline::InvalidInput>([&] {
                  tg::fabric_from_fast(fast, "f.json");
              }).find("\"C_warp\" must be a positive finite number, got -3"),
              std::string::npos);
    fast = fast_record();
    fast["E20_warp"] = 0.5;
    EXPECT_NE(message_of<tapeline::InvalidInput>([&] {
                  tg::fabric_from_fast(fast, "f.json");
              }).find("E5_warp < E20_warp"),
              std::string::npos);
    auto kes = kes_record();
    kes.erase("2HG5_weft");
    EXPECT_NE(message_of<tapeline::InvalidInput>([&] {
                  tg::fabric_from_kes(kes, "k.json");
              }).find("k.json: missing KES key(s): 2HG5_weft"),
              std::string::npos);
    kes = kes_record();
    kes["WT_warp"] = 20;
    EXPECT_NE(message_of<tapeline::InvalidInput>([&] {
                  tg::fabric_from_kes(kes, "k.json");
              }).find("WT_warp"),
              std::string::npos);
    EXPECT_NE(message_of<tapeline::InvalidInput>([&] {
                  tg::fabric_from_json({{"bending_un_m", "soft"}}, "x.json");
              }).find("x.json: \"bending_un_m\" must be a non-negative"),
              std::string::npos);
}

// FabricParams{} (the default of DressOptions, of the solver's users) carries the catalogue's
// name "cotton_jersey": its values must be that fabric's, or a default-built garment would be
// reported as a cloth it is not.
TEST(GarmentFabricLab, DefaultParamsAreTheCataloguesCottonJersey) {
    const tg::FabricParams d;
    const tg::Fabric* c = tg::library_fabric(d.name);
    ASSERT_NE(c, nullptr);
    EXPECT_EQ(tg::fabric_json(tg::Fabric{d, c->source}), tg::fabric_json(*c));
}

TEST(GarmentFabricLab, LibraryAndFileRoundTrip) {
    std::size_t wang = 0;
    for (const tg::Fabric& f : tg::fabric_library()) {
        const tg::Fabric back = tg::fabric_from_json(tg::fabric_json(f), "x");
        EXPECT_EQ(back.params.name, f.params.name);
        EXPECT_DOUBLE_EQ(back.params.bending_un_m, f.params.bending_un_m);
        EXPECT_DOUBLE_EQ(tg::bending_weft_of(back.params), tg::bending_weft_of(f.params));
        EXPECT_DOUBLE_EQ(tg::bending_bias_of(back.params), tg::bending_bias_of(f.params));
        EXPECT_DOUBLE_EQ(back.params.shear_n_m, f.params.shear_n_m);
        EXPECT_FALSE(f.source.empty());
        wang += f.source.find("Wang") != std::string::npos ? 1 : 0;
    }
    EXPECT_EQ(wang, 10u);
    // The denim of Wang et al.: 0.324 kg/m², hinge constants 64/73/97 µN·m at 0°/45°/90°.
    const tg::Fabric* d = tg::library_fabric("11oz-black-denim");
    ASSERT_NE(d, nullptr);
    EXPECT_DOUBLE_EQ(d->params.bending_un_m, 97.0 / 4);
    EXPECT_DOUBLE_EQ(tg::bending_weft_of(d->params), 64.0 / 4);
    EXPECT_DOUBLE_EQ(d->params.stretch_warp_n_m, 410);
    // A FAST record converted and written reads back with its lab figures.
    const tg::Fabric f = tg::fabric_from_fast(fast_record(), "f.json");
    const tapeline_test::TempDir tmp;
    const std::string path = tmp.file("fabric_fast.json");
    { std::ofstream(path) << tg::fabric_json(f).dump(1); }
    const tg::Fabric back = tg::fabric_record_from(path);
    EXPECT_DOUBLE_EQ(back.extension_warp_pct[1], 1.87);
    EXPECT_DOUBLE_EQ(back.bias_extension_pct, 4.7);
    EXPECT_DOUBLE_EQ(back.params.stretch_weft_n_m, f.params.stretch_weft_n_m);
}

// --- Bending: hinge energy against ½·B·κ²
// ---------------------------------------------------------

// Equilateral triangles of side `a` over about w × h (rows shifted by a/2), grain along x.
ClothModel equilateral_patch(double w, double h, double a) {
    ClothModel c;
    const int nx = static_cast<int>(std::round(w / a)),
              ny = static_cast<int>(std::round(h / (a * std::sqrt(3.0) / 2)));
    const double rh = a * std::sqrt(3.0) / 2;
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            c.positions.push_back({i * a + (j % 2) * a / 2, j * rh, 0});
        }
    }
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
    auto add = [&](std::uint32_t p, std::uint32_t q, std::uint32_t r) {
        c.triangles.push_back({p, q, r});
        auto uv = [&](std::uint32_t v) { return UV{c.positions[v][0], c.positions[v][1]}; };
        c.rest_uv.push_back({uv(p), uv(q), uv(r)});
        c.grain.push_back({1, 0});
    };
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            if (j % 2 == 0) {
                add(at(i, j), at(i + 1, j), at(i, j + 1));
                add(at(i + 1, j), at(i + 1, j + 1), at(i, j + 1));
            } else {
                add(at(i, j), at(i + 1, j + 1), at(i, j + 1));
                add(at(i, j), at(i + 1, j), at(i + 1, j + 1));
            }
        }
    }
    return c;
}

// Ratio of the hinge energy Σ ½·k_e·θ_e² to ½·B(ψ)·κ²·(area carried by the hinges, Σ A_e/3) over a
// window in the middle of the patch when
// the flat patch is wrapped isometrically onto a cylinder of radius R whose curvature runs along
// the direction at angle psi to the warp (x).
double hinge_energy_ratio(const ClothModel& c, const tg::FabricParams& f, double radius,
                          double psi) {
    const double dx = std::cos(psi), dy = std::sin(psi);
    std::vector<Vec3> x(c.positions.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        const double s = c.positions[i][0] * dx + c.positions[i][1] * dy;
        const double t = -c.positions[i][0] * dy + c.positions[i][1] * dx;
        const double u = radius * std::sin(s / radius);
        x[i] = {u * dx - t * dy, u * dy + t * dx, radius * (1 - std::cos(s / radius))};
    }
    auto sub = [](const Vec3& a, const Vec3& b) {
        return Vec3{a[0] - b[0], a[1] - b[1], a[2] - b[2]};
    };
    auto cross = [](const Vec3& a, const Vec3& b) {
        return Vec3{a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2],
                    a[0] * b[1] - a[1] * b[0]};
    };
    auto dot = [](const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; };
    std::map<std::pair<std::uint32_t, std::uint32_t>, std::vector<std::size_t>> edges;
    for (std::size_t t = 0; t < c.triangles.size(); ++t) {
        for (int k = 0; k < 3; ++k) {
            auto a = c.triangles[t][k], b = c.triangles[t][(k + 1) % 3];
            edges[{std::min(a, b), std::max(a, b)}].push_back(t);
        }
    }
    auto rest_area = [&](std::size_t t) {
        const auto& p = c.positions;
        const auto& tri = c.triangles[t];
        return 0.5 * std::abs((p[tri[1]][0] - p[tri[0]][0]) * (p[tri[2]][1] - p[tri[0]][1]) -
                              (p[tri[2]][0] - p[tri[0]][0]) * (p[tri[1]][1] - p[tri[0]][1]));
    };
    auto normal = [&](std::size_t t) {
        const auto& tri = c.triangles[t];
        Vec3 n = cross(sub(x[tri[1]], x[tri[0]]), sub(x[tri[2]], x[tri[0]]));
        const double l = std::sqrt(dot(n, n));
        return Vec3{n[0] / l, n[1] / l, n[2] / l};
    };
    double energy = 0, area = 0;
    for (const auto& [e, ts] : edges) {
        // Each edge belongs to its lower end (smaller y, then smaller x); the edges of the
        // vertices in the window [40, 160)² are all interior and weigh the window's triangles
        // once each (three edges per vertex; on right grids the alternating diagonals balance
        // over an even number of cells).
        const auto& pa = c.positions[e.first];
        const auto& pb = c.positions[e.second];
        const bool a_low = pa[1] < pb[1] || (pa[1] == pb[1] && pa[0] < pb[0]);
        const auto& owner = a_low ? pa : pb;
        if (owner[0] < 40 - 1e-9 || owner[0] >= 160 - 1e-9 || owner[1] < 40 - 1e-9 ||
            owner[1] >= 160 - 1e-9) {
            continue;
        }
        if (ts.size() != 2) {
            ADD_FAILURE() << "boundary edge in the window";
            continue;
        }
        const double area_e = rest_area(ts[0]) + rest_area(ts[1]);
        const UV edge{c.positions[e.second][0] - c.positions[e.first][0],
                      c.positions[e.second][1] - c.positions[e.first][1]};
        const double k = tg::hinge_stiffness_un_m(f, edge, {1, 0}, area_e);
        // Both triangles are oriented alike (counter-clockwise in the rest plane): the dihedral
        // angle is the angle between their normals.
        const double theta = std::acos(std::min(1.0, dot(normal(ts[0]), normal(ts[1]))));
        energy += 0.5 * k * theta * theta;
        area += area_e / 3;
    }
    const double kappa = 1 / radius;
    return energy / (0.5 * tg::bending_rigidity_un_m(f, dx, dy) * kappa * kappa * area);
}

// Orient every triangle counter-clockwise in the rest plane (the generators alternate).
ClothModel counter_clockwise(ClothModel c) {
    for (std::size_t t = 0; t < c.triangles.size(); ++t) {
        auto& tri = c.triangles[t];
        const auto& p = c.positions;
        const double det = (p[tri[1]][0] - p[tri[0]][0]) * (p[tri[2]][1] - p[tri[0]][1]) -
                           (p[tri[2]][0] - p[tri[0]][0]) * (p[tri[1]][1] - p[tri[0]][1]);
        if (det < 0) {
            std::swap(tri[1], tri[2]);
            std::swap(c.rest_uv[t][1], c.rest_uv[t][2]);
        }
    }
    return c;
}

// The energy of a cylindrical bend (radius 150 mm over a 200 mm patch, θ per edge ≤ 8°) matches
// ½·B·κ²·area within 2 % (the dihedral angle of a chord differs from the small-angle value by
// O(θ²) = 0.5 % at 20 mm; the rest is rounding) at 20, 10 and 5 mm: on equilateral meshes in
// every direction, on right-triangle grids along the warp and the weft (across them the grid's
// diagonals make it about 1.5 times stiffer, bending.h says why).
TEST(GarmentFabricBending, HingeEnergyIsTheContinuumEnergyAtEveryResolution) {
    tg::FabricParams iso;
    iso.bending_un_m = 12;
    for (double a : {20.0, 10.0, 5.0}) {
        const ClothModel eq = counter_clockwise(equilateral_patch(200, 200, a));
        const int n = static_cast<int>(200 / a);
        const ClothModel rt =
            counter_clockwise(tapeline_test::cloth_grid(n, n, a, {0, 0, 0}, {1, 0, 0}, {0, 1, 0}));
        for (double deg : {0.0, 20.0, 45.0, 90.0, 135.0}) {
            EXPECT_NEAR(hinge_energy_ratio(eq, iso, 150, deg * kPi / 180), 1, 0.02)
                << "equilateral, a = " << a << " mm, bend at " << deg << "°";
        }
        for (double deg : {0.0, 90.0}) {
            EXPECT_NEAR(hinge_energy_ratio(rt, iso, 150, deg * kPi / 180), 1, 0.02)
                << "right triangles, a = " << a << " mm, bend at " << deg << "°";
        }
        // Anisotropic (warp 10, weft 40 µN·m): along the grain lines of the right grid each
        // direction has its own rigidity.
        tg::FabricParams aniso;
        aniso.bending_un_m = 10;
        aniso.bending_weft_un_m = 40;
        aniso.bending_bias_un_m = 20;
        EXPECT_NEAR(hinge_energy_ratio(rt, aniso, 150, 0), 1, 0.02) << "warp, a = " << a;
        EXPECT_NEAR(hinge_energy_ratio(rt, aniso, 150, kPi / 2), 1, 0.02) << "weft, a = " << a;
    }
}

TEST(GarmentFabricBending, DirectionalRigidity) {
    tg::FabricParams f;
    f.bending_un_m = 10;
    f.bending_weft_un_m = 40;
    f.bending_bias_un_m = 20;
    EXPECT_DOUBLE_EQ(tg::bending_rigidity_un_m(f, 1, 0), 10);
    EXPECT_DOUBLE_EQ(tg::bending_rigidity_un_m(f, 0, 3), 40);
    EXPECT_NEAR(tg::bending_rigidity_un_m(f, 1, 1), 20, 1e-12);
    EXPECT_NEAR(tg::bending_rigidity_un_m(f, -1, 1), 20, 1e-12);
    tg::FabricParams iso;
    iso.bending_un_m = 7;
    for (double a = 0; a < 3; a += 0.3) {
        EXPECT_NEAR(tg::bending_rigidity_un_m(iso, std::cos(a), std::sin(a)), 7, 1e-12);
    }
    // A hinge along the warp bends the weft.
    EXPECT_NEAR(tg::hinge_stiffness_un_m(f, {10, 0}, {1, 0}, 100), 40, 1e-12);
    EXPECT_NEAR(tg::hinge_stiffness_un_m(f, {0, 10}, {1, 0}, 100), 10, 1e-12);
}

}  // namespace
