// The .vit writer round-trips through the Seamly2D reader (an independent parser: the strict XML
// reader): every finite measurement comes back under its Seamly2D name, in mm, to 0.001 mm (the
// precision written), and the names map back to ours through the catalogue.
#include <tapeline/core/xml.h>
#include <tapeline/sizes/catalogue.h>
#include <tapeline/sizes/read_input.h>
#include <tapeline/sizes/seamly.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <limits>
#include <regex>
#include <set>
#include <sstream>
#include <vector>

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
    // Every measurement has a full name and a description that declares its unit; the ISO
    // 8559-1 clause number goes into the description of those that have one, and the side of a
    // limb girth is its ISO item taken on that side.
    EXPECT_NE(line_of(out.str(), "\"bust_circ\"")
                  .find("full_name=\"bust girth\" description=\"Girth: a closed tape around the "
                        "body, in mm. ISO 8559-1:2017 5.3.4 bust girth.\""),
              std::string::npos)
        << out.str();
    EXPECT_NE(line_of(out.str(), "@wrist_girth_left")
                  .find("full_name=\"wrist girth (left)\" description=\"Girth: a closed tape "
                        "around the body, in mm, on the left side. ISO 8559-1:2017 5.3.19 wrist "
                        "girth.\""),
              std::string::npos)
        << out.str();
    EXPECT_NE(line_of(out.str(), "neck_side_to_waist_b")
                  .find("full_name=\"HPS to waist back\" description=\"Length: a tape along the "
                        "skin, in mm.\""),
              std::string::npos)
        << "hps_to_waist_back has no ISO number: " << out.str();
    EXPECT_NE(line_of(out.str(), "shoulder_slope_neck_side_angle").find("in degrees"),
              std::string::npos)
        << out.str();
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

// The layout Seamly2D's and Valentina's schema for individual measurements 0.3.3 fixes (an
// xs:sequence: every element present, in this order), without either program: a file that breaks
// it is refused by both ("Element gender is not defined in this scope" when birth-date is
// missing). tests/clients/ runs Valentina itself on the written file.
TEST(SeamlyVit, ElementsInTheOrderOfTheSchema) {
    std::ostringstream out;
    write_seamly_individual(out, NamedValues{{"bust_girth", 900}, {"wrist_girth_left", 150}});
    const tapeline::xml::Element root = tapeline::xml::parse(out.str(), "m.vit");
    std::vector<std::string> top, personal;
    for (const auto& c : root.children) {
        top.push_back(c.name);
    }
    EXPECT_EQ(top, (std::vector<std::string>{"version", "read-only", "notes", "unit", "pm_system",
                                             "personal", "body-measurements"}));
    EXPECT_EQ(root.child("version")->text, "0.3.3");
    EXPECT_EQ(root.child("unit")->text, "mm");
    const tapeline::xml::Element* p = root.child("personal");
    ASSERT_NE(p, nullptr);
    for (const auto& c : p->children) {
        personal.push_back(c.name);
    }
    EXPECT_EQ(personal, (std::vector<std::string>{"family-name", "given-name", "birth-date",
                                                  "gender", "email"}));
    // xs:date, and one of the schema's three genders.
    EXPECT_TRUE(std::regex_match(p->child("birth-date")->text, std::regex(R"(\d{4}-\d{2}-\d{2})")));
    EXPECT_EQ(p->child("gender")->text, "unknown");
}

// Every name written is a known name of Valentina (when its list is installed) or a custom
// name that fits the schema's shortName pattern ("@", then no space, operator or separator), and
// every measurement has a non-empty full name and description naming its unit.
TEST(SeamlyVit, NamesAreKnownOrValidCustomNames) {
    NamedValues all;
    for (const CatalogueEntry& e : catalogue()) {
        all.emplace_back(e.name, e.kind == MeasurementKind::angle ? 20.0 : 300.0);
        if (e.sided) {
            all.emplace_back(std::string(e.name) + "_left", 300.0);
            all.emplace_back(std::string(e.name) + "_right", 300.0);
        }
    }
    std::ostringstream out;
    write_seamly_individual(out, all);
    const tapeline::xml::Element root = tapeline::xml::parse(out.str(), "m.vit");
    const std::regex custom(R"(@[^\s*/&|!<>^()\-+.,=?:;'"]+)");
    std::size_t known = 0, n = 0;
    for (const auto& m : root.child("body-measurements")->children) {
        ++n;
        const std::string name = *m.attribute("name");
        if (name[0] == '@') {
            EXPECT_TRUE(std::regex_match(name, custom)) << name;
        } else {
            EXPECT_NE(from_seamly_name(name), nullptr) << name;
            ++known;
        }
        ASSERT_NE(m.attribute("full_name"), nullptr) << name;
        ASSERT_NE(m.attribute("description"), nullptr) << name;
        EXPECT_FALSE(m.attribute("full_name")->empty()) << name;
        const bool angle = is_angle_measurement(name.substr(name[0] == '@'));
        EXPECT_NE(m.attribute("description")->find(angle ? ", in degrees" : ", in mm"),
                  std::string::npos)
            << name << ": " << *m.attribute("description");
    }
    EXPECT_EQ(n, all.size());
    EXPECT_GE(known, 30u);
}

// The catalogue's Seamly2D names are Valentina's known names: its template of all measurements
// lists them (read when the Debian package valentina is installed).
TEST(SeamlyVit, CatalogueNamesAreValentinasKnownNames) {
    const std::string path = "/usr/share/valentina/tables/templates/template_all_measurements.vit";
    if (!std::ifstream(path)) {
        GTEST_SKIP() << path << " absent (Debian package valentina not installed)";
    }
    const MeasurementSet all = read_seamly_individual(path);
    EXPECT_GT(all.values.size(), 200u);
    for (const CatalogueEntry& e : catalogue()) {
        if (*e.seamly) {
            EXPECT_EQ(all.values.count(e.seamly), 1u) << e.name << " -> " << e.seamly;
        }
    }
}

}  // namespace
