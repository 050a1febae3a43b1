// Preparing a pattern for dressing: curves and outline edges split without moving the outline,
// mirrored copies of pieces sewn to folded ones (lengths, orientation and mirror images checked
// against the originals), and FreeSewing's sleeve cap split between two armholes in the ratio of
// their lengths.
#include <tapeline/garment/unfold.h>
#include <tapeline/pattern/io_detect.h>
#include <tapeline/pattern/validate.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <map>
#include <string>

namespace tg = tapeline::garment;
namespace tp = tapeline::pattern;

namespace {

tp::Edge line(tp::Point2 a, tp::Point2 b) {
    return {tp::Line{a, b}, ""};
}

// A front and a back cut on the fold (x = 0, half width 200, height 300) and a sleeve sewn to
// both, with its underarm seam: the smallest pattern with a left/right pair.
tp::Pattern folded_pattern() {
    tp::Pattern p;
    p.name = "synthetic";
    for (const char* name : {"front", "back"}) {
        tp::Piece piece;
        piece.name = name;
        // 0: fold (top to bottom at x = 0), 1: hem, 2: side, 3: armhole (a curve), 4: shoulder.
        piece.outline.edges = {
            line({0, 300}, {0, 0}),
            line({0, 0}, {200, 0}),
            line({200, 0}, {200, 150}),
            {tp::CubicBezier{{200, 150}, {160, 170}, {150, 220}, {150, 260}}, ""},
            line({150, 260}, {0, 300})};
        piece.fold = tp::Fold{tp::Line{{0, 300}, {0, 0}}, 0};
        piece.grain = tp::GrainLine{{100, 50}, {100, 250}};
        p.pieces.push_back(piece);
    }
    tp::Piece sleeve;
    sleeve.name = "sleeve";
    // 0: hem, 1: right underarm, 2: cap (an arc, the front), 3: cap (a Bézier, the back),
    // 4: left underarm.
    tp::Arc cap;
    cap.a = {150, 0};
    cap.b = {10, 120};
    cap.radius = 160;
    cap.ccw = true;
    sleeve.outline.edges = {line({-110, -400}, {110, -400}),
                            line({110, -400}, {150, 0}),
                            {cap, ""},
                            {tp::CubicBezier{{10, 120}, {-60, 110}, {-120, 60}, {-150, 0}}, ""},
                            line({-150, 0}, {-110, -400})};
    sleeve.grain = tp::GrainLine{{0, -300}, {0, 0}};
    sleeve.notches = {{2, 30, "front", "slit"}, {3, 40, "back", "slit"}};
    p.pieces.push_back(sleeve);
    p.seams = {{"side", {"front", 2, 1}, {"back", 2, 1}, tp::SeamDirection::same},
               {"armhole front", {"sleeve", 2, 1}, {"front", 3, 1}, tp::SeamDirection::opposite},
               {"armhole back", {"sleeve", 3, 1}, {"back", 3, 1}, tp::SeamDirection::same},
               {"underarm", {"sleeve", 1, 1}, {"sleeve", 4, 1}, tp::SeamDirection::opposite}};
    return p;
}

const tp::Piece& piece(const tp::Pattern& p, const std::string& name) {
    const tp::Piece* found = tp::find_piece(p, name);
    if (!found) {
        throw std::runtime_error("no piece " + name);
    }
    return *found;
}

// Start and end point of an edge range (in outline order).
std::pair<tp::Point2, tp::Point2> ends(const tp::Pattern& p, const tp::EdgeRange& r) {
    const auto& e = piece(p, r.piece).outline.edges;
    return {tp::start_point(e[r.first_edge]),
            tp::end_point(e[(r.first_edge + r.count - 1) % e.size()])};
}

const tp::Seam& seam(const tp::Pattern& p, const std::string& name) {
    for (const tp::Seam& s : p.seams) {
        if (s.name == name) {
            return s;
        }
    }
    throw std::runtime_error("no seam " + name);
}

tp::Point2 notch_point(const tp::Piece& piece, const tp::Notch& n) {
    const tp::Curve& c = piece.outline.edges[n.edge].curve;
    return tp::point_at(c, tp::parameter_at_length(c, n.offset));
}

}  // namespace

// Both parts of a split curve have the lengths of the parts of the whole, meet at the curve's
// point there, and follow the curve (points of the parts are points of the whole).
TEST(GarmentUnfold, SplitCurveKeepsTheCurve) {
    tp::Arc arc;
    arc.a = {100, 0};
    arc.b = {-100, 0};
    arc.radius = 100;
    arc.ccw = true;  // a half circle through (0, 100)
    tp::Arc big = arc;
    big.b = {0, -100};
    big.large_arc = true;  // three quarters
    const std::vector<tp::Curve> curves = {
        tp::Line{{0, 0}, {30, 40}}, tp::CubicBezier{{0, 0}, {10, 50}, {60, 50}, {80, 0}}, arc, big};
    for (const tp::Curve& c : curves) {
        for (double t : {0.2, 0.5, 0.8}) {
            const auto [first, second] = tg::internal::split_curve(c, t);
            EXPECT_NEAR(tapeline::distance(tp::end_point(first), tp::point_at(c, t)), 0, 1e-9);
            EXPECT_NEAR(tapeline::distance(tp::start_point(second), tp::point_at(c, t)), 0, 1e-9);
            EXPECT_NEAR(tapeline::distance(tp::start_point(first), tp::start_point(c)), 0, 1e-9);
            EXPECT_NEAR(tapeline::distance(tp::end_point(second), tp::end_point(c)), 0, 1e-9);
            EXPECT_NEAR(tp::length(first) + tp::length(second), tp::length(c),
                        1e-7 * tp::length(c));
            // Béziers: de Casteljau's parts are the same curve re-parametrised linearly.
            if (std::get_if<tp::CubicBezier>(&c)) {
                for (double u : {0.25, 0.5, 0.75}) {
                    EXPECT_NEAR(tapeline::distance(tp::point_at(first, u), tp::point_at(c, t * u)),
                                0, 1e-9);
                    EXPECT_NEAR(tapeline::distance(tp::point_at(second, u),
                                                   tp::point_at(c, t + (1 - t) * u)),
                                0, 1e-9);
                }
            }
        }
    }
    // The half circle's first part at t = 0.5 is a quarter circle.
    const auto halves = tg::internal::split_curve(arc, 0.5);
    EXPECT_NEAR(tp::length(halves.first), M_PI * 100 / 2, 1e-6);
    EXPECT_NEAR(tapeline::distance(tp::end_point(halves.first), {0, 100}), 0, 1e-9);
}

// Splitting an outline edge adds one edge and moves nothing: the outline stays closed, the seams
// on the piece keep their ends and lengths, notches stay where they were.
TEST(GarmentUnfold, SplitEdgeKeepsSeamsAndNotches) {
    tp::Pattern p = folded_pattern();
    const tp::Pattern before = p;
    tg::internal::split_outline_edge(p, 2, 2, 0.1);  // the front cap, before its notch
    const auto& e = p.pieces[2].outline.edges;
    ASSERT_EQ(e.size(), 6u);
    for (std::size_t k = 0; k < e.size(); ++k) {
        EXPECT_NEAR(tapeline::distance(tp::end_point(e[k]), tp::start_point(e[(k + 1) % e.size()])),
                    0, 1e-9);
    }
    for (std::size_t s = 0; s < p.seams.size(); ++s) {
        for (int side = 0; side < 2; ++side) {
            const tp::EdgeRange& r0 = side == 0 ? before.seams[s].a : before.seams[s].b;
            const tp::EdgeRange& r1 = side == 0 ? p.seams[s].a : p.seams[s].b;
            EXPECT_NEAR(tp::length(piece(p, r1.piece), r1), tp::length(piece(before, r0.piece), r0),
                        1e-6)
                << p.seams[s].name;
            EXPECT_NEAR(tapeline::distance(ends(p, r1).first, ends(before, r0).first), 0, 1e-9);
            EXPECT_NEAR(tapeline::distance(ends(p, r1).second, ends(before, r0).second), 0, 1e-9);
        }
    }
    EXPECT_EQ(seam(p, "armhole front").a.count, 2u);
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_NEAR(tapeline::distance(notch_point(p.pieces[2], p.pieces[2].notches[k]),
                                       notch_point(before.pieces[2], before.pieces[2].notches[k])),
                    0, 1e-6);
    }
    EXPECT_NE(p.pieces[2].notches[0].edge, 2u) << "the notch lies past the split";
    // A fold edge is not split.
    tp::Pattern q = folded_pattern();
    EXPECT_THROW(tg::internal::split_outline_edge(q, 0, 0, 0.5), tapeline::InvalidInput);
}

// A piece sewn to folded pieces gets a mirrored copy; each seam it takes part in exists twice,
// the copy's seam sides are the mirror images (x → −x) of the original's, with equal lengths,
// and the copy keeps the outline's orientation.
TEST(GarmentUnfold, PieceSewnToFoldedOnesGetsAMirroredCopy) {
    const tp::Pattern p = folded_pattern();
    const tp::Pattern u = tg::unfold_pieces(p);
    ASSERT_EQ(u.pieces.size(), 4u);
    const tp::Piece& copy = piece(u, "sleeve (mirror)");
    const tp::Piece& sleeve = piece(u, "sleeve");
    EXPECT_NEAR(tp::signed_area(copy.outline), tp::signed_area(sleeve.outline), 1e-6);
    EXPECT_GT(tp::signed_area(sleeve.outline), 0);
    EXPECT_EQ(copy.cut_count, 1);
    EXPECT_EQ(sleeve.cut_count, 1);
    ASSERT_TRUE(copy.grain);
    EXPECT_NEAR(copy.grain->from.x, -sleeve.grain->from.x, 1e-12);
    ASSERT_EQ(u.seams.size(), 8u);
    const auto mirrored = [](tp::Point2 q) { return tp::Point2{-q.x, q.y}; };
    for (const char* name : {"armhole front", "armhole back", "underarm"}) {
        const tp::Seam& s = seam(u, name);
        const tp::Seam& m = seam(u, std::string(name) + " (mirror)");
        EXPECT_EQ(m.direction, s.direction) << name;
        for (int side = 0; side < 2; ++side) {
            const tp::EdgeRange& rs = side == 0 ? s.a : s.b;
            const tp::EdgeRange& rm = side == 0 ? m.a : m.b;
            EXPECT_NEAR(tp::length(piece(u, rm.piece), rm), tp::length(piece(u, rs.piece), rs),
                        1e-6)
                << name;
            if (rs.piece == "sleeve") {
                EXPECT_EQ(rm.piece, "sleeve (mirror)");
                // A mirrored range runs the other way: its start is the mirror of the end.
                EXPECT_NEAR(tapeline::distance(ends(u, rm).first, mirrored(ends(u, rs).second)), 0,
                            1e-9)
                    << name;
                EXPECT_NEAR(tapeline::distance(ends(u, rm).second, mirrored(ends(u, rs).first)), 0,
                            1e-9)
                    << name;
            }
        }
    }
    // The notches of the copy are the mirror images of the original's.
    for (std::size_t k = 0; k < 2; ++k) {
        EXPECT_NEAR(tapeline::distance(notch_point(copy, copy.notches[k]),
                                       mirrored(notch_point(sleeve, sleeve.notches[k]))),
                    0, 1e-6);
    }
    // The unfolded pattern is still a valid pattern.
    EXPECT_TRUE(tp::validate(u).ok()) << tp::validate(u).errors.size();
}

// FreeSewing's T-shirt: the sleeve cap, one chain, against the front and the back armhole, two:
// split at the ratio of the armholes' lengths into "armhole (front)" and "armhole (back)", whose
// cap parts add up to the whole cap and meet at a new outline vertex; each part begins where its
// armhole does (the underarm points meet, the shoulder ends meet at the split).
TEST(GarmentUnfold, SleeveCapSplitBetweenTheArmholes) {
    const std::filesystem::path file = std::filesystem::path(TAPELINE_SHARED_DATA_DIR) /
                                       "patterns" / "freesewing" / "teagan_cisFemaleAdult36.json";
    if (!std::filesystem::exists(file)) {
        GTEST_SKIP() << file << " is absent";
    }
    tp::Pattern p = tp::read_pattern_file(file.string());
    const std::size_t edges_before = piece(p, "teagan.sleeve").outline.edges.size();
    const double cap = [&] {
        const tp::Piece& s = piece(p, "teagan.sleeve");
        const auto chain = tp::outline_chain(s.outline, s.points.at("bicepsRight"),
                                             s.points.at("bicepsLeft"), &s.points.at("capQ2"));
        double l = 0;
        for (std::size_t k : chain) {
            l += tp::length(s.outline.edges[k]);
        }
        return l;
    }();
    std::vector<std::string> skipped;
    ASSERT_EQ(tg::split_chain_seams(p, &skipped), 2u) << (skipped.empty() ? "" : skipped[0]);
    EXPECT_EQ(piece(p, "teagan.sleeve").outline.edges.size(), edges_before + 1);
    const tp::Seam& front = seam(p, "armhole (front)");
    const tp::Seam& back = seam(p, "armhole (back)");
    const double cap_front = tp::length(piece(p, front.a.piece), front.a);
    const double cap_back = tp::length(piece(p, back.a.piece), back.a);
    const double arm_front = tp::length(piece(p, front.b.piece), front.b);
    const double arm_back = tp::length(piece(p, back.b.piece), back.b);
    EXPECT_EQ(front.b.piece, "teagan.front");
    EXPECT_EQ(back.b.piece, "teagan.back");
    EXPECT_NEAR(cap_front + cap_back, cap, 1e-6);
    EXPECT_NEAR(cap_front / cap_back, arm_front / arm_back, 1e-6);
    EXPECT_GT(cap, arm_front + arm_back) << "a sleeve cap has ease";
    // Where the sides meet: the sleeve's front underarm point with the front armhole's.
    const auto meets = [&](const tp::Seam& s) {
        const auto [a0, a1] = ends(p, s.a);
        const auto [b0, b1] = ends(p, s.b);
        return s.direction == tp::SeamDirection::same
                   ? std::make_pair(std::make_pair(a0, b0), std::make_pair(a1, b1))
                   : std::make_pair(std::make_pair(a0, b1), std::make_pair(a1, b0));
    };
    const tp::Piece& sl = piece(p, "teagan.sleeve");
    const tp::Piece& fr = piece(p, "teagan.front");
    const tp::Piece& bk = piece(p, "teagan.back");
    for (const auto& [s, armhole] : {std::make_pair(&front, &fr), std::make_pair(&back, &bk)}) {
        const auto m = meets(*s);
        // One pair of meeting ends is the armhole point of the body piece, the other its shoulder.
        const tp::Point2 under = armhole->points.at("armhole");
        const tp::Point2 shoulder = armhole->points.at("shoulder");
        const bool first_under = tapeline::distance(m.first.second, under) < 0.01;
        const auto& at_under = first_under ? m.first : m.second;
        const auto& at_shoulder = first_under ? m.second : m.first;
        EXPECT_NEAR(tapeline::distance(at_under.second, under), 0, 0.01) << s->name;
        EXPECT_NEAR(tapeline::distance(at_shoulder.second, shoulder), 0, 0.01) << s->name;
        const tp::Point2 biceps = sl.points.at(armhole == &fr ? "bicepsRight" : "bicepsLeft");
        EXPECT_NEAR(tapeline::distance(at_under.first, biceps), 0, 0.01) << s->name;
    }
    // The two cap parts meet at the split vertex.
    EXPECT_TRUE(tapeline::distance(ends(p, front.a).second, ends(p, back.a).first) < 1e-9 ||
                tapeline::distance(ends(p, back.a).second, ends(p, front.a).first) < 1e-9);
    EXPECT_TRUE(tp::validate(p).ok());
    // A second call adds nothing: the seams are there.
    EXPECT_EQ(tg::split_chain_seams(p), 0u);
}

// Trousers drafted as one leg (titan): the front and the back get mirrored copies, their inseam
// and outseam are doubled, and the crotch seams join each piece to its copy, from the centre waist
// to the fork, both sides of equal length (a piece and its mirror image) and in the same direction
// (the waist ends meet). A draft whose crotch seam's named points are missing is refused naming the
// seam.
TEST(GarmentUnfold, TrouserLegsArePairedWithTheirMirrorImagesAndSewnAtTheCrotch) {
    const std::filesystem::path file = std::filesystem::path(TAPELINE_SHARED_DATA_DIR) /
                                       "patterns" / "freesewing" / "titan_cisFemaleAdult36.json";
    if (!std::filesystem::exists(file)) {
        GTEST_SKIP() << file << " is absent";
    }
    const tp::Pattern p = tp::read_pattern_file(file.string());
    const tp::Pattern u = tg::unfold_pieces(p);
    ASSERT_EQ(u.pieces.size(), 4u);
    std::map<std::string, const tp::Seam*> seams;
    for (const tp::Seam& s : u.seams) {
        seams[s.name] = &s;
    }
    ASSERT_EQ(seams.size(), 6u);
    for (const char* name : {"crotch front", "crotch back"}) {
        ASSERT_TRUE(seams.count(name)) << name;
        const tp::Seam& s = *seams[name];
        EXPECT_EQ(s.b.piece, s.a.piece + " (mirror)") << name;
        const double la = tp::length(piece(u, s.a.piece), s.a);
        const double lb = tp::length(piece(u, s.b.piece), s.b);
        EXPECT_NEAR(la, lb, 1e-9) << name;
        EXPECT_GT(la, 150) << name;
        // Where the two sides start: the same point of the piece and of its mirror image.
        const auto start = [&](const tp::EdgeRange& r, bool reversed) {
            const tp::Piece& q = piece(u, r.piece);
            const std::size_t n = q.outline.edges.size();
            return reversed ? tp::end_point(q.outline.edges[(r.first_edge + r.count - 1) % n])
                            : tp::start_point(q.outline.edges[r.first_edge]);
        };
        const bool opposite = s.direction == tp::SeamDirection::opposite;
        const tp::Point2 a = start(s.a, false), b = start(s.b, opposite);
        EXPECT_NEAR(a.x, -b.x, 1e-9) << name;  // the copy is mirrored about x = 0
        EXPECT_NEAR(a.y, b.y, 1e-9) << name;
    }
    for (const char* name : {"inseam", "inseam (mirror)", "outseam", "outseam (mirror)"}) {
        EXPECT_TRUE(seams.count(name)) << name;
    }
    tp::Pattern broken = p;
    for (tp::Piece& q : broken.pieces) {
        if (q.name == "titan.front") {
            q.points.erase("styleWaistIn");
        }
    }
    try {
        tg::unfold_pieces(broken);
        ADD_FAILURE() << "a crotch seam without its named points was accepted";
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("crotch front"), std::string::npos) << e.what();
    }
}
