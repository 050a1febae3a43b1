// Dressing real bodies: placement invariants (no cloth inside the body, no two pieces crossing)
// on the bundled body and on population bodies the placement was not developed on, the whole
// chain on the bundled body (seams closed, openings as the garment has, no penetration), and the
// refusals of dress().
#include <tapeline/garment/dress.h>
#include <tapeline/pattern/io_detect.h>
#include <tapeline_test/measured_body.h>

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <functional>
#include <string>

namespace tg = tapeline::garment;
namespace tmeas = tapeline::measurement;
namespace tp = tapeline::pattern;

namespace {

using tapeline_test::measurement::MeasuredBody;

MeasuredBody load_body(const std::string& path) {
    tmeas::BodyOptions o;
    o.name = path;
    o.unit = tmeas::LengthUnit::dm;
    return tapeline_test::measurement::load_measured_body(path, o);
}

std::string bundled(const std::string& rel) {
    return std::string(TAPELINE_DATA_DIR) + "/" + rel;
}

std::string message_of(const std::function<void()>& f) {
    try {
        f();
    } catch (const std::exception& e) {
        return e.what();
    }
    return "";
}

}  // namespace

// The whole chain on the bundled body in the bundled GarmentCode shirt: the placement leaves no
// cloth inside the body, the run ends without a solver failure, every seam is closable and the
// welded garment's openings are its neck, hem and two cuffs.
TEST(Dress, ShirtOnTheBundledBody) {
    const MeasuredBody b = load_body(bundled("bodies/mh_female_average.obj"));
    const tp::Pattern shirt =
        tp::read_pattern_file(bundled("patterns/shirt_mean_specification.json"));
    tg::DressOptions o;
    o.resolution_mm = 20;  // coarse: a unit test, not the benchmark
    const tg::DressResult r = tg::dress(b.body, b.landmarks, shirt, o);
    const tg::DressReport& rep = r.report;
    EXPECT_EQ(rep.placement_vertices_inside, 0u);
    EXPECT_EQ(rep.boundary_loops, 4u) << "a shirt has a neck, a hem and two cuffs";
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
    // The gates are measured, whatever their outcome, and every figure is finite.
    ASSERT_EQ(rep.gates.size(), 6u);
    for (const tg::Gate& g : rep.gates) {
        EXPECT_TRUE(std::isfinite(g.value)) << g.name;
    }
}

// The quality gates of the issue on the bundled body. Not reached yet (docs/garment.md lists the
// current figures: seams not all closed, cloth edges crossing the body, self-intersections and
// stretch above the limits); run it with --gtest_also_run_disabled_tests.
TEST(Dress, DISABLED_ShirtPassesTheQualityGates) {
    const MeasuredBody b = load_body(bundled("bodies/mh_female_average.obj"));
    const tp::Pattern shirt =
        tp::read_pattern_file(bundled("patterns/shirt_mean_specification.json"));
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
        tp::read_pattern_file(bundled("patterns/shirt_mean_specification.json"));
    for (const char* name : {"mh_pop_003.ply", "mh_pop_012.ply", "mh_pop_021.ply"}) {
        const MeasuredBody b = load_body((dir / name).string());
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

// No two placed pieces cross. Not reached yet: the shirt's sleeves meet its body pieces at the
// shoulders (6, 9, 11 and 6 crossing edges on the bundled body and these three).
TEST(Dress, DISABLED_PlacedPiecesDoNotCross) {
    place_on_population([](const char* name, const tg::DressReport& r) {
        EXPECT_EQ(r.placement_piece_intersections, 0u) << name;
    });
}

TEST(Dress, Refusals) {
    const MeasuredBody b = load_body(bundled("bodies/mh_female_average.obj"));
    tp::Pattern shirt = tp::read_pattern_file(bundled("patterns/shirt_mean_specification.json"));
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
}
