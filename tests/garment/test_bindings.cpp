// Girth bindings found by laying a pattern on a body (garment/bindings.h): checked against the
// garment placed on the same body by dressing (an independent route: the 3D cloth cut by the
// girth's plane), against FreeSewing's own naming, and on the refusals.
#include <tapeline/garment/bindings.h>
#include <tapeline/garment/dress.h>
#include <tapeline/pattern/io_detect.h>
#include <tapeline/pattern/io_json.h>
#include <tapeline_test/expect.h>
#include <tapeline_test/measured_body.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
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
        bound.push_back(g.measurement);
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
    EXPECT_EQ(bound, (std::vector<std::string>{"bust_girth", "underbust_girth", "waist_girth",
                                               "high_hip_girth"}));
    bool hip_note = false;
    for (const std::string& n : inf.notes) {
        hip_note = hip_note || (n.rfind("hip_girth: not bound (no torso or skirt piece", 0) == 0);
    }
    EXPECT_TRUE(hip_note);
}

// FreeSewing's aaron (a tank top, half pieces cut on the fold): spans count twice, bindings take
// the pattern's own FreeSewing names where it uses them (hips), and a level that cuts the
// armhole (sewn to the armhole binding, not to a torso piece) is not a girth of the garment.
TEST(GarmentBindings, TankTopHalvesCountTwiceAndAnOpenLevelIsNoGirth) {
    const MeasuredBody* b = nullptr;
    shirt_on_bundled_body(b);
    const tg::BindingInference inf = tg::infer_girth_bindings(
        b->body, b->landmarks, b->measurements,
        tp::read_pattern_file(bundled_path("patterns/aaron_cisFemaleAdult36.json")));
    bool hips = false, armhole = false, strips = false;
    for (const tp::MeasurementBinding& g : inf.pattern.bindings) {
        hips = hips || g.measurement == "hips";
        for (const tp::BoundFeature& f : g.features) {
            EXPECT_EQ(f.count, 2.0) << g.measurement << " on " << f.piece;
        }
    }
    for (const std::string& n : inf.notes) {
        armhole = armhole || (n.rfind("bust_girth: not bound", 0) == 0 &&
                              n.find("aaron.front edge") != std::string::npos);
        strips = strips || n.rfind("piece aaron.armBinding: in no girth", 0) == 0;
    }
    EXPECT_TRUE(hips);
    EXPECT_TRUE(armhole);
    EXPECT_TRUE(strips);
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
}

// A pattern of sleeves alone has no girth to bind: refused, saying what to give.
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
