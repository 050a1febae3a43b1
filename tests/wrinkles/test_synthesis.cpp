// Wrinkle synthesis from a database: a wave learned where the cloth is compressed comes back,
// with its wavelength and amplitude, where another garment is compressed and nowhere else; the
// self-check keeps the wrinkles out of a body; the check against a simulation measures what it
// says; the database file survives a round trip and refuses what is not one.
#include <tapeline/garment/collider.h>
#include <tapeline/wrinkles/spectrum.h>
#include <tapeline/wrinkles/synthesis.h>

#include <gtest/gtest.h>

#include "garment_grid.h"
#include "invalid_input.h"
#include "tapeline_test/garment_shapes.h"

#include <cmath>
#include <string>
#include <vector>

namespace tg = tapeline::garment;
namespace tw = tapeline::wrinkles;
using tw::Vec3;

using tapeline::test::add_grid;
using tapeline::test::expect_invalid;

namespace {

constexpr double kCell = 20;          // coarse edge, mm
constexpr double kWave = 40;          // pattern wavelength of the training wave, mm
constexpr double kAmplitude = 2;      // its amplitude, mm
constexpr double kCompressed = 0.95;  // draped length over pattern length where compressed

/// A sheet of nx × ny coarse cells lying in the plane y = 0 (normal +y), compressed along u by
/// kCompressed where `compressed(u)` holds and at its pattern length elsewhere.
tg::GarmentMesh sheet(int nx, int ny, const std::function<bool(double)>& compressed) {
    // Draped x of pattern u: the integral of the local stretch.
    const auto x_of = [&](double u) {
        double x = 0;
        const int steps = int(std::lround(u / 1.0));
        for (int i = 0; i < steps; ++i) {
            x += compressed(i + 0.5) ? kCompressed : 1.0;
        }
        return x;
    };
    tg::GarmentMesh g;
    add_grid(g, nx, ny, kCell, 0, 0, 0, [&](double u, double v) { return Vec3{x_of(u), 0, -v}; });
    g.piece_names = {"sheet"};
    return g;
}

/// The "fine simulation" of a sheet: subdivided twice, raised along +y by a cosine of kWave
/// (pattern) and kAmplitude where `compressed(u)` holds, with the given phase.
tg::GarmentMesh waved(const tg::GarmentMesh& coarse, const std::function<bool(double)>& compressed,
                      double phase = 0) {
    const tw::Subdivision s = tw::subdivide(coarse, 2);
    tg::GarmentMesh fine = s.mesh;
    std::vector<char> seen(fine.positions.size(), 0);
    for (std::size_t f = 0; f < fine.triangles.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = fine.triangles[f][std::size_t(k)];
            if (seen[v]) {
                continue;
            }
            seen[v] = 1;
            const double u = fine.uv[f][std::size_t(k)][0];
            if (compressed(u)) {
                fine.positions[v][1] += kAmplitude * std::cos(2 * M_PI * u / kWave + phase);
            }
        }
    }
    return fine;
}

tg::FabricParams fabric() {
    return tg::FabricParams{};
}  // cotton_jersey

/// Training: a 400 × 200 mm sheet compressed on its left half, waves there only.
tw::WrinkleDatabase trained() {
    const auto left = [](double u) { return u < 200; };
    static const tg::GarmentMesh coarse = sheet(20, 10, left);
    static const tg::GarmentMesh fine = waved(coarse, left);
    tw::WrinkleDatabase db;
    tw::TrainingPair pair{&coarse, &fine, nullptr, "left-compressed sheet"};
    EXPECT_GT(tw::add_training_pair(db, pair, fabric()), 150u);
    tw::finish_database(db);
    return db;
}

/// Amplitude of the best-fitting sine of wavelength `lambda` through (u, h), least squares.
double fitted_amplitude(const std::vector<double>& u, const std::vector<double>& h, double lambda) {
    double cc = 0, ss = 0, cs = 0, hc = 0, hs = 0;
    for (std::size_t i = 0; i < u.size(); ++i) {
        const double c = std::cos(2 * M_PI * u[i] / lambda), s = std::sin(2 * M_PI * u[i] / lambda);
        cc += c * c;
        ss += s * s;
        cs += c * s;
        hc += h[i] * c;
        hs += h[i] * s;
    }
    const double det = cc * ss - cs * cs;
    const double a = (hc * ss - hs * cs) / det, b = (hs * cc - hc * cs) / det;
    return std::hypot(a, b);
}

}  // namespace

TEST(Synthesis, TheLearnedWaveAppearsWhereAnotherGarmentIsCompressedAndNowhereElse) {
    const tw::WrinkleDatabase db = trained();
    // Held-out garment: 440 × 240 mm, compressed on its right part (u > 150).
    const auto right = [](double u) { return u > 150; };
    const tg::GarmentMesh coarse = sheet(22, 12, right);
    const tw::Synthesis s = tw::synthesize_wrinkles(coarse, db, fabric(), {});
    ASSERT_EQ(s.fine.positions.size(), s.height_mm.size());
    EXPECT_EQ(s.report.fine_triangles, coarse.triangles.size() * 16);
    // Heights by pattern u along a line across the middle, away from the outline.
    std::vector<double> u_in, h_in;
    double rms_out = 0;
    std::size_t n_out = 0;
    std::vector<char> seen(s.fine.positions.size(), 0);
    for (std::size_t f = 0; f < s.fine.triangles.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = s.fine.triangles[f][std::size_t(k)];
            if (seen[v]) {
                continue;
            }
            seen[v] = 1;
            const auto& p = s.fine.uv[f][std::size_t(k)];
            if (p[1] < 40 || p[1] > 200) {
                continue;
            }
            if (p[0] > 210 && p[0] < 430) {
                u_in.push_back(p[0]);
                h_in.push_back(s.height_mm[v]);
            } else if (p[0] < 90) {
                rms_out += s.height_mm[v] * s.height_mm[v];
                ++n_out;
            }
            // The displacement is along the normal (+y), nothing else moved.
            EXPECT_NEAR(s.fine.positions[v][1], s.height_mm[v], 1e-9);
        }
    }
    ASSERT_GT(u_in.size(), 100u);
    ASSERT_GT(n_out, 100u);
    rms_out = std::sqrt(rms_out / double(n_out));
    EXPECT_LT(rms_out, 0.1 * kAmplitude) << "waves where the held-out sheet is not compressed";
    // The wave where it is: amplitude by a least-squares sine, wavelength by the spectrum of the
    // heights along u (independent of the window measurement the database was trained with).
    const double a = fitted_amplitude(u_in, h_in, kWave);
    EXPECT_NEAR(a, kAmplitude, 0.3 * kAmplitude);
    const std::vector<double> profile = tw::resample_uniform(u_in, h_in, 1.25);
    const tw::Spectrum sp = tw::dominant_wavelength(profile, 1.25);
    EXPECT_NEAR(sp.wavelength, kWave, 0.1 * kWave);
    // Crests run across the compression axis: heights do not change along v at fixed u.
    EXPECT_EQ(s.report.new_self_crossings_left, 0u);
    EXPECT_FALSE(s.report.body_checked);
}

TEST(Synthesis, TheSelfCheckKeepsTheWrinklesOutOfTheBody) {
    const tw::WrinkleDatabase db = trained();
    const auto all = [](double) { return true; };
    const tg::GarmentMesh coarse = sheet(15, 12, all);
    // A sphere of radius 400 mm under the sheet's middle, its top 0.5 mm below the sheet: a wave
    // of 2 mm would dip 1.5 mm into it there.
    const double cx = 0.5 * 300 * kCompressed, cz = -120;
    const auto sphere = tapeline_test::uv_sphere({cx, -400.5, cz}, 400, 96, 48);
    const tg::SignedDistanceGrid sdf(sphere.points, sphere.triangles, tg::ColliderOptions{4});
    tw::SynthesisOptions o;
    o.body_clearance_mm = 0.5;
    const tw::Synthesis free = tw::synthesize_wrinkles(coarse, db, fabric(), {}, o);
    const tw::Synthesis held =
        tw::synthesize_wrinkles(coarse, db, fabric(), {&sphere.points, &sphere.triangles, &sdf}, o);
    // Without the body the waves reach into the sphere: the test has something to catch.
    std::size_t inside_free = 0;
    for (const Vec3& p : free.fine.positions) {
        inside_free += sdf.signed_distance(p, nullptr) < 0 ? 1 : 0;
    }
    EXPECT_GT(inside_free, 10u);
    EXPECT_TRUE(held.report.body_checked);
    EXPECT_GT(held.report.damped_vertices, 0u);
    EXPECT_EQ(held.report.new_body_contacts_left, 0u);
    EXPECT_EQ(held.report.quality_before.vertices_inside_body, 0u);
    EXPECT_EQ(held.report.quality_after.vertices_inside_body, 0u);
    EXPECT_EQ(held.report.quality_after.edges_crossing_body, 0u);
    // Far from the sphere's top (its surface 25 mm and more below) the waves are untouched.
    std::size_t far = 0;
    for (std::size_t v = 0; v < held.fine.positions.size(); ++v) {
        if (sdf.signed_distance(held.base.positions[v], nullptr) > 25) {
            ++far;
            EXPECT_EQ(held.height_mm[v], free.height_mm[v]) << v;
        }
    }
    EXPECT_GT(far, 100u);
}

TEST(Synthesis, TheCheckAgainstASimulationMeasuresWhatItSays) {
    const tw::WrinkleDatabase db = trained();
    const auto all = [](double) { return true; };
    const tg::GarmentMesh coarse = sheet(15, 12, all);
    const tw::Synthesis s = tw::synthesize_wrinkles(coarse, db, fabric(), {});
    // The synthesis against itself: no error, r = 1; against its negative: r = −1; against a
    // flat drape: no window with a wave.
    tg::GarmentMesh same = s.fine, negative = s.fine;
    for (std::size_t v = 0; v < negative.positions.size(); ++v) {
        negative.positions[v][1] = -negative.positions[v][1];
    }
    const tw::SynthesisCheck c1 = tw::check_synthesis(coarse, s, db, same);
    const tw::SynthesisCheck c2 = tw::check_synthesis(coarse, s, db, negative);
    const tw::SynthesisCheck c3 = tw::check_synthesis(coarse, s, db, s.base);
    const std::size_t comp = std::size_t(tw::WrinkleClass::compression);
    ASSERT_GT(c1.per_class[comp].simulated, 50u);
    EXPECT_EQ(c1.per_class[comp].both, c1.per_class[comp].simulated);
    EXPECT_NEAR(c1.per_class[comp].median_wavelength_error_percent, 0, 1e-6);
    EXPECT_NEAR(c1.per_class[comp].median_amplitude_error_percent, 0, 1e-6);
    EXPECT_NEAR(c1.per_class[comp].pearson_r, 1, 1e-9);
    EXPECT_NEAR(c2.per_class[comp].pearson_r, -1, 1e-9);
    EXPECT_NEAR(c2.per_class[comp].median_wavelength_error_percent, 0, 1e-6);
    EXPECT_EQ(c3.per_class[comp].simulated, 0u);
    EXPECT_NEAR(c1.simulated_rms_height_mm, c1.synthesised_rms_height_mm, 1e-9);
}

TEST(Synthesis, TheDatabaseSurvivesARoundTripAndSynthesisIsDeterministic) {
    const tw::WrinkleDatabase db = trained();
    const nlohmann::json j = nlohmann::json::parse(tw::wrinkle_database_json(db).dump());
    const tw::WrinkleDatabase back = tw::wrinkle_database_from_json(j, "db.json");
    ASSERT_EQ(back.features.size(), db.features.size());
    std::size_t no_wave = 0;
    for (std::size_t i = 0; i < db.features.size(); ++i) {
        EXPECT_EQ(back.features[i], db.features[i]);
        EXPECT_EQ(back.amplitude_mm[i], db.amplitude_mm[i]);
        EXPECT_EQ(std::isnan(back.wavelength_mm[i]), std::isnan(db.wavelength_mm[i]));
        no_wave += std::isnan(db.wavelength_mm[i]) ? 1 : 0;
    }
    EXPECT_GT(no_wave, 0u);  // the uncompressed half taught "no wave"
    EXPECT_EQ(back.mean, db.mean);
    EXPECT_EQ(back.scale, db.scale);
    const tg::GarmentMesh coarse = sheet(15, 12, [](double u) { return u > 150; });
    const tw::Synthesis a = tw::synthesize_wrinkles(coarse, db, fabric(), {});
    const tw::Synthesis b = tw::synthesize_wrinkles(coarse, back, fabric(), {});
    EXPECT_EQ(a.height_mm, b.height_mm);
}

TEST(Synthesis, BadInputsAreNamed) {
    const tw::WrinkleDatabase db = trained();
    const tg::GarmentMesh coarse = sheet(4, 4, [](double) { return true; });
    tg::FabricParams other = fabric();
    other.name = "denim";
    expect_invalid([&] { tw::synthesize_wrinkles(coarse, db, other, {}); },
                   "trained on fabric 'cotton_jersey', the garment is of 'denim'");
    tw::WrinkleDatabase with_body = db;
    with_body.uses_body = true;
    expect_invalid([&] { tw::synthesize_wrinkles(coarse, with_body, fabric(), {}); },
                   "give the body");
    tw::SynthesisOptions o;
    o.levels = 0;
    expect_invalid([&] { tw::synthesize_wrinkles(coarse, db, fabric(), {}, o); }, "levels");
    o = {};
    o.neighbours = 0;
    expect_invalid([&] { tw::synthesize_wrinkles(coarse, db, fabric(), {}, o); }, "neighbours");
    o = {};
    o.body_clearance_mm = -1;
    expect_invalid([&] { tw::synthesize_wrinkles(coarse, db, fabric(), {}, o); },
                   "body_clearance_mm");
    // Training pairs that disagree, or miss a mesh.
    tw::WrinkleDatabase empty;
    expect_invalid(
        [&] {
            tw::add_training_pair(empty, {&coarse, nullptr, nullptr, "p1"}, fabric());
        },
        "pair 'p1' misses a mesh");
    expect_invalid([&] { tw::finish_database(empty); }, "no samples");
    tw::WrinkleDatabase odd;
    odd.options.min_periods = 0;
    expect_invalid(
        [&] {
            tw::add_training_pair(odd, {&coarse, &coarse, nullptr, "p2"}, fabric());
        },
        "min_periods must be finite and >= 2, got 0");
    // Database files.
    const nlohmann::json good = tw::wrinkle_database_json(db);
    const auto expect_bad = [&](const std::function<void(nlohmann::json&)>& spoil,
                                const std::string& needle) {
        nlohmann::json j = good;
        spoil(j);
        expect_invalid([&] { tw::wrinkle_database_from_json(j, "db.json"); }, "db.json: " + needle);
    };
    expect_bad([](nlohmann::json& j) { j = nlohmann::json::array(); }, "not a wrinkle database");
    expect_bad([](nlohmann::json& j) { j["format"] = "tapeline-pattern"; },
               "not a wrinkle database");
    expect_bad([](nlohmann::json& j) { j["version"] = 2; }, "unsupported version");
    expect_bad([](nlohmann::json& j) { j["features"][1] = "compression"; }, "feature 1 must be");
    expect_bad([](nlohmann::json& j) { j["scale"][3] = 0; },
               "\"scale\"[3] must be a finite number > 0");
    expect_bad([](nlohmann::json& j) { j["samples"][5][0] = "nan"; },
               "sample 5: feature compression is not a finite number");
    expect_bad([](nlohmann::json& j) { j["samples"][2][tw::kWrinkleFeatures] = -1; },
               "sample 2: the amplitude must be a finite number >= 0");
    expect_bad(
        [](nlohmann::json& j) {
            j["samples"][0][tw::kWrinkleFeatures] = 1;
            j["samples"][0][tw::kWrinkleFeatures + 1] = nullptr;
        },
        "sample 0: an amplitude above 0 needs a wavelength");
    expect_bad([](nlohmann::json& j) { j["samples"] = nlohmann::json::array(); },
               "\"samples\" must be a non-empty array");
    expect_bad([](nlohmann::json& j) { j["samples"][1].erase(0); }, "sample 1 must hold");
    expect_bad([](nlohmann::json& j) { j.erase("fabric"); }, "\"fabric\" must be");
}
