// Grading: synthetic patterns with known answers, the FreeSewing size pair, bad inputs.
#include <tapeline/core/errors.h>
#include <tapeline_test/grading.h>

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <utility>

namespace tg = tapeline::grading;
namespace tp = tapeline::pattern;
namespace ts = tapeline::sizes;

namespace {

/// A w × h rectangle piece with named corners and a horizontal span "chest" across it.
tp::Piece rectangle(const std::string& name, double w, double h) {
    tp::Piece p;
    p.name = name;
    const tp::Point2 a{0, 0}, b{w, 0}, c{w, h}, d{0, h};
    p.outline.edges = {
        {tp::Line{a, b}, ""}, {tp::Line{b, c}, ""}, {tp::Line{c, d}, ""}, {tp::Line{d, a}, ""}};
    p.points = {{"bl", a}, {"br", b}, {"tr", c}, {"tl", d}};
    p.grain = tp::GrainLine{{w / 2, 0.2 * h}, {w / 2, 0.8 * h}};
    return p;
}

ts::MeasurementSet set(const std::string& name, std::map<std::string, double> v) {
    ts::MeasurementSet m;
    m.name = name;
    m.values = std::move(v);
    return m;
}

tg::GradingOptions quick() {
    tg::GradingOptions o;
    o.population = 16;
    o.generations = 20;
    o.threads = 2;
    return o;
}

}  // namespace

// The FreeSewing drafts and sets live in ../shared/data: without them these tests skip, naming
// the path.
#define SKIP_WITHOUT_FREESEWING()                                                                 \
    do {                                                                                          \
        const std::string sets_ =                                                                 \
            std::string(TAPELINE_SHARED_DATA_DIR) + "/patterns/freesewing/measurement_sets.json"; \
        if (!std::ifstream(sets_))                                                                \
            GTEST_SKIP() << sets_ << " absent";                                                   \
    } while (0)

// One piece, width bound to "chest" (count 2, ease 20), height to "length": the graded rectangle
// must realise both targets, stay a rectangle (right angles) and keep its grain vertical.
TEST(Grading, RectangleMeetsBothBindingsAndKeepsItsAngles) {
    tp::Pattern p;
    p.name = "rect";
    p.pieces.push_back(rectangle("body", 250, 600));
    p.bindings.push_back({"chest", {{"body", {}, "bl", "br", 2}}, 20});  // 2·250 = 480 + 20
    p.bindings.push_back({"length", {{"body", {}, "bl", "tl", 1}}, 0});
    const auto from = set("base", {{"chest", 480}, {"length", 600}});
    const auto to = set("big", {{"chest", 560}, {"length", 630}});
    tg::GradingOptions o = quick();
    o.ease = tg::EaseMode::keep_mm;
    const tg::GradeResult r = tapeline_test::grade(p, from, to, o);
    ASSERT_EQ(r.report.fit.size(), 2u);
    for (const tg::FitRow& f : r.report.fit) {
        std::printf("%s target %.2f achieved %.3f\n", f.measurement.c_str(), f.target_mm,
                    f.achieved_mm);
        EXPECT_NEAR(f.achieved_mm, f.target_mm, 2.0) << f.measurement;
    }
    const tp::Piece& g = r.pattern.pieces[0];
    const double width = tp::distance(g.points.at("bl"), g.points.at("br"));
    EXPECT_NEAR(2 * width, 560 + 20, 4.0);  // keep_mm: ease stays 20 mm
    // A rectangle stretched in x and y stays a rectangle: angles within 0.5°.
    EXPECT_LT(r.report.style.max_angle_change_deg, 0.5);
    EXPECT_LT(r.report.style.max_grain_change_deg, 0.5);
    EXPECT_TRUE(r.report.within_tolerance);
    EXPECT_LT(r.report.chosen, r.report.front.size());
    std::printf("timings: total %.3f s (ceres %.3f, nsga2 %.3f, polish %.3f)\n",
                r.report.timings.total_s, r.report.timings.ceres_fast_path_s,
                r.report.timings.nsga2_s, r.report.timings.polish_s);
}

// Two panels sewn along their side edges; only the front is bound. The seam (a constraint) must
// bring the back's side to the front's new length.
TEST(Grading, SeamSidesStayEqual) {
    tp::Pattern p;
    p.name = "two";
    p.pieces.push_back(rectangle("front", 250, 600));
    p.pieces.push_back(rectangle("back", 240, 600));
    p.bindings.push_back({"length", {{"front", {}, "bl", "tl", 1}}, 0});
    p.seams.push_back({"side", {"front", 1, 1}, {"back", 3, 1}, tp::SeamDirection::opposite});
    const tg::GradeResult r =
        tapeline_test::grade(p, set("a", {{"length", 600}}), set("b", {{"length", 660}}), quick());
    ASSERT_EQ(r.report.seams.size(), 1u);
    std::printf("seam %.3f vs %.3f\n", r.report.seams[0].length_a_mm,
                r.report.seams[0].length_b_mm);
    EXPECT_LT(r.report.seams[0].mismatch_mm, 1.0);
    EXPECT_NEAR(r.report.seams[0].length_a_mm, 660, 2.0);
}

// Sides that differ in the base draft (here 600 against 630 mm, beyond the 1 mm seam tolerance)
// are a deliberate difference (sleeve-cap ease): the graded seam keeps the base ratio a/b.
TEST(Grading, SeamWithDeliberateEaseKeepsItsRatio) {
    tp::Pattern p;
    p.name = "eased";
    p.pieces.push_back(rectangle("front", 250, 600));
    p.pieces.push_back(rectangle("back", 240, 630));
    p.bindings.push_back({"length", {{"front", {}, "bl", "tl", 1}}, 0});
    const std::vector<tg::SeamSpec> seams = {{"side", {{"front", 1, 1}}, {{"back", 3, 1}}}};
    const tg::GradeResult r = tapeline_test::grade(p, set("a", {{"length", 600}}),
                                                   set("b", {{"length", 660}}), quick(), seams);
    ASSERT_EQ(r.report.seams.size(), 1u);
    const tg::SeamRow& s = r.report.seams[0];
    std::printf("seam %.3f vs %.3f ratio %.4f\n", s.length_a_mm, s.length_b_mm, s.ratio);
    EXPECT_NEAR(s.ratio, 600.0 / 630.0, 1e-9);
    EXPECT_NEAR(s.length_a_mm, 660, 2.0);
    EXPECT_NEAR(s.length_b_mm, 660 * 630.0 / 600.0, 2.0);
    EXPECT_LT(s.mismatch_mm, 1.0);
}

// A girth over two pieces of base widths 250 and 200: with split_girths each piece's part grows
// in proportion to its base share (the front/back ratio stays 1.25), and the girth is met.
TEST(Grading, GirthGrowthIsSplitByBaseShare) {
    tp::Pattern p;
    p.name = "split";
    p.pieces.push_back(rectangle("front", 250, 600));
    p.pieces.push_back(rectangle("back", 200, 600));
    p.bindings.push_back({"chest", {{"front", {}, "bl", "br", 2}, {"back", {}, "bl", "br", 2}}, 0});
    const std::vector<tg::SeamSpec> seams = {{"side", {{"front", 1, 1}}, {{"back", 3, 1}}}};
    const tg::GradeResult r = tapeline_test::grade(p, set("a", {{"chest", 900}}),
                                                   set("b", {{"chest", 1000}}), quick(), seams);
    const double wf =
        tp::distance(r.pattern.pieces[0].points.at("bl"), r.pattern.pieces[0].points.at("br"));
    const double wb =
        tp::distance(r.pattern.pieces[1].points.at("bl"), r.pattern.pieces[1].points.at("br"));
    std::printf("front %.2f back %.2f\n", wf, wb);
    EXPECT_NEAR(2 * (wf + wb), 1000, 2.0);
    EXPECT_NEAR(wf / wb, 1.25, 0.01);
}

TEST(Grading, SeamOnAMissingPieceOrEdgeIsRefused) {
    tp::Pattern p;
    p.name = "rect";
    p.pieces.push_back(rectangle("body", 250, 600));
    p.bindings.push_back({"chest", {{"body", {}, "bl", "br", 2}}, 20});
    const auto from = set("a", {{"chest", 480}}), to = set("b", {{"chest", 520}});
    auto message = [&](const std::vector<tg::SeamSpec>& seams) {
        try {
            tapeline_test::grade(p, from, to, quick(), seams);
        } catch (const tapeline::InvalidInput& e) {
            return std::string(e.what());
        }
        return std::string("no exception");
    };
    EXPECT_NE(message({{"side", {{"body", 0, 1}}, {{"sleeve", 0, 1}}}}).find("no piece 'sleeve'"),
              std::string::npos);
    EXPECT_NE(message({{"side", {{"body", 7, 1}}, {{"body", 2, 1}}}}).find("has no edges 7"),
              std::string::npos);
}

TEST(Grading, SameSeedSameResult) {
    tp::Pattern p;
    p.name = "rect";
    p.pieces.push_back(rectangle("body", 250, 600));
    p.bindings.push_back({"chest", {{"body", {}, "bl", "br", 2}}, 20});
    const auto from = set("a", {{"chest", 480}}), to = set("b", {{"chest", 520}});
    const tg::GradeResult r1 = tapeline_test::grade(p, from, to, quick());
    const tg::GradeResult r2 = tapeline_test::grade(p, from, to, quick());
    ASSERT_EQ(r1.report.front.size(), r2.report.front.size());
    for (std::size_t i = 0; i < r1.report.front.size(); ++i) {
        EXPECT_EQ(r1.report.front[i].fit, r2.report.front[i].fit);
        EXPECT_EQ(r1.report.front[i].style, r2.report.front[i].style);
    }
    EXPECT_EQ(r1.report.chosen, r2.report.chosen);
}

TEST(Grading, TargetMissingABoundMeasurementIsRefused) {
    tp::Pattern p;
    p.name = "rect";
    p.pieces.push_back(rectangle("body", 250, 600));
    p.bindings.push_back({"chest", {{"body", {}, "bl", "br", 2}}, 20});
    try {
        tapeline_test::grade(p, set("a", {{"chest", 480}}), set("tgt", {{"waist", 700}}), quick());
        FAIL() << "no exception";
    } catch (const tapeline::InvalidInput& e) {
        EXPECT_NE(std::string(e.what()).find("no measurement 'chest'"), std::string::npos)
            << e.what();
        EXPECT_NE(std::string(e.what()).find("tgt"), std::string::npos) << e.what();
    }
}

// A target no grade of this draft can reach (another unit, garbage) is refused before Ceres runs:
// beyond GradingOptions::max_target_ratio of the base value either way, not finite, not positive.
TEST(Grading, TargetsBeyondTheRatioLimitAreRefused) {
    tp::Pattern p;
    p.name = "rect";
    p.pieces.push_back(rectangle("body", 250, 600));
    p.bindings.push_back({"chest", {{"body", {}, "bl", "br", 2}}, 20});
    const auto from = set("a", {{"chest", 480}});
    tg::GradingOptions o = quick();
    o.generations = 0;
    auto message = [&](double target, double limit) {
        o.max_target_ratio = limit;
        try {
            tapeline_test::grade(p, from, set("tgt", {{"chest", target}}), o);
        } catch (const tapeline::InvalidInput& e) {
            return std::string(e.what());
        }
        return std::string("graded");
    };
    for (double t : {1e9, 1e-9, 1e308, 1441.0, 159.0}) {
        const std::string m = message(t, 3);
        EXPECT_NE(m.find("target set 'tgt': measurement 'chest' is "), std::string::npos) << m;
        EXPECT_NE(m.find("times the base set 'a''s 480 mm; a grade beyond 3 times"),
                  std::string::npos)
            << m;
    }
    EXPECT_NE(message(1e9, 3).find("2.083e+06 times"), std::string::npos) << message(1e9, 3);
    for (double t : {std::nan(""), HUGE_VAL, -480.0, 0.0}) {
        EXPECT_NE(message(t, 3).find("a bound length must be a positive number"), std::string::npos)
            << t;
    }
    // Just inside the limit both ways, and a wider limit, grade.
    EXPECT_EQ(message(1439, 3), "graded");
    EXPECT_EQ(message(161, 3), "graded");
    EXPECT_EQ(message(1900, 4), "graded");
    EXPECT_EQ(message(1e4, 0), "graded");  // 0: no limit
}

TEST(Grading, PatternWithoutBindingsIsRefused) {
    tp::Pattern p;
    p.name = "plain";
    p.pieces.push_back(rectangle("body", 250, 600));
    EXPECT_THROW(tapeline_test::grade(p, set("a", {}), set("b", {}), quick()),
                 tapeline::InvalidInput);
}

// FreeSewing's own size pair: grade Brian from size 36 to the size-42 set. Every binding within
// 2 mm, and the outlines much closer to FreeSewing's size-42 draft than the unchanged size 36.
TEST(Grading, BrianSize36To42BeatsUnchanged) {
    SKIP_WITHOUT_FREESEWING();
    const tp::Pattern base = tapeline_test::freesewing_draft("brian", "cisFemaleAdult36");
    const tp::Pattern ref = tapeline_test::freesewing_draft("brian", "cisFemaleAdult42");
    ASSERT_GE(base.bindings.size(), 4u);
    tg::GradingOptions o;
    o.threads = 2;
    const auto t0 = std::chrono::steady_clock::now();
    const tg::GradeResult r =
        tapeline_test::grade(base, tapeline_test::freesewing_set("cisFemaleAdult36"),
                             tapeline_test::freesewing_set("cisFemaleAdult42"), o);
    const double secs =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    for (const tg::FitRow& f : r.report.fit) {
        std::printf("%-20s %-30s target %7.1f achieved %8.2f error %6.2f\n", f.measurement.c_str(),
                    f.where.c_str(), f.target_mm, f.achieved_mm, f.error_mm);
        EXPECT_LT(std::abs(f.error_mm), 2.0) << f.measurement << " on " << f.where;
    }
    const auto unchanged = tapeline_test::deviation(ref, base);
    const auto graded = tapeline_test::deviation(ref, r.pattern);
    std::printf(
        "outline deviation: graded mean %.2f max %.2f; unchanged mean %.2f max %.2f; "
        "%.2f s\n",
        graded.mean_mm, graded.max_mm, unchanged.mean_mm, unchanged.max_mm, secs);
    EXPECT_LT(graded.mean_mm, 0.5 * unchanged.mean_mm);
}

// Seams derived from FreeSewing's design conventions: every rule applies to its design's size-36
// draft, and the sides that are sewn without ease are equal there (within 1 mm) — the check that
// the chains run between the right points.
TEST(Grading, FreeSewingSeamsAreFoundOnEveryDesign) {
    SKIP_WITHOUT_FREESEWING();
    const std::map<std::string, std::vector<std::string>> want = {
        {"aaron", {"side", "shoulder", "armhole binding", "neck binding"}},
        {"brian", {"side", "shoulder", "armhole", "sleeve"}},
        {"simon", {"side", "shoulder", "armhole", "sleeve", "cuff"}},
        {"teagan", {"side", "shoulder", "armhole", "sleeve"}},
        {"titan", {"outseam", "inseam"}}};
    for (const auto& [design, names] : want) {
        const tp::Pattern p = tapeline_test::freesewing_draft(design, "cisFemaleAdult36");
        std::vector<std::string> skipped;
        const std::vector<tg::SeamSpec> seams = tapeline_test::freesewing_seams(p, &skipped);
        EXPECT_TRUE(skipped.empty()) << design << ": " << skipped.front();
        ASSERT_EQ(seams.size(), names.size()) << design;
        for (std::size_t i = 0; i < seams.size(); ++i) {
            EXPECT_EQ(seams[i].name, names[i]);
            auto len = [&](const std::vector<tp::EdgeRange>& side) {
                double l = 0;
                for (const tp::EdgeRange& r : side) {
                    l += tp::length(*tp::find_piece(p, r.piece), r);
                }
                return l;
            };
            const double a = len(seams[i].a), b = len(seams[i].b);
            std::printf("%-7s %-16s %8.2f %8.2f\n", design.c_str(), names[i].c_str(), a, b);
            if (names[i] == "side" || names[i] == "shoulder" || names[i] == "sleeve" ||
                names[i] == "inseam") {
                EXPECT_NEAR(a, b, 1.0) << design << " " << names[i];
            }
            // Vertical seams meet lower end to lower end: the recorded direction must say so.
            if (names[i] == "side" || names[i] == "inseam" || names[i] == "outseam") {
                auto ends = [&](const tp::EdgeRange& r) {
                    const tp::Piece& piece = *tp::find_piece(p, r.piece);
                    const std::size_t n = piece.outline.edges.size();
                    return std::pair<double, double>{
                        tp::start_point(piece.outline.edges[r.first_edge]).y,
                        tp::end_point(piece.outline.edges[(r.first_edge + r.count - 1) % n]).y};
                };
                const auto ea = ends(seams[i].a[0]), eb = ends(seams[i].b[0]);
                const bool a_starts_low = ea.first < ea.second;
                const bool b_starts_low = eb.first < eb.second;
                EXPECT_EQ(seams[i].direction == tp::SeamDirection::same,
                          a_starts_low == b_starts_low)
                    << design << " " << names[i];
            }
        }
    }
}

// Brian and Teagan graded both ways with their derived seams: bindings within 2 mm, every seam
// within 1 mm, outlines within 3 mm (mean) of FreeSewing's own draft of the target size. Grading
// to the smaller size (42 → 36) is the second half.
TEST(Grading, FreeSewingBothWaysWithSeams) {
    SKIP_WITHOUT_FREESEWING();
    for (const std::string design : {"brian", "teagan"}) {
        for (const auto& [from, to] : {std::pair<std::string, std::string>{"36", "42"},
                                       std::pair<std::string, std::string>{"42", "36"}}) {
            const tp::Pattern base =
                tapeline_test::freesewing_draft(design, "cisFemaleAdult" + from);
            const tp::Pattern ref = tapeline_test::freesewing_draft(design, "cisFemaleAdult" + to);
            tg::GradingOptions o;
            o.threads = 2;
            const tg::GradeResult r =
                tapeline_test::grade(base, tapeline_test::freesewing_set("cisFemaleAdult" + from),
                                     tapeline_test::freesewing_set("cisFemaleAdult" + to), o,
                                     tapeline_test::freesewing_seams(base, nullptr));
            for (const tg::FitRow& f : r.report.fit) {
                EXPECT_LT(std::abs(f.error_mm), 2.0) << design << " " << f.measurement;
            }
            ASSERT_FALSE(r.report.seams.empty());
            for (const tg::SeamRow& s : r.report.seams) {
                EXPECT_LT(s.mismatch_mm, 1.0) << design << " seam " << s.name;
            }
            const auto graded = tapeline_test::deviation(ref, r.pattern);
            std::printf("%s %s -> %s: mean %.2f max %.2f mm\n", design.c_str(), from.c_str(),
                        to.c_str(), graded.mean_mm, graded.max_mm);
            EXPECT_LT(graded.mean_mm, 3.0) << design << " " << from << " -> " << to;
        }
    }
}

// An invariant: grading to a size and back returns the base draft (the problem is the same both
// ways, up to the optimiser's tolerance). Teagan 36 → 42 → 36, with its seams.
TEST(Grading, RoundTripReturnsToTheBase) {
    SKIP_WITHOUT_FREESEWING();
    const tp::Pattern base = tapeline_test::freesewing_draft("teagan", "cisFemaleAdult36");
    const auto s36 = tapeline_test::freesewing_set("cisFemaleAdult36");
    const auto s42 = tapeline_test::freesewing_set("cisFemaleAdult42");
    const auto seams = tapeline_test::freesewing_seams(base, nullptr);
    tg::GradingOptions o;
    o.threads = 2;
    const tg::GradeResult up = tapeline_test::grade(base, s36, s42, o, seams);
    const tg::GradeResult back = tapeline_test::grade(up.pattern, s42, s36, o, seams);
    const auto d = tapeline_test::deviation(base, back.pattern);
    std::printf("36 -> 42 -> 36: mean %.3f max %.3f mm\n", d.mean_mm, d.max_mm);
    EXPECT_LT(d.mean_mm, 0.5);
    EXPECT_LT(d.max_mm, 2.0);
}

TEST(Grading, ParetoPngIsAPng) {
    tp::Pattern p;
    p.name = "rect";
    p.pieces.push_back(rectangle("body", 250, 600));
    p.bindings.push_back({"chest", {{"body", {}, "bl", "br", 2}}, 20});
    const tg::GradeResult r =
        tapeline_test::grade(p, set("a", {{"chest", 480}}), set("b", {{"chest", 520}}), quick());
    const auto png = tapeline_test::pareto_png(r.report);
    ASSERT_GT(png.size(), 8u);
    EXPECT_EQ(png[1], 'P');
    EXPECT_EQ(png[2], 'N');
    EXPECT_EQ(png[3], 'G');
}
