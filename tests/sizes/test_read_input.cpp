// Reading a measurement set whatever file it comes in (the base and target sets of grading);
// every rejection names what and where.
#include <tapeline/core/errors.h>
#include <tapeline/sizes/read_input.h>

#include <gtest/gtest.h>

#include <unistd.h>
#include <cstdio>
#include <fstream>
#include <string>

namespace {

using tapeline::sizes::read_measurement_input;

std::string write_temp(const std::string& name, const std::string& text) {
    const std::string path = "/tmp/tapeline_sizes_test_" + std::to_string(::getpid()) + "_" + name;
    std::ofstream(path) << text;
    return path;
}

void expect_input_refused(const std::string& path, const std::string& needle) {
    try {
        read_measurement_input(path);
        ADD_FAILURE() << path << ": no exception";
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find(needle), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find(path), std::string::npos) << e.what();
    }
    std::remove(path.c_str());
}

}  // namespace

TEST(MeasurementInput, FlatJsonInMillimetresAndCentimetres) {
    const std::string a = write_temp("flat.json", R"({"chest": 979, "waist": 788})");
    const auto m = read_measurement_input(a);
    EXPECT_DOUBLE_EQ(*m.get("chest"), 979);
    std::remove(a.c_str());
    const std::string b = write_temp("cm.json", R"({"units": "cm", "chest": 97.9})");
    EXPECT_DOUBLE_EQ(*read_measurement_input(b).get("chest"), 979);
    std::remove(b.c_str());
}

TEST(MeasurementInput, MeasureJsonKeepsBothNames) {
    const std::string a = write_temp(
        "measure.json",
        R"({"measurements": [{"name": "bust_girth", "freesewing_name": "chest", "value_mm": 1001},
                             {"freesewing_name": "waist", "value_mm": 812},
                             {"name": "hip_girth", "value_mm": null}]})");
    const auto m = read_measurement_input(a);
    EXPECT_DOUBLE_EQ(*m.get("chest"), 1001);
    EXPECT_DOUBLE_EQ(*m.get("bust_girth"), 1001);
    EXPECT_DOUBLE_EQ(*m.get("waist"), 812);
    EXPECT_FALSE(m.get("hip_girth"));
    std::remove(a.c_str());
}

TEST(MeasurementInput, FreeSewingSetsFileNeedsASetName) {
    const std::string path =
        std::string(TAPELINE_SHARED_DATA_DIR) + "/patterns/freesewing/measurement_sets.json";
    if (!std::ifstream(path))
        GTEST_SKIP() << path << " absent";
    const auto m = read_measurement_input(path, "cisFemaleAdult42");
    EXPECT_DOUBLE_EQ(*m.get("chest"), 1143);
    EXPECT_THROW(read_measurement_input(path), tapeline::InvalidInput);
    EXPECT_THROW(read_measurement_input(path, "nope"), tapeline::InvalidInput);
}

TEST(MeasurementInput, SeamlyIndividualFile) {
    const auto m =
        read_measurement_input(std::string(TAPELINE_DATA_DIR) + "/patterns/example_individual.vit");
    // The file is in cm: every value scaled to mm, Seamly2D names with their FreeSewing aliases,
    // the angle left as it is.
    EXPECT_DOUBLE_EQ(*m.get("height"), 1659);
    EXPECT_DOUBLE_EQ(*m.get("bust_circ"), 979);
    EXPECT_DOUBLE_EQ(*m.get("chest"), 979);
    EXPECT_DOUBLE_EQ(*m.get("waist_circ"), 788);
    EXPECT_DOUBLE_EQ(*m.get("waist"), 788);
    EXPECT_DOUBLE_EQ(*m.get("hip_circ"), 953);
    EXPECT_DOUBLE_EQ(*m.get("seat"), 953);
}

// A .vit as `tapeline measure --vit` writes it: Seamly2D known names, and "@" + our name where
// Seamly2D has none. Patterns bind FreeSewing names: each known one gets its FreeSewing alias.
TEST(MeasurementInput, SeamlyNamesGetTheirFreeSewingNames) {
    const std::string a = write_temp("body.vit", R"(<?xml version="1.0" encoding="UTF-8"?>
<vit>
  <version>0.3.3</version>
  <read-only>false</read-only>
  <notes/>
  <unit>mm</unit>
  <pm_system>998</pm_system>
  <personal>
    <family-name/>
    <given-name/>
    <birth-date>1800-01-01</birth-date>
    <gender>unknown</gender>
    <email/>
  </personal>
  <body-measurements>
    <m name="height" value="1590"/>
    <m name="bust_circ" value="1001.5"/>
    <m name="neck_side_to_waist_b" value="420"/>
    <m name="hip_circ" value="1050"/>
    <m name="highhip_circ" value="990"/>
    <m name="@waist_to_armpit" value="190"/>
    <m name="@mid_thigh_girth" value="520"/>
  </body-measurements>
</vit>
)");
    const auto m = read_measurement_input(a);
    EXPECT_DOUBLE_EQ(*m.get("chest"), 1001.5);
    EXPECT_DOUBLE_EQ(*m.get("bust_circ"), 1001.5);
    EXPECT_DOUBLE_EQ(*m.get("hpsToWaistBack"), 420);
    EXPECT_DOUBLE_EQ(*m.get("seat"), 1050);  // Seamly2D's hip is FreeSewing's seat
    EXPECT_DOUBLE_EQ(*m.get("hips"), 990);   // and its high hip FreeSewing's hips
    EXPECT_DOUBLE_EQ(*m.get("waistToArmpit"), 190);
    EXPECT_DOUBLE_EQ(*m.get("mid_thigh_girth"), 520);
    std::remove(a.c_str());
}

TEST(MeasurementInput, AbsurdSetsAreRefused) {
    expect_input_refused(write_temp("neg.json", R"({"chest": -979})"), "must be positive");
    expect_input_refused(write_temp("tall.json", R"({"waist": 1900, "height": 1700})"),
                         "bigger than the height");
    expect_input_refused(write_temp("unit.json", R"({"units": "furlong", "chest": 1})"),
                         "unknown unit 'furlong'");
    expect_input_refused(write_temp("text.json", R"({"chest": "big"})"), "chest");
}

TEST(MeasurementInput, ValuesNoHumanBodyHasAreRefused) {
    const std::string girths = "(10 to 4000 mm for girths); check its unit";
    expect_input_refused(write_temp("1e9.json", R"({"chest": 1e9})"), "'chest' is 1e+09 mm");
    expect_input_refused(write_temp("1e9b.json", R"({"chest": 1e9})"), girths);
    expect_input_refused(write_temp("1e-9.json", R"({"chest": 1e-9})"), "'chest' is 1e-09 mm");
    expect_input_refused(write_temp("1e308.json", R"({"chest": 1e308})"), "is 1e+308 mm");
    // Metres given without their unit, millimetres declared as centimetres; each naming of the
    // catalogue: ours (with sides), Seamly2D's.
    expect_input_refused(write_temp("m.json", R"({"chest": 0.979})"), "is 0.979 mm");
    expect_input_refused(write_temp("cm.json", R"({"units": "cm", "chest": 979})"), "is 9790 mm");
    expect_input_refused(write_temp("side.json", R"({"thigh_girth_left": 5})"), girths);
    expect_input_refused(write_temp("seamly.json", R"({"bust_circ": 9.79})"), girths);
    expect_input_refused(write_temp("stature.json", R"({"height": 17500})"),
                         "(10 to 4000 mm for heights)");
    expect_input_refused(write_temp("angle.json", R"({"shoulderSlope": 130})"),
                         "(-90 to 90 degree for angles)");

    // The bounds themselves, angles below zero and names outside the catalogue are accepted.
    const std::string ok = write_temp(
        "edges.json", R"({"chest": 4000, "waist": 10, "shoulderSlope": -5, "myLength": 1e6})");
    const auto m = read_measurement_input(ok);
    EXPECT_DOUBLE_EQ(*m.get("myLength"), 1e6);
    std::remove(ok.c_str());
}

TEST(MeasurementInput, EveryBundledSetIsWithinTheHumanRange) {
    // The range must not refuse real data: the bundled individual file, and every FreeSewing
    // size set of the shared data.
    EXPECT_NO_THROW(read_measurement_input(std::string(TAPELINE_DATA_DIR) +
                                           "/patterns/example_individual.vit"));
    EXPECT_NO_THROW(read_measurement_input(std::string(TAPELINE_DATA_DIR) +
                                           "/patterns/aaron_cisFemaleAdult36_measurements.json"));
    const std::string sets =
        std::string(TAPELINE_SHARED_DATA_DIR) + "/patterns/freesewing/measurement_sets.json";
    if (!std::ifstream(sets)) {
        GTEST_SKIP() << sets << " absent";
    }
    for (const char* name : {"cisFemaleAdult36", "cisFemaleAdult42"}) {
        EXPECT_NO_THROW(read_measurement_input(sets, name)) << name;
    }
}
