// Measurement sets: FreeSewing JSON, flat JSON with a declared unit, Seamly2D .vit/.vst (XML),
// and the strict XML reader's rejections.
#include <tapeline/core/xml.h>
#include <tapeline/sizes/json_formats.h>
#include <tapeline/sizes/seamly.h>

#include <tapeline_test/sizes.h>

#include <gtest/gtest.h>

#include <functional>

using namespace tapeline::sizes;
namespace xml = tapeline::xml;
using tapeline_test::TempDir;

namespace {

std::string data(const std::string& name) {
    return tapeline_test::sizes::data_patterns(name);
}

void expect_invalid(const std::function<void()>& f, std::initializer_list<std::string> parts) {
    try {
        f();
        FAIL() << "expected InvalidInput";
    } catch (const tapeline::InvalidInput& e) {
        const std::string msg = e.what();
        for (const std::string& p : parts) {
            EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' missing from: " << msg;
        }
    }
}

const std::string vit_head =
    "<?xml version=\"1.0\"?>\n<vit>\n<unit>mm</unit>\n<body-measurements>\n";

}  // namespace

TEST(MeasurementSets, FreeSewingSets) {
    const std::string path =
        tapeline_test::sizes::shared_patterns("freesewing/measurement_sets.json");
    if (!std::ifstream(path)) {
        GTEST_SKIP() << path << " absent";
    }
    const auto sets = read_freesewing_measurement_sets(path);
    ASSERT_EQ(sets.size(), 2u);
    EXPECT_EQ(sets[0].name, "cisFemaleAdult36");
    EXPECT_EQ(sets[0].get("chest"), 979.0);
    EXPECT_EQ(sets[0].get("shoulderSlope"), 13.0);  // degrees, untouched
    EXPECT_FALSE(sets[0].get("inseamToMoon"));
    EXPECT_EQ(sets[0].values.size(), 38u);
}

TEST(MeasurementSets, FlatJsonWithDeclaredUnit) {
    TempDir dir;
    dir.write("me.json", R"({"chest": 97.9, "shoulderSlope": 13})");
    const MeasurementSet m = read_measurement_json(dir.file("me.json"), "cm");
    EXPECT_EQ(m.name, "me");
    EXPECT_DOUBLE_EQ(*m.get("chest"), 979);
    EXPECT_DOUBLE_EQ(*m.get("shoulderSlope"), 13);
    expect_invalid([&] { read_measurement_json(dir.file("me.json"), "cubit"); },
                   {dir.file("me.json"), "unknown unit 'cubit'"});
    dir.write("bad.json", R"({"chest": "97.9"})");
    expect_invalid([&] { read_measurement_json(dir.file("bad.json"), "cm"); },
                   {dir.file("bad.json"), "chest", "expected a number"});
}

TEST(MeasurementSets, SeamlyIndividualFile) {
    const MeasurementSet m = read_seamly_individual(data("example_individual.vit"));
    EXPECT_EQ(m.name, "example_individual");
    EXPECT_DOUBLE_EQ(*m.get("bust_circ"), 979);
    EXPECT_DOUBLE_EQ(*m.get("height"), 1659);
    EXPECT_DOUBLE_EQ(*m.get("shoulder_slope_degrees"), 13);
    EXPECT_EQ(m.values.size(), 5u);
}

TEST(MeasurementSets, SeamlyMultisizeFileIsLinearInSizeAndHeight) {
    const MultisizeTable t = read_seamly_multisize(data("example_multisize.vst"));
    EXPECT_EQ(t.base_size, 48);
    EXPECT_EQ(t.base_height, 170);
    EXPECT_EQ(t.size_step, 2);  // Seamly2D's grid, in cm
    EXPECT_EQ(t.height_step, 6);
    const MeasurementSet base = t.at(48, 170);
    EXPECT_DOUBLE_EQ(*base.get("bust_circ"), 960);
    const MeasurementSet m = t.at(52, 176);  // two size steps, one height step
    EXPECT_DOUBLE_EQ(*m.get("bust_circ"), 960 + 2 * 40);
    EXPECT_DOUBLE_EQ(*m.get("waist_circ"), 800 + 2 * 40 + 5);
    EXPECT_DOUBLE_EQ(*m.get("height"), 1760);
}

TEST(MeasurementSets, SeamlyErrorsNameFileAndLine) {
    expect_invalid(
        [] {
            parse_seamly_individual(vit_head +
                                        "<m name=\"x\" value=\"sqrt(4)+2\"/>\n"
                                        "</body-measurements>\n</vit>",
                                    "f.vit");
        },
        {"f.vit:5", "measurement 'x'", "'sqrt(4)+2'", "function 'sqrt' is not supported"});
    expect_invalid([] { parse_seamly_individual("<vit><unit>furlong</unit></vit>", "f.vit"); },
                   {"f.vit", "unknown unit 'furlong'"});
    expect_invalid([] { parse_seamly_individual("<vit><unit>cm</unit></vit>", "f.vit"); },
                   {"f.vit", "no <body-measurements>"});
    expect_invalid([] { parse_seamly_individual("<vst><unit>cm</unit></vst>", "f.vit"); },
                   {"f.vit", "<vst>", "not an individual measurement file"});
    expect_invalid(
        [] {
            parse_seamly_individual(vit_head + "<m value=\"1\"/></body-measurements></vit>",
                                    "f.vit");
        },
        {"f.vit:5", "without a name"});
    expect_invalid(
        [] { parse_seamly_multisize("<vst><unit>cm</unit><height base=\"170\"/></vst>", "t.vst"); },
        {"t.vst", "no <size base=...>"});
    expect_invalid(
        [] {
            parse_seamly_individual(
                vit_head + "<m name=\"a\" value=\"nan\"/></body-measurements></vit>", "f.vit");
        },
        {"f.vit:5", "not finite"});
}

TEST(Xml, ParsesWhatSeamlyAndSvgUse) {
    const xml::Element e = xml::parse(
        "<?xml version=\"1.0\"?>\n<!-- c -->\n<a x='1' "
        "y=\"&lt;&amp;&#65;&#x42;\">t<![CDATA[<raw>]]>"
        "<b/><c k=\"v\">in</c></a>\n",
        "x.xml");
    EXPECT_EQ(e.name, "a");
    EXPECT_EQ(*e.attribute("x"), "1");
    EXPECT_EQ(*e.attribute("y"), "<&AB");
    EXPECT_EQ(e.text, "t<raw>");
    ASSERT_EQ(e.children.size(), 2u);
    EXPECT_EQ(e.child("c")->text, "in");
    EXPECT_EQ(e.child("c")->line, 3u);
}

TEST(Xml, RejectsMalformedDocumentsWithLineAndColumn) {
    expect_invalid([] { xml::parse("<a>\n<b></a>", "x.xml"); }, {"x.xml:2:", "</a> closes <b>"});
    expect_invalid([] { xml::parse("<a>\n<b>", "x.xml"); }, {"x.xml:2", "not closed"});
    expect_invalid([] { xml::parse("<a x=1/>", "x.xml"); }, {"x.xml:1:", "not quoted"});
    expect_invalid([] { xml::parse("<a x='1' x='2'/>", "x.xml"); }, {"duplicate attribute 'x'"});
    expect_invalid([] { xml::parse("<a>&nbsp;</a>", "x.xml"); }, {"unknown entity '&nbsp;'"});
    expect_invalid([] { xml::parse("<!DOCTYPE a><a/>", "x.xml"); }, {"DOCTYPE"});
    expect_invalid([] { xml::parse("<a/><b/>", "x.xml"); }, {"content after the root element"});
    expect_invalid([] { xml::parse("", "x.xml"); }, {"expected the root element"});
    expect_invalid([] { xml::parse("<a><!-- x </a>", "x.xml"); }, {"unterminated comment"});
}
