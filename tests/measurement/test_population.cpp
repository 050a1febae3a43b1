// The MakeHuman population in ../shared/data/bodies/population (random gender, age, muscle,
// weight, height, proportions, breasts; decimetres, +Y up, A-pose): on every body every landmark
// is found, every measurement taken and no self-check warns. Skipped when the data is absent.
#include <tapeline_test/measurement.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace {

using namespace tapeline_test::measurement;

const std::string kDir = std::string(TAPELINE_SHARED_DATA_DIR) + "/bodies/population/";

class Population : public ::testing::TestWithParam<int> {};

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
