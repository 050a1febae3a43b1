// Hostile JSON and XML documents (nesting deep enough to exhaust the stack of a recursive walker,
// a directory given as a file) and hostile output paths (a missing directory, one path twice, a
// 255-byte name, temporaries of a killed process). Each refusal is one line naming the path.
#include <tapeline/core/atomic_write.h>
#include <tapeline/core/json_read.h>
#include <tapeline/core/xml.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/sizes/json_formats.h>
#include <tapeline/sizes/seamly.h>

#include <tapeline_test/pattern.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <functional>
#include <string>

#include <sys/wait.h>
#include <unistd.h>

using namespace tapeline::pattern;
namespace xml = tapeline::xml;
using tapeline::sizes::read_measurement_json;
using tapeline::sizes::read_seamly_individual;

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

}  // namespace

TEST(HostileDocuments, JsonDepthLimitIsExact) {
    // The top-level object is one level: 255 arrays inside it reach the limit, 256 exceed it.
    EXPECT_NO_THROW(
        tapeline::json::parse_json(nested_json(tapeline::json::max_json_depth - 1), "ok.json"));
    const std::string m = invalid_message([] {
        tapeline::json::parse_json(nested_json(tapeline::json::max_json_depth), "deep.json");
    });
    EXPECT_NE(m.find("deep.json: JSON nested deeper than 256 levels at byte 265"),
              std::string::npos)
        << m;
}

TEST(HostileDocuments, JsonDepthIgnoresBracketsInStrings) {
    const std::string text = "{\"name\": \"" + std::string(1000, '[') + "\\\"{\"}";
    EXPECT_NO_THROW(tapeline::json::parse_json(text, "strings.json"));
}

TEST(HostileDocuments, MeasurementFileWithThreeHundredThousandLevels) {
    const tapeline_test::TempDir tmp;
    const std::string path = tmp.file("T.json");
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
    const tapeline_test::TempDir tmp;
    const std::string path = tmp.file("deep.vit");
    std::ofstream(path) << nested_xml(30000);
    const std::string m = invalid_message([&] { read_seamly_individual(path); });
    EXPECT_NE(m.find("nested deeper than 256 levels"), std::string::npos) << m;
}

TEST(HostileDocuments, DirectoryAsDocument) {
    const tapeline_test::TempDir tmp;
    const std::string dir = tmp.file("a_directory.json");
    std::filesystem::create_directories(dir);
    const std::string m = invalid_message([&] { read_pattern_json(dir); });
    EXPECT_EQ(m, dir + ": is a directory, not a file");
}

// --- outputs: checked before anything is written, renamed together
// --------------------------------

namespace {

std::vector<std::string> files_in(const std::string& dir) {
    std::vector<std::string> out;
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        out.push_back(e.path().filename().string());
    }
    std::sort(out.begin(), out.end());
    return out;
}

}  // namespace

TEST(HostileOutputs, MissingDirectoryRefusedBeforeAnythingIsWritten) {
    const tapeline_test::TempDir tmp;  // empty, removed at the end
    const std::string dir = tmp.path.string();
    const std::string m = invalid_message([&] {
        tapeline::OutputFiles outs({dir + "/g.json", dir + "/nodir/x.svg"});
    });
    EXPECT_EQ(m, dir + "/nodir/x.svg: directory " + dir + "/nodir does not exist");
    EXPECT_TRUE(files_in(dir).empty());
}

TEST(HostileOutputs, FailureLeavesNoFileAndCommitRenamesAll) {
    const tapeline_test::TempDir tmp;  // empty, removed at the end
    const std::string dir = tmp.path.string();
    {
        tapeline::OutputFiles outs({dir + "/a.json", dir + "/b.svg"});
        outs.write(dir + "/a.json", [](std::ostream& o) { o << "{}"; });
        EXPECT_EQ(files_in(dir).size(), 1u);  // a temporary, not a.json
        EXPECT_EQ(files_in(dir)[0].rfind(tapeline::temporary_file_prefix, 0), 0u);
        // b.svg fails: leaving the scope without commit removes the temporary.
    }
    EXPECT_TRUE(files_in(dir).empty());
    tapeline::OutputFiles outs({dir + "/a.json", dir + "/b.svg"});
    outs.write(dir + "/a.json", [](std::ostream& o) { o << "{}"; });
    outs.write(dir + "/b.svg", [](std::ostream& o) { o << "<svg/>"; });
    outs.commit();
    EXPECT_EQ(files_in(dir), (std::vector<std::string>{"a.json", "b.svg"}));
}

TEST(HostileOutputs, SamePathTwiceAndDirectoryAsOutput) {
    const tapeline_test::TempDir tmp;  // empty, removed at the end
    const std::string dir = tmp.path.string();
    EXPECT_NE(invalid_message([&] {
                  tapeline::OutputFiles outs({dir + "/a.svg", dir + "/./a.svg"});
              }).find("given as two different outputs"),
              std::string::npos);
    EXPECT_EQ(invalid_message([&] { tapeline::check_output_path(dir); }),
              dir + ": is a directory; give a file name");
}

TEST(HostileOutputs, LongNameGetsAShortTemporary) {
    const tapeline_test::TempDir tmp;  // empty, removed at the end
    const std::string dir = tmp.path.string();
    const std::string name = std::string(250, 'n') + ".json";  // 255 bytes: NAME_MAX on Linux
    tapeline::write_file_atomically(dir + "/" + name, [](std::ostream& o) { o << "{}"; });
    EXPECT_EQ(files_in(dir), std::vector<std::string>{name});
    const std::string m =
        invalid_message([&] { tapeline::check_output_path(dir + "/" + std::string(300, 'n')); });
    EXPECT_NE(m.find("the file name has 300 bytes, more than the 255"), std::string::npos) << m;
}

TEST(HostileOutputs, StaleTemporariesOfADeadProcessAreRemoved) {
    const tapeline_test::TempDir tmp;  // empty, removed at the end
    const std::string dir = tmp.path.string();
    // A PID that is not running: a child that has exited and been reaped.
    const pid_t child = ::fork();
    if (child == 0) {
        ::_exit(0);
    }
    int status = 0;
    ::waitpid(child, &status, 0);
    const std::string stale =
        std::string(tapeline::temporary_file_prefix) + std::to_string(child) + "-0.json";
    const std::string alive = std::string(tapeline::temporary_file_prefix) + "1-0.json";
    std::ofstream(dir + "/" + stale) << "half";
    std::ofstream(dir + "/" + alive) << "init's";  // PID 1 runs: kept
    tapeline::write_file_atomically(dir + "/a.json", [](std::ostream& o) { o << "{}"; });
    EXPECT_EQ(files_in(dir), (std::vector<std::string>{alive, "a.json"}));
}
