// Girth bindings found by laying a pattern on a body (garment/bindings.h): checked against the
// garment placed on the same body by dressing (an independent route: the 3D cloth cut by the
// girth's plane), against FreeSewing's own naming, and on the refusals.
#include <tapeline/garment/bindings.h>
#include <tapeline/garment/dress.h>
#include <tapeline/pattern/io_detect.h>
#include <tapeline/pattern/io_garmentcode.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline/pattern/seam_chains.h>
#include <tapeline_test/expect.h>
#include <tapeline_test/measured_body.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <filesystem>
#include <map>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace tg = tapeline::garment;
namespace tmeas = tapeline::measurement;
namespace tp = tapeline::pattern;

namespace {

using tapeline_test::measurement::bundled_path;
using tapeline_test::measurement::load_dm_body;
using tapeline_test::measurement::MeasuredBody;

/// Length of the section of triangles `tris` of positions `x` by the plane y = `y`.
double section_length(const std::vector<tg::Vec3>& x, const std::vector<tg::Tri>& tris, double y) {
    double total = 0;
    for (const tg::Tri& t : tris) {
        std::vector<tg::Vec3> cut;
        for (int k = 0; k < 3; ++k) {
            const tg::Vec3& a = x[t[k]];
            const tg::Vec3& b = x[t[(k + 1) % 3]];
            if ((a[1] < y) != (b[1] < y)) {
                const double s = (y - a[1]) / (b[1] - a[1]);
                cut.push_back({a[0] + s * (b[0] - a[0]), y, a[2] + s * (b[2] - a[2])});
            }
        }
        if (cut.size() == 2) {
            total += std::hypot(cut[1][0] - cut[0][0], cut[1][2] - cut[0][2]);
        }
    }
    return total;
}

/// Distance from `p` to the segment a–b.
double segment_distance(const tp::Point2& a, const tp::Point2& b, const tp::Point2& p) {
    const double dx = b.x - a.x, dy = b.y - a.y, l2 = dx * dx + dy * dy;
    const double t = l2 > 0 ? std::clamp(((p.x - a.x) * dx + (p.y - a.y) * dy) / l2, 0.0, 1.0) : 0;
    return std::hypot(a.x + t * dx - p.x, a.y + t * dy - p.y);
}

/// Whether a found binding is a girth (its points are named girth:...), not a length.
bool is_girth(const tp::MeasurementBinding& b) {
    return b.features.front().from_point.rfind("girth:", 0) == 0;
}

/// The FreeSewing design `name` of ../shared/data; empty when the data is absent.
std::string freesewing(const std::string& name) {
    const std::filesystem::path p = std::filesystem::path(TAPELINE_SHARED_DATA_DIR) / "patterns" /
                                    "freesewing" / (name + ".json");
    return std::filesystem::exists(p) ? p.string() : std::string();
}

/// FreeSewing's aaron, brian and teagan drafted for cisFemaleAdult36 (../shared/data); all three
/// empty when one is absent.
std::array<std::string, 3> three_drafts() {
    std::array<std::string, 3> p = {freesewing("aaron_cisFemaleAdult36"),
                                    freesewing("brian_cisFemaleAdult36"),
                                    freesewing("teagan_cisFemaleAdult36")};
    if (p[0].empty() || p[1].empty() || p[2].empty()) {
        return {};
    }
    return p;
}

/// Whether some note starts with `prefix` and holds `part`.
bool has_note(const std::vector<std::string>& notes, const std::string& prefix,
              const std::string& part = "") {
    return std::any_of(notes.begin(), notes.end(), [&](const std::string& n) {
        return n.rfind(prefix, 0) == 0 && n.find(part) != std::string::npos;
    });
}

double span_mm(const tp::Point2& p, const tp::Point2& q) {
    return std::hypot(p.x - q.x, p.y - q.y);
}

const tg::BindingInference& shirt_on_bundled_body(const MeasuredBody*& body) {
    static const MeasuredBody b = load_dm_body(bundled_path("bodies/mh_female_average.obj"));
    static const tg::BindingInference inf = tg::infer_girth_bindings(
        b.body, b.landmarks, b.measurements,
        tp::read_pattern_file(bundled_path("patterns/shirt_mean_specification.json")));
    body = &b;
    return inf;
}

}  // namespace

// The GarmentCode shirt on the bundled body: each inferred girth (the sum of the spans, counted)
// equals the length of the section of the torso pieces as dressing places them, cut by the
// girth's plane; its ease is that length minus the body's girth; the spans' ends lie on the
// outline. The hip lies below the shirt's hem: not bound, with the reason.
TEST(GarmentBindings, ShirtGirthsAreTheSectionsOfThePlacedGarment) {
    const MeasuredBody* b = nullptr;
    const tg::BindingInference& inf = shirt_on_bundled_body(b);
    tp::Pattern shirt =
        tp::read_pattern_file(bundled_path("patterns/shirt_mean_specification.json"));
    tg::DressOptions o;
    o.resolution_mm = 10;
    o.sewing.sew_seconds = 0;  // placement only
    o.sewing.settle_seconds = 0;
    o.sewing.max_extra_seconds = 0;
    o.without_pieces = {"left_sleeve_f", "left_sleeve_b", "right_sleeve_f", "right_sleeve_b"};
    const tg::DressResult placed = tg::dress(b->body, b->landmarks, shirt, o);
    std::vector<std::string> bound;
    for (const tp::MeasurementBinding& g : inf.pattern.bindings) {
        if (!is_girth(g)) {
            continue;  // the lengths: LengthsRunBetweenTheLevelsAndEndOnFreeSewingsOwnPoints
        }
        bound.push_back(g.measurement);
        if (g.features.front().piece.find("sleeve") != std::string::npos) {
            continue;  // the arm girths: SleeveGirthsAtTheBodysDistanceFromTheShoulderPoint
        }
        const tmeas::Measurement* body_girth = b->measurements.find(g.measurement);
        ASSERT_NE(body_girth, nullptr) << g.measurement;
        double garment = 0;
        for (const tp::BoundFeature& f : g.features) {
            const tp::Piece* piece = tp::find_piece(inf.pattern, f.piece);
            ASSERT_NE(piece, nullptr);
            const tp::Point2 p = piece->points.at(f.from_point), q = piece->points.at(f.to_point);
            garment += f.count * std::hypot(q.x - p.x, q.y - p.y);
            for (const tp::Point2& end : {p, q}) {
                double nearest = 1e300;
                const std::vector<tp::Point2> ring = tp::sample(piece->outline, 0.05).points;
                for (std::size_t k = 0; k + 1 < ring.size(); ++k) {
                    nearest = std::min(nearest, segment_distance(ring[k], ring[k + 1], end));
                }
                EXPECT_LT(nearest, 0.3) << g.measurement << " on " << f.piece;
            }
        }
        EXPECT_EQ(g.features.size(), 4u) << g.measurement << ": the four torso panels";
        EXPECT_NEAR(g.ease_mm, garment - body_girth->value, 1e-6) << g.measurement;
        const double section =
            section_length(placed.placed, placed.cloth.triangles, body_girth->plane_point[1]);
        EXPECT_NEAR(garment, section, 0.015 * section)
            << g.measurement << " at " << body_girth->plane_point[1] << " mm";
    }
    EXPECT_EQ(std::vector<std::string>(bound.begin(),
                                       bound.begin() + std::min<std::size_t>(4, bound.size())),
              (std::vector<std::string>{"bust_girth", "underbust_girth", "waist_girth",
                                        "high_hip_girth"}));
    bool hip_note = false;
    for (const std::string& n : inf.notes) {
        hip_note = hip_note || (n.rfind("hip_girth: not bound (no torso or skirt piece", 0) == 0);
    }
    EXPECT_TRUE(hip_note);
}

// FreeSewing's aaron (a tank top, half pieces cut on the fold): spans count twice, bindings take
// the pattern's own FreeSewing names where it uses them (hips); the body's bust level cuts the
// armhole (sewn to the armhole binding, not to a torso piece), so the chest is taken 25 mm below
// it. A level that cuts an opening is not a girth of the garment: simon's fronts button over
// each other, sewn to nothing at the centre front, so its waist is left out.
TEST(GarmentBindings, TankTopHalvesCountTwiceAndAnOpenLevelIsNoGirth) {
    const MeasuredBody* b = nullptr;
    shirt_on_bundled_body(b);
    const tg::BindingInference inf = tg::infer_girth_bindings(
        b->body, b->landmarks, b->measurements,
        tp::read_pattern_file(bundled_path("patterns/aaron_cisFemaleAdult36.json")));
    bool hips = false, strips = false;
    for (const tp::MeasurementBinding& g : inf.pattern.bindings) {
        hips = hips || g.measurement == "hips";
        for (const tp::BoundFeature& f : g.features) {
            EXPECT_EQ(f.count, is_girth(g) || g.measurement == "shoulderToShoulder" ? 2.0 : 1.0)
                << g.measurement << " on " << f.piece;
        }
    }
    for (const std::string& n : inf.notes) {
        strips = strips || n.rfind("piece aaron.armBinding: in no girth", 0) == 0;
    }
    EXPECT_TRUE(hips);
    EXPECT_TRUE(strips);
    EXPECT_TRUE(has_note(inf.notes, "chest: aaron.front ×2, aaron.back ×2;",
                         "(25 mm below the armhole; the body's level is "));
    const std::string simon = freesewing("simon_cisFemaleAdult36");
    if (simon.empty()) {
        GTEST_SKIP() << "simon_cisFemaleAdult36 of ../shared/data is absent";
    }
    const tg::BindingInference open = tg::infer_girth_bindings(
        b->body, b->landmarks, b->measurements, tp::read_pattern_file(simon));
    EXPECT_TRUE(has_note(open.notes, "waist_girth: not bound (at ",
                         "it crosses piece simon.frontRight edge "));
    for (const tp::MeasurementBinding& g : open.pattern.bindings) {
        EXPECT_NE(g.measurement, "waist");
    }
}

// A bindings file carries the bindings and the points they use; given back to the base pattern
// it restores them, and its bindings replace those of the same measurement.
TEST(GarmentBindings, BindingsFileRoundTripAndOverride) {
    const MeasuredBody* b = nullptr;
    const tg::BindingInference& inf = shirt_on_bundled_body(b);
    nlohmann::json file = tp::bindings_file_json(inf.pattern);
    tp::Pattern fresh =
        tp::read_pattern_file(bundled_path("patterns/shirt_mean_specification.json"));
    tp::apply_bindings_file(fresh, file, "b.json");
    EXPECT_EQ(tp::to_json(fresh), tp::to_json(inf.pattern));
    file["bindings"][0]["ease"] = 300;
    file["bindings"].erase(1);
    tp::apply_bindings_file(fresh, file, "b.json");
    EXPECT_EQ(fresh.bindings.size(), inf.pattern.bindings.size());
    EXPECT_EQ(fresh.bindings[0].ease_mm, 300);
    file["points"]["no_such_piece"] = {{"x", {1, 2}}};
    tapeline_test::expect_error<tapeline::InvalidInput>(
        [&] { tp::apply_bindings_file(fresh, file, "b.json"); },
        {"b.json", "has no piece 'no_such_piece'"}, "a point on a missing piece");

    // A length bound once per piece (aaron's waist to armpit, front and back) keeps both of its
    // bindings, given back once or twice.
    const tg::BindingInference aaron = tg::infer_girth_bindings(
        b->body, b->landmarks, b->measurements,
        tp::read_pattern_file(bundled_path("patterns/aaron_cisFemaleAdult36.json")));
    const nlohmann::json aaron_file = tp::bindings_file_json(aaron.pattern);
    const auto sides = [](const tp::Pattern& p) {
        return std::count_if(p.bindings.begin(), p.bindings.end(),
                             [](const auto& x) { return x.measurement == "waistToArmpit"; });
    };
    ASSERT_EQ(sides(aaron.pattern), 2);
    tp::Pattern again = tp::read_pattern_file(bundled_path("patterns/aaron_cisFemaleAdult36.json"));
    again.bindings.clear();
    for (int k = 0; k < 2; ++k) {
        tp::apply_bindings_file(again, aaron_file, "b.json");
        EXPECT_EQ(tp::to_json(again), tp::to_json(aaron.pattern)) << "given back " << k + 1;
        EXPECT_EQ(sides(again), 2);
    }
}

// FreeSewing's brian (a body block with long sleeves, one sleeve drafted for both arms), its
// declared measurements taken away (a draft that says nothing of the body it was made for): the
// arm girths cut the sleeve at the distance below the top of its cap (the top of the drafted
// sleeve) at which the body's girth plane lies from the shoulder point; the span's ends are the
// outermost crossings of that line with the outline, counted once (one arm); the sleeve there is
// wider than the arm and no wider than FreeSewing's own biceps line (the sleeve tapers below its
// cap). The upper arm is the sleeve's width at its underarm points instead (1 mm below FreeSewing's
// biceps line, as long as it), where the body's upper-arm level would cross the cap. A level below
// the hem of a short sleeve (teagan's wrist) is not bound, saying so.
TEST(GarmentBindings, SleeveGirthsAtTheBodysDistanceFromTheShoulderPoint) {
    const std::filesystem::path dir =
        std::filesystem::path(TAPELINE_SHARED_DATA_DIR) / "patterns" / "freesewing";
    if (!std::filesystem::exists(dir / "brian_cisFemaleAdult36.json")) {
        GTEST_SKIP() << dir << " is absent";
    }
    const MeasuredBody* b = nullptr;
    shirt_on_bundled_body(b);
    tp::Pattern brian = tp::read_pattern_file((dir / "brian_cisFemaleAdult36.json").string());
    brian.measurements_used.clear();
    const tg::BindingInference inf =
        tg::infer_girth_bindings(b->body, b->landmarks, b->measurements, brian);
    const tp::Piece* sleeve = tp::find_piece(inf.pattern, "library.sleeve");
    ASSERT_NE(sleeve, nullptr);
    const std::vector<tp::Point2> ring = tp::sample(sleeve->outline, 0.05).points;
    double ymax = -1e300;
    for (const tp::Point2& q : ring) {
        ymax = std::max(ymax, q.y);
    }
    std::vector<std::string> bound;
    for (const tp::MeasurementBinding& g : inf.pattern.bindings) {
        if (g.features.front().piece != "library.sleeve" || !is_girth(g)) {
            continue;
        }
        bound.push_back(g.measurement);
        ASSERT_EQ(g.features.size(), 1u) << g.measurement;
        const tp::BoundFeature& f = g.features.front();
        EXPECT_EQ(f.count, 1.0) << g.measurement << ": one sleeve per arm";
        const tmeas::Measurement* arm = b->measurements.find(g.measurement);  // the base value
        ASSERT_NE(arm, nullptr) << g.measurement;
        const tg::Vec3 acromion =
            *b->landmarks.point(arm->plane_point[0] > 0 ? "acromion_left" : "acromion_right");
        const tg::Vec3 d{arm->plane_point[0] - acromion[0], arm->plane_point[1] - acromion[1],
                         arm->plane_point[2] - acromion[2]};
        const double down = std::abs(d[0] * arm->plane_normal[0] + d[1] * arm->plane_normal[1] +
                                     d[2] * arm->plane_normal[2]);
        const tp::Point2 l = sleeve->points.at("bicepsLeft"), r = sleeve->points.at("bicepsRight");
        if (g.measurement == "upper_arm_girth") {
            const tp::Point2 p = sleeve->points.at(f.from_point), q = sleeve->points.at(f.to_point);
            EXPECT_NEAR(p.y, l.y - 1, 0.01);
            EXPECT_NEAR(q.y, l.y - 1, 0.01);
            EXPECT_NEAR(std::hypot(q.x - p.x, q.y - p.y), std::hypot(r.x - l.x, r.y - l.y), 1.5);
            EXPECT_GT(ymax - down, l.y) << "the body's level is in the cap";
            continue;
        }
        const double y = ymax - down;
        double xmin = 1e300, xmax = -1e300;
        for (std::size_t k = 0; k + 1 < ring.size(); ++k) {
            const tp::Point2 &u = ring[k], &v = ring[k + 1];
            if ((u.y < y) != (v.y < y)) {
                const double x = u.x + (y - u.y) / (v.y - u.y) * (v.x - u.x);
                xmin = std::min(xmin, x);
                xmax = std::max(xmax, x);
            }
        }
        const tp::Point2 p = sleeve->points.at(f.from_point), q = sleeve->points.at(f.to_point);
        EXPECT_NEAR(p.y, y, 0.3) << g.measurement;
        EXPECT_NEAR(q.y, y, 0.3) << g.measurement;
        EXPECT_NEAR(std::min(p.x, q.x), xmin, 0.3) << g.measurement;
        EXPECT_NEAR(std::max(p.x, q.x), xmax, 0.3) << g.measurement;
        const double width = std::hypot(q.x - p.x, q.y - p.y);
        EXPECT_NEAR(g.ease_mm, width - arm->value, 1e-6) << g.measurement;
        EXPECT_GT(g.ease_mm, 0) << g.measurement << ": the sleeve is wider than the arm";
        EXPECT_LE(width, std::hypot(r.x - l.x, r.y - l.y) + 0.5) << g.measurement;
        EXPECT_LT(y, l.y) << g.measurement << ": below the cap";
    }
    EXPECT_EQ(bound, (std::vector<std::string>{"upper_arm_girth", "elbow_girth", "wrist_girth"}));
    EXPECT_TRUE(has_note(inf.notes, "upper_arm_girth: library.sleeve;",
                         "(the underarm point; the body's level is "));

    tp::Pattern teagan = tp::read_pattern_file((dir / "teagan_cisFemaleAdult36.json").string());
    teagan.measurements_used.clear();
    const tg::BindingInference tshirt =
        tg::infer_girth_bindings(b->body, b->landmarks, b->measurements, teagan);
    bool wrist_note = false;
    for (const std::string& n : tshirt.notes) {
        wrist_note = wrist_note || n.rfind("wrist_girth: not bound (no sleeve reaches", 0) == 0;
    }
    EXPECT_TRUE(wrist_note);
}

// A pattern of sleeves alone, without seams, has no girth to bind: refused, saying what to give.
TEST(GarmentBindings, NoTorsoPieceIsRefused) {
    const MeasuredBody* b = nullptr;
    shirt_on_bundled_body(b);
    tp::Pattern sleeves =
        tp::read_pattern_file(bundled_path("patterns/shirt_mean_specification.json"));
    sleeves.pieces.erase(std::remove_if(sleeves.pieces.begin(), sleeves.pieces.end(),
                                        [](const tp::Piece& p) {
                                            return p.name.find("torso") != std::string::npos;
                                        }),
                         sleeves.pieces.end());
    sleeves.seams.clear();
    tapeline_test::expect_error<tapeline::InvalidInput>(
        [&] { tg::infer_girth_bindings(b->body, b->landmarks, b->measurements, sleeves); },
        {"no binding was found: give the bindings (--bindings)"}, "sleeves alone");
}

// A draft that declares the measurements it was drafted for (FreeSewing's `measurements`) is
// bound on those alone, each eased against its declared value, and its levels are where the
// declared lengths put them below the layout's top (each torso piece's highest point: the waist
// at the declared back length, the high hip the declared waist-to-hip length below it), not
// where this body (smaller than the draft's size) has them. Checked against FreeSewing's own
// drafted lines: aaron's hip line (cbHips–hips) and brian's wrist line (wristLeft–wristRight, at
// the sleeve's hem: the declared arm length reaches it).
TEST(GarmentBindings, DeclaredMeasurementsPutTheLevelsWhereTheDraftHasThem) {
    const auto [aaron_path, brian_path, teagan_path] = three_drafts();
    if (aaron_path.empty()) {
        GTEST_SKIP() << "the FreeSewing drafts of ../shared/data are absent";
    }
    const MeasuredBody* b = nullptr;
    shirt_on_bundled_body(b);
    const auto top_of = [](const tp::Piece& p) {
        double ymax = -1e300;
        for (const tp::Point2& q : tp::sample(p.outline, 0.05).points) {
            ymax = std::max(ymax, q.y);
        }
        return ymax;
    };
    const auto span = [](const tp::Piece& p, const std::string& a, const std::string& c) {
        const tp::Point2 u = p.points.at(a), v = p.points.at(c);
        return std::hypot(v.x - u.x, v.y - u.y);
    };
    for (const std::string& path : {aaron_path, brian_path, teagan_path}) {
        const tp::Pattern draft = tp::read_pattern_file(path);
        const tg::BindingInference inf =
            tg::infer_girth_bindings(b->body, b->landmarks, b->measurements, draft);
        for (const tp::MeasurementBinding& g : inf.pattern.bindings) {
            ASSERT_TRUE(draft.measurements_used.count(g.measurement))
                << draft.name << ": " << g.measurement << " is not declared";
        }
        EXPECT_TRUE(has_note(inf.notes, "underbust_girth: not bound (pattern '" + draft.name,
                             "declares the measurements it was drafted for"))
            << draft.name;
        EXPECT_TRUE(has_note(inf.notes, "levels: where the draft's declared lengths put them"));
    }
    // teagan: waist and hips, each eased against the declared value, on the declared levels.
    const tg::BindingInference teagan = tg::infer_girth_bindings(
        b->body, b->landmarks, b->measurements, tp::read_pattern_file(teagan_path));
    const auto& declared = teagan.pattern.measurements_used;
    for (const tp::MeasurementBinding& g : teagan.pattern.bindings) {
        if (!is_girth(g) || (g.measurement != "waist" && g.measurement != "hips")) {
            continue;
        }
        double garment = 0;
        for (const tp::BoundFeature& f : g.features) {
            const tp::Piece& p = *tp::find_piece(teagan.pattern, f.piece);
            const double below = declared.at("hpsToWaistBack") +
                                 (g.measurement == "hips" ? declared.at("waistToHips") : 0.0);
            EXPECT_NEAR(p.points.at(f.from_point).y, top_of(p) - below, 0.01) << f.piece;
            EXPECT_NEAR(p.points.at(f.to_point).y, top_of(p) - below, 0.01) << f.piece;
            garment += f.count * span(p, f.from_point, f.to_point);
        }
        EXPECT_NEAR(g.ease_mm, garment - declared.at(g.measurement), 1e-6) << g.measurement;
    }
    // aaron: the hip girth found equals FreeSewing's own hip line to 0.5 %.
    const tg::BindingInference aaron = tg::infer_girth_bindings(
        b->body, b->landmarks, b->measurements, tp::read_pattern_file(aaron_path));
    double found = 0, drafted = 0;
    for (const tp::MeasurementBinding& g : aaron.pattern.bindings) {
        if (g.measurement != "hips") {
            continue;
        }
        for (const tp::BoundFeature& f : g.features) {
            const tp::Piece& p = *tp::find_piece(aaron.pattern, f.piece);
            found += f.count * span(p, f.from_point, f.to_point);
            drafted += 2 * span(p, "cbHips", "hips");
        }
    }
    ASSERT_GT(drafted, 0);
    EXPECT_NEAR(found, drafted, 0.005 * drafted);
    // brian: the declared arm length puts the wrist on the sleeve's hem, where FreeSewing draws
    // its wrist line; the girth there is that line's length to 1 mm.
    const tg::BindingInference brian = tg::infer_girth_bindings(
        b->body, b->landmarks, b->measurements, tp::read_pattern_file(brian_path));
    bool wrist = false;
    for (const tp::MeasurementBinding& g : brian.pattern.bindings) {
        if (g.measurement != "wrist") {
            continue;
        }
        wrist = true;
        const tp::Piece& sleeve = *tp::find_piece(brian.pattern, g.features.front().piece);
        EXPECT_NEAR(span(sleeve, g.features.front().from_point, g.features.front().to_point),
                    span(sleeve, "wristLeft", "wristRight"), 1.0);
    }
    EXPECT_TRUE(wrist);
}

// The vertical lengths, one binding per piece: between two levels (aaron's waist to high hip:
// exactly the declared 130 mm, eased by 0), up the side seam from the waist to its top (ending
// on FreeSewing's own `armhole` point, the bottom of the armhole), from the top of the back
// at its centre line (FreeSewing's `cbNeck`) to the waist; down a sleeve that reaches the wrist
// from the top of its cap (brian: `sleeveTop` to `centerWrist`, the declared 600 mm); a short
// sleeve (teagan's) is not bound, saying how far above the wrist it ends.
TEST(GarmentBindings, LengthsRunBetweenTheLevelsAndEndOnFreeSewingsOwnPoints) {
    const auto [aaron_path, brian_path, teagan_path] = three_drafts();
    if (aaron_path.empty()) {
        GTEST_SKIP() << "the FreeSewing drafts of ../shared/data are absent";
    }
    const MeasuredBody* b = nullptr;
    shirt_on_bundled_body(b);
    const auto near = [](const tp::Point2& p, const tp::Point2& q, double tol) {
        return std::hypot(p.x - q.x, p.y - q.y) < tol;
    };
    const tg::BindingInference aaron = tg::infer_girth_bindings(
        b->body, b->landmarks, b->measurements, tp::read_pattern_file(aaron_path));
    std::map<std::string, int> count;
    for (const tp::MeasurementBinding& g : aaron.pattern.bindings) {
        if (is_girth(g)) {
            continue;
        }
        ASSERT_EQ(g.features.size(), 1u) << g.measurement;
        const tp::BoundFeature& f = g.features.front();
        // The shoulder width goes across both halves of the back.
        EXPECT_EQ(f.count, g.measurement == "shoulderToShoulder" ? 2.0 : 1.0);
        ++count[g.measurement];
        const tp::Piece& p = *tp::find_piece(aaron.pattern, f.piece);
        const tp::Point2 lo = p.points.at(f.from_point), hi = p.points.at(f.to_point);
        const double len = f.count * std::hypot(hi.x - lo.x, hi.y - lo.y);
        EXPECT_NEAR(g.ease_mm, len - aaron.pattern.measurements_used.at(g.measurement), 1e-6);
        if (g.measurement == "waistToHips") {
            EXPECT_NEAR(len, 130, 1e-6) << f.piece;
        } else if (g.measurement == "waistToArmpit") {
            EXPECT_TRUE(near(hi, p.points.at("armhole"), 0.01))
                << f.piece << ": " << hi.x << ", " << hi.y;
        } else if (g.measurement == "hpsToWaistBack") {
            EXPECT_EQ(f.piece, "aaron.back");
            EXPECT_TRUE(near(hi, p.points.at("cbNeck"), 1.5)) << hi.x << ", " << hi.y;
        }
    }
    EXPECT_EQ(count, (std::map<std::string, int>{{"hpsToWaistBack", 1},
                                                 {"shoulderToShoulder", 1},
                                                 {"waistToArmpit", 2},
                                                 {"waistToHips", 2}}));

    const tg::BindingInference brian = tg::infer_girth_bindings(
        b->body, b->landmarks, b->measurements, tp::read_pattern_file(brian_path));
    bool arm = false;
    for (const tp::MeasurementBinding& g : brian.pattern.bindings) {
        if (g.measurement != "shoulderToWrist") {
            continue;
        }
        arm = true;
        const tp::Piece& p = *tp::find_piece(brian.pattern, g.features.front().piece);
        const tp::Point2 top = p.points.at(g.features.front().from_point);
        const tp::Point2 end = p.points.at(g.features.front().to_point);
        // The line goes through the highest sample of the outline (0.25 mm apart); the cap's top
        // is flat to 0.04 mm over a millimetre either side of sleeveTop.
        EXPECT_TRUE(near(top, p.points.at("sleeveTop"), 1.0)) << top.x << ", " << top.y;
        EXPECT_TRUE(near(end, p.points.at("centerWrist"), 1.0)) << end.x << ", " << end.y;
        EXPECT_NEAR(g.ease_mm, 0, 0.1);
    }
    EXPECT_TRUE(arm);
    const tg::BindingInference teagan = tg::infer_girth_bindings(
        b->body, b->landmarks, b->measurements, tp::read_pattern_file(teagan_path));
    EXPECT_TRUE(has_note(teagan.notes, "shoulder_to_wrist: not bound (the sleeve ends ",
                         " mm above the wrist"));
}

// Where the garment's chest, biceps, neck and shoulder width are found, against FreeSewing's own
// points of brian (an independent naming of the same places): the chest 25 mm below the bottom of
// the armhole (its `armhole` point), as long as FreeSewing's chest line there (the side seam runs
// straight below the armhole); the biceps on the sleeve's underarm points (`bicepsLeft`,
// `bicepsRight`, where the cap begins); the neck on the neckline's edges, the chain FreeSewing's
// `neck` and `cbNeck`/`cfNeck` points bound; the shoulder width from `cbShoulder` to `shoulder` on
// the back, counted twice. Teagan's and aaron's scooped necklines are wider than the neck by more
// than a quarter: not bound, with the reason.
TEST(GarmentBindings, ChestBicepsNeckAndShoulderWidthWhereTheDraftHasThem) {
    const auto [aaron_path, brian_path, teagan_path] = three_drafts();
    if (aaron_path.empty()) {
        GTEST_SKIP() << "the FreeSewing drafts of ../shared/data are absent";
    }
    const MeasuredBody* b = nullptr;
    shirt_on_bundled_body(b);
    const auto dist = [](const tp::Point2& p, const tp::Point2& q) {
        return std::hypot(p.x - q.x, p.y - q.y);
    };
    const tg::BindingInference brian = tg::infer_girth_bindings(
        b->body, b->landmarks, b->measurements, tp::read_pattern_file(brian_path));
    std::map<std::string, int> seen;
    for (const tp::MeasurementBinding& g : brian.pattern.bindings) {
        ++seen[g.measurement];
        if (g.measurement == "chest") {
            double found = 0, drafted = 0;
            for (const tp::BoundFeature& f : g.features) {
                const tp::Piece& p = *tp::find_piece(brian.pattern, f.piece);
                const tp::Point2 u = p.points.at(f.from_point), v = p.points.at(f.to_point);
                EXPECT_NEAR(u.y, p.points.at("armhole").y - tg::kChestBelowArmhole, 0.01);
                EXPECT_NEAR(v.y, p.points.at("armhole").y - tg::kChestBelowArmhole, 0.01);
                found += f.count * dist(u, v);
                drafted += 2 * dist(p.points.at("cbChest"), p.points.at("chest"));
            }
            ASSERT_GT(drafted, 0);
            EXPECT_NEAR(found, drafted, 0.002 * drafted);
        } else if (g.measurement == "biceps") {
            ASSERT_EQ(g.features.size(), 1u);
            const tp::BoundFeature& f = g.features.front();
            const tp::Piece& p = *tp::find_piece(brian.pattern, f.piece);
            const tp::Point2 u = p.points.at(f.from_point), v = p.points.at(f.to_point);
            EXPECT_LT(std::abs(u.y - p.points.at("bicepsLeft").y), 1.5) << u.y;
            EXPECT_NEAR(dist(u, v), dist(p.points.at("bicepsLeft"), p.points.at("bicepsRight")),
                        1.5);
        } else if (g.measurement == "neck") {
            ASSERT_EQ(g.features.size(), 2u);
            for (const tp::BoundFeature& f : g.features) {
                const tp::Piece& p = *tp::find_piece(brian.pattern, f.piece);
                std::vector<std::size_t> chain =
                    tp::outline_chain(p.outline, p.points.at("neck"), p.points.at("cbNeck"));
                if (chain.empty()) {  // the front's centre is cfNeck (the table's order)
                    chain =
                        tp::outline_chain(p.outline, p.points.at("neck"), p.points.at("cfNeck"));
                }
                std::vector<std::size_t> edges = f.edges;
                std::sort(chain.begin(), chain.end());
                std::sort(edges.begin(), edges.end());
                EXPECT_FALSE(edges.empty());
                EXPECT_EQ(edges, chain) << f.piece;
                EXPECT_EQ(f.count, 2.0);
            }
        } else if (g.measurement == "shoulderToShoulder") {
            ASSERT_EQ(g.features.size(), 1u);
            const tp::BoundFeature& f = g.features.front();
            EXPECT_EQ(f.piece, "brian.back");
            EXPECT_EQ(f.count, 2.0);
            const tp::Piece& p = *tp::find_piece(brian.pattern, f.piece);
            EXPECT_LT(dist(p.points.at(f.from_point), p.points.at("cbShoulder")), 0.5);
            EXPECT_LT(dist(p.points.at(f.to_point), p.points.at("shoulder")), 0.5);
            EXPECT_NEAR(g.ease_mm,
                        2 * dist(p.points.at("cbShoulder"), p.points.at("shoulder")) -
                            brian.pattern.measurements_used.at("shoulderToShoulder"),
                        1.0);
        }
    }
    for (const char* m : {"chest", "biceps", "neck", "shoulderToShoulder"}) {
        EXPECT_EQ(seen[m], 1) << m;
    }
    for (const std::string& path : {aaron_path, teagan_path}) {
        const tg::BindingInference inf = tg::infer_girth_bindings(
            b->body, b->landmarks, b->measurements, tp::read_pattern_file(path));
        EXPECT_TRUE(has_note(inf.notes, "neck_girth: not bound (the neckline, ",
                             "a style line, not set by the neck"))
            << path;
        EXPECT_TRUE(has_note(inf.notes, "chest: ", "25 mm below the armhole")) << path;
    }
}

// FreeSewing's titan (trousers): its front and back are trouser legs (they carry the fork), placed
// on the right leg (their mirrored copies on the left), and bound from the body: the waist on its
// edges labelled as the waist, the seat across both pieces above the crotch, twice (once per leg),
// the knee round one leg below it, the waist to the knee and to the floor down each piece, the
// cross seam along the centre seams. FreeSewing's own points, which the inference does not read,
// are the check: the table's spans (grading/freesewing_bindings.h).
TEST(GarmentBindings, TrouserLegsBindTheirWaistSeatKneeAndLengthsFromTheBody) {
    const std::string titan_path = freesewing("titan_cisFemaleAdult36");
    if (titan_path.empty()) {
        GTEST_SKIP() << "the FreeSewing drafts of ../shared/data are absent";
    }
    const MeasuredBody* b = nullptr;
    shirt_on_bundled_body(b);
    const tp::Pattern titan = tp::read_pattern_file(titan_path);
    for (const tp::Piece& p : titan.pieces) {
        std::string why;
        const auto r = tg::piece_region(p, why);
        ASSERT_TRUE(r.has_value()) << p.name << ": " << why;
        EXPECT_EQ(
            *r, p.name == "titan.front" ? tg::Region::leg_right_front : tg::Region::leg_right_back)
            << p.name;
        tp::Piece copy = p;
        copy.name += " (mirror)";
        EXPECT_EQ(*tg::piece_region(copy, why),
                  p.name == "titan.front" ? tg::Region::leg_left_front : tg::Region::leg_left_back)
            << copy.name;
    }
    const tg::BindingInference inf =
        tg::infer_girth_bindings(b->body, b->landmarks, b->measurements, titan);
    const auto span = [&](const std::string& piece, const char* from, const char* to) {
        const tp::Piece& p = *tp::find_piece(titan, piece);
        return span_mm(p.points.at(from), p.points.at(to));
    };
    const auto bound_span = [&](const tp::BoundFeature& f) {
        const tp::Piece& p = *tp::find_piece(inf.pattern, f.piece);
        return span_mm(p.points.at(f.from_point), p.points.at(f.to_point));
    };
    const auto edges_length = [&](const tp::BoundFeature& f) {
        double len = 0;
        for (const std::size_t e : f.edges) {
            len += tp::length(tp::find_piece(titan, f.piece)->outline.edges[e]);
        }
        return len;
    };
    const auto declared = [&](const char* m) { return titan.measurements_used.at(m); };
    std::map<std::string, int> seen;
    for (const tp::MeasurementBinding& g : inf.pattern.bindings) {
        ++seen[g.measurement];
        if (g.measurement == "waist") {
            // The labelled edges are the straight styleWaistIn–styleWaistOut of each piece.
            double garment = 0, table = 0;
            ASSERT_EQ(g.features.size(), 2u);
            for (const tp::BoundFeature& f : g.features) {
                EXPECT_EQ(f.count, 2.0) << f.piece;
                garment += f.count * edges_length(f);
                table += 2 * span(f.piece, "styleWaistIn", "styleWaistOut");
            }
            EXPECT_NEAR(garment, table, 0.5);
            EXPECT_NEAR(g.ease_mm, garment - declared("waist"), 1e-6);
        } else if (g.measurement == "seat" || g.measurement == "knee") {
            // The seat across front and back, twice (once per leg), 260 mm (the declared waist to
            // seat) below the top of each piece (its style waist); the knee round one leg, once
            // each, 623 mm (the declared waist to knee) below it. The points lie on the outline
            // where that level crosses it (the draft's own knee points are construction points
            // inside the curved leg: the outline is wider there): the seat within 6 % of the
            // draft's seat line, the knee no narrower than the draft's knee line.
            const bool seat = g.measurement == "seat";
            const double depth = declared(seat ? "waistToSeat" : "waistToKnee");
            ASSERT_EQ(g.features.size(), 2u);
            double garment = 0, table = 0;
            for (const tp::BoundFeature& f : g.features) {
                EXPECT_EQ(f.count, seat ? 2.0 : 1.0) << f.piece;
                const tp::Piece& p = *tp::find_piece(inf.pattern, f.piece);
                const tp::OutlinePolyline line = tp::sample(p.outline, 0.02);
                double top = -1e300;
                for (const tp::Point2& q : line.points) {
                    top = std::max(top, q.y);
                }
                const double y = top - depth;
                // The outline's crossings with the level, found here on a fine polyline.
                double xmin = 1e300, xmax = -1e300;
                for (std::size_t k = 0; k + 1 < line.points.size(); ++k) {
                    const tp::Point2 a = line.points[k], c = line.points[k + 1];
                    if ((a.y - y) * (c.y - y) <= 0 && a.y != c.y) {
                        const double x = a.x + (y - a.y) / (c.y - a.y) * (c.x - a.x);
                        xmin = std::min(xmin, x);
                        xmax = std::max(xmax, x);
                    }
                }
                const tp::Point2 pa = p.points.at(f.from_point), pb = p.points.at(f.to_point);
                EXPECT_NEAR(pa.y, y, 0.5) << g.measurement << " " << f.piece;
                EXPECT_NEAR(pb.y, y, 0.5) << g.measurement << " " << f.piece;
                EXPECT_NEAR(std::min(pa.x, pb.x), xmin, 0.5) << g.measurement << " " << f.piece;
                EXPECT_NEAR(std::max(pa.x, pb.x), xmax, 0.5) << g.measurement << " " << f.piece;
                garment += f.count * bound_span(f);
                table +=
                    f.count *
                    (seat ? span(f.piece, f.piece == "titan.front" ? "cfSeat" : "cbSeat", "seatOut")
                          : span(f.piece, "kneeIn", "kneeOut"));
            }
            if (seat) {
                EXPECT_NEAR(garment, table, 0.06 * table);
            } else {
                EXPECT_GE(garment, table);
                EXPECT_LE(garment, 1.15 * table);
            }
            EXPECT_NEAR(g.ease_mm, garment - declared(g.measurement.c_str()), 1e-6);
        } else if (g.measurement == "waistToKnee" || g.measurement == "waistToFloor") {
            ASSERT_EQ(g.features.size(), 1u);
            const tp::BoundFeature& f = g.features.front();
            const double len = bound_span(f);
            const double table =
                span(f.piece, "waistX", g.measurement == "waistToKnee" ? "knee" : "floor");
            EXPECT_NEAR(len, table, 15) << g.measurement << " " << f.piece;
            EXPECT_NEAR(g.ease_mm, len - declared(g.measurement.c_str()), 1e-6);
        } else if (g.measurement == "crossSeam") {
            // The centre seams from the style waist to the fork, front and back.
            ASSERT_EQ(g.features.size(), 2u);
            double garment = 0;
            for (const tp::BoundFeature& f : g.features) {
                const tp::Piece& p = *tp::find_piece(titan, f.piece);
                std::vector<std::size_t> chain =
                    tp::outline_chain(p.outline, p.points.at("styleWaistIn"), p.points.at("fork"));
                std::vector<std::size_t> edges = f.edges;
                std::sort(chain.begin(), chain.end());
                std::sort(edges.begin(), edges.end());
                EXPECT_EQ(edges, chain) << f.piece;
                garment += edges_length(f);
            }
            EXPECT_NEAR(g.ease_mm, garment - declared("crossSeam"), 1e-6);
        } else {
            ADD_FAILURE() << "unexpected binding " << g.measurement;
        }
    }
    EXPECT_EQ(seen["waist"], 1);
    EXPECT_EQ(seen["seat"], 1);
    EXPECT_EQ(seen["knee"], 1);
    EXPECT_EQ(seen["waistToKnee"], 2);  // one per piece
    EXPECT_EQ(seen["waistToFloor"], 2);
    EXPECT_EQ(seen["crossSeam"], 1);
    // Titan declares no thigh girth (upperLeg) and no high hip girth (hips).
    EXPECT_TRUE(has_note(inf.notes, "thigh_girth (trouser legs): not bound (pattern ",
                         "declares the measurements it was drafted for"));
}

// GarmentCode's jumpsuit: its four pant panels hang below a bodice that binds the waist. The hip
// cuts all four above their crotch (the lowest point of the seams joining the legs), the knee the
// two panels of the body's left leg, each once; the body's thigh level lies above the jumpsuit's
// low crotch, where the garment is still round the seat: no thigh; the cross seam follows that
// leg's centre seams; no length runs from the legs' top, which is not the waist. The check is the
// panels' own 3-D placement, which the inference uses only through the layout: every girth's
// points lie in one horizontal plane, at the body's distances apart.
TEST(GarmentBindings, JumpsuitLegsBindTheHipAboveTheCrotchAndTheKneeRoundOneLeg) {
    const std::filesystem::path path = std::filesystem::path(TAPELINE_SHARED_DATA_DIR) /
                                       "patterns" / "garmentcode" /
                                       "js_mean_all_specification.json";
    if (!std::filesystem::exists(path)) {
        GTEST_SKIP() << path << " is absent";
    }
    const MeasuredBody* b = nullptr;
    shirt_on_bundled_body(b);
    const tp::Pattern jumpsuit = tp::read_pattern_file(path.string());
    const tg::BindingInference inf =
        tg::infer_girth_bindings(b->body, b->landmarks, b->measurements, jumpsuit);
    std::map<std::string, double> level;  // the placed height of each leg girth's points
    for (const tp::MeasurementBinding& g : inf.pattern.bindings) {
        const bool hip = g.measurement == "hip_girth";
        EXPECT_NE(g.measurement, "thigh_girth");
        if (!hip && g.measurement != "knee_girth") {
            EXPECT_NE(g.measurement, "waist_to_knee");
            if (g.measurement == "cross_seam") {
                ASSERT_EQ(g.features.size(), 2u);
                for (const tp::BoundFeature& f : g.features) {
                    EXPECT_EQ(f.piece.substr(f.piece.size() - 2), "_l") << f.piece;
                    EXPECT_FALSE(f.edges.empty());
                }
            }
            continue;
        }
        ASSERT_EQ(g.features.size(), hip ? 4u : 2u) << g.measurement;
        double garment = 0, y0 = 0;
        int n = 0;
        for (const tp::BoundFeature& f : g.features) {
            EXPECT_EQ(f.piece.rfind("pant_", 0), 0u) << g.measurement << " " << f.piece;
            if (!hip) {
                EXPECT_EQ(f.piece.substr(f.piece.size() - 2), "_l") << f.piece;
            }
            EXPECT_EQ(f.count, 1.0);
            const tp::Piece& p = *tp::find_piece(inf.pattern, f.piece);
            ASSERT_TRUE(p.placement.has_value()) << f.piece;
            for (const std::string* name : {&f.from_point, &f.to_point}) {
                const double y = tp::placed_point(*p.placement, p.points.at(*name))[1];
                if (n++ == 0) {
                    y0 = y;
                }
                EXPECT_NEAR(y, y0, 0.5) << g.measurement << " " << f.piece;
            }
            garment += span_mm(p.points.at(f.from_point), p.points.at(f.to_point));
        }
        level[g.measurement] = y0;
        // Round the body or the leg: no smaller than the body (a loose jumpsuit).
        EXPECT_GE(garment, b->measurements.find(g.measurement)->value) << g.measurement;
    }
    ASSERT_EQ(level.size(), 2u);
    const auto body_y = [&](const char* m) { return b->measurements.find(m)->plane_point[1]; };
    EXPECT_NEAR(level["hip_girth"] - level["knee_girth"],
                body_y("hip_girth") - body_y("knee_girth"), 1.0);
    EXPECT_TRUE(has_note(inf.notes,
                         "thigh_girth (trouser legs): not bound (no leg piece reaches "
                         "it below the crotch"));
    EXPECT_TRUE(has_note(inf.notes, "waist_to_knee (trouser legs): not bound (the legs are sewn"));
}

// Pieces that are too narrow to go round the body at a level (aaron's halves made half as wide)
// make no girth there, saying so.
TEST(GarmentBindings, PiecesTooNarrowForTheBodyMakeNoGirth) {
    const std::string aaron_path = freesewing("aaron_cisFemaleAdult36");
    if (aaron_path.empty()) {
        GTEST_SKIP() << "the FreeSewing drafts of ../shared/data are absent";
    }
    const MeasuredBody* b = nullptr;
    shirt_on_bundled_body(b);
    tp::Pattern narrow = tp::read_pattern_file(aaron_path);
    for (tp::Piece& p : narrow.pieces) {
        const double xf = p.fold ? p.fold->line.a.x : 0;
        const auto squeeze = [xf](tp::Point2& q) { q.x = xf + 0.5 * (q.x - xf); };
        for (tp::Edge& e : p.outline.edges) {
            std::visit(
                [&](auto& c) {
                    using C = std::decay_t<decltype(c)>;
                    if constexpr (std::is_same_v<C, tp::CubicBezier>) {
                        for (tp::Point2* q : {&c.p0, &c.p1, &c.p2, &c.p3}) {
                            squeeze(*q);
                        }
                    } else {
                        squeeze(c.a);
                        squeeze(c.b);
                    }
                },
                e.curve);
        }
        if (p.fold) {
            squeeze(p.fold->line.a);
            squeeze(p.fold->line.b);
        }
    }
    const tg::BindingInference inf =
        tg::infer_girth_bindings(b->body, b->landmarks, b->measurements, narrow);
    EXPECT_TRUE(has_note(inf.notes, "high_hip_girth: not bound (at ",
                         "mm: they do not go round the body there)"));
    for (const tp::MeasurementBinding& g : inf.pattern.bindings) {
        EXPECT_FALSE(is_girth(g)) << g.measurement;
    }
}
