// The measurement JSON: written from a set and read back, the set is unchanged; the document
// `tapeline measure` writes reads back under both names of each measurement; every rejection
// names the file and the entry.
#include <tapeline/core/errors.h>
#include <tapeline/core/json_read.h>
#include <tapeline/sizes/json_formats.h>
#include <tapeline/sizes/read_input.h>

#include <tapeline_test/expect.h>
#include <tapeline_test/sizes.h>

#include <gtest/gtest.h>

namespace {

using namespace tapeline::sizes;
using tapeline_test::TempDir;

MeasurementSet read_back(const nlohmann::ordered_json& doc, const std::string& path) {
    return parse_measurement_json(tapeline::json::parse_json(doc.dump(1), path), path);
}

TEST(MeasurementJson, EntryCarriesTheCatalogueColumns) {
    const auto j = measurement_json_entry("waist_girth", "girth", 731.004);
    EXPECT_EQ(j["value_mm"], 731.0);
    EXPECT_EQ(j["iso_clause"], "waist girth");
    EXPECT_EQ(j["iso_number"], "5.3.10");
    EXPECT_EQ(j["freesewing_name"], "waist");
    EXPECT_EQ(j["seamly2d_name"], "waist_circ");
    const auto side = measurement_json_entry("knee_girth_left", "girth", 370);
    EXPECT_EQ(side["iso_clause"], "knee girth");
    EXPECT_TRUE(side["iso_number"].is_null());
    EXPECT_TRUE(side["freesewing_name"].is_null());
    EXPECT_EQ(side["seamly2d_name"], "@knee_girth_left");
    const auto angle = measurement_json_entry("shoulder_slope", "angle", 21.456);
    EXPECT_TRUE(angle["value_mm"].is_null());
    EXPECT_EQ(angle["value_degrees"], 21.46);
}

TEST(MeasurementJson, SetToJsonToSetToJson) {
    // Our names, FreeSewing names and names nobody knows: read back, each keeps its value, and
    // a name with a FreeSewing name also comes under it.
    const NamedValues values = {{"bust_girth", 1001.25},
                                {"mid_thigh_girth", 520.5},
                                {"inseam", 781.75},
                                {"ease_allowance", 12.5}};
    const auto doc = measurement_json(values, "body.obj");
    EXPECT_EQ(doc["format"], "tapeline-measurements");
    const MeasurementSet first = read_back(doc, "a.json");
    const std::map<std::string, double> expected = {{"bust_girth", 1001.25},
                                                    {"chest", 1001.25},
                                                    {"mid_thigh_girth", 520.5},
                                                    {"inseam", 781.75},
                                                    {"ease_allowance", 12.5}};
    EXPECT_EQ(first.values, expected);
    // Written again from what was read: the same document, the same set.
    const auto again = measurement_json(named_values(first), "body.obj");
    EXPECT_EQ(read_back(again, "b.json").values, first.values);
    EXPECT_EQ(measurement_json(named_values(read_back(again, "c.json")), "body.obj"), again);
}

TEST(MeasurementJson, AnglesAndUntakenMeasurementsAreNotRead) {
    // value_mm is what grading reads: an angle has none, and neither has a measurement that
    // could not be taken.
    TempDir dir;
    const std::string path = dir.write(
        "m.json",
        measurement_json(NamedValues{{"shoulder_slope", 20}, {"waist_girth", 700}}).dump());
    const MeasurementSet m = read_measurement_input(path);
    EXPECT_EQ(m.values, (std::map<std::string, double>{{"waist", 700}, {"waist_girth", 700}}));
}

TEST(MeasurementJson, BadEntriesNameTheFileAndEntry) {
    using tapeline::InvalidInput;
    using tapeline_test::expect_error;
    const auto parse = [](const std::string& text) {
        parse_measurement_json(tapeline::json::parse_json(text, "m.json"), "m.json");
    };
    expect_error<InvalidInput>([&] { parse(R"({"measurements": [{"name": "a"}]})"); },
                               {"m.json: measurements[0]", "no value_mm"}, "no value");
    expect_error<InvalidInput>([&] { parse(R"({"measurements": [{"value_mm": 3}]})"); },
                               {"m.json: measurements[0]", "no name or freesewing_name"}, "name");
    expect_error<InvalidInput>(
        [&] { parse(R"({"measurements": [{"name": "a", "value_mm": "3"}]})"); },
        {"measurements[0].value_mm", "expected a number"}, "text");
    expect_error<InvalidInput>([&] { parse(R"({"measurements": {}})"); },
                               {"m.json: measurements", "expected an array"}, "array");
}

}  // namespace
