// Every validation error and warning, fed on purpose; messages must name the piece and edge.
#include <tapeline/pattern/validate.h>

#include <tapeline_test/pattern.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

using namespace tapeline::pattern;
using tapeline_test::polygon;
using tapeline_test::rectangle_piece;
using tapeline_test::two_piece_pattern;

namespace {

const ValidationIssue* find_issue(const std::vector<ValidationIssue>& issues,
                                  const std::string& code) {
    for (const ValidationIssue& i : issues) {
        if (i.code == code) {
            return &i;
        }
    }
    return nullptr;
}

bool contains(const std::string& s, const std::string& part) {
    return s.find(part) != std::string::npos;
}

/// require_valid throws InvalidInput whose message contains every one of `parts`.
void expect_rejected(const Pattern& p, std::initializer_list<std::string> parts) {
    try {
        require_valid(p, {}, "pattern.json");
        FAIL() << "expected InvalidInput";
    } catch (const tapeline::InvalidInput& e) {
        const std::string msg = e.what();
        EXPECT_TRUE(contains(msg, "pattern.json: ")) << msg;
        for (const std::string& part : parts) {
            EXPECT_TRUE(contains(msg, part)) << "'" << part << "' missing from: " << msg;
        }
    }
}

}  // namespace

TEST(PatternValidate, WellFormedPatternPasses) {
    const Pattern p = two_piece_pattern();
    const ValidationReport rep = validate(p);
    EXPECT_TRUE(rep.ok()) << rep.errors.front().message;
    EXPECT_TRUE(rep.warnings.empty());
    EXPECT_EQ(rep.pieces_checked, 2u);
    EXPECT_EQ(rep.seams_checked, 1u);
    EXPECT_NEAR(rep.largest_seam_mismatch_mm, 0, 1e-12);
    EXPECT_NO_THROW(require_valid(p));
}

TEST(PatternValidate, OpenOutline) {
    Pattern p = two_piece_pattern();
    p.pieces[1].outline.edges.pop_back();  // the back loses its left side
    const ValidationReport rep = validate(p);
    const ValidationIssue* e = find_issue(rep.errors, "open_outline");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->piece, "back");
    EXPECT_EQ(e->edge, std::optional<std::size_t>(2));
    expect_rejected(p, {"piece 'back'", "open between edge 2", "edge 0", "gap 300.000 mm"});
}

TEST(PatternValidate, SelfIntersectingOutline) {
    Pattern p;
    p.name = "bow tie";
    Piece piece;
    piece.name = "bow";
    piece.outline = polygon({{0, 0}, {100, 100}, {100, 0}, {0, 100}});  // a figure eight
    p.pieces.push_back(piece);
    const ValidationReport rep = validate(p);
    const ValidationIssue* e = find_issue(rep.errors, "self_intersection");
    ASSERT_TRUE(e);
    expect_rejected(p,
                    {"piece 'bow'", "crosses itself", "edge 0 meets edge 2", "(50.000, 50.000)"});
}

TEST(PatternValidate, CurveFoldingBackOnItselfIntersects) {
    Pattern p;
    Piece piece = rectangle_piece("loop", 100, 100);
    // The bottom edge makes a loop: control points pull it past its own end and back.
    piece.outline.edges[0] = {CubicBezier{{0, 0}, {200, 60}, {-100, 60}, {100, 0}}, ""};
    p.pieces.push_back(piece);
    expect_rejected(p, {"piece 'loop'", "crosses itself", "edge 0 meets edge 0"});
}

TEST(PatternValidate, NanCoordinate) {
    Pattern p = two_piece_pattern();
    std::get<Line>(p.pieces[0].outline.edges[1].curve).b.y =
        std::numeric_limits<double>::quiet_NaN();
    expect_rejected(p, {"piece 'front'", "edge 1", "NaN"});
    Pattern q = two_piece_pattern();
    q.pieces[1].points["bad"] = {std::numeric_limits<double>::infinity(), 0};
    expect_rejected(q, {"piece 'back'", "point 'bad'", "not finite"});
    Pattern r = two_piece_pattern();
    r.measurements_used["waist"] = std::nan("");
    expect_rejected(r, {"measurement 'waist'", "not finite"});
}

TEST(PatternValidate, UnknownUnits) {
    Pattern p = two_piece_pattern();
    p.units = "furlong";
    expect_rejected(p, {"units 'furlong'", "millimetres"});
}

TEST(PatternValidate, SeamNamingMissingEdgeOrPiece) {
    Pattern p = two_piece_pattern();
    p.seams[0].b.first_edge = 7;
    const ValidationReport rep = validate(p);
    const ValidationIssue* e = find_issue(rep.errors, "missing_edge");
    ASSERT_TRUE(e);
    EXPECT_EQ(e->piece, "back");
    expect_rejected(p, {"seam 0 'side' side B", "edges 7..8", "piece 'back'", "has 4 edges"});

    Pattern q = two_piece_pattern();
    q.seams[0].a.piece = "sleeve";
    expect_rejected(q, {"seam 0 'side' side A", "piece 'sleeve'", "does not have"});

    Pattern r = two_piece_pattern();
    r.seams[0].a.count = 0;
    expect_rejected(r, {"seam 0 'side' side A", "piece 'front'"});
}

TEST(PatternValidate, SeamLengthMismatchIsAWarningWithBothLengths) {
    Pattern p = two_piece_pattern();
    // Lengthen the back's left side: move the top-left corner up by 12 mm.
    std::get<Line>(p.pieces[1].outline.edges[2].curve).b = {0, 312};
    std::get<Line>(p.pieces[1].outline.edges[3].curve).a = {0, 312};
    const ValidationReport rep = validate(p);
    EXPECT_TRUE(rep.ok());
    const ValidationIssue* w = find_issue(rep.warnings, "seam_length_mismatch");
    ASSERT_TRUE(w);
    EXPECT_TRUE(contains(w->message, "300.000 mm")) << w->message;
    EXPECT_TRUE(contains(w->message, "312.000 mm")) << w->message;
    EXPECT_TRUE(contains(w->message, "differ by 12.000 mm")) << w->message;
    EXPECT_NEAR(rep.largest_seam_mismatch_mm, 12, 1e-9);
    // A tolerance above the difference silences it.
    ValidationOptions o;
    o.seam_length_tolerance_mm = 12.5;
    EXPECT_TRUE(validate(p, o).warnings.empty());
    o.seam_length_tolerance_mm = 0;
    o.seam_length_relative_tolerance = 0.05;  // 5 % of 312 mm = 15.6 mm
    EXPECT_TRUE(validate(p, o).warnings.empty());
}

TEST(PatternValidate, ArcRadiusBelowHalfChord) {
    Pattern p = two_piece_pattern();
    std::get<Arc>(p.pieces[0].outline.edges[2].curve).radius = 50;  // chord 200 mm
    expect_rejected(p, {"piece 'front'", "edge 2", "radius 50.000 mm", "half its chord 100.000"});
}

TEST(PatternValidate, EmptyDuplicateAndBadCounts) {
    Pattern p = two_piece_pattern();
    p.pieces[1].name = "front";
    expect_rejected(p, {"piece 'front'", "two pieces have this name"});
    Pattern q = two_piece_pattern();
    q.pieces[0].outline.edges.clear();
    expect_rejected(q, {"piece 'front'", "no edges"});
    Pattern r = two_piece_pattern();
    r.pieces[1].cut_count = 0;
    expect_rejected(r, {"piece 'back'", "cut count 0"});
}

TEST(PatternValidate, NotchFoldAndBindingReferences) {
    Pattern p = two_piece_pattern();
    p.pieces[0].notches[0].edge = 9;
    expect_rejected(p, {"piece 'front'", "notch 'hip notch'", "edge 9"});
    Pattern q = two_piece_pattern();
    q.pieces[0].fold->edge = 4;
    expect_rejected(q, {"piece 'front'", "fold is on edge 4"});
    Pattern r = two_piece_pattern();
    r.bindings[0].features[0].to_point = "knee";
    expect_rejected(r, {"measurement 'hips'", "point 'knee'", "piece 'front'"});
    Pattern s = two_piece_pattern();
    s.bindings[0].features[1].edges = {12};
    expect_rejected(s, {"measurement 'hips'", "edge 12", "piece 'back'"});
}

TEST(PatternValidate, DegenerateEdgeIsAWarning) {
    Pattern p = two_piece_pattern();
    auto& edges = p.pieces[1].outline.edges;
    edges.insert(edges.begin() + 1, Edge{Line{{200, 0}, {200, 0}}, ""});
    const ValidationReport rep = validate(p);
    const ValidationIssue* w = find_issue(rep.warnings, "degenerate_edge");
    ASSERT_TRUE(w);
    EXPECT_EQ(w->edge, std::optional<std::size_t>(1));
    EXPECT_TRUE(contains(w->message, "piece 'back'"));
}

TEST(PatternValidate, FeatureLengthUsesEdgesOrPoints) {
    const Pattern p = two_piece_pattern();
    EXPECT_DOUBLE_EQ(feature_length(p, p.bindings[0].features[0]), 200);
    EXPECT_NEAR(feature_length(p, p.bindings[0].features[1]), length(p.pieces[1].outline.edges[0]),
                1e-12);
}

TEST(PatternValidate, NoPiecesZeroAreaAndFarCoordinatesAreRefused) {
    Pattern empty;
    empty.name = "nothing";
    expect_rejected(empty, {"pattern 'nothing' has no pieces"});

    Pattern flat;
    flat.name = "flat";
    Piece line;
    line.name = "line";
    line.outline = polygon({{0, 0}, {100, 0}, {100, 0.001}});  // a sliver of 0.05 mm2
    flat.pieces.push_back(line);
    ASSERT_TRUE(find_issue(validate(flat).errors, "zero_area"));
    expect_rejected(flat, {"piece 'line'", "encloses 0.050 mm2, less than 1.000 mm2"});

    Pattern point;
    point.name = "point";
    Piece dot;
    dot.name = "dot";
    dot.outline = polygon({{5, 5}});  // a single point: one edge of length 0
    point.pieces.push_back(dot);
    expect_rejected(point, {"piece 'dot'", "encloses 0.000 mm2"});

    Pattern far;
    far.name = "far";
    Piece huge;
    huge.name = "huge";
    huge.outline = polygon({{0, 0}, {1e308, 0}, {0, 1e308}});
    far.pieces.push_back(huge);
    expect_rejected(far, {"piece 'huge'", "edge 0 reaches 1e+308 mm from the origin",
                          "beyond the 10000000.000 mm a pattern may span"});
}
