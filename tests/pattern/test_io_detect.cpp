// Reading a pattern file of any format (io_detect.h), and the seams a FreeSewing file gets from
// its design (freesewing_designs.h): FreeSewing states no seam lengths, so the two sides of each
// stored seam are measured on the outline and must agree.
#include <tapeline/core/errors.h>
#include <tapeline/pattern/database.h>
#include <tapeline/pattern/freesewing_designs.h>
#include <tapeline/pattern/io_detect.h>
#include <tapeline/pattern/validate.h>
#include <tapeline_test/expect.h>
#include <tapeline_test/pattern.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <map>
#include <string>

using namespace tapeline::pattern;

namespace {

std::string data(const std::string& name) {
    return std::string(TAPELINE_DATA_DIR) + "/patterns/" + name;
}
const std::string aaron = data("aaron_cisFemaleAdult36.json");
const std::string shirt = data("shirt_mean_specification.json");

/// The start of the first edge and the end of the last edge of `r`.
std::pair<Point2, Point2> ends(const Piece& piece, const EdgeRange& r) {
    const std::size_t n = piece.outline.edges.size();
    return {start_point(piece.outline.edges[r.first_edge % n]),
            end_point(piece.outline.edges[(r.first_edge + r.count - 1) % n])};
}

}  // namespace

TEST(PatternDetect, RecognisesEveryFormatFromItsKeys) {
    EXPECT_EQ(detect_pattern_format(aaron), "freesewing");
    EXPECT_EQ(detect_pattern_format(shirt), "garmentcode");
    tapeline_test::TempDir dir;
    const std::string json = dir.file("aaron.json");
    write_pattern_json(read_pattern_file(aaron), json);
    EXPECT_EQ(detect_pattern_format(json), "json");
    // Each format reads back the same pattern as its own importer.
    EXPECT_EQ(read_pattern_file(json).pieces.size(), read_freesewing(aaron).pieces.size());
    EXPECT_EQ(read_pattern_file(shirt).seams.size(), read_garmentcode(shirt).seams.size());
    EXPECT_EQ(read_pattern_file(aaron, "freesewing").name, "aaron_cisFemaleAdult36");
}

TEST(PatternDetect, RejectsWhatItCannotReadWithMessage) {
    using tapeline::InvalidInput;
    using tapeline_test::expect_error;
    tapeline_test::TempDir dir;
    const std::string missing = dir.file("missing.json");
    expect_error<InvalidInput>([&] { read_pattern_file(missing); }, {missing, "cannot open"},
                               "missing file");
    const std::string text = dir.file("pattern.txt");
    tapeline_test::write_text(text, "not json at all");
    expect_error<InvalidInput>([&] { detect_pattern_format(text); }, {text, "not valid JSON"},
                               "not JSON");
    const std::string other = dir.file("other.json");
    tapeline_test::write_text(other, R"({"pieces": [], "author": "someone"})");
    expect_error<InvalidInput>([&] { read_pattern_file(other, "auto"); },
                               {other, "cannot tell the pattern format"}, "unknown keys");
    expect_error<InvalidInput>([&] { read_pattern_file(aaron, "dxf"); },
                               {"unknown pattern format 'dxf'", "freesewing, garmentcode, json"},
                               "unknown format name");
}

// Aaron's seams of one range per side (side, shoulder) come with the import; the binding strips
// sewn to two pieces stay with freesewing_seams. Sewn sides must be equally long on the outline
// and run between the named points of the design's rule.
TEST(PatternFreeSewingSeams, ImportedAaronHasItsSeamsWithEqualSides) {
    ImportReport rep;
    const Pattern p = read_pattern_file(aaron, "auto", &rep);
    ASSERT_EQ(p.seams.size(), 2u);
    EXPECT_EQ(rep.seams, 2u);
    const std::map<std::string, std::pair<std::string, std::string>> points = {
        {"side", {"hem", "armhole"}}, {"shoulder", {"strapRight", "strapLeft"}}};
    for (const Seam& s : p.seams) {
        ASSERT_TRUE(points.count(s.name)) << s.name;
        const Piece* a = find_piece(p, s.a.piece);
        const Piece* b = find_piece(p, s.b.piece);
        ASSERT_TRUE(a && b) << s.name;
        EXPECT_EQ(a->name, "aaron.front");
        EXPECT_EQ(b->name, "aaron.back");
        const double la = length(*a, s.a), lb = length(*b, s.b);
        std::printf("%-9s front %.3f mm, back %.3f mm\n", s.name.c_str(), la, lb);
        EXPECT_NEAR(la, lb, 0.5) << s.name;
        EXPECT_GT(la, 10.0) << s.name;
        // The chain runs between the rule's points, not the long way round the piece.
        for (const auto* side : {&s.a, &s.b}) {
            const Piece& piece = *find_piece(p, side->piece);
            const auto [from, to] = ends(piece, *side);
            const Point2 p0 = piece.points.at(points.at(s.name).first);
            const Point2 p1 = piece.points.at(points.at(s.name).second);
            EXPECT_LT(std::min(distance(from, p0) + distance(to, p1),
                               distance(from, p1) + distance(to, p0)),
                      0.02)
                << s.name << " on " << piece.name;
            EXPECT_LT(length(piece, *side), 0.5 * length(piece.outline)) << s.name;
        }
    }
    // Validation measures the same: no seam mismatch.
    const ValidationReport v = validate(p);
    EXPECT_EQ(v.seams_checked, 2u);
    EXPECT_LT(v.largest_seam_mismatch_mm, 0.5);

    // Every seam of the design, multi-piece sides included, for modules that handle chains.
    const std::vector<SeamSpec> all = freesewing_seams(p);
    ASSERT_EQ(all.size(), 4u);
    EXPECT_EQ(all[2].name, "armhole binding");
    EXPECT_EQ(all[2].b.size(), 2u);
    // Adding them again changes nothing: the pattern holds them by name.
    Pattern q = p;
    EXPECT_EQ(add_freesewing_seams(q), 0u);
    EXPECT_EQ(q.seams.size(), 2u);
}

TEST(PatternFreeSewingSeams, DatabaseKeepsTheImportedSeams) {
    tapeline_test::TempDir dir;
    const Pattern p = read_pattern_file(aaron);
    PatternDatabase db(dir.file("p.sqlite"));
    db.store(p);
    const Pattern q = db.load(p.name);
    ASSERT_EQ(q.seams.size(), p.seams.size());
    for (std::size_t i = 0; i < p.seams.size(); ++i) {
        EXPECT_EQ(q.seams[i].name, p.seams[i].name);
        EXPECT_EQ(q.seams[i].a.first_edge, p.seams[i].a.first_edge);
        EXPECT_EQ(q.seams[i].b.count, p.seams[i].b.count);
        EXPECT_EQ(q.seams[i].direction, p.seams[i].direction);
    }
}

// A draft whose points the rule needs are missing gets no seam, and the import says why.
TEST(PatternFreeSewingSeams, MissingRulePointIsNoted) {
    nlohmann::json doc = nlohmann::json::parse(tapeline_test::slurp(aaron));
    for (auto& piece : doc["pieces"]) {
        if (piece["name"] == "aaron.back") {
            piece["points"].erase("hem");
        }
    }
    ImportReport rep;
    const Pattern p = freesewing_from_json(doc, "aaron.json", &rep);
    ASSERT_EQ(p.seams.size(), 1u);
    EXPECT_EQ(p.seams[0].name, "shoulder");
    const bool noted = std::any_of(rep.notes.begin(), rep.notes.end(), [](const std::string& n) {
        return tapeline_test::contains(n, "seam 'aaron side' not derived");
    });
    EXPECT_TRUE(noted);
}
