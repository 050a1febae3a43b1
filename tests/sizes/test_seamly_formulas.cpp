// Reading Seamly2D/Valentina measurement files with formulas, separators, special units and the
// multisize layout Valentina 0.5 introduced; and every file of Valentina's own bundled tables,
// when Valentina is installed. Expected values are computed by hand from the formulas (the unit
// scale applied once, to the result).
#include <tapeline/core/errors.h>
#include <tapeline/sizes/seamly.h>
#include <tapeline_test/expect.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

using namespace tapeline::sizes;

namespace {

using tapeline_test::message_of;

std::string vit(const std::string& unit, const std::string& body) {
    return "<?xml version=\"1.0\"?>\n<vit>\n<unit>" + unit + "</unit>\n<body-measurements>\n" +
           body + "</body-measurements>\n</vit>\n";
}

void expect_refused(const std::string& body, std::initializer_list<std::string> parts) {
    const std::string msg = message_of<tapeline::InvalidInput>(
        [&] { parse_seamly_individual(vit("mm", body), "f.vit"); });
    EXPECT_EQ(msg.find('\n'), std::string::npos) << "one line: " << msg;
    for (const std::string& p : parts) {
        EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' missing from: " << msg;
    }
}

TEST(SeamlyFormulas, ArithmeticOverTheFilesMeasurementsInItsUnit) {
    // b refers to a defined later, c to b: the order of the file does not matter. In cm.
    const MeasurementSet m = parse_seamly_individual(
        vit("cm",
            "<m name=\"c\" value=\"-b + 2 * (a - 1) / 4\"/>\n"
            "<m name=\"b\" value=\"(a - 4) * 2 / 3\"/>\n"
            "<m name=\"a\" value=\"10\"/>\n"
            "<m name=\"@Длина_юбки\" value=\" 0.91*a \"/>\n"
            "<m name=\"shoulder_slope_neck_side_angle\" value=\"a + 10\"/>\n"),
        "f.vit");
    EXPECT_DOUBLE_EQ(m.values.at("a"), 100);
    EXPECT_DOUBLE_EQ(m.values.at("b"), 40);        // (10 − 4)·2/3 = 4 cm
    EXPECT_DOUBLE_EQ(m.values.at("c"), -40 + 45);  // −4 + 2·9/4 = 0.5 cm
    EXPECT_DOUBLE_EQ(m.values.at("@Длина_юбки"), 91);
    EXPECT_DOUBLE_EQ(m.values.at("shoulder_slope_neck_side_angle"), 20);  // degrees, unscaled
    EXPECT_TRUE(m.left_out.empty());
}

TEST(SeamlyFormulas, SeparatorsAreSkippedAndSpecialUnitsKept) {
    const MeasurementSet m =
        parse_seamly_individual(vit("cm",
                                    "<m name=\"a\" value=\"10\"/>\n"
                                    "<m name=\"@sep\" type=\"separator\"/>\n"
                                    "<m name=\"@ratio\" value=\"a / 4\" specialUnits=\"true\"/>\n"),
                                "f.vit");
    EXPECT_EQ(m.values.size(), 2u);
    EXPECT_DOUBLE_EQ(m.values.at("@ratio"), 2.5);
}

TEST(SeamlyFormulas, AnUndefinedNameLeavesItsMeasurementsOut) {
    // Valentina's own t_Aldrich_Women.vit refers to names it does not define; Valentina opens it
    // and marks those values as errors. Whatever depends on them is left out too.
    const MeasurementSet m = parse_seamly_individual(vit("mm",
                                                         "<m name=\"a\" value=\"10\"/>\n"
                                                         "<m name=\"@x\" value=\"@nowhere + a\"/>\n"
                                                         "<m name=\"@y\" value=\"@x * 2\"/>\n"),
                                                     "f.vit");
    EXPECT_EQ(m.values.size(), 1u);
    ASSERT_EQ(m.left_out.size(), 2u);
    EXPECT_NE(m.left_out.at("@x").find("f.vit:6: measurement '@x': formula '@nowhere + a': refers "
                                       "to '@nowhere', which the file does not define"),
              std::string::npos)
        << m.left_out.at("@x");
    EXPECT_NE(m.left_out.at("@y").find("'@nowhere'"), std::string::npos) << m.left_out.at("@y");
}

TEST(SeamlyFormulas, WhatCannotBeEvaluatedIsRefusedInOneLine) {
    expect_refused("<m name=\"a\" value=\"sqrt(4)\"/>\n",
                   {"f.vit:5: measurement 'a': formula 'sqrt(4)': the function 'sqrt' is not "
                    "supported",
                    "+ - * /"});
    expect_refused("<m name=\"a\" value=\"2 ^ 3\"/>\n", {"'2 ^ 3'", "'^' at character 3"});
    expect_refused("<m name=\"a\" value=\"b > 1 ? 2 : 3\"/>\n<m name=\"b\" value=\"1\"/>\n",
                   {"'>' at character 3"});
    expect_refused("<m name=\"a\" value=\"b + 1\"/>\n<m name=\"b\" value=\"a\"/>\n",
                   {"refers back to itself"});
    expect_refused("<m name=\"a\" value=\"1 / (2 - 2)\"/>\n", {"division by zero"});
    expect_refused("<m name=\"a\" value=\"(1 + 2\"/>\n", {"'(' is not closed"});
    expect_refused("<m name=\"a\" value=\"1 +\"/>\n", {"ends where a number or a name"});
    expect_refused("<m name=\"a\" value=\"1\"/>\n<m name=\"a\" value=\"2\"/>\n",
                   {"f.vit:6: measurement 'a' is defined twice"});
    expect_refused(
        "<m name=\"a\" value=\"" + std::string(100, '(') + "1" + std::string(100, ')') + "\"/>\n",
        {"nesting deeper than 64"});
    // A chain of references deeper than the bound is refused, not followed down the stack.
    std::string chain = "<m name=\"m0\" value=\"1\"/>\n";
    for (int i = 1; i <= 1500; ++i) {
        chain += "<m name=\"m" + std::to_string(i) + "\" value=\"m" + std::to_string(i - 1) +
                 " + 1\"/>\n";
    }
    const std::string msg = message_of<tapeline::InvalidInput>([&] {
        parse_seamly_individual(vit("mm", "<m name=\"top\" value=\"m1500\"/>\n" + chain), "f.vit");
    });
    EXPECT_NE(msg.find("more than 1000 deep"), std::string::npos) << msg;
}

TEST(SeamlyFormulas, ValentinaFiveMultisizeTablesAreRefusedByName) {
    const std::string msg = message_of<tapeline::InvalidInput>([] {
        parse_seamly_multisize(
            "<vst>\n<unit>cm</unit>\n<dimensions>\n<dimension type=\"x\"/>\n"
            "</dimensions>\n<body-measurements/>\n</vst>",
            "t.vst");
    });
    EXPECT_NE(msg.find("t.vst:3: multisize tables with <dimensions> (Valentina 0.5 and later) are "
                       "not supported"),
              std::string::npos)
        << msg;
}

// Every measurement file Valentina bundles loads: its templates (formulas, and names they do not
// define) and its multisize table.
TEST(SeamlyFormulas, ValentinasBundledTablesLoad) {
    const std::filesystem::path dir = "/usr/share/valentina/tables";
    if (!std::filesystem::is_directory(dir)) {
        GTEST_SKIP() << dir << " absent (Debian package valentina not installed)";
    }
    int files = 0;
    for (const auto& e : std::filesystem::recursive_directory_iterator(dir)) {
        const std::string p = e.path().string(), ext = e.path().extension().string();
        if (ext == ".vit") {
            const MeasurementSet m = read_seamly_individual(p);
            EXPECT_GT(m.values.size(), 0u) << p;
            ++files;
        } else if (ext == ".vst") {
            const MultisizeTable t = read_seamly_multisize(p);
            EXPECT_GT(t.entries.size(), 0u) << p;
            ++files;
        }
    }
    EXPECT_GE(files, 3) << "Valentina 0.7.52 bundles two templates and one multisize table";
}

}  // namespace
