// The JSON writers of the measurement options and report: every field of a default-constructed
// struct appears with the struct's value and nothing else does; the hand-written field lists are
// checked against the struct's member count, so a field added without a writer line fails here.
#include <tapeline/measurement/measurement_json.h>

#include <tapeline_test/json_fields.h>

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace tapeline::measurement;
using nlohmann::json;
using Fields = tapeline::test::JsonFields;
using tapeline::test::expect_fields;

#define FIELD TAPELINE_JSON_FIELD

TEST(MeasurementJson, BodyOptions) {
    const BodyOptions o;
    const Fields f = {
        {"unit", nullptr}, FIELD(o, up), FIELD(o, front), FIELD(o, pose), FIELD(o, name)};
    EXPECT_EQ(tapeline::test::field_count<BodyOptions>(), f.size());
    const json j = o;
    expect_fields(j, f, "BodyOptions");
    EXPECT_EQ(j["up"], "+Y");
    EXPECT_EQ(j["front"], "+Z");
    BodyOptions given;
    given.unit = LengthUnit::dm;
    given.up = Axis::parse("-z", "test");
    EXPECT_EQ(json(given)["unit"], "dm");
    EXPECT_EQ(json(given)["up"], "-Z");
}

TEST(MeasurementJson, MeasureOptions) {
    const MeasureOptions o;
    const Fields f = {FIELD(o, scan_step), FIELD(o, level_tolerance),
                      FIELD(o, max_neck_tilt_degrees), FIELD(o, smooth_surface)};
    EXPECT_EQ(tapeline::test::field_count<MeasureOptions>(), f.size());
    expect_fields(json(o), f, "MeasureOptions");
    EXPECT_EQ(json(o)["level_tolerance"], 0.1);
}

TEST(MeasurementJson, MeasureReport) {
    MeasureReport r;
    r.sections = 12;
    r.warnings = {"neck not found"};
    const Fields f = {
        FIELD(r, vertices),          FIELD(r, faces),          FIELD(r, components),
        FIELD(r, sections),          FIELD(r, smooth_surface), FIELD(r, frame_seconds),
        FIELD(r, landmark_seconds),  FIELD(r, girth_seconds),  FIELD(r, landmarks_found),
        FIELD(r, landmarks_missing), FIELD(r, warnings),       FIELD(r, holes)};
    EXPECT_EQ(tapeline::test::field_count<MeasureReport>(), f.size());
    expect_fields(json(r), f, "MeasureReport");
    EXPECT_EQ(json(r)["warnings"][0], "neck not found");
}

}  // namespace
