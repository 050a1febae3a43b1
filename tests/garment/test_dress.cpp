// Dressing real bodies: placement invariants (no cloth inside the body, no two pieces crossing)
// on the bundled body and on population bodies the placement was not developed on, the whole
// chain on the bundled body (seams closed, openings as the garment has, no penetration), and the
// refusals of dress().
#include <tapeline/garment/dress.h>
#include <tapeline/pattern/io_detect.h>
#include <tapeline_test/measured_body.h>

#include <tapeline_test/expect.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <map>
#include <string>
#include <vector>

namespace tg = tapeline::garment;
namespace tmeas = tapeline::measurement;
namespace tp = tapeline::pattern;

namespace {

using tapeline_test::message_of;

using tapeline_test::measurement::bundled_path;
using tapeline_test::measurement::load_dm_body;
using tapeline_test::measurement::MeasuredBody;

}  // namespace

// A bent arm made of two round tubes (upper arm radius 40 mm, 300 mm long; forearm radius 30 mm
// bent 50° away from it): the axis a short sleeve is wrapped round follows the upper arm (the
// straight line from the shoulder to the wrist misses the elbow by centimetres), passes through
// the shoulder joint and gives the upper arm's radius; a sleeve as long as the whole arm gets a
// line between the two tubes' directions.
TEST(GarmentPlacement, ArmAxisFollowsTheUpperArmOfABentArm) {
    using tapeline::vec3::add;
    using tapeline::vec3::cross;
    using tapeline::vec3::dot;
    using tapeline::vec3::norm;
    using tapeline::vec3::normalized;
    using tapeline::vec3::scale;
    using tapeline::vec3::sub;
    const tg::Vec3 shoulder{200, 1300, 0};
    const tg::Vec3 u = normalized(tg::Vec3{1, -1.5, 0});
    const tg::Vec3 w = normalized(tg::Vec3{0.2, -1, 0.9});
    const double r_upper = 40, r_fore = 30, l_upper = 300, l_fore = 250;
    const tg::Vec3 elbow = add(shoulder, scale(u, l_upper));
    const tg::Vec3 wrist = add(elbow, scale(w, l_fore));
    tg::BodyShape b;
    const auto tube = [&](const tg::Vec3& from, const tg::Vec3& dir, double len, double r) {
        tg::Vec3 n1 = normalized(cross(dir, tg::Vec3{0, 0, 1}));
        if (norm(cross(dir, tg::Vec3{0, 0, 1})) < 0.1) {
            n1 = normalized(cross(dir, tg::Vec3{1, 0, 0}));
        }
        const tg::Vec3 n2 = cross(dir, n1);
        for (double t = 0; t <= len; t += 5) {
            for (int k = 0; k < 36; ++k) {
                const double a = 2 * M_PI * k / 36;
                b.points.push_back(add(add(from, scale(dir, t)), add(scale(n1, r * std::cos(a)),
                                                                     scale(n2, r * std::sin(a)))));
            }
        }
    };
    tube(shoulder, u, l_upper, r_upper);
    tube(elbow, w, l_fore, r_fore);
    b.is_arm.assign(b.points.size(), 1);
    b.shoulder[0] = shoulder;
    b.wrist[0] = wrist;
    const double angle_naive = std::acos(dot(normalized(sub(wrist, shoulder)), u)) * 180 / M_PI;
    ASSERT_GT(angle_naive, 15) << "the test needs an arm whose wrist is off the upper arm's line";
    const tg::ArmAxis a = tg::fit_arm_axis(b, 0, 200);
    EXPECT_LT(std::acos(std::min(1.0, dot(a.direction, u))) * 180 / M_PI, 2.0);
    // The fitted line passes (nearly) through the shoulder joint, and `start` is on it.
    const tg::Vec3 q = sub(shoulder, a.start);
    EXPECT_LT(norm(sub(q, scale(a.direction, dot(q, a.direction)))), 3.0);
    EXPECT_NEAR(a.radius, r_upper, 1.5);
    EXPECT_GT(a.length, 0.9 * norm(sub(wrist, shoulder)));
    // The whole arm: the direction lies between the upper arm's and the forearm's.
    const tg::ArmAxis whole = tg::fit_arm_axis(b, 0, l_upper + l_fore);
    EXPECT_GT(dot(whole.direction, u), dot(w, u));
    EXPECT_GT(dot(whole.direction, w), dot(w, u));
}

// The whole chain on the bundled body in the bundled GarmentCode shirt: the placement leaves no
// cloth inside the body, the run ends without a solver failure, every seam is closable and the
// welded garment's openings are its neck, hem and two cuffs.
// Three triangles of a 2 × 1 strip over the vertices 0-1-2 (bottom) and 3-4-5 (top): (0, 1, 4),
// (0, 4, 3), (1, 2, 5). A pair sewn shut inside one piece (as at a dart's tip) welds 1 to 4:
// triangle (0, 1, 4) collapses and is left out; the weld class sits at its members' mean and the
// kept triangles keep their pattern coordinates, grain and piece.
TEST(Dress, WeldedGarmentLeavesOutTrianglesTheSeamsCollapse) {
    tg::ClothModel c;
    c.positions = {{0, 0, 0}, {10, 0, 0}, {20, 0, 0}, {0, 10, 0}, {10, 10, 0}, {20, 10, 0}};
    c.triangles = {{0, 1, 4}, {0, 4, 3}, {1, 2, 5}};
    c.rest_uv = {{tg::UV{0, 0}, tg::UV{10, 0}, tg::UV{10, 10}},
                 {tg::UV{0, 0}, tg::UV{10, 10}, tg::UV{0, 10}},
                 {tg::UV{10, 0}, tg::UV{20, 0}, tg::UV{20, 10}}};
    c.grain = {tg::UV{0, 1}, tg::UV{1, 0}, tg::UV{0, -1}};
    const std::vector<std::uint32_t> piece = {7, 8, 9};
    const tg::Welding w = tg::weld_pairs(6, {{1, 4, 0, 0}});
    const tg::GarmentMesh g = tg::internal::welded_garment(c, c.positions, w, piece);
    ASSERT_EQ(g.positions.size(), 5u);
    ASSERT_EQ(g.triangles.size(), 2u);
    EXPECT_EQ(g.triangle_piece, (std::vector<std::uint32_t>{8, 9}));
    EXPECT_EQ(g.grain[0], (tg::UV{1, 0}));
    EXPECT_EQ(g.grain[1], (tg::UV{0, -1}));
    EXPECT_EQ(g.uv[0][1], (tg::UV{10, 10}));
    EXPECT_EQ(g.uv[1][1], (tg::UV{20, 0}));
    for (const tg::Tri& t : g.triangles) {
        EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    }
    EXPECT_EQ(g.positions[w.weld_map[0]], (tg::Vec3{0, 0, 0}));
    EXPECT_EQ(g.positions[w.weld_map[4]], (tg::Vec3{10, 5, 0}));
}

TEST(Dress, ShirtOnTheBundledBody) {
    const MeasuredBody b = load_dm_body(bundled_path("bodies/mh_female_average.obj"));
    const tp::Pattern shirt =
        tp::read_pattern_file(bundled_path("patterns/shirt_mean_specification.json"));
    tg::DressOptions o;
    o.resolution_mm = 20;  // coarse: a unit test, not the benchmark
    const tg::DressResult r = tg::dress(b.body, b.landmarks, shirt, o);
    const tg::DressReport& rep = r.report;
    EXPECT_EQ(rep.placement_vertices_inside, 0u);
    EXPECT_EQ(rep.boundary_loops, 4u) << "a shirt has a neck, a hem and two cuffs";
    // The openings, lowest first: the hem's rim lies about horizontal and outside the body, the
    // hull of its projection is no longer than the rim, and the neckline is the highest.
    ASSERT_EQ(rep.openings.size(), rep.boundary_loops);
    for (std::size_t k = 1; k < rep.openings.size(); ++k) {
        EXPECT_LE(rep.openings[k - 1].height_mm, rep.openings[k].height_mm);
    }
    const tg::Opening& hem = rep.openings.front();
    EXPECT_GT(hem.normal[1], 0.9);
    EXPECT_GT(hem.clearance_mean_mm, 0);
    EXPECT_LE(hem.hull_perimeter_mm, hem.length_mm + 1e-9);
    // Width and depth: the rim's extents across (x) and front to back (z), recomputed here. (A
    // loose hem is about round: 297 mm wide and 299 mm deep here, so its shape says nothing of the
    // body's.)
    double lo[2] = {1e300, 1e300}, hi[2] = {-1e300, -1e300};
    for (const auto& p : hem.points) {
        for (int k = 0; k < 2; ++k) {
            lo[k] = std::min(lo[k], p[2 * k]);
            hi[k] = std::max(hi[k], p[2 * k]);
        }
    }
    EXPECT_NEAR(hem.width_mm, hi[0] - lo[0], 1e-9);
    EXPECT_NEAR(hem.depth_mm, hi[1] - lo[1], 1e-9);
    EXPECT_GT(hem.depth_mm, 200) << "a hem round a woman's torso";
    for (std::size_t i = 0; i < hem.loop.size(); ++i) {
        EXPECT_EQ(hem.points[i], r.garment.positions[hem.loop[i]]);
    }
    ASSERT_NE(b.landmarks.find("bust_left"), nullptr);
    EXPECT_GT(rep.openings.back().height_mm, b.landmarks.find("bust_left")->point[1]);
    EXPECT_EQ(rep.pieces.size(), 8u);
    for (const tg::SeamReport& s : rep.seams) {
        EXPECT_TRUE(s.closable) << s.name << ": " << s.problem;
        EXPECT_GT(s.pairs, 0u) << s.name;
    }
    // Pairs the sewing closed were welded before the drape: they end exactly together, and a
    // seam whose pairs all were welded reports no gap.
    EXPECT_GT(rep.pairs_welded_before_drape, 0u);
    EXPECT_LE(rep.pairs_welded_before_drape, r.sewing.pairs.size());
    std::size_t together = 0;
    for (const tg::Stitch& s : r.sewing.pairs) {
        together += r.draped[s.a] == r.draped[s.b] ? 1 : 0;
    }
    EXPECT_GE(together, rep.pairs_welded_before_drape);
    // The welded garment has no triangle two of whose corners the weld merged, and each kept
    // triangle has its pattern coordinates and piece.
    ASSERT_EQ(r.garment.uv.size(), r.garment.triangles.size());
    ASSERT_EQ(r.garment.triangle_piece.size(), r.garment.triangles.size());
    ASSERT_EQ(r.stretch.size(), r.garment.triangles.size());
    for (const tg::Tri& t : r.garment.triangles) {
        EXPECT_TRUE(t[0] != t[1] && t[1] != t[2] && t[0] != t[2]);
    }
    // At 20 mm the shirt passes every gate on this body (docs/garment.md): the drape leaves
    // fold-overs (cloth compressed under the arms), flattened before and after the static solve;
    // the quality report counts none left with its own exact test.
    ASSERT_EQ(rep.gates.size(), 7u);
    for (const tg::Gate& g : rep.gates) {
        EXPECT_TRUE(std::isfinite(g.value)) << g.name;
        EXPECT_TRUE(g.passed) << g.name << " " << g.value << " (limit " << g.limit << ")";
    }
    ASSERT_FALSE(rep.folds.empty());
    EXPECT_GT(rep.folds.front().crossings_before, 0u);
    EXPECT_EQ(rep.folds.back().crossings_after, 0u);
    EXPECT_EQ(rep.quality.self_intersections, 0u);
    EXPECT_GE(rep.relax_runs, 1);
    EXPECT_LE(rep.relax_runs, o.fold_cycles);
    // Every solve is reported; the last is the one the report's summary gives, and each ends
    // within its options' iteration limit for a reason it names.
    ASSERT_EQ(rep.relax_solves.size(), std::size_t(rep.relax_runs));
    EXPECT_EQ(rep.relax_solves.back().iterations, rep.relax.iterations);
    EXPECT_EQ(rep.relax_solves.back().stop, rep.relax.stop);
    for (std::size_t k = 0; k < rep.relax_solves.size(); ++k) {
        const tg::RelaxOptions& ro = k == 0 ? o.relax_options : o.relax_again_options;
        EXPECT_LE(rep.relax_solves[k].iterations, ro.max_iterations) << k;
        EXPECT_TRUE(
            rep.relax_solves[k].stop == "converged" || rep.relax_solves[k].stop == "settled" ||
            rep.relax_solves[k].stop == "stalled" || rep.relax_solves[k].stop == "iterations")
            << k << " " << rep.relax_solves[k].stop;
    }
    // The shirt hangs from the shoulders: its top came down from the placement (placed a gap
    // above the skin), by less than the gate's limit, and the gate reads that figure.
    EXPECT_GT(rep.quality.top_drop_mm, 0);
    EXPECT_LT(rep.quality.top_drop_mm, tg::kMaxTopDropMm);
    double placed_top = -1e300, draped_top = -1e300;
    for (std::size_t v = 0; v < r.placed.size(); ++v) {
        placed_top = std::max(placed_top, r.placed[v][1]);
        draped_top = std::max(draped_top, r.draped[v][1]);
    }
    EXPECT_DOUBLE_EQ(rep.quality.top_drop_mm, placed_top - draped_top);
    EXPECT_EQ(rep.gates.back().name, "top_drop_mm");
    EXPECT_TRUE(rep.gates.back().passed);
}

// A vertex sewn in several pairs (a corner) is pulled to the mean of its strings' targets; on a
// heavy, muscular body that mean lay inside the neck and shoulders, the pull and the body's push
// fought, and the sewing blew up (SolverFailure at frame 17, a vertex faster than 200 m/s). The
// target is now lifted out of the body: the run ends, nothing inside the body, the garment on it.
TEST(Dress, ShirtOnAHeavyMuscularBodySewsWithoutBlowingUp) {
    const std::filesystem::path file =
        std::filesystem::path(TAPELINE_SHARED_DATA_DIR) / "bodies" / "mh_male_muscular_heavy.obj";
    if (!std::filesystem::exists(file)) {
        GTEST_SKIP() << file << " is absent";
    }
    const MeasuredBody b = load_dm_body(file.string());
    const tp::Pattern shirt =
        tp::read_pattern_file(bundled_path("patterns/shirt_mean_specification.json"));
    tg::DressOptions o;
    o.resolution_mm = 20;
    tg::DressResult r;
    ASSERT_NO_THROW(r = tg::dress(b.body, b.landmarks, shirt, o));
    EXPECT_EQ(r.report.quality.vertices_inside_body, 0u);
    EXPECT_LT(r.report.quality.top_drop_mm, tg::kMaxTopDropMm);
    EXPECT_EQ(r.report.boundary_loops, 4u);
}

// A garment that slid down or fell off the body fails the top-drop gate whatever the other
// figures say (at 10 mm and 10 sub-steps the GarmentCode shirt ends below the feet, its top
// about 1360 mm below the placement, and only this gate says it plainly).
TEST(Dress, AGarmentThatFellOffFailsTheTopDropGate) {
    tg::QualityFigures q;
    q.top_drop_mm = 1359;
    const std::vector<tg::Gate> gates = tg::quality_gates(q);
    std::size_t failed = 0;
    for (const tg::Gate& g : gates) {
        failed += g.passed ? 0 : 1;
        if (g.name == "top_drop_mm") {
            EXPECT_FALSE(g.passed);
            EXPECT_EQ(g.value, 1359);
            EXPECT_EQ(g.limit, tg::kMaxTopDropMm);
        }
    }
    EXPECT_EQ(failed, 1u) << "every other figure is at its ideal value";
    q.top_drop_mm = tg::kMaxTopDropMm;
    for (const tg::Gate& g : tg::quality_gates(q)) {
        EXPECT_TRUE(g.passed) << g.name;
    }
}

// The quality gates of the issue on the bundled body at the 10 mm. Not reached yet
// (docs/garment.md lists the current figures); run it with --gtest_also_run_disabled_tests.
TEST(Dress, DISABLED_ShirtPassesTheQualityGates) {
    const MeasuredBody b = load_dm_body(bundled_path("bodies/mh_female_average.obj"));
    const tp::Pattern shirt =
        tp::read_pattern_file(bundled_path("patterns/shirt_mean_specification.json"));
    tg::DressOptions o;
    const tg::DressResult r = tg::dress(b.body, b.landmarks, shirt, o);
    for (const tg::Gate& g : r.report.gates) {
        EXPECT_TRUE(g.passed) << g.name << " " << g.value << " (limit " << g.limit << ")";
    }
}

// The shirt placed (no sewing, no drape) on population bodies, other shapes and sizes than the
// bundled body; `check` is called with each body's name and report. Skips when the population is
// absent.
void place_on_population(const std::function<void(const char*, const tg::DressReport&)>& check) {
    const std::filesystem::path dir =
        std::filesystem::path(TAPELINE_SHARED_DATA_DIR) / "bodies" / "population";
    if (!std::filesystem::is_directory(dir)) {
        GTEST_SKIP() << dir << " is absent";
    }
    const tp::Pattern shirt =
        tp::read_pattern_file(bundled_path("patterns/shirt_mean_specification.json"));
    for (const char* name : {"mh_pop_003.ply", "mh_pop_012.ply", "mh_pop_021.ply"}) {
        const MeasuredBody b = load_dm_body((dir / name).string());
        tg::DressOptions o;
        o.resolution_mm = 25;
        o.sewing.sew_seconds = 0;  // placement and strings only
        o.sewing.settle_seconds = 0;
        o.sewing.max_extra_seconds = 0;
        check(name, tg::dress(b.body, b.landmarks, shirt, o).report);
    }
}

// No cloth vertex inside the body after placement.
TEST(Dress, PlacementHoldsOnPopulationBodies) {
    place_on_population([](const char* name, const tg::DressReport& r) {
        EXPECT_EQ(r.placement_vertices_inside, 0u) << name;
    });
}

// No two placed pieces cross (nor touch: the halves of a sleeve meet a layer gap apart).
TEST(Dress, PlacedPiecesDoNotCross) {
    place_on_population([](const char* name, const tg::DressReport& r) {
        EXPECT_EQ(r.placement_piece_intersections, 0u) << name;
        EXPECT_EQ(r.quality.self_intersections, 0u) << name;  // nor a piece itself
    });
}

// FreeSewing's T-shirt drafts its sleeve once: dressing pairs it with a mirrored copy, splits the
// sleeve cap between the front and back armholes, and places each sleeve on its own arm (the
// original on the body's left, +x, where the original halves of the folded front and back go),
// the cap's front part towards the front of the arm. Placement only; on the bundled body and on
// a population body.
TEST(Dress, TShirtSleevesArePairedAndPlacedOnTheirArms) {
    const std::filesystem::path file = std::filesystem::path(TAPELINE_SHARED_DATA_DIR) /
                                       "patterns" / "freesewing" / "teagan_cisFemaleAdult36.json";
    const std::filesystem::path pop = std::filesystem::path(TAPELINE_SHARED_DATA_DIR) / "bodies" /
                                      "population" / "mh_pop_007.ply";
    if (!std::filesystem::exists(file)) {
        GTEST_SKIP() << file << " is absent";
    }
    const tp::Pattern tshirt = tp::read_pattern_file(file.string());
    std::vector<std::string> bodies = {bundled_path("bodies/mh_female_average.obj")};
    if (std::filesystem::exists(pop)) {
        bodies.push_back(pop.string());
    }
    for (const std::string& path : bodies) {
        SCOPED_TRACE(path);
        const MeasuredBody b = load_dm_body(path);
        tg::DressOptions o;
        o.resolution_mm = 25;
        o.sewing.sew_seconds = 0;  // placement and strings only
        o.sewing.settle_seconds = 0;
        o.sewing.max_extra_seconds = 0;
        const tg::DressResult r = tg::dress(b.body, b.landmarks, tshirt, o);
        const tg::DressReport& rep = r.report;
        EXPECT_EQ(rep.placement_vertices_inside, 0u);
        ASSERT_EQ(rep.pieces.size(), 4u);
        std::map<std::string, std::pair<std::size_t, std::size_t>> range;  // piece → vertices
        std::size_t at = 0;
        for (const tg::PieceReport& p : rep.pieces) {
            range[p.name] = {at, at + p.vertices};
            at += p.vertices;
        }
        EXPECT_EQ(rep.pieces[2].name, "teagan.sleeve");
        EXPECT_EQ(rep.pieces[2].region, "sleeve_left");
        EXPECT_EQ(rep.pieces[3].name, "teagan.sleeve (mirror)");
        EXPECT_EQ(rep.pieces[3].region, "sleeve_right");
        // Mean x of each sleeve: on its own side of the body.
        const auto mean = [&](const std::string& piece, int axis) {
            double sum = 0;
            const auto [lo, hi] = range.at(piece);
            for (std::size_t v = lo; v < hi; ++v) {
                sum += r.placed[v][axis];
            }
            return sum / double(hi - lo);
        };
        EXPECT_GT(mean("teagan.sleeve", 0), 100);
        EXPECT_LT(mean("teagan.sleeve (mirror)", 0), -100);
        // Each armhole seam and its mirror has pairs; on each sleeve, the cap part sewn to the
        // front lies in front of the part sewn to the back.
        std::map<std::string, double> cap_z;
        std::map<std::string, std::size_t> cap_n;
        for (std::size_t k = 0; k < r.sewing.pairs.size(); ++k) {
            const std::string& seam = rep.seams[r.sewing.seam_of_pair[k]].name;
            for (std::uint32_t v : {r.sewing.pairs[k].a, r.sewing.pairs[k].b}) {
                for (const char* sleeve : {"teagan.sleeve", "teagan.sleeve (mirror)"}) {
                    const auto [lo, hi] = range.at(sleeve);
                    if (v >= lo && v < hi) {
                        cap_z[seam] += r.placed[v][2];
                        ++cap_n[seam];
                    }
                }
            }
        }
        for (const char* seam : {"armhole (front)", "armhole (back)", "armhole (front) (mirror)",
                                 "armhole (back) (mirror)", "sleeve", "sleeve (mirror)"}) {
            EXPECT_GT(cap_n[seam], 0u) << seam;
        }
        for (const std::string m : {"", " (mirror)"}) {
            EXPECT_GT(cap_z["armhole (front)" + m] / cap_n["armhole (front)" + m],
                      cap_z["armhole (back)" + m] / cap_n["armhole (back)" + m] + 20)
                << "sleeve" << m;
        }
        // Each sleeve is wrapped round its whole arm: the two sides of its underarm seam start
        // close together under the arm (a tube wider than the arm by a bent-arm axis or a
        // shoulder-wide radius leaves them a quarter of the way round the arm or more apart).
        for (std::size_t k = 0; k < r.sewing.pairs.size(); ++k) {
            const std::string& seam = rep.seams[r.sewing.seam_of_pair[k]].name;
            if (seam == "sleeve" || seam == "sleeve (mirror)") {
                const double apart = tapeline::vec3::norm(tapeline::vec3::sub(
                    r.placed[r.sewing.pairs[k].a], r.placed[r.sewing.pairs[k].b]));
                EXPECT_LT(apart, 60) << seam << " pair " << k;
            }
        }
    }
}

// Trousers: FreeSewing's titan drafts one leg (a front and a back with a fork); dressing pairs
// each with its mirrored copy, adds the crotch seams between them, and wraps each leg's pieces on
// its own leg: the drafted pieces on the right (−x), the copies on the left, every vertex on its
// leg's side of the centre line, the forks at the centre line. GarmentCode's jumpsuit carries its
// legs as panels: each on the side its own placement puts it. Placement only (no sewing, no drape),
// on the bundled body and on two population bodies: no leg vertex inside the body, no pieces
// crossing. (The jumpsuit's long sleeves leave a vertex or two inside at the hand on population
// bodies: the sleeves' placement, not the legs'.)
TEST(Dress, TrouserLegsArePairedAndPlacedOnTheirLegs) {
    const std::filesystem::path data = TAPELINE_SHARED_DATA_DIR;
    const std::filesystem::path titan_file =
        data / "patterns" / "freesewing" / "titan_cisFemaleAdult36.json";
    const std::filesystem::path jumpsuit_file =
        data / "patterns" / "garmentcode" / "js_mean_all_specification.json";
    if (!std::filesystem::exists(titan_file) || !std::filesystem::exists(jumpsuit_file)) {
        GTEST_SKIP() << titan_file << " or " << jumpsuit_file << " is absent";
    }
    std::vector<std::string> bodies = {bundled_path("bodies/mh_female_average.obj")};
    for (const char* name : {"mh_pop_005.ply", "mh_pop_030.ply"}) {
        const auto p = data / "bodies" / "population" / name;
        if (std::filesystem::exists(p)) {
            bodies.push_back(p.string());
        }
    }
    const tp::Pattern titan = tp::read_pattern_file(titan_file.string());
    const tp::Pattern jumpsuit = tp::read_pattern_file(jumpsuit_file.string());
    tg::DressOptions o;
    o.resolution_mm = 25;
    o.sewing.sew_seconds = 0;  // placement and strings only
    o.sewing.settle_seconds = 0;
    o.sewing.max_extra_seconds = 0;
    for (const std::string& path : bodies) {
        SCOPED_TRACE(path);
        const MeasuredBody b = load_dm_body(path);
        for (const tp::Pattern* pattern : {&titan, &jumpsuit}) {
            SCOPED_TRACE(pattern->name);
            const tg::DressResult r = tg::dress(b.body, b.landmarks, *pattern, o);
            const tg::DressReport& rep = r.report;
            EXPECT_EQ(rep.placement_piece_intersections, 0u);
            std::size_t at = 0, legs = 0;
            for (const tg::PieceReport& p : rep.pieces) {
                const bool left = p.region == "leg_left_front" || p.region == "leg_left_back";
                const bool right = p.region == "leg_right_front" || p.region == "leg_right_back";
                if (left || right) {
                    ++legs;
                    EXPECT_EQ(p.placed_inside, 0u) << p.name;
                    double nearest = 1e300;
                    for (std::size_t v = at; v < at + p.vertices; ++v) {
                        const double x = r.placed[v][0];
                        EXPECT_GT(left ? x : -x, 0) << p.name << " vertex " << v - at;
                        nearest = std::min(nearest, std::abs(x));
                    }
                    // The fork (the inner edge) half a layer gap off the centre line.
                    EXPECT_LT(nearest, o.placement.layer_gap_mm) << p.name;
                }
                at += p.vertices;
            }
            EXPECT_EQ(legs, 4u);
        }
        const tg::DressResult r = tg::dress(b.body, b.landmarks, titan, o);
        const tg::DressReport& rep = r.report;
        ASSERT_EQ(rep.pieces.size(), 4u);
        std::map<std::string, std::string> region;
        for (const tg::PieceReport& p : rep.pieces) {
            region[p.name] = p.region;
        }
        EXPECT_EQ(region["titan.front"], "leg_right_front");
        EXPECT_EQ(region["titan.back"], "leg_right_back");
        EXPECT_EQ(region["titan.front (mirror)"], "leg_left_front");
        EXPECT_EQ(region["titan.back (mirror)"], "leg_left_back");
        std::map<std::string, const tg::SeamReport*> seams;
        for (const tg::SeamReport& sr : rep.seams) {
            seams[sr.name] = &sr;
        }
        for (const char* name : {"outseam", "outseam (mirror)", "inseam", "inseam (mirror)",
                                 "crotch front", "crotch back"}) {
            ASSERT_TRUE(seams.count(name)) << name;
            EXPECT_GT(seams[name]->pairs, 0u) << name;
            EXPECT_TRUE(seams[name]->closable) << name;
        }
        // A crotch seam joins a piece to its mirror image: equal sides, and the inseam and
        // outseam keep their lengths on the copies.
        for (const char* name : {"crotch front", "crotch back"}) {
            EXPECT_NEAR(seams[name]->side_a_mm, seams[name]->side_b_mm, 1e-6) << name;
            EXPECT_GT(seams[name]->side_a_mm, 200) << name;
        }
        EXPECT_NEAR(seams["inseam"]->side_a_mm, seams["inseam (mirror)"]->side_a_mm, 1e-6);
        EXPECT_NEAR(seams["outseam"]->side_b_mm, seams["outseam (mirror)"]->side_b_mm, 1e-6);
        // The waistband holds titan's four open waist edges (straight lines: as many vertices
        // as the meshing's equal steps of at most the resolution give them), nothing else.
        std::size_t expected = 0;
        for (const tp::Piece& piece : titan.pieces) {
            for (const tp::Edge& e : piece.outline.edges) {
                if (e.label == tp::waist_label()) {
                    expected += 2 * (std::size_t(std::ceil(tp::length(e) / o.resolution_mm)) + 1);
                }
            }
        }
        EXPECT_GT(expected, 0u);
        EXPECT_EQ(rep.waistband_vertices, expected);
        tg::DressOptions no_band = o;
        no_band.waistband = false;
        EXPECT_EQ(tg::dress(b.body, b.landmarks, titan, no_band).report.waistband_vertices, 0u);
    }
}

// Which waists the waistband holds: a jumpsuit's is sewn to its bodice (none held); the pencil
// dress's skirt alone (its bodice left out) has its waist open, the edges GarmentCode labels
// `lower_interface`: each of them held, their vertices at the top of the placed skirt.
TEST(Dress, WaistbandHoldsOpenWaistsOnly) {
    const std::filesystem::path data = TAPELINE_SHARED_DATA_DIR;
    const auto gc = data / "patterns" / "garmentcode";
    if (!std::filesystem::exists(gc / "js_mean_all_specification.json") ||
        !std::filesystem::exists(gc / "dress_pencil_specification.json")) {
        GTEST_SKIP() << gc << " lacks the jumpsuit or the pencil dress";
    }
    const MeasuredBody b = load_dm_body(bundled_path("bodies/mh_female_average.obj"));
    tg::DressOptions o;
    o.resolution_mm = 25;
    o.sewing.sew_seconds = 0;  // placement only
    o.sewing.settle_seconds = 0;
    o.sewing.max_extra_seconds = 0;
    const tp::Pattern jumpsuit =
        tp::read_pattern_file((gc / "js_mean_all_specification.json").string());
    EXPECT_EQ(tg::dress(b.body, b.landmarks, jumpsuit, o).report.waistband_vertices, 0u);
    const tp::Pattern dress =
        tp::read_pattern_file((gc / "dress_pencil_specification.json").string());
    EXPECT_EQ(tg::dress(b.body, b.landmarks, dress, o).report.waistband_vertices, 0u);
    o.without_pieces = {"left_ftorso", "left_btorso", "right_ftorso", "right_btorso"};
    const tg::DressResult skirt = tg::dress(b.body, b.landmarks, dress, o);
    std::size_t labelled_edges = 0;
    double labelled_length = 0;
    for (const tp::Piece& piece : dress.pieces) {
        for (const tp::Edge& e : piece.outline.edges) {
            if (e.label == "lower_interface") {
                ++labelled_edges;
                labelled_length += tp::length(e);
            }
        }
    }
    ASSERT_EQ(labelled_edges, 9u);
    // At least a vertex per resolution step along them; at most both ends of every edge more.
    const std::size_t n = skirt.report.waistband_vertices;
    EXPECT_GE(double(n), labelled_length / o.resolution_mm);
    EXPECT_LE(double(n), std::ceil(labelled_length / o.resolution_mm) + 2 * labelled_edges);
    double top = -1e300;
    for (const auto& x : skirt.placed) {
        top = std::max(top, x[1]);
    }
    // As many vertices of the placed skirt lie within 60 mm of its top as are held: the held
    // ones are its waist line (curved by a few cm), not edges further down.
    std::vector<double> heights;
    for (const auto& x : skirt.placed) {
        heights.push_back(x[1]);
    }
    std::sort(heights.rbegin(), heights.rend());
    EXPECT_GT(heights[n - 1], top - 60) << "the " << n << "th highest vertex";
}

// Titan as drafted (size 36) in cotton jersey on the bundled body: without a waistband it slides
// down over the hips (docs/garment.md); with it (the default) the waist stays where the sewing
// left it and the trousers hang from it.
TEST(Dress, WaistbandHoldsUngradedTrousersUp) {
    const std::filesystem::path file = std::filesystem::path(TAPELINE_SHARED_DATA_DIR) /
                                       "patterns" / "freesewing" / "titan_cisFemaleAdult36.json";
    if (!std::filesystem::exists(file)) {
        GTEST_SKIP() << file << " is absent";
    }
    const MeasuredBody b = load_dm_body(bundled_path("bodies/mh_female_average.obj"));
    tg::DressOptions o;
    o.resolution_mm = 30;
    o.drape.threads = 2;
    const tp::Pattern titan = tp::read_pattern_file(file.string());
    const tg::DressResult r = tg::dress(b.body, b.landmarks, titan, o);
    const tg::DressReport& rep = r.report;
    // The welded waist: a ring round both legs (each piece's waist edge twice), at least a
    // vertex per resolution step.
    double waist_length = 0;
    for (const tp::Piece& piece : titan.pieces) {
        for (const tp::Edge& e : piece.outline.edges) {
            waist_length += e.label == tp::waist_label() ? 2 * tp::length(e) : 0;
        }
    }
    EXPECT_GE(double(rep.waistband_vertices), waist_length / o.resolution_mm);
    EXPECT_LT(rep.quality.top_drop_mm, 50);
    EXPECT_EQ(rep.quality.vertices_inside_body, 0u);
    EXPECT_EQ(rep.quality.edges_crossing_body, 0u);
    EXPECT_LT(rep.quality.stretch_p95, 1.1);
    // Its openings: the two hems and, far above them, the waist.
    ASSERT_EQ(rep.openings.size(), 3u);
    const double waist = rep.openings.back().height_mm;
    EXPECT_GT(waist, rep.openings.front().height_mm + 600);
}

// The T-shirt (sleeves drafted once, paired with their mirror) dressed on the bundled body: the
// garment is one mesh with its four openings, no cloth edge crosses the body, no vertex is inside
// it, and the garment comes to rest (at most 1 % of the vertices moving more than 0.3 mm in the
// last frame) — three of the gates, with the sleeves on. Then the same with the static
// solve after the drape: a lower energy, the stretch gate met, the cloth outside the body and
// still hanging from it. (The rest gate is checked on the drape alone: the static solve's own
// rest is its convergence, which the report gives.)
TEST(Dress, TShirtComesToRestOutsideTheBody) {
    const std::filesystem::path file = std::filesystem::path(TAPELINE_SHARED_DATA_DIR) /
                                       "patterns" / "freesewing" / "teagan_cisFemaleAdult36.json";
    if (!std::filesystem::exists(file)) {
        GTEST_SKIP() << file << " is absent";
    }
    const MeasuredBody b = load_dm_body(bundled_path("bodies/mh_female_average.obj"));
    const tp::Pattern teagan = tp::read_pattern_file(file.string());
    // The sub-stepped drape alone (no static solve, fold-overs kept) comes to rest outside the
    // body...
    tg::DressOptions o;
    o.resolution_mm = 20;
    o.relax = false;
    o.smooth_folds = false;
    const tg::DressReport rep = tg::dress(b.body, b.landmarks, teagan, o).report;
    EXPECT_EQ(rep.relax.iterations, 0);
    EXPECT_EQ(rep.boundary_loops, 4u) << "neck, hem and two sleeve openings";
    EXPECT_EQ(rep.quality.edges_crossing_body, 0u);
    EXPECT_EQ(rep.quality.vertices_inside_body, 0u);
    EXPECT_LE(rep.quality.moving_fraction, 0.01);
    // ...and the static solve after it lowers the energy and takes the stretch to the gate's
    // 1.05 while keeping the cloth outside the body and on it.
    o.relax = true;
    o.smooth_folds = true;
    const tg::DressReport relaxed = tg::dress(b.body, b.landmarks, teagan, o).report;
    EXPECT_GT(relaxed.relax.iterations, 0);
    EXPECT_LT(relaxed.relax.energy_after_j, relaxed.relax.energy_before_j);
    EXPECT_EQ(relaxed.quality.vertices_inside_body, 0u);
    EXPECT_LT(relaxed.quality.stretch_p95, rep.quality.stretch_p95);
    EXPECT_LE(relaxed.quality.stretch_p95, 1.05);
    EXPECT_EQ(relaxed.quality.self_intersections, 0u);  // its fold-overs flattened
    EXPECT_LE(relaxed.quality.top_drop_mm, tg::kMaxTopDropMm);
    RecordProperty("stretch_p95_drape", std::to_string(rep.quality.stretch_p95));
    RecordProperty("stretch_p95_relaxed", std::to_string(relaxed.quality.stretch_p95));
}

TEST(Dress, Refusals) {
    const MeasuredBody b = load_dm_body(bundled_path("bodies/mh_female_average.obj"));
    tp::Pattern shirt =
        tp::read_pattern_file(bundled_path("patterns/shirt_mean_specification.json"));
    tg::DressOptions o;
    tp::Pattern no_seams = shirt;
    no_seams.seams.clear();
    EXPECT_NE(message_of([&] { tg::dress(b.body, b.landmarks, no_seams, o); }).find("has no seams"),
              std::string::npos);
    tp::Pattern odd = shirt;
    odd.pieces[0].name = "pocket";
    for (auto& s : odd.seams) {
        for (auto* side : {&s.a, &s.b}) {
            if (side->piece == shirt.pieces[0].name) {
                side->piece = "pocket";
            }
        }
    }
    odd.pieces[0].placement.reset();
    EXPECT_NE(message_of([&] {
                  tg::dress(b.body, b.landmarks, odd, o);
              }).find("piece 'pocket' has no body region"),
              std::string::npos);
    tg::DressOptions without = o;
    without.without_pieces = {"collar"};
    EXPECT_NE(message_of([&] {
                  tg::dress(b.body, b.landmarks, shirt, without);
              }).find("has no piece 'collar' to leave out"),
              std::string::npos);
    tg::DressOptions coarse = o;
    coarse.resolution_mm = 0.5;
    EXPECT_NE(message_of([&] { tg::dress(b.body, b.landmarks, shirt, coarse); }).find("resolution"),
              std::string::npos);
    // Both static solves' options are checked before anything runs, the later ones' too
    // (which run only when a flattening found fold-overs).
    tg::DressOptions bad_first = o;
    bad_first.relax_options.max_iterations = 0;
    EXPECT_NE(message_of([&] {
                  tg::dress(b.body, b.landmarks, shirt, bad_first);
              }).find("dress: relax_options: max_iterations must be >= 1, got 0"),
              std::string::npos);
    tg::DressOptions bad_again = o;
    bad_again.relax_again_options.release_until_iteration = -1;
    EXPECT_NE(message_of([&] { tg::dress(b.body, b.landmarks, shirt, bad_again); })
                  .find("dress: relax_again_options: friction_from_iteration and "
                        "release_until_iteration must be >= 0"),
              std::string::npos);
    // The fold options too, though the flattening runs only after the drape.
    tg::DressOptions bad_folds = o;
    bad_folds.fold_options.sweeps = 0;
    EXPECT_NE(message_of([&] { tg::dress(b.body, b.landmarks, shirt, bad_folds); })
                  .find("dress: fold_options: fold options need max_rounds >= 0, rings >= 0 and "
                        "sweeps >= 1, got 20, 1 and 0"),
              std::string::npos);
}
