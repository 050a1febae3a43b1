// The .vit export round-trips through the pattern module's Seamly2D reader (an independent
// parser): every finite measurement comes back under its Seamly2D name, in mm, to 0.001 mm (the
// precision written).
#include <tapeline/measurement/seamly_vit.h>
#include <tapeline/pattern/measurement_set.h>

#include <gtest/gtest.h>

#include <limits>
#include <sstream>

namespace {

using namespace tapeline::measurement;

Measurement make(const std::string& name, MeasurementKind kind, double value) {
    Measurement m;
    m.name = name;
    m.kind = kind;
    m.value = value;
    m.iso_clause = name == "bust_girth" ? "bust girth" : "";
    m.iso_number = name == "bust_girth" ? "5.3.4" : "";
    return m;
}

TEST(SeamlyVit, RoundTripsThroughThePatternReader) {
    MeasurementSet set;
    set.add(make("stature", MeasurementKind::height, 1659.4));
    set.add(make("bust_girth", MeasurementKind::girth, 912.3456));
    set.add(make("waist_girth", MeasurementKind::girth, 731.0004));
    set.add(make("wrist_girth_left", MeasurementKind::girth, 151.25));  // no Seamly2D name
    set.add(make("shoulder_to_wrist", MeasurementKind::length, 561.5));
    set.add(make("shoulder_slope", MeasurementKind::angle, 21.5));  // degrees, never scaled
    set.add(make("not_finite", MeasurementKind::girth, std::numeric_limits<double>::quiet_NaN()));
    set.add_missing("knee_girth", "knee_girth: knee_left not found");

    std::ostringstream out;
    write_seamly_individual(out, set, "Anna's body <a&b>.obj");
    const auto read = tapeline::pattern::parse_seamly_individual(out.str(), "m.vit");

    EXPECT_EQ(read.values.size(), 6u) << out.str();
    EXPECT_NEAR(read.values.at("height"), 1659.4, 1e-3);
    EXPECT_NEAR(read.values.at("bust_circ"), 912.3456, 1e-3);
    EXPECT_NEAR(read.values.at("waist_circ"), 731.0004, 1e-3);
    EXPECT_NEAR(read.values.at("@wrist_girth_left"), 151.25, 1e-3);
    EXPECT_NEAR(read.values.at("arm_shoulder_tip_to_wrist"), 561.5, 1e-3);
    EXPECT_NEAR(read.values.at("shoulder_slope_neck_side_angle"), 21.5, 1e-3);
    EXPECT_EQ(read.values.count("@not_finite"), 0u);
    EXPECT_EQ(read.values.count("leg_knee_circ"), 0u);
    // The ISO 8559-1 clause number goes into the description of the measurements that have one.
    EXPECT_NE(out.str().find("description=\"ISO 8559-1:2017 5.3.4 bust girth\""), std::string::npos)
        << out.str();
    EXPECT_EQ(out.str().find("description=", out.str().find("waist_circ")), std::string::npos);
}

TEST(SeamlyVit, EveryKnownNameIsDistinct) {
    // Two of our measurements under one Seamly2D name would overwrite each other on reading.
    std::map<std::string, std::string> seen;
    for (const char* n : {"stature",
                          "head_girth",
                          "neck_girth",
                          "neck_base_girth",
                          "high_bust_girth",
                          "bust_girth",
                          "underbust_girth",
                          "waist_girth",
                          "high_hip_girth",
                          "hip_girth",
                          "thigh_girth",
                          "mid_thigh_girth",
                          "knee_girth",
                          "calf_girth",
                          "ankle_girth",
                          "upper_arm_girth",
                          "elbow_girth",
                          "wrist_girth",
                          "shoulder_width_back",
                          "hps_to_waist_back",
                          "hps_to_waist_front",
                          "shoulder_to_elbow",
                          "shoulder_to_wrist",
                          "inseam",
                          "outseam",
                          "back_neck_to_waist",
                          "front_neck_to_waist",
                          "hps_to_bust",
                          "cross_seam",
                          "cross_seam_front",
                          "cross_seam_back",
                          "shoulder_slope",
                          "waist_to_hips",
                          "waist_to_armpit"}) {
        const std::string s = seamly_name(n);
        ASSERT_FALSE(s.empty()) << n;
        EXPECT_TRUE(seen.emplace(s, n).second) << n << " and " << seen[s] << " -> " << s;
    }
}

}  // namespace
