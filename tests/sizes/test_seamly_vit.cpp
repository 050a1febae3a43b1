// The .vit writer round-trips through the Seamly2D reader (an independent parser: the strict XML
// reader): every finite measurement comes back under its Seamly2D name, in mm, to 0.001 mm (the
// precision written), and the names map back to ours through the catalogue.
#include <tapeline/sizes/catalogue.h>
#include <tapeline/sizes/read_input.h>
#include <tapeline/sizes/seamly.h>

#include <gtest/gtest.h>

#include <limits>
#include <sstream>

namespace {

using namespace tapeline::sizes;

/// The line of `text` holding `needle`.
std::string line_of(const std::string& text, const std::string& needle) {
    const std::size_t at = text.find(needle);
    if (at == std::string::npos) {
        return "";
    }
    const std::size_t begin = text.rfind('\n', at) + 1;
    return text.substr(begin, text.find('\n', at) - begin);
}

TEST(SeamlyVit, RoundTripsThroughTheReader) {
    const NamedValues values = {{"stature", 1659.4},
                                {"bust_girth", 912.3456},
                                {"hps_to_waist_back", 431.0004},
                                {"wrist_girth_left", 151.25},  // a side: no Seamly2D name
                                {"shoulder_to_wrist", 561.5},
                                {"shoulder_slope", 21.5},  // degrees, never scaled
                                {"not_finite", std::numeric_limits<double>::quiet_NaN()}};
    std::ostringstream out;
    write_seamly_individual(out, values, "Anna's body <a&b>.obj");
    const MeasurementSet read = parse_seamly_individual(out.str(), "m.vit");

    EXPECT_EQ(read.values.size(), 6u) << out.str();
    EXPECT_NEAR(read.values.at("height"), 1659.4, 1e-3);
    EXPECT_NEAR(read.values.at("bust_circ"), 912.3456, 1e-3);
    EXPECT_NEAR(read.values.at("neck_side_to_waist_b"), 431.0004, 1e-3);
    EXPECT_NEAR(read.values.at("@wrist_girth_left"), 151.25, 1e-3);
    EXPECT_NEAR(read.values.at("arm_shoulder_tip_to_wrist"), 561.5, 1e-3);
    EXPECT_NEAR(read.values.at("shoulder_slope_neck_side_angle"), 21.5, 1e-3);
    EXPECT_EQ(read.values.count("@not_finite"), 0u);
    // The ISO 8559-1 clause number goes into the description of the measurements that have one;
    // the side of a limb girth is its ISO item taken on that side.
    EXPECT_NE(out.str().find("description=\"ISO 8559-1:2017 5.3.4 bust girth\""), std::string::npos)
        << out.str();
    EXPECT_NE(out.str().find("description=\"ISO 8559-1:2017 5.3.19 wrist girth\""),
              std::string::npos)
        << out.str();
    EXPECT_EQ(line_of(out.str(), "neck_side_to_waist_b").find("description="), std::string::npos)
        << "hps_to_waist_back has no ISO number";
    EXPECT_NE(out.str().find("<notes>Anna&apos;s body &lt;a&amp;b&gt;.obj</notes>"),
              std::string::npos)
        << out.str();

    // Every name read back maps to the one written: Seamly2D known names through the catalogue,
    // custom ones by dropping the "@".
    for (const auto& [seamly, v] : read.values) {
        const CatalogueEntry* e = from_seamly_name(seamly);
        const std::string ours = e ? e->name : seamly.substr(1);
        bool found = false;
        for (const auto& [name, value] : values) {
            if (name == ours) {
                EXPECT_NEAR(v, value, 1e-3) << seamly;
                found = true;
            }
        }
        EXPECT_TRUE(found) << seamly << " -> " << ours;
    }
}

TEST(SeamlyVit, WriteThenReadGivesTheSameSet) {
    MeasurementSet set;
    set.values = {{"bust_girth", 912.125},
                  {"waist_girth", 731.5},
                  {"knee_girth_right", 370.25},
                  {"across_back_shoulder_width", 402.75},
                  {"shoulder_slope", 19.5}};
    std::ostringstream out;
    write_seamly_individual(out, set);
    const MeasurementSet read = parse_seamly_individual(out.str(), "m.vit");
    MeasurementSet back;
    for (const auto& [k, v] : read.values) {
        const CatalogueEntry* e = from_seamly_name(k);
        back.values[e ? e->name : k.substr(1)] = v;
    }
    EXPECT_EQ(back.values, set.values);
}

TEST(SeamlyVit, AFileOfOurNamesGetsFreeSewingNamesOnReading) {
    std::ostringstream out;
    write_seamly_individual(
        out, NamedValues{{"hip_girth", 1050}, {"high_hip_girth", 990}, {"mid_thigh_girth", 520}});
    MeasurementSet m = parse_seamly_individual(out.str(), "m.vit");
    add_freesewing_aliases(m);
    EXPECT_DOUBLE_EQ(*m.get("seat"), 1050);  // Seamly2D's hip is FreeSewing's seat
    EXPECT_DOUBLE_EQ(*m.get("hips"), 990);   // and its high hip FreeSewing's hips
    EXPECT_DOUBLE_EQ(*m.get("leg_thigh_mid_circ"), 520);
    EXPECT_EQ(m.values.size(), 5u);  // FreeSewing has no mid-thigh girth
}

}  // namespace
