// Hostile JSON and XML documents: nesting deep enough to exhaust the stack of a recursive walker,
// a directory given as a file. Each is refused with one line naming the source.
#include <tapeline/pattern/internal/json_read.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/measurement_set.h>
#include <tapeline/pattern/xml.h>

#include <tapeline_test/pattern.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <unistd.h>

using namespace tapeline::pattern;

namespace {

std::string invalid_message(const std::function<void()>& f) {
    try {
        f();
    } catch (const tapeline::InvalidInput& e) {
        const std::string m = e.what();
        EXPECT_EQ(m.find('\n'), std::string::npos) << "not one line: " << m;
        return m;
    }
    ADD_FAILURE() << "expected InvalidInput";
    return "";
}

std::string nested_json(std::size_t levels) {
    return "{\"chest\": " + std::string(levels, '[') + std::string(levels, ']') + "}";
}

std::string nested_xml(std::size_t levels) {
    std::string s = "<?xml version=\"1.0\"?>\n<vit>";
    for (std::size_t i = 0; i < levels; ++i) {
        s += "<e>";
    }
    for (std::size_t i = 0; i < levels; ++i) {
        s += "</e>";
    }
    return s + "</vit>";
}

std::string temp_path(const std::string& name) {
    const auto dir =
        std::filesystem::temp_directory_path() / ("tapeline_hostile_" + std::to_string(::getpid()));
    std::filesystem::create_directories(dir);
    return (dir / name).string();
}

}  // namespace

TEST(HostileDocuments, JsonDepthLimitIsExact) {
    // The top-level object is one level: 255 arrays inside it reach the limit, 256 exceed it.
    EXPECT_NO_THROW(internal::parse_json(nested_json(internal::max_json_depth - 1), "ok.json"));
    const std::string m = invalid_message(
        [] { internal::parse_json(nested_json(internal::max_json_depth), "deep.json"); });
    EXPECT_NE(m.find("deep.json: JSON nested deeper than 256 levels at byte 265"),
              std::string::npos)
        << m;
}

TEST(HostileDocuments, JsonDepthIgnoresBracketsInStrings) {
    const std::string text = "{\"name\": \"" + std::string(1000, '[') + "\\\"{\"}";
    EXPECT_NO_THROW(internal::parse_json(text, "strings.json"));
}

TEST(HostileDocuments, MeasurementFileWithThreeHundredThousandLevels) {
    const std::string path = temp_path("T.json");
    std::ofstream(path) << nested_json(300000);
    const std::string m = invalid_message([&] { read_measurement_json(path, "mm"); });
    EXPECT_NE(m.find(path + ": JSON nested deeper than 256 levels"), std::string::npos) << m;
}

TEST(HostileDocuments, XmlDepthLimit) {
    EXPECT_NO_THROW(xml::parse(nested_xml(xml::max_depth - 1), "ok.vit"));
    const std::string m =
        invalid_message([] { xml::parse(nested_xml(xml::max_depth), "deep.vit"); });
    EXPECT_NE(m.find("deep.vit:2:"), std::string::npos) << m;
    EXPECT_NE(m.find("XML: elements nested deeper than 256 levels"), std::string::npos) << m;
}

TEST(HostileDocuments, SeamlyFileWithThirtyThousandLevels) {
    const std::string path = temp_path("deep.vit");
    std::ofstream(path) << nested_xml(30000);
    const std::string m = invalid_message([&] { read_seamly_individual(path); });
    EXPECT_NE(m.find("nested deeper than 256 levels"), std::string::npos) << m;
}

TEST(HostileDocuments, DirectoryAsDocument) {
    const std::string dir = temp_path("a_directory.json");
    std::filesystem::create_directories(dir);
    const std::string m = invalid_message([&] { read_pattern_json(dir); });
    EXPECT_EQ(m, dir + ": is a directory, not a file");
}
