// The embedding of a fine drape in a coarse one through the pattern coordinates: known heights
// come back on a plane, pieces do not see each other, a fine outline outside the coarse one is
// measured, bad inputs are named.
#include <tapeline/wrinkles/embedding.h>

#include <gtest/gtest.h>

#include "garment_grid.h"
#include "invalid_input.h"

#include <cmath>
#include <functional>
#include <string>

namespace tg = tapeline::garment;
namespace tw = tapeline::wrinkles;
using tw::Vec3;

using tapeline::test::add_grid;
using tapeline::test::error_of;

namespace {

// A tilted plane: (u, v) -> o + u·a + v·b with a, b orthonormal; normal a × b.
const Vec3 kA = tapeline::vec3::normalized({1, 0.2, 0.1});
const Vec3 kB =
    tapeline::vec3::normalized(tapeline::vec3::cross(tapeline::vec3::cross(kA, Vec3{0, 1, 0}), kA));
const Vec3 kN = tapeline::vec3::cross(kA, kB);

Vec3 on_plane(double u, double v, double h = 0) {
    return {5 + u * kA[0] + v * kB[0] + h * kN[0], -3 + u * kA[1] + v * kB[1] + h * kN[1],
            2 + u * kA[2] + v * kB[2] + h * kN[2]};
}

}  // namespace

TEST(Embedding, HeightsOfAFineWaveOverACoarsePlaneComeBack) {
    // Coarse: 20 mm cells; fine: 4 mm cells of the same 200 × 100 mm pattern, lifted along the
    // normal by a wave of 37 mm wavelength and 2 mm amplitude.
    tg::GarmentMesh coarse, fine;
    add_grid(coarse, 10, 5, 20, 0, 0, 0, [](double u, double v) { return on_plane(u, v); });
    auto wave = [](double v) { return 2.0 * std::sin(2 * M_PI * v / 37); };
    add_grid(fine, 50, 25, 4, 0, 0, 0, [&](double u, double v) { return on_plane(u, v, wave(v)); });
    const tw::Embedding e = tw::embed_fine_in_coarse(coarse, fine);
    ASSERT_EQ(e.used, fine.positions.size());
    for (std::size_t k = 0; k < fine.positions.size(); ++k) {
        const double v = 4.0 * double(k / 51);
        EXPECT_NEAR(e.vertices[k].height_mm, wave(v), 1e-9) << k;
        EXPECT_NEAR(e.vertices[k].tangential_mm, 0, 1e-9) << k;
        EXPECT_NEAR(e.vertices[k].outside_mm, 0, 1e-9) << k;
        const auto& b = e.vertices[k].barycentric;
        EXPECT_NEAR(b[0] + b[1] + b[2], 1, 1e-12);
        for (double x : b) {
            EXPECT_GE(x, -1e-9);
        }
    }
    EXPECT_NEAR(e.rms_height_mm, std::sqrt(2.0), 0.05);  // 2/√2 over whole-ish periods
    EXPECT_NEAR(e.max_abs_height_mm, 2, 0.01);
}

TEST(Embedding, HeightsAreOverTheSmoothSurfaceNotTheFacets) {
    // Half a cylinder of radius 100 mm: coarse, 8 facets around (chords of 39 mm, whose middles
    // lie 1.92 mm inside the cylinder); fine, 64 around, on the cylinder and 1 mm outside it.
    // Over the facets the fine drape would rise by up to the sagitta, a wave of the facets'
    // width; over the smooth surface it rises by 0 and by 1 mm.
    const double r = 100, cell = M_PI * r / 8;
    const auto on_cylinder = [&](double lift) {
        return [=](double u, double v) {
            return Vec3{(r + lift) * std::sin(u / r), v, (r + lift) * std::cos(u / r)};
        };
    };
    tg::GarmentMesh coarse, fine, outside;
    add_grid(coarse, 8, 3, cell, 0, 0, 0, on_cylinder(0));
    add_grid(fine, 64, 24, cell / 8, 0, 0, 0, on_cylinder(0));
    add_grid(outside, 64, 24, cell / 8, 0, 0, 0, on_cylinder(1));
    const double sagitta = r * (1 - std::cos(M_PI / 16));
    ASSERT_GT(sagitta, 1.9);
    const tw::Embedding e = tw::embed_fine_in_coarse(coarse, fine);
    const tw::Embedding o = tw::embed_fine_in_coarse(coarse, outside);
    // Away from the outline (whose vertex normals lean towards the side with more triangle area)
    // the coarse normals are radial: heights within a few per cent of the sagitta.
    double flat_max = 0, on_max = 0, out_max = 0;
    for (std::size_t k = 0; k < fine.positions.size(); ++k) {
        const std::size_t column = k % 65, row = k / 65;
        if (column < 8 || column > 56 || row < 8 || row > 16) {
            continue;
        }
        // Over the facets: the distance of the fine point from the chord plane.
        const double phi = double(column) * M_PI / 64,
                     mid = (std::floor(phi / (M_PI / 8)) + 0.5) * M_PI / 8;
        flat_max = std::max(flat_max, r * std::cos(phi - mid) - r * std::cos(M_PI / 16));
        on_max = std::max(on_max, std::abs(e.vertices[k].height_mm));
        out_max = std::max(out_max, std::abs(o.vertices[k].height_mm - 1));
    }
    EXPECT_NEAR(flat_max, sagitta, 1e-9);  // what flat facets would have given
    EXPECT_LT(on_max, 0.05 * sagitta);
    EXPECT_LT(out_max, 0.05 * sagitta);
}

TEST(Embedding, PiecesDoNotSeeEachOther) {
    // Two pieces with the same pattern coordinates, placed 300 mm apart: each fine vertex lands
    // on its own piece's coarse surface (height 0), not on the other's (300 mm away).
    tg::GarmentMesh coarse, fine;
    for (std::uint32_t p = 0; p < 2; ++p) {
        const double off = 300.0 * p;
        add_grid(coarse, 4, 4, 25, 0, 0, p, [&](double u, double v) { return Vec3{u, v, off}; });
        add_grid(fine, 20, 20, 5, 0, 0, p, [&](double u, double v) { return Vec3{u, v, off}; });
    }
    const tw::Embedding e = tw::embed_fine_in_coarse(coarse, fine);
    EXPECT_NEAR(e.max_abs_height_mm, 0, 1e-9);
    EXPECT_NEAR(e.rms_tangential_mm, 0, 1e-9);
    for (std::size_t k = 0; k < fine.positions.size(); ++k) {
        const std::uint32_t piece = k < 441 ? 0 : 1;
        EXPECT_EQ(coarse.triangle_piece[e.vertices[k].coarse_triangle], piece) << k;
    }
}

TEST(Embedding, FineOutlineOutsideTheCoarseOneIsMeasured) {
    // The fine pattern reaches 3 mm beyond the coarse one on its right: those vertices are
    // 3 mm outside, located on the coarse outline, and their height is still measured.
    tg::GarmentMesh coarse, fine;
    add_grid(coarse, 5, 5, 20, 0, 0, 0, [](double u, double v) { return on_plane(u, v); });
    add_grid(fine, 26, 25, 4, 0, 0, 0,
             [](double u, double v) { return on_plane(u, v, 1.5); });  // 104 × 100 mm
    const tw::Embedding e = tw::embed_fine_in_coarse(coarse, fine);
    EXPECT_NEAR(e.max_outside_mm, 4, 1e-9);
    EXPECT_NEAR(e.max_abs_height_mm, 1.5, 1e-9);
    // Beyond the outline the point is pulled back along u: its displacement gains that 4 mm as
    // a tangential part.
    EXPECT_GT(e.rms_tangential_mm, 0.1);
}

TEST(Embedding, BadInputsAreNamed) {
    tg::GarmentMesh coarse, fine;
    add_grid(coarse, 2, 2, 10, 0, 0, 0, [](double u, double v) { return Vec3{u, v, 0}; });
    add_grid(fine, 4, 4, 5, 0, 0, 0, [](double u, double v) { return Vec3{u, v, 0}; });
    auto bad = fine;
    bad.triangle_piece[7] = 3;
    EXPECT_NE(error_of([&] {
                  tw::embed_fine_in_coarse(coarse, bad);
              }).find("fine triangle 7 lies on piece 3, the coarse mesh has 1"),
              std::string::npos);
    bad = fine;
    bad.positions[4][2] = NAN;
    EXPECT_NE(error_of([&] { tw::embed_fine_in_coarse(coarse, bad); }).find("fine mesh: vertex 4"),
              std::string::npos);
    auto badc = coarse;
    badc.uv.pop_back();
    EXPECT_NE(
        error_of([&] { tw::embed_fine_in_coarse(badc, fine); }).find("coarse mesh: 8 triangles"),
        std::string::npos);
    badc = coarse;
    badc.triangles[2][0] = 40;
    EXPECT_NE(error_of([&] {
                  tw::embed_fine_in_coarse(badc, fine);
              }).find("coarse mesh: triangle 2 names vertex 40"),
              std::string::npos);
    badc = coarse;
    for (auto& t : badc.uv) {
        t[1] = t[0];
    }
    EXPECT_NE(error_of([&] { tw::embed_fine_in_coarse(badc, fine); }).find("non-zero area"),
              std::string::npos);
}

#include <tapeline/wrinkles/compare.h>

TEST(WrinkleComparison, AFineWaveOfKnownWavelengthIsMeasuredAgainstThePrediction) {
    // A flat 300 × 300 mm panel pulled 3 % along u (weft) and shortened 5 % along v (warp):
    // tension wrinkles predicted with the tension term over L = 300 mm. The fine drape (3 mm)
    // carries a wave along the warp of 1.1 times the predicted wavelength (draped length) and
    // 2 mm amplitude: the comparison finds the ratio 1.1 and the amplitude.
    tg::FabricParams fabric;
    fabric.bending_un_m = 2;
    tw::ClassifyOptions co;
    co.tension_length_mm = 300;
    tg::GarmentMesh coarse;
    add_grid(coarse, 15, 15, 20, 0, 0, 0,
             [](double u, double v) { return on_plane(1.03 * u, 0.95 * v); });
    const tw::WrinkleField field = tw::classify_wrinkles(coarse, fabric, co);
    const double predicted = field.triangles[0].wavelength_mm;
    ASSERT_TRUE(std::isfinite(predicted));
    ASSERT_EQ(field.report.count[std::size_t(tw::WrinkleClass::tension)], coarse.triangles.size());
    const double lambda = 1.1 * predicted, amp = 2;
    tg::GarmentMesh fine;
    add_grid(fine, 100, 100, 3, 0, 0, 0, [&](double u, double v) {
        return on_plane(1.03 * u, 0.95 * v, amp * std::sin(2 * M_PI * 0.95 * v / lambda));
    });
    const tw::Comparison c = tw::compare_wrinkles(coarse, field, fine);
    EXPECT_EQ(c.report.windows, coarse.triangles.size());
    EXPECT_GT(c.report.measured, c.report.windows / 2);
    EXPECT_NEAR(c.report.median_wavelength_ratio, 1.1, 0.02);
    EXPECT_NEAR(c.report.median_wavelength_error_percent_all, 10, 2);
    const double amp_err = 100 * std::abs(amp / field.triangles[0].amplitude_mm - 1);
    EXPECT_NEAR(c.report.median_amplitude_error_percent_all, amp_err, 5);
    for (const auto& w : c.windows) {
        if (w.measured) {
            EXPECT_NEAR(w.measured_wavelength_mm / w.predicted_wavelength_mm, 1.1, 0.06)
                << w.triangle;
        }
    }
    // A flat fine drape shows no wavelength anywhere.
    tg::GarmentMesh flat;
    add_grid(flat, 100, 100, 3, 0, 0, 0,
             [&](double u, double v) { return on_plane(1.03 * u, 0.95 * v); });
    EXPECT_EQ(tw::compare_wrinkles(coarse, field, flat).report.measured, 0u);
}

#include <tapeline/wrinkles/picture.h>

TEST(WrinkleComparison, PictureShowsCrestsAndTroughs) {
    // A panel on a cylinder (so that the views see it) and its fine copy with a 4 mm wave:
    // the lower half of the picture holds red (crests) and blue (troughs).
    const double R = 150;
    auto on_cylinder = [&](double u, double v, double h) {
        const double a = u / R;
        return Vec3{(R + h) * std::sin(a), v, (R + h) * std::cos(a)};
    };
    tg::GarmentMesh coarse, fine;
    add_grid(coarse, 10, 10, 20, 0, 0, 0,
             [&](double u, double v) { return on_cylinder(u - 100, v, 0); });
    add_grid(fine, 50, 50, 4, 0, 0, 0, [&](double u, double v) {
        return on_cylinder(u - 100, v, 4 * std::sin(2 * M_PI * v / 40));
    });
    const tw::WrinkleField field = tw::classify_wrinkles(coarse, tg::FabricParams{});
    const tw::Embedding e = tw::embed_fine_in_coarse(coarse, fine);
    const auto img = tw::comparison_picture(coarse, field, fine, e, "wave");
    std::size_t red = 0, blue = 0;
    for (std::size_t y = img.height / 2; y < img.height; ++y) {
        for (std::size_t x = 0; x < img.width; ++x) {
            const std::uint8_t* p = img.pixel(x, y);
            red += p[0] > 150 && p[1] < 110 && p[2] < 110;
            blue += p[2] > 150 && p[0] < 110;
        }
    }
    EXPECT_GT(red, 300u);
    EXPECT_GT(blue, 300u);
}
