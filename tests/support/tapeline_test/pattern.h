// Small fixtures for the pattern tests: hand-built pieces and patterns, temporary directories.
// Header-only: the pattern module has no CGAL, so nothing needs compiling once.
#pragma once

#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/pattern/io_garmentcode.h>
#include <tapeline/pattern/pattern.h>
#include <tapeline_test/temp_dir.h>

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace tapeline_test {

inline std::string shared_patterns_dir() {
    return std::string(TAPELINE_SHARED_DATA_DIR) + "/patterns";
}

inline bool exists(const std::string& path) {
    return std::filesystem::exists(path);
}

/// Files in `dir` whose names end with `suffix`, sorted.
inline std::vector<std::string> files_ending(const std::string& dir, const std::string& suffix) {
    std::vector<std::string> out;
    if (!std::filesystem::is_directory(dir)) {
        return out;
    }
    for (const auto& e : std::filesystem::directory_iterator(dir)) {
        const std::string p = e.path().string();
        if (p.size() >= suffix.size() &&
            p.compare(p.size() - suffix.size(), suffix.size(), suffix) == 0) {
            out.push_back(p);
        }
    }
    std::sort(out.begin(), out.end());
    return out;
}

/// Every shared FreeSewing draft and GarmentCode specification (empty when ../shared is absent).
inline std::vector<std::string> shared_pattern_files() {
    std::vector<std::string> out;
    for (const auto& f : files_ending(shared_patterns_dir() + "/freesewing", ".json")) {
        if (f.find("measurement_sets") == std::string::npos) {
            out.push_back(f);
        }
    }
    for (const auto& f : files_ending(shared_patterns_dir() + "/garmentcode", ".json")) {
        out.push_back(f);
    }
    return out;
}

/// Imports a file of shared_pattern_files() with the importer its folder calls for.
inline tapeline::pattern::Pattern load_shared_pattern(const std::string& path) {
    return path.find("/garmentcode/") != std::string::npos
               ? tapeline::pattern::read_garmentcode(path)
               : tapeline::pattern::read_freesewing(path);
}

inline std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

inline void write_text(const std::string& path, const std::string& text) {
    std::ofstream out(path, std::ios::binary);
    out << text;
}

/// A closed polygon of line edges through `pts`.
inline tapeline::pattern::Outline polygon(const std::vector<tapeline::pattern::Point2>& pts) {
    tapeline::pattern::Outline o;
    for (std::size_t i = 0; i < pts.size(); ++i) {
        o.edges.push_back({tapeline::pattern::Line{pts[i], pts[(i + 1) % pts.size()]}, ""});
    }
    return o;
}

inline tapeline::pattern::Piece rectangle_piece(const std::string& name, double w, double h) {
    tapeline::pattern::Piece p;
    p.name = name;
    p.outline = polygon({{0, 0}, {w, 0}, {w, h}, {0, h}});
    return p;
}

/// Two 200 × 300 mm rectangles sewn along their right/left sides, with every model feature set
/// (arc and cubic edges, notch, dart, fold, grain, internal line, placement, binding).
inline tapeline::pattern::Pattern two_piece_pattern() {
    using namespace tapeline::pattern;
    Pattern pat;
    pat.name = "test pattern";
    pat.designer = "Tapeline tests";
    pat.garment_type = "skirt";
    pat.size = "M";
    pat.tags = {"test", "two pieces"};
    pat.source = "tapeline_test::two_piece_pattern";
    Piece front = rectangle_piece("front", 200, 300);
    // Replace the top edge by an arc bulging up (radius 150 mm, clockwise seen from (200,300)).
    front.outline.edges[2] = {Arc{{200, 300}, {0, 300}, 150, false, true}, "waist"};
    front.points = {{"hip", {200, 150}}, {"cf", {0, 150}}};
    front.grain = GrainLine{{100, 50}, {100, 250}};
    front.notches.push_back({1, 150, "hip notch", "v"});
    front.internal_lines.push_back({"hem fold", "fold", {{Line{{0, 30}, {200, 30}}, ""}}});
    front.darts.push_back(
        {"waist dart", {{Line{{90, 300}, {100, 200}}, ""}, {Line{{100, 200}, {110, 300}}, ""}}});
    front.fold = Fold{Line{{0, 0}, {0, 300}}, std::size_t{3}};
    front.placement = Placement3D{{0, 950, 120}, {0, 0, 0}, "XYZ"};
    Piece back = rectangle_piece("back", 200, 300);
    back.outline.edges[0] = {CubicBezier{{0, 0}, {60, -20}, {140, -20}, {200, 0}}, "hem"};
    back.cut_count = 2;
    back.mirrored = true;
    back.placement = Placement3D{{0, 950, -120}, {0, 180, 0}, "XYZ"};
    pat.pieces = {front, back};
    pat.seams.push_back({"side", {"front", 1, 1}, {"back", 3, 1}, SeamDirection::opposite});
    pat.measurements_used = {{"hips", 960.5}, {"waist", 720}};
    pat.bindings.push_back({"hips", {{"front", {}, "cf", "hip", 2}, {"back", {0}, "", "", 2}}, 40});
    return pat;
}

}  // namespace tapeline_test
