// The MakeHuman population in ../shared/data/bodies/population (random gender, age, muscle,
// weight, height, proportions, breasts; decimetres, +Y up, A-pose): on every body every landmark
// is found, every measurement taken and no self-check warns, except on the bodies listed in
// known_failure, where the failure must be flagged. Skipped when the data is absent.
#include <tapeline_test/measurement.h>

#include <gtest/gtest.h>

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
        case 5:
            return "knees found at 0.221 of the stature, below the 0.23-0.34 band";
        case 18:
            return "knees found at 0.228 of the stature, just below the 0.23-0.34 band";
        case 24:
            return "waist found at 0.705 of the stature, just above the 0.53-0.70 band";
        case 33:
            return "knees found at 0.219 of the stature, below the 0.23-0.34 band";
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

INSTANTIATE_TEST_SUITE_P(Bodies, Population, ::testing::Range(0, 40));

}  // namespace
