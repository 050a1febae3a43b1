// DXF-AAMA export read back by an independent reader (python3-ezdxf via dxf_extract.py): header
// units and extents, one block per piece with its texts, boundary within the 0.05 mm sampling
// tolerance of the model outline both ways, notch positions and counts, grain and fold lines, one
// INSERT per block.
#include <tapeline/pattern/dxf.h>
#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/pattern/io_garmentcode.h>

#include <tapeline_test/pattern.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>

using namespace tapeline::pattern;
using tapeline_test::TempDir;
using Json = nlohmann::json;

namespace {

const std::string extractor = std::string(TAPELINE_DATA_DIR) + "/../tests/pattern/dxf_extract.py";

/// ezdxf's reading of `dxf`; sets `skip` when python3-ezdxf is missing.
Json read_with_ezdxf(const std::string& dxf, bool& skip) {
    const std::string err = dxf + ".stderr";
    const std::string cmd = "/usr/bin/python3 '" + extractor + "' '" + dxf + "' 2>'" + err + "'";
    FILE* pipe = ::popen(cmd.c_str(), "r");
    if (!pipe) {
        ADD_FAILURE() << "cannot run " << cmd;
        return {};
    }
    std::string out;
    char buf[65536];
    std::size_t n;
    while ((n = std::fread(buf, 1, sizeof buf, pipe)) > 0) {
        out.append(buf, n);
    }
    const int status = ::pclose(pipe);
    if (WIFEXITED(status) && WEXITSTATUS(status) == 3) {
        skip = true;
        return {};
    }
    EXPECT_EQ(status, 0) << cmd << ": " << tapeline_test::slurp(err);
    return Json::parse(out, nullptr, false);
}

Point2 pt(const Json& j) {
    return {j[0].get<double>(), j[1].get<double>()};
}

double distance_to_polyline(const Point2& p, const std::vector<Point2>& ring, bool closed) {
    double best = std::numeric_limits<double>::infinity();
    const std::size_t n = ring.size();
    for (std::size_t i = 0; i + (closed ? 0 : 1) < n; ++i) {
        best = std::min(best, internal::distance_to_segment(p, ring[i], ring[(i + 1) % n]));
    }
    return best;
}

/// The header's extents are the box of everything drawn as ezdxf places it: the geometry's
/// points exactly, each text by the writer's estimate (one em per character, 0.35 em below the
/// baseline); they contain ezdxf's own box (its font metrics for the texts). The sheet for a 1:1
/// plot is the extents plus 10 mm on each side.
void check_extents(const Json& doc, const DxfReport& rep) {
    const Json& placed = doc["placed"];
    ASSERT_TRUE(placed["geometry_box"].is_array());
    double x0 = placed["geometry_box"][0], y0 = placed["geometry_box"][1];
    double x1 = placed["geometry_box"][2], y1 = placed["geometry_box"][3];
    for (const Json& t : placed["texts"]) {
        const double x = t[0], y = t[1], h = t[2], n = t[3];
        x0 = std::min(x0, x);
        y0 = std::min(y0, y - 0.35 * h);
        x1 = std::max(x1, x + n * h);
        y1 = std::max(y1, y + h);
    }
    const double tol = 2e-6;  // coordinates are written to 1e-6 mm
    EXPECT_NEAR(doc["extmin"][0].get<double>(), x0, tol);
    EXPECT_NEAR(doc["extmin"][1].get<double>(), y0, tol);
    EXPECT_NEAR(doc["extmax"][0].get<double>(), x1, tol);
    EXPECT_NEAR(doc["extmax"][1].get<double>(), y1, tol);
    EXPECT_EQ(doc["limmin"], doc["extmin"]);
    EXPECT_EQ(doc["limmax"], doc["extmax"]);
    EXPECT_NEAR(rep.extents_min.x, x0, tol);
    EXPECT_NEAR(rep.extents_max.y, y1, tol);
    const Json& ez = placed["ezdxf_box"];
    EXPECT_LE(doc["extmin"][0].get<double>(), ez[0].get<double>() + tol);
    EXPECT_LE(doc["extmin"][1].get<double>(), ez[1].get<double>() + tol);
    EXPECT_GE(doc["extmax"][0].get<double>(), ez[2].get<double>() - tol);
    EXPECT_GE(doc["extmax"][1].get<double>(), ez[3].get<double>() - tol);
    EXPECT_EQ(doc["plimmin"], Json::array({0.0, 0.0}));
    EXPECT_NEAR(doc["plimmax"][0].get<double>(), x1 - x0 + 20, tol);
    EXPECT_NEAR(doc["plimmax"][1].get<double>(), y1 - y0 + 20, tol);
    EXPECT_NEAR(doc["pinsbase"][0].get<double>(), 10 - x0, tol);
    EXPECT_NEAR(doc["pinsbase"][1].get<double>(), 10 - y0, tol);
}

struct Deviation {
    double dxf_to_model = 0, model_to_dxf = 0;
    std::size_t vertices = 0;
};

/// Checks one pattern; `dev` receives the boundary deviations.
void check_pattern(const Pattern& pat, const std::string& dxf_path, bool& skip, Deviation& dev) {
    const DxfReport rep = write_dxf(pat, dxf_path);
    const Json doc = read_with_ezdxf(dxf_path, skip);
    if (skip || doc.is_discarded() || doc.is_null()) {
        EXPECT_TRUE(skip) << "ezdxf output is not JSON";
        return;
    }
    EXPECT_EQ(doc["dxfversion"], "AC1009");
    EXPECT_EQ(doc["insunits"], 4);
    EXPECT_EQ(doc["measurement"], 1);
    EXPECT_EQ(doc["audit_errors"], 0);
    check_extents(doc, rep);
    for (const char* l : {"1", "2", "3", "4", "6", "7", "8"}) {
        EXPECT_NE(std::find(doc["layers"].begin(), doc["layers"].end(), l), doc["layers"].end())
            << "layer " << l;
    }
    const Json& blocks = doc["blocks"];
    EXPECT_EQ(blocks.size(), pat.pieces.size());
    // Modelspace: one INSERT per block, in piece order, plus the style text.
    std::size_t inserts = 0;
    bool style = false;
    for (const Json& e : doc["modelspace"]) {
        if (e["type"] == "INSERT") {
            ASSERT_LT(inserts, rep.block_names.size());
            EXPECT_EQ(e["block"], rep.block_names[inserts]);
            EXPECT_LE(distance(pt(e["point"]), rep.insert_points[inserts]), 1e-5);
            ++inserts;
        } else if (e["type"] == "TEXT") {
            style = style || e["text"] == "Style Name: " + pat.name;
        }
    }
    EXPECT_EQ(inserts, pat.pieces.size());
    EXPECT_TRUE(style);

    for (std::size_t i = 0; i < pat.pieces.size() && i < blocks.size(); ++i) {
        const Piece& piece = pat.pieces[i];
        const Json& block = blocks[i];
        EXPECT_EQ(block["name"], rep.block_names[i]);
        std::vector<Point2> boundary;
        std::size_t boundaries = 0, marked_points = 0, internals = 0;
        std::vector<std::pair<Point2, Point2>> notches;
        std::vector<std::string> texts;
        for (const Json& e : block["entities"]) {
            const std::string type = e["type"], layer = e["layer"];
            if (type == "POLYLINE" && layer == "1") {
                ++boundaries;
                EXPECT_TRUE(e["closed"].get<bool>());
                for (const Json& p : e["points"]) {
                    boundary.push_back(pt(p));
                }
            } else if (type == "POLYLINE" && layer == "8") {
                ++internals;
                EXPECT_FALSE(e["closed"].get<bool>());
            } else if (type == "POINT" && (layer == "2" || layer == "3")) {
                ++marked_points;
            } else if (type == "LINE" && (layer == "4" || layer.size() == 2)) {
                notches.push_back({pt(e["start"]), pt(e["end"])});
            } else if (type == "LINE" && layer == "7") {
                ASSERT_TRUE(piece.grain.has_value()) << piece.name;
                EXPECT_LE(distance(pt(e["start"]), piece.grain->from), 1e-5);
                EXPECT_LE(distance(pt(e["end"]), piece.grain->to), 1e-5);
            } else if (type == "LINE" && layer == "6") {
                ASSERT_TRUE(piece.fold.has_value()) << piece.name;
                EXPECT_LE(distance(pt(e["start"]), piece.fold->line.a), 1e-5);
            } else if (type == "TEXT") {
                texts.push_back(e["text"]);
            }
        }
        EXPECT_EQ(boundaries, 1u) << piece.name;
        EXPECT_EQ(marked_points, boundary.size()) << piece.name;
        EXPECT_EQ(internals, piece.internal_lines.size() + piece.darts.size()) << piece.name;
        EXPECT_NE(std::find(texts.begin(), texts.end(), "Piece Name: " + piece.name), texts.end())
            << piece.name;
        EXPECT_NE(
            std::find(texts.begin(), texts.end(), "Quantity: " + std::to_string(piece.cut_count)),
            texts.end())
            << piece.name;
        // Notches: same count, each starting on the outline where the model puts it, pointing
        // 6 mm into the piece.
        ASSERT_EQ(notches.size(), piece.notches.size()) << piece.name;
        for (std::size_t k = 0; k < notches.size(); ++k) {
            EXPECT_LE(distance(notches[k].first, notch_position(piece, piece.notches[k])), 1e-5)
                << piece.name << " notch " << k;
            EXPECT_NEAR(distance(notches[k].first, notches[k].second), 6.0, 1e-5);
        }
        // Boundary: every DXF vertex on the model outline, every model point near the polyline.
        dev.vertices += boundary.size();
        for (const Point2& p : boundary) {
            const auto pos = project(piece.outline, p, 1e-4);
            dev.dxf_to_model = std::max(dev.dxf_to_model, pos->distance);
        }
        for (const Edge& e : piece.outline.edges) {
            for (int k = 0; k <= 256; ++k) {
                dev.model_to_dxf =
                    std::max(dev.model_to_dxf,
                             distance_to_polyline(point_at(e.curve, k / 256.0), boundary, true));
            }
        }
    }
}

}  // namespace

TEST(PatternDxf, TwoPiecePatternReadBackByEzdxf) {
    TempDir dir;
    bool skip = false;
    const Pattern pat = tapeline_test::two_piece_pattern();
    Deviation d;
    check_pattern(pat, dir.file("two.dxf"), skip, d);
    if (skip) {
        GTEST_SKIP() << "python3-ezdxf missing (apt install python3-ezdxf)";
    }
    EXPECT_LE(d.dxf_to_model, 2e-4);
    EXPECT_LE(d.model_to_dxf, 0.05);
}

TEST(PatternDxf, EverySharedPatternReadBackByEzdxf) {
    const std::vector<std::string> files = tapeline_test::shared_pattern_files();
    if (files.empty()) {
        GTEST_SKIP() << tapeline_test::shared_patterns_dir() << " absent";
    }
    TempDir dir;
    double worst_in = 0, worst_out = 0;
    for (const std::string& f : files) {
        const Pattern pat = tapeline_test::load_shared_pattern(f);
        bool skip = false;
        Deviation d;
        check_pattern(pat, dir.file(pat.name + ".dxf"), skip, d);
        if (skip) {
            GTEST_SKIP() << "python3-ezdxf missing (apt install python3-ezdxf)";
        }
        std::printf("  %-26s %5zu boundary vertices; DXF→model %.2g mm, model→DXF %.4f mm\n",
                    pat.name.c_str(), d.vertices, d.dxf_to_model, d.model_to_dxf);
        // Vertices are points of the curves, written to 1e-6 mm; the projection measures against
        // a polyline within 1e-4 mm of the outline, hence the bound 2e-4.
        EXPECT_LE(d.dxf_to_model, 2e-4) << f;
        EXPECT_LE(d.model_to_dxf, 0.05) << f;
        worst_in = std::max(worst_in, d.dxf_to_model);
        worst_out = std::max(worst_out, d.model_to_dxf);
    }
    std::printf("worst: DXF→model %.2g mm, model→DXF %.4f mm (tolerance 0.05)\n", worst_in,
                worst_out);
}

TEST(PatternDxf, TurnPointsAndBlockNames) {
    std::ostringstream out;
    tapeline::pattern::Pattern pat = tapeline_test::two_piece_pattern();
    pat.pieces[1].name = "fr/ont";
    const DxfReport rep = write_dxf(pat, out);
    EXPECT_EQ(rep.block_names, (std::vector<std::string>{"front", "fr_ont"}));
    // Every join of the two rectangles is a corner (the waist arc and the hem curve meet the
    // sides at an angle): 4 + 4 turn points.
    EXPECT_EQ(rep.turn_points, 8u);
    EXPECT_EQ(rep.notches, 1u);
    EXPECT_EQ(rep.internal_lines, 2u);
    pat.pieces[1].name = "front";  // a duplicate name gets a suffix
    EXPECT_EQ(write_dxf(pat, out).block_names, (std::vector<std::string>{"front", "front_2"}));
}

TEST(PatternDxf, BadInputIsRejected) {
    std::ostringstream out;
    Pattern pat = tapeline_test::two_piece_pattern();
    DxfOptions o;
    o.tolerance_mm = 0;
    try {
        write_dxf(pat, out, o);
        ADD_FAILURE();
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("tolerance"), std::string::npos);
    }
    pat.pieces[1].outline.edges.clear();
    try {
        write_dxf(pat, out);
        ADD_FAILURE();
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("piece 'back' has no outline"), std::string::npos);
    }
    pat = tapeline_test::two_piece_pattern();
    pat.pieces[0].notches[0].edge = 9;
    try {
        write_dxf(pat, out);
        ADD_FAILURE();
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("notch 'hip notch' names missing edge 9"),
                  std::string::npos);
    }
}
