// The measurement catalogue is consistent: names, ISO numbers, FreeSewing and Seamly2D names are
// unique; every Seamly2D and FreeSewing name maps back to its row; ISO numbers are only the
// sourced ones; the per-side variants resolve to their row. (That every name `tapeline measure`
// produces is in the catalogue is checked on a measured body in
// tests/measurement/test_catalogue_names.cpp.)
#include <tapeline/core/units.h>
#include <tapeline/sizes/catalogue.h>
#include <tapeline/sizes/read_input.h>

#include <tapeline_test/expect.h>

#include <gtest/gtest.h>

#include <map>
#include <set>
#include <string>

namespace {

using namespace tapeline::sizes;

TEST(Catalogue, NamesAndForeignNamesAreUniqueAndMapBack) {
    std::set<std::string> names;
    std::map<std::string, std::string> seamly, freesewing, iso;
    for (const CatalogueEntry& e : catalogue()) {
        EXPECT_TRUE(names.insert(e.name).second) << e.name << " twice";
        EXPECT_EQ(catalogue_entry(e.name), &e) << e.name;
        if (*e.seamly) {
            // Two rows under one Seamly2D name would overwrite each other in a .vit.
            EXPECT_TRUE(seamly.emplace(e.seamly, e.name).second)
                << e.name << " and " << seamly[e.seamly] << " -> " << e.seamly;
            ASSERT_NE(from_seamly_name(e.seamly), nullptr) << e.seamly;
            EXPECT_STREQ(from_seamly_name(e.seamly)->name, e.name);
            EXPECT_EQ(seamly_name(e.name), e.seamly);
            EXPECT_EQ(seamly_name(e.seamly), "") << "a Seamly2D name is not one of ours";
        }
        if (*e.freesewing) {
            EXPECT_TRUE(freesewing.emplace(e.freesewing, e.name).second)
                << e.name << " and " << freesewing[e.freesewing] << " -> " << e.freesewing;
            ASSERT_NE(from_freesewing_name(e.freesewing), nullptr) << e.freesewing;
            EXPECT_STREQ(from_freesewing_name(e.freesewing)->name, e.name);
            // A .vit of Seamly2D names and one of our names reach the same FreeSewing name.
            EXPECT_EQ(freesewing_alias(e.name), e.freesewing) << e.name;
            if (*e.seamly) {
                EXPECT_EQ(freesewing_alias(e.seamly), e.freesewing) << e.seamly;
                EXPECT_EQ(freesewing_alias(std::string("@") + e.name), e.freesewing) << e.name;
            }
        }
        if (*e.iso_number) {
            EXPECT_TRUE(iso.emplace(e.iso_number, e.name).second)
                << e.name << " and " << iso[e.iso_number] << " share " << e.iso_number;
            EXPECT_NE(*e.iso_title, '\0') << e.name << ": a number without a title";
        }
        EXPECT_EQ(is_angle_measurement(e.name), e.kind == MeasurementKind::angle) << e.name;
        EXPECT_STREQ(e.unit(), e.kind == MeasurementKind::angle ? "degree" : "mm");
    }
    EXPECT_GE(names.size(), 30u);
}

TEST(Catalogue, OnlySourcedIsoNumbers) {
    // The fifteen clause numbers Bodygram's definitions page states (catalogue.h); any other
    // number would be one nobody checked.
    const std::map<std::string, std::string> sourced = {
        {"neck_girth", "5.3.2"},         {"neck_base_girth", "5.3.3"},
        {"bust_girth", "5.3.4"},         {"underbust_girth", "5.3.8"},
        {"waist_girth", "5.3.10"},       {"high_hip_girth", "5.3.12"},
        {"hip_girth", "5.3.13"},         {"upper_arm_girth", "5.3.16"},
        {"wrist_girth", "5.3.19"},       {"thigh_girth", "5.3.20"},
        {"mid_thigh_girth", "5.3.21"},   {"across_back_shoulder_width", "5.4.3"},
        {"back_neck_to_waist", "5.4.5"}, {"back_neck_to_wrist", "5.4.17"},
        {"shoulder_to_wrist", "5.7.8"}};
    std::size_t numbered = 0;
    for (const CatalogueEntry& e : catalogue()) {
        const auto it = sourced.find(e.name);
        EXPECT_EQ(e.iso_number, it == sourced.end() ? std::string() : it->second) << e.name;
        numbered += *e.iso_number ? 1 : 0;
    }
    EXPECT_EQ(numbered, sourced.size());
    for (const char* name :
         {"stature", "inseam", "outseam", "cross_seam", "knee_girth", "shoulder_to_elbow"}) {
        EXPECT_EQ(iso_number(name), "") << name;
        EXPECT_NE(iso_title(name), "") << name << " is an ISO 8559-1 item";
    }
}

TEST(Catalogue, SidesShareTheirRowWithoutForeignNames) {
    const CatalogueMatch m = find_measurement("wrist_girth_left");
    ASSERT_TRUE(m);
    EXPECT_STREQ(m.entry->name, "wrist_girth");
    EXPECT_EQ(m.side, "left");
    EXPECT_FALSE(m.whole());
    EXPECT_EQ(iso_number("wrist_girth_right"), "5.3.19");
    EXPECT_EQ(iso_title("wrist_girth_right"), "wrist girth");
    EXPECT_EQ(freesewing_name("wrist_girth_right"), "");
    EXPECT_EQ(seamly_name("wrist_girth_right"), "");
    EXPECT_TRUE(is_angle_measurement("shoulder_slope_left"));
    // Only sided rows have sides, and unknown names resolve to nothing.
    EXPECT_FALSE(find_measurement("waist_girth_left"));
    EXPECT_FALSE(find_measurement("_left"));
    EXPECT_FALSE(find_measurement("chest"));
    EXPECT_EQ(freesewing_alias("@chest"), "chest");
    EXPECT_EQ(freesewing_alias("leg_thigh_mid_circ"), "leg_thigh_mid_circ");
}

TEST(Units, OneTableInMillimetres) {
    using tapeline::LengthUnit;
    EXPECT_EQ(tapeline::millimetres_per_unit("mm", "u"), 1);
    EXPECT_EQ(tapeline::millimetres_per_unit("cm", "u"), 10);
    EXPECT_EQ(tapeline::millimetres_per_unit("dm", "u"), 100);
    EXPECT_EQ(tapeline::millimetres_per_unit("m", "u"), 1000);
    EXPECT_EQ(tapeline::millimetres_per_unit("inch", "u"), 25.4);
    EXPECT_EQ(tapeline::millimetres_per_unit("in", "u"), 25.4);
    for (LengthUnit u :
         {LengthUnit::mm, LengthUnit::cm, LengthUnit::dm, LengthUnit::m, LengthUnit::inch}) {
        ASSERT_TRUE(tapeline::length_unit(tapeline::to_string(u)));
        EXPECT_EQ(*tapeline::length_unit(tapeline::to_string(u)), u);
    }
    EXPECT_FALSE(tapeline::length_unit("MM"));
    tapeline_test::expect_error<tapeline::InvalidInput>(
        [] { tapeline::millimetres_per_unit("furlong", "f.json: units"); },
        {"f.json: units", "unknown unit 'furlong'", "mm, cm, dm, m or inch"}, "unit");
}

}  // namespace
