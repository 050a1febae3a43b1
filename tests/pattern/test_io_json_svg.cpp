// The model's JSON round trip (bit-exact) and the SVG drawing (well-formed, one group per piece,
// a 100 mm scale bar at 1 user unit per mm).
#include <tapeline/core/xml.h>
#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/pattern/io_garmentcode.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/svg.h>
#include <tapeline/pattern/validate.h>

#include <tapeline_test/pattern.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <functional>
#include <sstream>

using namespace tapeline::pattern;
namespace xml = tapeline::xml;
using tapeline_test::two_piece_pattern;

namespace {

/// Bitwise equality of every double in two patterns, via their JSON trees (nlohmann compares
/// floats with ==, and writes them shortest-round-trip).
void expect_same(const Pattern& a, const Pattern& b) {
    const nlohmann::json ja = to_json(a), jb = to_json(b);
    EXPECT_EQ(ja, jb);
    ASSERT_EQ(a.pieces.size(), b.pieces.size());
    for (std::size_t i = 0; i < a.pieces.size(); ++i) {
        ASSERT_EQ(a.pieces[i].outline.edges.size(), b.pieces[i].outline.edges.size());
        for (std::size_t e = 0; e < a.pieces[i].outline.edges.size(); ++e) {
            const Point2 pa = point_at(a.pieces[i].outline.edges[e].curve, 0.37);
            const Point2 pb = point_at(b.pieces[i].outline.edges[e].curve, 0.37);
            EXPECT_EQ(std::memcmp(&pa, &pb, sizeof pa), 0);
        }
    }
}

void expect_invalid_json(const nlohmann::json& doc, std::initializer_list<std::string> parts) {
    try {
        from_json(doc, "p.json");
        FAIL() << "expected InvalidInput";
    } catch (const tapeline::InvalidInput& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind("p.json: ", 0), 0u) << msg;
        for (const std::string& p : parts) {
            EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' missing from: " << msg;
        }
    }
}

}  // namespace

TEST(PatternJson, RoundTripIsExact) {
    tapeline_test::TempDir dir;
    const Pattern p = two_piece_pattern();
    write_pattern_json(p, dir.file("p.json"));
    const Pattern q = read_pattern_json(dir.file("p.json"));
    expect_same(p, q);
    EXPECT_EQ(q.pieces[1].cut_count, 2);
    EXPECT_TRUE(q.pieces[1].mirrored);
    EXPECT_EQ(q.seams[0].direction, SeamDirection::opposite);
    EXPECT_EQ(*q.pieces[0].fold->edge, 3u);
    // Writing the re-read pattern gives the same bytes.
    write_pattern_json(q, dir.file("q.json"));
    EXPECT_EQ(tapeline_test::slurp(dir.file("p.json")), tapeline_test::slurp(dir.file("q.json")));
}

TEST(PatternJson, RoundTripOfEverySharedPattern) {
    const auto files = tapeline_test::shared_pattern_files();
    if (files.empty()) {
        GTEST_SKIP() << tapeline_test::shared_patterns_dir() << " absent";
    }
    for (const std::string& path : files) {
        SCOPED_TRACE(path);
        const Pattern p = tapeline_test::load_shared_pattern(path);
        const std::string text = to_json(p).dump();
        const Pattern q = from_json(nlohmann::json::parse(text), "memory");
        expect_same(p, q);
        EXPECT_TRUE(validate(q).ok());
    }
}

TEST(PatternJson, OtherUnitsAreConverted) {
    nlohmann::json j = to_json(two_piece_pattern());
    j["units"] = "cm";
    const Pattern q = from_json(j, "cm.json");
    EXPECT_EQ(q.units, "mm");
    EXPECT_DOUBLE_EQ(std::get<Line>(q.pieces[1].outline.edges[1].curve).a.x, 2000);
    EXPECT_DOUBLE_EQ(q.pieces[0].notches[0].offset, 1500);
    EXPECT_DOUBLE_EQ(q.measurements_used.at("hips"), 960.5);  // measurements are always mm
}

TEST(PatternJson, MalformedDocumentsAreRejected) {
    const nlohmann::json good = to_json(two_piece_pattern());
    nlohmann::json d = good;
    d["units"] = "furlong";
    expect_invalid_json(d, {"units", "unknown unit 'furlong'"});
    d = good;
    d["format_version"] = 99;
    expect_invalid_json(d, {"format_version", "99"});
    d = good;
    d["pieces"][0].erase("outline");
    expect_invalid_json(d, {"piece 'front'", "missing field 'outline'"});
    d = good;
    d["pieces"][1]["outline"][2]["a"][1] = nullptr;  // how nlohmann writes a NaN
    expect_invalid_json(d, {"piece 'back'", "outline[2].a[1]", "null (NaN?)"});
    d = good;
    d["pieces"][1]["outline"][0]["type"] = "spline";
    expect_invalid_json(d, {"piece 'back'", "outline[0].type", "'spline'"});
    d = good;
    d["seams"][0]["direction"] = "sideways";
    expect_invalid_json(d, {"seams[0].direction", "'sideways'"});
    // A seam naming a missing edge reads, and validation names it.
    d = good;
    d["seams"][0]["b"]["first_edge"] = 9;
    const Pattern p = from_json(d, "p.json");
    try {
        require_valid(p, {}, "p.json");
        FAIL();
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("p.json: seam 0 'side' side B names edges 9..10"),
                  std::string::npos)
            << e.what();
    }
    tapeline_test::TempDir dir;
    const std::string text = good.dump(1);
    tapeline_test::write_text(dir.file("t.json"), text.substr(0, text.size() - 40));
    try {
        read_pattern_json(dir.file("t.json"));
        FAIL();
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find(dir.file("t.json") + ": malformed JSON at byte"),
                  std::string::npos);
    }
}

TEST(PatternSvg, WellFormedWithOneGroupPerPieceAndAScaleBar) {
    Pattern p = two_piece_pattern();
    tapeline_test::TempDir dir;
    const SvgReport rep = write_svg(p, dir.file("p.svg"));
    const xml::Element svg = xml::parse(tapeline_test::slurp(dir.file("p.svg")), "p.svg");
    ASSERT_EQ(svg.name, "svg");
    // 1 user unit = 1 mm: width "<W>mm" and viewBox "0 0 W H".
    const std::string w = *svg.attribute("width"), vb = *svg.attribute("viewBox");
    ASSERT_EQ(w.substr(w.size() - 2), "mm");
    const double width = std::stod(w.substr(0, w.size() - 2));
    double vx, vy, vw, vh;
    ASSERT_EQ(std::sscanf(vb.c_str(), "%lf %lf %lf %lf", &vx, &vy, &vw, &vh), 4);
    EXPECT_DOUBLE_EQ(vw, width);
    EXPECT_NEAR(vw, rep.width_mm, 1e-3);

    std::vector<const xml::Element*> pieces;
    const xml::Element* bar = nullptr;
    for (const xml::Element& c : svg.children) {
        if (c.name == "g" && c.attribute("class") && *c.attribute("class") == "piece") {
            pieces.push_back(&c);
        }
        if (c.name == "g" && c.attribute("id") && *c.attribute("id") == "scale-bar") {
            bar = &c;
        }
    }
    ASSERT_EQ(pieces.size(), p.pieces.size());
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        EXPECT_EQ(*pieces[i]->attribute("data-name"), p.pieces[i].name);
        bool has_outline = false, has_name = false;
        for (const xml::Element& c : pieces[i]->children) {
            has_outline |= c.name == "path" && *c.attribute("class") == "outline";
            has_name |= c.name == "text" && c.text == p.pieces[i].name;
        }
        EXPECT_TRUE(has_outline);
        EXPECT_TRUE(has_name);
    }
    // Each outline path draws the model's outline: its commands, edge by edge, with the model's
    // points moved by the piece offset and y flipped (written to 0.001 mm: 1e-3).
    for (std::size_t i = 0; i < pieces.size(); ++i) {
        const xml::Element* path = nullptr;
        for (const xml::Element& c : pieces[i]->children)
            if (c.name == "path" && *c.attribute("class") == "outline")
                path = &c;
        ASSERT_TRUE(path);
        std::istringstream d(*path->attribute("d"));
        const Point2 off = rep.piece_offsets[i];
        std::string cmd;
        auto point = [&](const Point2& q, const std::string& what) {
            double x = NAN, y = NAN;
            d >> x >> y;
            EXPECT_NEAR(x, q.x + off.x, 1e-3) << p.pieces[i].name << " " << what;
            EXPECT_NEAR(y, off.y - q.y, 1e-3) << p.pieces[i].name << " " << what;
        };
        const auto& edges = p.pieces[i].outline.edges;
        for (std::size_t e = 0; e < edges.size(); ++e) {
            const std::string what = "edge " + std::to_string(e);
            d >> cmd;
            if (e == 0) {
                ASSERT_EQ(cmd, "M") << what;
                point(start_point(edges[e].curve), what);
                d >> cmd;
            }
            if (const auto* l = std::get_if<Line>(&edges[e].curve)) {
                ASSERT_EQ(cmd, "L") << what;
                point(l->b, what);
            } else if (const auto* c = std::get_if<CubicBezier>(&edges[e].curve)) {
                ASSERT_EQ(cmd, "C") << what;
                point(c->p1, what);
                point(c->p2, what);
                point(c->p3, what);
            } else {
                const Arc& a = std::get<Arc>(edges[e].curve);
                ASSERT_EQ(cmd, "A") << what;
                double rx = 0, ry = 0, rot = 1;
                int large = -1, sweep = -1;
                d >> rx >> ry >> rot >> large >> sweep;
                EXPECT_NEAR(rx, arc_frame(a).radius, 1e-3) << what;
                EXPECT_EQ(large, a.large_arc ? 1 : 0) << what;
                EXPECT_EQ(sweep, a.ccw ? 0 : 1) << what;  // y flipped
                point(a.b, what);
            }
        }
        d >> cmd;
        EXPECT_EQ(cmd, "Z") << p.pieces[i].name;
        EXPECT_FALSE(d >> cmd) << p.pieces[i].name << ": more path data";
    }
    // Front: grain line, fold line, one notch, a seam mark; back: a seam mark.
    auto count = [](const xml::Element& g, const std::string& cls) {
        int n = 0;
        for (const xml::Element& c : g.children) {
            n += c.attribute("class") && *c.attribute("class") == cls;
        }
        return n;
    };
    EXPECT_EQ(count(*pieces[0], "grain"), 1);
    EXPECT_EQ(count(*pieces[0], "fold"), 1);
    EXPECT_EQ(count(*pieces[0], "notch"), 1);
    EXPECT_EQ(count(*pieces[0], "seam-mark"), 1);
    EXPECT_EQ(count(*pieces[1], "seam-mark"), 1);
    ASSERT_TRUE(bar);
    const xml::Element* rect = bar->child("rect");
    ASSERT_TRUE(rect);
    EXPECT_DOUBLE_EQ(std::stod(*rect->attribute("width")), 100.0);
    EXPECT_EQ(bar->child("text")->text, "100 mm");

    // The notch tick starts on the outline where the model says, with y flipped.
    const Point2 at = notch_position(p.pieces[0], p.pieces[0].notches[0]);
    for (const xml::Element& c : pieces[0]->children) {
        if (c.attribute("class") && *c.attribute("class") == "notch") {
            EXPECT_NEAR(std::stod(*c.attribute("x1")), at.x + rep.piece_offsets[0].x, 1e-3);
            EXPECT_NEAR(std::stod(*c.attribute("y1")), rep.piece_offsets[0].y - at.y, 1e-3);
        }
    }
}

TEST(PatternSvg, EverySharedPatternDrawsAndParses) {
    const auto files = tapeline_test::shared_pattern_files();
    if (files.empty()) {
        GTEST_SKIP() << tapeline_test::shared_patterns_dir() << " absent";
    }
    for (const std::string& path : files) {
        SCOPED_TRACE(path);
        const Pattern p = tapeline_test::load_shared_pattern(path);
        const xml::Element svg = xml::parse(to_svg(p), path + ".svg");
        std::size_t groups = 0;
        for (const xml::Element& c : svg.children) {
            groups += c.name == "g" && c.attribute("class") && *c.attribute("class") == "piece";
        }
        EXPECT_EQ(groups, p.pieces.size());
    }
}

TEST(PatternSvg, NamesAreEscaped) {
    Pattern p = two_piece_pattern();
    p.pieces[0].name = "front <left> & \"right\"";
    p.seams[0].a.piece = p.pieces[0].name;
    const xml::Element svg = xml::parse(to_svg(p), "escaped.svg");
    bool found = false;
    for (const xml::Element& c : svg.children) {
        if (c.attribute("data-name") && *c.attribute("data-name") == p.pieces[0].name) {
            found = true;
        }
    }
    EXPECT_TRUE(found);
}
