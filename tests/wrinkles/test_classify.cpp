// Wrinkle strains, curvatures and classes against analytic deformations; the wavelength and
// amplitude laws against their closed forms and an independent arc-length integration; the
// garment OBJ round trip; bad inputs.
#include <tapeline/garment/garment_io.h>
// Every wrinkle header in one unit: they must not define the same name twice.
#include <tapeline/wrinkles/buckling_tests.h>
#include <tapeline/wrinkles/classify.h>
#include <tapeline/wrinkles/compare.h>
#include <tapeline/wrinkles/picture.h>

#include <gtest/gtest.h>
#include <tapeline_test/temp_dir.h>

#include "invalid_input.h"

#include <cmath>
#include <cstdio>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>

namespace tw = tapeline::wrinkles;
namespace tg = tapeline::garment;
using tw::UV;
using tw::Vec3;

using tapeline::test::error_of;

namespace {

/// A grid of nx × ny cells of `cell` mm in the pattern (u, v), each cell two triangles, placed in
/// 3D by `place(u, v)`; grain +y (the warp along v).
tg::GarmentMesh grid(int nx, int ny, double cell,
                     const std::function<Vec3(double, double)>& place) {
    tg::GarmentMesh g;
    auto id = [&](int i, int j) { return std::uint32_t(j * (nx + 1) + i); };
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            g.positions.push_back(place(i * cell, j * cell));
        }
    }
    auto uv = [&](std::uint32_t k) {
        return UV{double(k % std::uint32_t(nx + 1)) * cell,
                  double(k / std::uint32_t(nx + 1)) * cell};
    };
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            const tg::Tri a{id(i, j), id(i + 1, j), id(i + 1, j + 1)};
            const tg::Tri b{id(i, j), id(i + 1, j + 1), id(i, j + 1)};
            for (const tg::Tri& t : {a, b}) {
                g.triangles.push_back(t);
                g.uv.push_back({uv(t[0]), uv(t[1]), uv(t[2])});
                g.triangle_piece.push_back(0);
            }
        }
    }
    g.piece_names = {"panel"};
    return g;
}

/// An affine map of the pattern plane into 3D: (u, v) -> u·a + v·b + o.
std::function<Vec3(double, double)> affine(Vec3 a, Vec3 b, Vec3 o = {0, 0, 0}) {
    return [=](double u, double v) {
        return Vec3{u * a[0] + v * b[0] + o[0], u * a[1] + v * b[1] + o[1],
                    u * a[2] + v * b[2] + o[2]};
    };
}

/// Rotation about the unit axis `k` by `angle`.
Vec3 rotate(const Vec3& p, const Vec3& k, double angle) {
    const double c = std::cos(angle), s = std::sin(angle);
    const Vec3 kxp = tapeline::vec3::cross(k, p);
    const double kp = tapeline::vec3::dot(k, p);
    return {p[0] * c + kxp[0] * s + k[0] * kp * (1 - c),
            p[1] * c + kxp[1] * s + k[1] * kp * (1 - c),
            p[2] * c + kxp[2] * s + k[2] * kp * (1 - c)};
}

}  // namespace

TEST(WrinkleStrain, PrincipalStretchesAndGrainStrainsOfAnAffineMap) {
    // Weft (u) shortened to 0.9, warp (v) stretched to 1.1, then turned in space: a rigid motion
    // changes no strain.
    const Vec3 axis = tapeline::vec3::normalized({1, 2, 3});
    const tg::GarmentMesh g = grid(1, 1, 10, [&](double u, double v) {
        return tapeline::vec3::add(rotate({0.9 * u, 1.1 * v, 0}, axis, 0.7), Vec3{5, -3, 2});
    });
    const tw::TriangleStrain s =
        tw::triangle_strain(g.positions[g.triangles[0][0]], g.positions[g.triangles[0][1]],
                            g.positions[g.triangles[0][2]], g.uv[0], UV{0, 1});
    ASSERT_TRUE(s.valid);
    EXPECT_NEAR(s.s_max, 1.1, 1e-12);
    EXPECT_NEAR(s.s_min, 0.9, 1e-12);
    EXPECT_NEAR(s.warp_strain, 0.1, 1e-12);
    EXPECT_NEAR(s.weft_strain, -0.1, 1e-12);
    EXPECT_NEAR(s.shear_rad, 0, 1e-12);
    EXPECT_NEAR(s.min_angle_from_warp_deg, 90, 1e-9);  // shortened across the warp
    EXPECT_NEAR(std::abs(s.rest_max[1]), 1, 1e-12);    // stretched along v
    const Vec3 v_dir = rotate({0, 1, 0}, axis, 0.7);
    EXPECT_NEAR(std::abs(tapeline::vec3::dot(s.dir_max, v_dir)), 1, 1e-12);
}

TEST(WrinkleStrain, SimpleShearHasItsAngleAndItsAxesOnTheBias) {
    // Warp along u; v slides by γ·v along u: the yarns close by atan γ, det F = 1, and the
    // principal axes of C = FᵀF lie at 45° + atan(γ/2)/2 (stretch) and 135° + atan(γ/2)/2
    // (compression) from the warp: near the bias.
    const double gamma = 0.2;
    const tg::GarmentMesh g = grid(1, 1, 10, affine({1, 0, 0}, {gamma, 1, 0}));
    const tw::TriangleStrain s =
        tw::triangle_strain(g.positions[g.triangles[0][0]], g.positions[g.triangles[0][1]],
                            g.positions[g.triangles[0][2]], g.uv[0], UV{1, 0});
    EXPECT_NEAR(s.shear_rad, std::atan(gamma), 1e-12);
    EXPECT_NEAR(s.s_max * s.s_min, 1, 1e-12);
    const double expect_max =
        std::sqrt(1 + gamma * gamma / 2 + gamma * std::sqrt(1 + gamma * gamma / 4));
    EXPECT_NEAR(s.s_max, expect_max, 1e-12);
    EXPECT_NEAR(s.min_angle_from_warp_deg, 135 + 0.5 * std::atan(gamma / 2) * 180 / M_PI, 1e-9);
    tg::FabricParams f;
    tg::GarmentMesh gw = g;
    gw.grain.assign(g.triangles.size(), UV{1, 0});
    const tw::WrinkleField ws = tw::classify_wrinkles(gw, f);
    for (const auto& t : ws.triangles) {
        EXPECT_EQ(t.cls, tw::WrinkleClass::shear);
    }
}

TEST(WrinkleClasses, EachDeformationHasItsClass) {
    tg::FabricParams f;
    struct Case {
        double su, sv;
        tw::WrinkleClass expect;
    };
    // Warp along v (default grain): su is the weft stretch, sv the warp stretch.
    for (const Case& c : {Case{1.05, 1.05, tw::WrinkleClass::none},     // stretched both ways
                          Case{1.0, 1.0, tw::WrinkleClass::none},       // at rest
                          Case{0.995, 1.0, tw::WrinkleClass::none},     // below the threshold
                          Case{0.95, 1.04, tw::WrinkleClass::tension},  // pulled along v
                          Case{1.04, 0.95, tw::WrinkleClass::tension},  // pulled along u
                          Case{0.95, 1.0, tw::WrinkleClass::compression},
                          Case{0.9, 0.9, tw::WrinkleClass::compression}}) {
        const tg::GarmentMesh g = grid(2, 2, 10, affine({c.su, 0, 0}, {0, c.sv, 0}));
        const tw::WrinkleField w = tw::classify_wrinkles(g, f);
        for (const auto& t : w.triangles) {
            EXPECT_EQ(t.cls, c.expect) << c.su << " " << c.sv << ": " << tw::to_string(t.cls);
        }
        EXPECT_EQ(w.report.count[std::size_t(c.expect)], g.triangles.size());
        EXPECT_NEAR(w.report.area_percent[std::size_t(c.expect)], 100, 1e-9);
    }
}

TEST(WrinkleClasses, ThresholdsMoveTheBorders) {
    tg::FabricParams f;
    const tg::GarmentMesh g = grid(1, 1, 10, affine({0.97, 0, 0}, {0, 1.02, 0}));
    EXPECT_EQ(tw::classify_wrinkles(g, f).triangles[0].cls, tw::WrinkleClass::tension);
    tw::ClassifyOptions o;
    o.tension_threshold = 0.05;
    EXPECT_EQ(tw::classify_wrinkles(g, f, o).triangles[0].cls, tw::WrinkleClass::compression);
    o.compression_threshold = 0.05;
    EXPECT_EQ(tw::classify_wrinkles(g, f, o).triangles[0].cls, tw::WrinkleClass::none);
}

TEST(WrinkleCurvature, SphereAndCylinderHaveTheirNormalCurvatures) {
    // A cylinder of radius 100 mm around the y axis: 1/R around, 0 along the axis. A fine grid
    // of the pattern wrapped on it (angle = u/R), so the fitted shape operator is close to exact.
    const double R = 100;
    const tg::GarmentMesh cyl = grid(40, 10, 4, [&](double u, double v) {
        return Vec3{R * std::sin(u / R), v, R * std::cos(u / R)};
    });
    const auto n = tapeline::draw::vertex_normals(cyl.positions, cyl.triangles);
    for (std::size_t f = 80; f < cyl.triangles.size() - 80; f += 7) {  // rows 1 to 8 of 10
        const std::size_t col = (f % 80) / 2;
        if (col == 0 || col == 39) {
            continue;  // the border's vertex normals are one-sided
        }
        const auto k = tw::triangle_curvature(cyl.positions, cyl.triangles[f], n);
        const auto& t = cyl.triangles[f];
        const Vec3 c = tapeline::vec3::scale(
            tapeline::vec3::add(tapeline::vec3::add(cyl.positions[t[0]], cyl.positions[t[1]]),
                                cyl.positions[t[2]]),
            1.0 / 3);
        const Vec3 around = tapeline::vec3::normalized({c[2], 0, -c[0]});
        EXPECT_NEAR(std::abs(k.along(around)), 1 / R, 0.02 / R) << f;
        EXPECT_NEAR(k.along({0, 1, 0}), 0, 0.02 / R) << f;
    }
    // A sphere patch of radius 50 mm: 1/R in every direction.
    const double Rs = 50;
    const tg::GarmentMesh sph = grid(20, 20, 2, [&](double u, double v) {
        const double th = (u - 20) / Rs, ph = (v - 20) / Rs;
        return Vec3{Rs * std::sin(th) * std::cos(ph), Rs * std::sin(ph),
                    Rs * std::cos(th) * std::cos(ph)};
    });
    const auto ns = tapeline::draw::vertex_normals(sph.positions, sph.triangles);
    for (std::size_t f = 300; f < 500; f += 11) {
        const std::size_t col = (f % 40) / 2;
        if (col == 0 || col == 19) {
            continue;  // the border's vertex normals are one-sided
        }
        const auto k = tw::triangle_curvature(sph.positions, sph.triangles[f], ns);
        for (const Vec3& d : {k.t1, k.t2, tapeline::vec3::add(k.t1, k.t2)}) {
            EXPECT_NEAR(std::abs(k.along(d)), 1 / Rs, 0.03 / Rs) << f;
        }
    }
}

TEST(WrinkleWavelength, CurvedTensionedSheetFollowsTheLaw) {
    // Cloth wrapped on a cylinder of radius R: pulled 2 % around (the weft: pattern u), 6 % short
    // along the axis (the warp: pattern v, grain +y). Tension wrinkles with crests around the
    // cylinder, waves along the axis: T = k_weft·0.02 around, κ = 1/R along the crests, B the
    // warp rigidity (curvature along the warp): λ = 2π·(B·R²/T)^{1/4}.
    const double R = 80;
    tg::FabricParams f;
    f.stretch_weft_n_m = 900;
    f.bending_un_m = 4;
    f.bending_weft_un_m = 9;
    const tg::GarmentMesh g = grid(60, 12, 4, [&](double u, double v) {
        const double a = 1.02 * u / R;
        return Vec3{R * std::sin(a), 0.94 * v, R * std::cos(a)};
    });
    const tw::WrinkleField w = tw::classify_wrinkles(g, f);
    const double T = 900 * 0.02, Rm = R * 1e-3, B = 4e-6;
    const double expect = 2 * M_PI * std::pow(B * Rm * Rm / T, 0.25) * 1e3;
    const double expect_amp = expect / M_PI * std::sqrt(0.06);
    std::size_t checked = 0;
    for (std::size_t f0 = 0; f0 < w.triangles.size(); ++f0) {
        const auto& t = w.triangles[f0];
        EXPECT_EQ(t.cls, tw::WrinkleClass::tension);
        EXPECT_NEAR(t.tension_n_m, T, 0.01 * T);
        EXPECT_NEAR(t.bending_un_m, 4, 1e-9);
        // The border rows' normals lean: check the interior.
        const std::size_t row = f0 / 120, col = (f0 % 120) / 2;
        if (row >= 1 && row + 1 < 12 && col >= 1 && col + 1 < 60) {
            EXPECT_NEAR(t.wavelength_mm, expect, 0.02 * expect) << f0;
            EXPECT_NEAR(t.amplitude_mm, expect_amp, 0.02 * expect_amp) << f0;
            ++checked;
        }
    }
    EXPECT_GT(checked, 500u);
    EXPECT_NEAR(w.report.median_wavelength_mm[std::size_t(tw::WrinkleClass::tension)], expect,
                0.01 * expect);
    EXPECT_EQ(w.report.predicted, w.triangles.size());
    // Sixteen times the rigidity: twice the wavelength.
    f.bending_un_m = 64;
    const tw::WrinkleField w16 = tw::classify_wrinkles(g, f);
    EXPECT_NEAR(w16.report.median_wavelength_mm[1] / w.report.median_wavelength_mm[1], 2, 1e-9);
}

TEST(WrinkleWavelength, FlatSheetHasNoFoundationUnlessALengthIsGiven) {
    tg::FabricParams f;
    const tg::GarmentMesh g = grid(4, 4, 10, affine({1.03, 0, 0}, {0, 0.95, 0}));
    const tw::WrinkleField w = tw::classify_wrinkles(g, f);
    EXPECT_EQ(w.report.predicted, 0u);
    EXPECT_EQ(w.report.no_foundation, g.triangles.size());
    EXPECT_TRUE(std::isnan(w.triangles[0].wavelength_mm));
    tw::ClassifyOptions o;
    o.tension_length_mm = 300;
    const tw::WrinkleField wl = tw::classify_wrinkles(g, f, o);
    // K = T·(π/L)², T along the weft (u) = k_weft·0.03; waves along the warp: B = bending_un_m.
    const double T = f.stretch_weft_n_m * 0.03, q = M_PI / 0.3;
    const double expect = 2 * M_PI * std::pow(f.bending_un_m * 1e-6 / (T * q * q), 0.25) * 1e3;
    EXPECT_NEAR(wl.triangles[0].wavelength_mm, expect, 1e-9 * expect);
    EXPECT_EQ(wl.report.predicted, g.triangles.size());
}

TEST(WrinkleAmplitude, ExcessLengthOfASineGivesItsAmplitude) {
    // Independent: the arc length of A·sin(2πx/λ) over one period, by Simpson's rule.
    const double lambda = 40, A = 2.0;
    const int n = 20000;
    double len = 0;
    for (int i = 0; i <= n; ++i) {
        const double x = lambda * i / n;
        const double d = 2 * M_PI * A / lambda * std::cos(2 * M_PI * x / lambda);
        const double w = (i == 0 || i == n) ? 1 : (i % 2 ? 4 : 2);
        len += w * std::sqrt(1 + d * d);
    }
    len *= lambda / n / 3;
    const double excess = len / lambda - 1;
    // Small slopes (2πA/λ = 0.31): the law is good to the next order, (3/16)·(2πA/λ)².
    EXPECT_NEAR(tw::wrinkle_amplitude_mm(lambda, excess), A, 0.03 * A);
    EXPECT_TRUE(std::isnan(tw::wrinkle_amplitude_mm(lambda, -0.1)));
    EXPECT_NEAR(tw::buckling_wavelength_mm(1, 1e3), 2 * M_PI * std::pow(1e-9, 0.25) * 1e3, 1e-9);
    EXPECT_TRUE(std::isnan(tw::buckling_wavelength_mm(1, 0)));
}

TEST(WrinkleClasses, BadInputsAreNamed) {
    tg::FabricParams f;
    tg::GarmentMesh g = grid(2, 1, 10, affine({0.9, 0, 0}, {0, 1, 0}));
    auto bad = g;
    bad.positions[2][1] = std::nan("");
    EXPECT_NE(error_of([&] { tw::classify_wrinkles(bad, f); }).find("vertex 2"), std::string::npos);
    bad = g;
    bad.triangles[3][1] = 99;
    EXPECT_NE(error_of([&] { tw::classify_wrinkles(bad, f); }).find("triangle 3 names vertex 99"),
              std::string::npos);
    bad = g;
    bad.uv.pop_back();
    EXPECT_NE(error_of([&] { tw::classify_wrinkles(bad, f); }).find("pattern triangles"),
              std::string::npos);
    bad = g;
    bad.uv[1][2][0] = INFINITY;
    EXPECT_NE(error_of([&] { tw::classify_wrinkles(bad, f); }).find("triangle 1"),
              std::string::npos);
    bad = g;
    bad.grain.assign(g.triangles.size(), UV{0, 1});
    bad.grain[2] = {0, 0};
    EXPECT_NE(error_of([&] { tw::classify_wrinkles(bad, f); }).find("triangle 2 has a grain"),
              std::string::npos);
    tg::FabricParams limp = f;
    limp.bending_un_m = 0;
    EXPECT_NE(error_of([&] { tw::classify_wrinkles(g, limp); }).find("bending_un_m"),
              std::string::npos);
    tw::ClassifyOptions o;
    o.compression_threshold = 0;
    EXPECT_NE(error_of([&] { tw::classify_wrinkles(g, f, o); }).find("compression_threshold"),
              std::string::npos);
    o = {};
    o.bias_window_deg = 50;
    EXPECT_NE(error_of([&] { tw::classify_wrinkles(g, f, o); }).find("bias_window_deg"),
              std::string::npos);
    // A degenerate pattern triangle is no error: class none, counted.
    bad = g;
    bad.uv[0][1] = bad.uv[0][0];
    const tw::WrinkleField w = tw::classify_wrinkles(bad, f);
    EXPECT_EQ(w.report.degenerate, 1u);
    EXPECT_EQ(w.triangles[0].cls, tw::WrinkleClass::none);
}

TEST(GarmentObj, RoundTripKeepsPositionsPatternAndGrain) {
    tg::GarmentMesh g = grid(3, 2, 10, affine({0.9, 0.1, 0}, {0, 1.1, 0.2}, {1, 2, 3}));
    // Two pieces, the second with its own grain.
    g.piece_names = {"front", "back piece"};
    g.grain.assign(g.triangles.size(), UV{0, 1});
    for (std::size_t f = 6; f < g.triangles.size(); ++f) {
        g.triangle_piece[f] = 1;
        g.grain[f] = {0.6, 0.8};
    }
    std::ostringstream os;
    tg::write_garment_obj(os, g, [](const Vec3& p) { return p; });
    const tapeline_test::TempDir tmp;
    const std::string path = tmp.file("wrinkles_roundtrip.obj");
    std::ofstream(path) << os.str();
    const tg::GarmentMesh r = tg::read_garment_obj(path);
    ASSERT_EQ(r.triangles.size(), g.triangles.size());
    ASSERT_EQ(r.positions.size(), g.positions.size());
    EXPECT_EQ(r.piece_names, (std::vector<std::string>{"front", "back_piece"}));
    for (std::size_t f = 0; f < g.triangles.size(); ++f) {
        EXPECT_EQ(r.triangles[f], g.triangles[f]);
        EXPECT_EQ(r.triangle_piece[f], g.triangle_piece[f]);
        for (int k = 0; k < 2; ++k) {
            EXPECT_NEAR(r.grain[f][std::size_t(k)], g.grain[f][std::size_t(k)], 1e-9);
        }
        for (int c = 0; c < 3; ++c) {
            for (int k = 0; k < 2; ++k) {
                EXPECT_NEAR(r.uv[f][std::size_t(c)][std::size_t(k)],
                            g.uv[f][std::size_t(c)][std::size_t(k)], 1e-9);
            }
        }
    }
    for (std::size_t v = 0; v < g.positions.size(); ++v) {
        for (int k = 0; k < 3; ++k) {
            EXPECT_NEAR(r.positions[v][std::size_t(k)], g.positions[v][std::size_t(k)], 1e-7);
        }
    }
    // The classes read back are the classes written.
    tg::FabricParams fab;
    const auto a = tw::classify_wrinkles(g, fab), b = tw::classify_wrinkles(r, fab);
    for (std::size_t f = 0; f < g.triangles.size(); ++f) {
        EXPECT_EQ(a.triangles[f].cls, b.triangles[f].cls);
    }
}

TEST(GarmentObj, BadFilesAreNamedWithTheirLine) {
    const tapeline_test::TempDir tmp;
    auto with = [&](const std::string& name, const std::string& text) {
        const std::string p = tmp.file(name);
        std::ofstream(p) << text;
        return error_of([&] { tg::read_garment_obj(p); });
    };
    const std::string head = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 1 0\nvt 0 1\n";
    EXPECT_NE(with("quad.obj", head + "f 1/1 2/2 4/3 3/1\n").find("quad.obj:8: face with 4"),
              std::string::npos);
    EXPECT_NE(
        with("novt.obj", head + "f 1 2 3\n").find("novt.obj:8: face corner '1' has no pattern"),
        std::string::npos);
    EXPECT_NE(with("range.obj", head + "f 1/1 2/2 9/3\n").find("range.obj:8: vertex index 9"),
              std::string::npos);
    EXPECT_NE(with("nan.obj", "v 0 nan 0\n").find("nan.obj:1: y 'nan'"), std::string::npos);
    EXPECT_NE(with("grain.obj", head + "g a\n# grain 0 0\n").find("grain.obj:9: grain direction"),
              std::string::npos);
    EXPECT_NE(with("empty.obj", head).find("no triangles"), std::string::npos);
    EXPECT_NE(
        error_of([&] { tg::read_garment_obj(tmp.file("does_not_exist.obj")); }).find("cannot open"),
        std::string::npos);
}

TEST(WrinklePicture, ClassesAreDrawnInTheirColours) {
    // A cylinder half compressed: the picture holds red (compression) and grey-blue (none).
    const double R = 60;
    tg::GarmentMesh g = grid(30, 20, 6, [&](double u, double v) {
        const double a = u / R;
        return Vec3{R * std::sin(a), v < 60 ? v : 60 + 0.9 * (v - 60), R * std::cos(a)};
    });
    tg::FabricParams f;
    const tw::WrinkleField w = tw::classify_wrinkles(g, f);
    EXPECT_GT(w.report.count[3], 0u);
    EXPECT_GT(w.report.count[0], 0u);
    const auto img = tw::wrinkle_picture(g, w, "test");
    std::size_t red = 0, grey = 0;
    for (std::size_t i = 0; i + 3 < img.rgba.size(); i += 4) {
        const int r = img.rgba[i], gg = img.rgba[i + 1], b = img.rgba[i + 2];
        red += r > 120 && gg < 60 && b < 60;
        grey += b > gg && gg > r && r > 60 && b < 240;
    }
    EXPECT_GT(red, 500u);
    EXPECT_GT(grey, 500u);
}
