// FreeSewing import against the export's own numbers: the seam path length FreeSewing measured
// (length_mm, rounded to 1 µm) and its flattened polylines (rounded to 1 µm, y down).
#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/pattern/validate.h>

#include <tapeline_test/pattern.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <chrono>

using namespace tapeline::pattern;
using tapeline_test::shared_patterns_dir;

namespace {

std::vector<std::string> freesewing_files() {
    return tapeline_test::files_ending(shared_patterns_dir() + "/freesewing", ".json");
}

std::vector<std::string> pattern_files() {
    std::vector<std::string> out;
    for (const std::string& f : freesewing_files()) {
        if (f.find("measurement_sets") == std::string::npos) {
            out.push_back(f);
        }
    }
    return out;
}

std::string bundled_freesewing() {
    return std::string(TAPELINE_DATA_DIR) + "/patterns/aaron_cisFemaleAdult36.json";
}

void expect_invalid(const std::string& text, std::initializer_list<std::string> parts) {
    try {
        freesewing_from_json(nlohmann::json::parse(text), "fs.json");
        FAIL() << "expected InvalidInput for " << text;
    } catch (const tapeline::InvalidInput& e) {
        const std::string msg = e.what();
        EXPECT_EQ(msg.rfind("fs.json", 0), 0u) << msg;
        for (const std::string& p : parts) {
            EXPECT_NE(msg.find(p), std::string::npos) << "'" << p << "' missing from: " << msg;
        }
    }
}

const char* minimal_piece =
    R"({"units": "mm; y down", "pieces": [{"name": "p", "paths": {"seam": {"ops": [
        {"type": "move", "to": [0, 0]}, {"type": "line", "to": [100, 0]},
        {"type": "line", "to": [100, 50]}, {"type": "close"}]}}}]})";

}  // namespace

TEST(PatternFreeSewing, SeamLengthsAndPolylinesMatchTheExport) {
    const auto files = pattern_files();
    if (files.empty()) {
        GTEST_SKIP() << "no FreeSewing files in " << shared_patterns_dir();
    }
    std::size_t pieces = 0, points = 0;
    double worst_length = 0, worst_point = 0;
    for (const std::string& path : files) {
        SCOPED_TRACE(path);
        const auto t0 = std::chrono::steady_clock::now();
        ImportReport rep;
        const Pattern p = read_freesewing(path, &rep);
        const double ms =
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count();
        std::cout << "[ info ] " << path.substr(path.find_last_of('/') + 1) << ": "
                  << p.pieces.size() << " pieces, " << rep.skipped_pieces
                  << " skipped, imported in " << ms << " ms\n";
        const nlohmann::json doc = nlohmann::json::parse(tapeline_test::slurp(path));
        for (const auto& jp : doc["pieces"]) {
            const std::string name = jp["name"];
            const Piece* piece = find_piece(p, name);
            if (!jp["paths"].contains("seam")) {
                EXPECT_FALSE(piece) << name;
                continue;
            }
            ASSERT_TRUE(piece) << name;
            ++pieces;
            const auto& seam = jp["paths"]["seam"];
            // FreeSewing's length_mm is rounded to 0.001 mm; 0.01 mm leaves room for its own
            // flattening-based measure.
            const double ref = seam["length_mm"];
            const double ours = length(piece->outline);
            EXPECT_NEAR(ours, ref, 0.01) << name;
            worst_length = std::max(worst_length, std::abs(ours - ref));
            // Every exported polyline point (rounded to 1 µm) lies on our outline after the flip.
            for (const auto& pl : seam["polylines"]) {
                for (const auto& xy : pl["pts"]) {
                    const Point2 q{xy[0].get<double>(), -xy[1].get<double>()};
                    const auto pos = project(piece->outline, q, 0.001);
                    ASSERT_TRUE(pos);
                    EXPECT_LE(pos->distance, 0.05) << name << " point " << xy.dump();
                    worst_point = std::max(worst_point, pos->distance);
                    ++points;
                }
            }
        }
        const ValidationReport v = validate(p);
        EXPECT_TRUE(v.ok()) << (v.errors.empty() ? "" : v.errors.front().message);
    }
    std::cout << "[ info ] " << pieces << " pieces: worst length error " << worst_length << " mm; "
              << points << " polyline points: worst distance " << worst_point << " mm\n";
}

TEST(PatternFreeSewing, FoldGrainNotchesAndMeasurements) {
    const std::string path = shared_patterns_dir() + "/freesewing/teagan_cisFemaleAdult36.json";
    if (!tapeline_test::exists(path)) {
        GTEST_SKIP() << path << " absent";
    }
    const Pattern p = read_freesewing(path);
    EXPECT_EQ(p.name, "teagan_cisFemaleAdult36");
    EXPECT_EQ(p.designer, "FreeSewing");
    EXPECT_EQ(p.garment_type, "t-shirt");
    EXPECT_EQ(p.size, "cisFemaleAdult36");
    ASSERT_TRUE(p.measurements_used.count("chest"));
    EXPECT_EQ(p.measurements_used.at("chest"), 979);
    const Piece* front = find_piece(p, "teagan.front");
    ASSERT_TRUE(front);
    ASSERT_TRUE(front->fold);
    ASSERT_TRUE(front->fold->edge);
    // The fold edge is the centre-front line x = 0 and the bracket lies on it.
    const Line& fold_edge = std::get<Line>(front->outline.edges[*front->fold->edge].curve);
    EXPECT_EQ(fold_edge.a.x, 0);
    EXPECT_EQ(fold_edge.b.x, 0);
    EXPECT_EQ(front->fold->line.a.x, 0);
    // y is flipped: FreeSewing's points are y down, ours y up.
    ASSERT_TRUE(front->points.count("cfNeck"));
    const nlohmann::json doc = nlohmann::json::parse(tapeline_test::slurp(path));
    const auto cf = doc["pieces"][0]["points"]["cfNeck"];
    EXPECT_EQ(front->points.at("cfNeck").y, -cf[1].get<double>());
    const Piece* sleeve = find_piece(p, "teagan.sleeve");
    ASSERT_TRUE(sleeve);
    ASSERT_TRUE(sleeve->grain);
    ASSERT_EQ(sleeve->notches.size(), 2u);
    for (const Notch& n : sleeve->notches) {
        const Point2 at = notch_position(*sleeve, n);
        EXPECT_LE(distance(at, sleeve->points.at(n.name)), 0.5) << n.name;
    }
    // The chest help lines bind the chest measurement; half pieces on the fold count twice.
    const auto it =
        std::find_if(p.bindings.begin(), p.bindings.end(),
                     [](const MeasurementBinding& b) { return b.measurement == "chest"; });
    ASSERT_NE(it, p.bindings.end());
    double total = 0;
    for (const BoundFeature& f : it->features) {
        EXPECT_EQ(f.count, 2);
        total += f.count * feature_length(p, f);
    }
    EXPECT_NEAR(total, 979 + it->ease_mm, 1e-9);
    EXPECT_GT(it->ease_mm, 0);
}

TEST(PatternFreeSewing, PiecesWithoutSeamPathAreSkippedAndNoted) {
    const std::string path = shared_patterns_dir() + "/freesewing/simon_cisFemaleAdult36.json";
    if (!tapeline_test::exists(path)) {
        GTEST_SKIP() << path << " absent";
    }
    ImportReport rep;
    const Pattern p = read_freesewing(path, &rep);
    EXPECT_EQ(rep.skipped_pieces, 2u);
    EXPECT_EQ(p.pieces.size(), 10u);
    ASSERT_EQ(rep.notes.size(), 2u);
    EXPECT_NE(rep.notes[0].find("simon.buttonholePlacket"), std::string::npos);
    const Piece* back = find_piece(p, "simon.back");
    ASSERT_TRUE(back);
    EXPECT_EQ(back->darts.size(), 1u);
}

// The bundled copy (always present): every piece's outline is as long as the seam path
// FreeSewing measured (length_mm, rounded to 0.001 mm; 0.01 mm as for the shared drafts).
TEST(PatternFreeSewing, BundledCopyImports) {
    const Pattern p = read_freesewing(bundled_freesewing());
    EXPECT_EQ(p.pieces.size(), 4u);
    EXPECT_TRUE(validate(p).ok());
    const nlohmann::json doc = nlohmann::json::parse(tapeline_test::slurp(bundled_freesewing()));
    std::size_t checked = 0;
    for (const auto& jp : doc["pieces"]) {
        const std::string name = jp["name"];
        const Piece* piece = find_piece(p, name);
        ASSERT_TRUE(piece) << name;
        const double ref = jp["paths"]["seam"]["length_mm"];
        EXPECT_NEAR(length(piece->outline), ref, 0.01) << name;
        ++checked;
    }
    EXPECT_EQ(checked, p.pieces.size());
}

TEST(PatternFreeSewing, MalformedInputIsRejectedWithItsLocation) {
    // Truncated file.
    tapeline_test::TempDir dir;
    const std::string text = tapeline_test::slurp(bundled_freesewing());
    const std::string cut = dir.file("truncated.json");
    tapeline_test::write_text(cut, text.substr(0, text.size() / 2));
    try {
        read_freesewing(cut);
        FAIL() << "expected InvalidInput";
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find(cut + ": malformed JSON at byte"), std::string::npos)
            << e.what();
    }
    EXPECT_THROW(read_freesewing(dir.file("missing.json")), tapeline::InvalidInput);

    EXPECT_NO_THROW(freesewing_from_json(nlohmann::json::parse(minimal_piece), "fs.json"));
    expect_invalid(R"({"units": "mm"})", {"missing field 'pieces'"});
    expect_invalid(R"({"units": "inch; y down", "pieces": []})", {"units", "unknown unit 'inch"});
    std::string nan_piece = minimal_piece;
    nan_piece.replace(nan_piece.find("[100, 50]"), 9, "[100, null]");
    expect_invalid(nan_piece, {"piece 'p'", "paths.seam.ops[2].to[1]", "null (NaN?)"});
    std::string bad_op = minimal_piece;
    bad_op.replace(bad_op.find("\"close\""), 7, "\"arc\"");
    expect_invalid(bad_op, {"piece 'p'", "ops[3]", "unknown path operation 'arc'"});
    std::string no_ops = minimal_piece;
    no_ops.replace(no_ops.find("\"ops\""), 5, "\"opz\"");
    expect_invalid(no_ops, {"piece 'p'", "paths.seam", "missing field 'ops'"});
}

TEST(PatternFreeSewing, OpenSeamPathIsClosedAndNoted) {
    std::string open = minimal_piece;
    open.replace(open.find(", {\"type\": \"close\"}"), 19, "");
    ImportReport rep;
    const Pattern p = freesewing_from_json(nlohmann::json::parse(open), "fs.json", &rep);
    ASSERT_EQ(p.pieces.size(), 1u);
    EXPECT_EQ(p.pieces[0].outline.edges.size(), 3u);
    ASSERT_EQ(rep.notes.size(), 1u);
    EXPECT_NE(rep.notes[0].find("piece 'p'"), std::string::npos);
    EXPECT_TRUE(validate(p).ok());
}

// Titan's waist (the design table's rule, styleWaistIn to styleWaistOut on the front and the
// back) is labelled for the waistband on import, and nothing else is, on any shared draft; a
// draft without one of the rule's points gets no label there and a note naming the rule.
TEST(PatternFreeSewing, TitanWaistEdgesAreLabelledForTheWaistband) {
    const std::string path = shared_patterns_dir() + "/freesewing/titan_cisFemaleAdult36.json";
    if (!tapeline_test::exists(path)) {
        GTEST_SKIP() << path << " absent";
    }
    for (const std::string& file : pattern_files()) {
        const Pattern p = read_freesewing(file);
        const bool titan = p.name.rfind("titan", 0) == 0;
        std::size_t labelled = 0;
        for (const Piece& piece : p.pieces) {
            std::vector<std::size_t> waist;
            for (std::size_t e = 0; e < piece.outline.edges.size(); ++e) {
                if (piece.outline.edges[e].label == waist_label()) {
                    waist.push_back(e);
                }
            }
            labelled += waist.size();
            if (!titan) {
                continue;
            }
            ASSERT_EQ(waist.size(), 1u) << file << " " << piece.name;
            const Edge& e = piece.outline.edges[waist[0]];
            const Point2 in = piece.points.at("styleWaistIn"),
                         out = piece.points.at("styleWaistOut");
            const Point2 a = start_point(e), b = end_point(e);
            EXPECT_LT(
                std::min(distance(a, in) + distance(b, out), distance(a, out) + distance(b, in)),
                0.02)
                << file << " " << piece.name;
        }
        EXPECT_EQ(labelled, titan ? 2u : 0u) << file;
    }
    nlohmann::json doc = nlohmann::json::parse(tapeline_test::slurp(path));
    for (auto& jp : doc["pieces"]) {
        if (jp["name"] == "titan.front") {
            jp["points"].erase("styleWaistOut");
        }
    }
    ImportReport rep;
    const Pattern p = freesewing_from_json(doc, "titan.json", &rep);
    const auto note = std::find_if(rep.notes.begin(), rep.notes.end(), [](const std::string& n) {
        return n.find("edge label 'titan front waist' not given") != std::string::npos;
    });
    EXPECT_NE(note, rep.notes.end());
    for (const Edge& e : find_piece(p, "titan.front")->outline.edges) {
        EXPECT_TRUE(e.label.empty());
    }
    std::size_t back = 0;
    for (const Edge& e : find_piece(p, "titan.back")->outline.edges) {
        back += e.label == waist_label() ? 1 : 0;
    }
    EXPECT_EQ(back, 1u);
}
