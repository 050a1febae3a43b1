// The MakeHuman population in ../shared/data/bodies/population (random gender, age, muscle,
// weight, height, proportions, breasts; decimetres, +Y up, A-pose): on every body every landmark
// is found, every measurement taken and no self-check warns, except on the bodies listed in
// known_failure, where the failure must be flagged. The bust, waist, knee, ankle and side neck
// levels are held against MakeHuman's own loops on the same mesh, an independent placement.
// Skipped when the data is absent.
#include <tapeline_test/measurement.h>
#include <tapeline_test/measurement_checks.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

using namespace tapeline_test::measurement;

const std::string kDir = std::string(TAPELINE_SHARED_DATA_DIR) + "/bodies/population/";

class Population : public ::testing::TestWithParam<int> {};

// Bodies on which the landmark rules still fail, each with what fails. On these the test checks
// that the failure is not silent (a landmark reported missing or a self-check warning), then
// reports the body as skipped with the reason, so the count of failures stays in sight.
const char* known_failure(int body) {
    switch (body) {
        case 0:
        case 16:
            return "short, thick neck: the neck taken at the jaw (side neck points above the "
                   "chin's underside, the neck girth around the mouth)";
        default:
            return nullptr;
    }
}

TEST_P(Population, EveryLandmarkEveryMeasurementNoWarning) {
    char name[32];
    std::snprintf(name, sizeof name, "mh_pop_%03d.ply", GetParam());
    if (!std::ifstream(kDir + name).good()) {
        GTEST_SKIP() << "no " << kDir << name;
    }
    BodyOptions o;
    o.unit = LengthUnit::dm;
    o.name = name;
    const Result r = measure_file(kDir + name, o);
    if (const char* why = known_failure(GetParam())) {
        EXPECT_FALSE(r.warnings.empty() && r.measurements.missing.empty())
            << name << ": listed as a known failure (" << why
            << ") but measured cleanly: take it off the list";
        if (r.warnings.empty() && r.measurements.missing.empty()) {
            return;
        }
        GTEST_SKIP() << name << ": known failure: " << why;
    }
    for (const auto& l : r.landmarks.landmarks) {
        EXPECT_TRUE(l.available()) << name << ": " << l.reason;
    }
    for (const auto& m : r.measurements.missing) {
        ADD_FAILURE() << name << ": " << m.reason;
    }
    for (const auto& w : r.warnings) {
        ADD_FAILURE() << name << ": " << w.rule << ": " << w.message;
    }
    // Every girth positive and below the stature (the self-checks hold the finer rules).
    for (const auto& m : r.measurements.measurements) {
        if (m.kind == MeasurementKind::girth) {
            EXPECT_GT(m.value, 0) << name << ": " << m.name;
            EXPECT_LT(m.value, r.frame.height) << name << ": " << m.name;
        }
    }
}

// MakeHuman's rulers are fixed loops of the base mesh's vertices, carried along by every shape:
// their mean heights place the bust, waist, knee and ankle levels independently of our scan.
// - Bust: the same level, within 2.5 % of the stature (the front growing towards a belly below
//   the nipples put the bust point 3.1-3.3 % under them on mh_pop_024 and 039).
// - Ankle: ISO 8559-1 takes its girth just above the malleoli, where MakeHuman's ankle loop is.
//   Ours is within 1.5 % of the stature of it (a straight shin's smallest girth, taken before,
//   lay 1.6-3.2 % above it, halfway to the calf).
// - Knee: ours is the joint's level (the hollow at the knee's back), MakeHuman's loop runs 0-5 %
//   of the stature below it (on average 1.5 %); within 4 % of it on every body (the narrowing
//   below the kneecap, taken before, lay up to 8.4 % below it).
// - Waist: MakeHuman's waist loop is lower than the natural waist (nearer the navel) and keeps
//   its place on the skeleton: 0.43-0.53 of the way from crotch to armpit on every body. Ours is
//   above it by 0-6 % of the stature (1.7-4.9 % here; 1.0-6.6 % over 180 bodies of three other
//   draws). The narrowest girth, taken up to 0.85 of the way before, lay under the chest on
//   bodies with a belly: 7.8 % above the loop on mh_pop_024, 6.3-7.3 % on such bodies elsewhere.
// - Side neck points: MakeHuman's neck loop is tilted (its front lower than its back); where it
//   passes the side of the neck (its vertex furthest to that side) is the side neck point's
//   level. Ours lie within 0.6 % of the stature of it (-0.46 to +0.24 % on the bodies not
//   flagged; -1.05 to +0.34 % over 359 such bodies of nine draws), except where the neck was
//   taken at the jaw: those (+1.34 and +1.81 % here, +0.74 to +1.81 % over the draws) must carry
//   the neck_below_chin warning, and a body within the band must not. neck_base_narrow (the neck
//   base tape shorter than 1.05 times the neck girth), which needs no chin, may fire only on
//   bodies beyond the band.
TEST_P(Population, LevelsAtMakeHumansLoops) {
    char name[32];
    std::snprintf(name, sizeof name, "mh_pop_%03d.ply", GetParam());
    const std::string rulers = std::string(TAPELINE_SHARED_DATA_DIR) + "/bodies/measurements.json";
    if (!std::ifstream(kDir + name).good() || !std::ifstream(rulers).good()) {
        GTEST_SKIP() << "no " << kDir << name << " or " << rulers;
    }
    const auto loops = nlohmann::json::parse(std::ifstream(rulers))["ruler_vertex_sequences"];
    const Soup soup = read_body_soup(kDir + name);
    ASSERT_EQ(soup.points.size(), 13380u) << name << ": not MakeHuman's base-mesh vertices";
    double floor = soup.points.front()[1], top = floor;
    for (const auto& p : soup.points) {
        floor = std::min(floor, p[1]);
        top = std::max(top, p[1]);
    }
    const double stature = (top - floor) * 100;  // dm -> mm
    BodyOptions o;
    o.unit = LengthUnit::dm;
    o.name = name;
    const Result r = measure_file(kDir + name, o);
    ASSERT_NEAR(r.frame.height, stature, 1.0) << name;
    // A loop's mean height above the floor, mm.
    auto loop_height = [&](const char* loop_name) {
        double mean = 0;
        const auto loop = loops[loop_name].get<std::vector<int>>();
        for (int v : loop) {
            mean += soup.points[static_cast<std::size_t>(v)][1];
        }
        return (mean / static_cast<double>(loop.size()) - floor) * 100;
    };
    struct Level {
        const char* loop;
        const char* landmark;
        double tolerance;  // fraction of the stature
    };
    for (const Level& level :
         {Level{"bust_circ", "bust", 0.025}, Level{"ankle_circ", "ankle", 0.015},
          Level{"knee_circ", "knee", 0.04}}) {
        // The bust loop goes round the chest; the leg loops are the left leg's (+x), and the
        // body mirrors, so they stand for both legs.
        for (int v : loops[level.loop].get<std::vector<int>>()) {
            ASSERT_TRUE(std::string(level.landmark) == "bust" ||
                        soup.points[static_cast<std::size_t>(v)][0] > 0)
                << name << ": " << level.loop;
        }
        const double loop_mm = loop_height(level.loop);
        for (const char* side : {"_left", "_right"}) {
            const std::string landmark = std::string(level.landmark) + side;
            const auto* l = r.landmarks.find(landmark);
            ASSERT_TRUE(l && l->available()) << name << ": " << landmark;
            EXPECT_NEAR(l->point[1], loop_mm, level.tolerance * stature)
                << name << ": " << landmark << " at " << l->point[1] / stature
                << " of the stature, MakeHuman's " << level.loop << " at " << loop_mm / stature;
        }
    }
    const auto* waist = r.landmarks.find("waist_front");
    ASSERT_TRUE(waist && waist->available()) << name << ": waist_front";
    const double above = (waist->point[1] - loop_height("waist_circ")) / stature;
    EXPECT_GE(above, 0.0) << name << ": the waist under MakeHuman's waist loop";
    EXPECT_LE(above, 0.06) << name << ": the waist " << above * 100
                           << " % of the stature above MakeHuman's waist loop";
    const auto neck = loops["neck_circ"].get<std::vector<int>>();
    for (const double sign : {1.0, -1.0}) {
        const std::string landmark = sign > 0 ? "side_neck_left" : "side_neck_right";
        const auto side = *std::max_element(neck.begin(), neck.end(), [&](int a, int b) {
            return sign * soup.points[static_cast<std::size_t>(a)][0] <
                   sign * soup.points[static_cast<std::size_t>(b)][0];
        });
        const double loop_mm = (soup.points[static_cast<std::size_t>(side)][1] - floor) * 100;
        const auto* l = r.landmarks.find(landmark);
        ASSERT_TRUE(l && l->available()) << name << ": " << landmark;
        const double above = (l->point[1] - loop_mm) / stature;
        const bool flagged = std::any_of(r.warnings.begin(), r.warnings.end(), [&](const auto& w) {
            return w.rule == "neck_below_chin" && w.measurement == landmark;
        });
        const bool narrow = std::any_of(r.warnings.begin(), r.warnings.end(),
                                        [](const auto& w) { return w.rule == "neck_base_narrow"; });
        if (narrow) {
            EXPECT_GT(above, 0.006)
                << name << ": neck_base_narrow, but " << landmark << " " << above * 100
                << " % of the stature from MakeHuman's neck loop";
        }
        if (flagged) {
            EXPECT_GT(above, 0.006)
                << name << ": " << landmark << " flagged at the jaw, but " << above * 100
                << " % of the stature from MakeHuman's neck loop";
        } else {
            EXPECT_NEAR(above, 0.0, 0.006)
                << name << ": " << landmark << " " << above * 100
                << " % of the stature above MakeHuman's neck loop's side, and not flagged";
        }
    }
}

INSTANTIATE_TEST_SUITE_P(Bodies, Population, ::testing::Range(0, 40));

}  // namespace
