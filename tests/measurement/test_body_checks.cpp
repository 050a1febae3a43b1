// What is not one upright human body is refused with one line saying what looks wrong and what
// to try; a plausible body passes every self-check, and a landmark put in the wrong place breaks
// the rule that names it.
#include <tapeline/core/errors.h>
#include <tapeline_test/expect.h>
#include <tapeline_test/measurement.h>
#include <tapeline_test/measurement_checks.h>
#include <tapeline_test/measurement_holes.h>
#include <tapeline_test/measurement_landmarks.h>
#include <tapeline_test/temp_dir.h>

#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <string>

namespace {

using namespace tapeline_test::measurement;
using tapeline::InvalidInput;
using tapeline_test::expect_error;

const std::string kBundled = std::string(TAPELINE_DATA_DIR) + "/bodies/mh_female_average.obj";

TEST(BodyChecks, DecimetreBodyMeasuredInMetresIsRefusedNamingUnits) {
    const Soup s = read_body_soup(kBundled);
    BodyOptions o = body_options("body.obj", LengthUnit::dm);
    o.unit = LengthUnit::m;
    expect_error<InvalidInput>([&] { measure_mesh(s.points, s.triangles, o); },
                               {"body.obj", "stature 15.9 m", "not a human height", "--units"},
                               "metres");
    o.unit = LengthUnit::cm;
    expect_error<InvalidInput>([&] { measure_mesh(s.points, s.triangles, o); },
                               {"body.obj", "stature 0.159 m", "--units"}, "centimetres");
}

TEST(BodyChecks, TwoBodiesSideBySideAreRefused) {
    Soup s = read_body_soup(kBundled);
    const std::size_t n = s.points.size(), nt = s.triangles.size();
    for (std::size_t v = 0; v < n; ++v) {
        s.points.push_back({s.points[v][0] + 12.0, s.points[v][1], s.points[v][2]});
    }
    for (std::size_t f = 0; f < nt; ++f) {
        const auto& t = s.triangles[f];
        s.triangles.push_back({static_cast<std::uint32_t>(t[0] + n),
                               static_cast<std::uint32_t>(t[1] + n),
                               static_cast<std::uint32_t>(t[2] + n)});
    }
    expect_error<InvalidInput>(
        [&] { measure_mesh(s.points, s.triangles, body_options("two.obj", LengthUnit::dm)); },
        {"two.obj", "not one body", "2 separate parts", "one body per file"}, "two bodies");
}

TEST(BodyChecks, BodyOnItsSideIsRefusedNamingUpAndMeasuresWithTheRightAxis) {
    Soup s = read_body_soup(kBundled);
    for (auto& p : s.points) {
        p = {-p[1], p[0], p[2]};  // a quarter turn about z: the body's up is now -X
    }
    expect_error<InvalidInput>(
        [&] { measure_mesh(s.points, s.triangles, body_options("side.obj", LengthUnit::dm)); },
        {"side.obj", "not upright", "tall along the up axis +Y", "--up"}, "on its side");
    BodyOptions o = body_options("side.obj", LengthUnit::dm);
    o.up = Axis::parse("-X", "--up");
    const Result r = measure_mesh(s.points, s.triangles, o);
    EXPECT_EQ(r.landmarks.available_count(), r.landmarks.landmarks.size());
}

// Arms raised sideways but measured as the default A-pose: refused naming --pose (measured so,
// the armpits are lost and the shoulder points go out along the arms).
TEST(BodyChecks, TPoseMeasuredAsAnAPoseIsRefusedNamingPose) {
    const BodyOptions dm = body_options("a.obj", LengthUnit::dm);
    const Soup soup = canonical_soup(kBundled, dm);
    const Result a =
        measure_mesh(soup.points, soup.triangles, body_options("a.obj", LengthUnit::mm));
    const auto posed = raise_arms_to_t_pose(soup.points, a.landmarks, 0.02 * a.frame.height);
    expect_error<InvalidInput>(
        [&] { measure_mesh(posed, soup.triangles, body_options("t.obj", LengthUnit::mm)); },
        {"t.obj", "the arms are spread sideways", "the hands at 0.", "--pose T"}, "T-pose as A");
    BodyOptions t = body_options("t.obj", LengthUnit::mm);
    t.pose = Pose::t_pose;
    const Result r = measure_mesh(posed, soup.triangles, t);
    EXPECT_EQ(r.landmarks.available_count(), r.landmarks.landmarks.size());
}

TEST(BodyChecks, UpsideDownBodyIsRefusedNamingUp) {
    Soup s = read_body_soup(kBundled);
    for (auto& p : s.points) {
        p = {-p[0], -p[1], p[2]};  // half a turn about the front axis
    }
    expect_error<InvalidInput>(
        [&] { measure_mesh(s.points, s.triangles, body_options("flip.obj", LengthUnit::dm)); },
        {"flip.obj", "upside down", "--up"}, "upside down");
}

TEST(BodyChecks, EllipsoidIsNotABody) {
    const Soup s = ellipsoid({0, 0.85, 0}, {0.22, 0.85, 0.15});
    const BodyOptions o = body_options("egg.obj", LengthUnit::m);
    expect_error<InvalidInput>([&] { measure_mesh(s.points, s.triangles, o); },
                               {"egg.obj", "does not look like a body", "no legs"}, "ellipsoid");
}

TEST(BodyChecks, ArmadilloIsNotABody) {
    const std::string path = std::string(TAPELINE_SHARED_DATA_DIR) + "/meshes/armadillo.obj";
    if (!std::ifstream(path).good()) {
        GTEST_SKIP() << "no " << path;
    }
    const Soup s = read_body_soup(path);
    BodyOptions o = body_options("armadillo.obj", LengthUnit::m);  // 1.0 units tall
    // Whichever check catches it first, the message names the mesh and says what to try; its
    // raised forelimbs read as a T-pose's arms, and doing what that message says (--pose T) is
    // refused too.
    for (const Pose pose : {Pose::a_pose, Pose::t_pose}) {
        o.pose = pose;
        try {
            measure_mesh(s.points, s.triangles, o);
            ADD_FAILURE() << "the armadillo was measured";
        } catch (const InvalidInput& e) {
            const std::string what = e.what();
            EXPECT_NE(what.find("armadillo.obj: "), std::string::npos) << what;
            EXPECT_TRUE(what.find("does not look like a body") != std::string::npos ||
                        what.find("implausible proportions") != std::string::npos ||
                        what.find("not upright") != std::string::npos ||
                        what.find("upside down") != std::string::npos ||
                        (pose == Pose::a_pose && what.find("as in a T-pose") != std::string::npos))
                << what;
            EXPECT_NE(what.find("--"), std::string::npos) << what;
        }
    }
}

TEST(SelfChecks, PlausibleBodyHasNoWarnings) {
    BodyOptions o = body_options("mh_female_average.obj", LengthUnit::dm);
    const Result r = measure_file(kBundled, o);
    for (const auto& w : r.warnings) {
        ADD_FAILURE() << w.rule << ": " << w.message;
    }
}

std::string write_overrides(const std::string& name, const std::string& landmarks) {
    static const tapeline_test::TempDir dir;  // removed at exit
    const std::string path = dir.file(name);
    std::ofstream(path) << "{\"frame\": \"canonical\", \"landmarks\": {" << landmarks << "}}";
    return path;
}

std::string point_json(const Vec3& p) {
    char b[96];
    std::snprintf(b, sizeof b, "[%.3f, %.3f, %.3f]", p[0], p[1], p[2]);
    return b;
}

bool has_warning(const Result& r, const std::string& measurement, const std::string& rule) {
    for (const auto& w : r.warnings) {
        if (w.measurement == measurement && w.rule == rule &&
            w.message.find(measurement) != std::string::npos) {
            return true;
        }
    }
    return false;
}

TEST(SelfChecks, WristMidForearmBreaksSymmetryAndForearmLength) {
    const BodyOptions o = body_options("mh_female_average.obj", LengthUnit::dm);
    const Result base = measure_file(kBundled, o);
    const Landmark* elbow = base.landmarks.find("elbow_right");
    const Landmark* wrist = base.landmarks.find("wrist_right");
    ASSERT_TRUE(elbow->available() && wrist->available());
    const Vec3 mid{0.5 * (elbow->point[0] + wrist->point[0]),
                   0.5 * (elbow->point[1] + wrist->point[1]),
                   0.5 * (elbow->point[2] + wrist->point[2])};
    const Result r = measure_file(
        kBundled, o, write_overrides("wrist.json", "\"wrist_right\": " + point_json(mid)));
    EXPECT_TRUE(has_warning(r, "wrist_left", "left_right"));
    EXPECT_TRUE(has_warning(r, "wrist_right", "segment_length"));
}

TEST(SelfChecks, BustPointsAtWaistHeightBreakTheHeightBand) {
    const BodyOptions o = body_options("mh_female_average.obj", LengthUnit::dm);
    const Result base = measure_file(kBundled, o);
    const auto waist = base.landmarks.point("waist_front");
    const auto bl = base.landmarks.point("bust_left");
    const auto br = base.landmarks.point("bust_right");
    ASSERT_TRUE(waist && bl && br);
    const Vec3 l{(*bl)[0], (*waist)[1], (*waist)[2]}, rr{(*br)[0], (*waist)[1], (*waist)[2]};
    const Result r =
        measure_file(kBundled, o,
                     write_overrides("bust.json", "\"bust_left\": " + point_json(l) +
                                                      ", \"bust_right\": " + point_json(rr)));
    EXPECT_TRUE(has_warning(r, "bust_left", "landmark_height"));
    EXPECT_TRUE(has_warning(r, "bust_right", "landmark_height"));
}

// Overrides moving both bust points down to `drop` of the stature under the landmark `under`
// ("bust" or "armpit") of their side.
std::string busts_lowered(const Result& base, const std::string& under, double drop) {
    std::string json;
    for (const char* side : {"left", "right"}) {
        const auto b = base.landmarks.point(std::string("bust_") + side);
        const auto ref = base.landmarks.point(under + "_" + side);
        EXPECT_TRUE(b && ref) << side;
        if (b && ref) {
            json += std::string(json.empty() ? "" : ", ") + "\"bust_" + side +
                    "\": " + point_json({(*b)[0], (*ref)[1] - drop * base.frame.height, (*b)[2]});
        }
    }
    return json;
}

// Bust points on the lower ribs (where a thin, flat-chested body's front is furthest forward
// below a sternum as far forward as its nipples), 6 % of the stature under the bust, still
// within the bust's height band: the tape there is far under the chest's.
TEST(SelfChecks, BustPointsOnTheLowerRibsAreUnderTheHighBust) {
    const BodyOptions o = body_options("mh_female_average.obj", LengthUnit::dm);
    const Result base = measure_file(kBundled, o);
    EXPECT_FALSE(has_warning(base, "bust_girth", "bust_high_bust"));
    const Result r =
        measure_file(kBundled, o, write_overrides("ribs.json", busts_lowered(base, "bust", 0.06)));
    EXPECT_TRUE(has_warning(r, "bust_girth", "bust_high_bust"));
    EXPECT_FALSE(has_warning(r, "bust_left", "landmark_height"));
}

// Bust points 0.10 of the stature under the armpits (the lowest of 419 MakeHuman bodies lie
// 0.084 under them, with the largest, least firm breasts): below the chest, whatever the girth.
TEST(SelfChecks, BustPointsFarUnderTheArmpitsAreBelowTheChest) {
    const BodyOptions o = body_options("mh_female_average.obj", LengthUnit::dm);
    const Result base = measure_file(kBundled, o);
    EXPECT_FALSE(has_warning(base, "bust_left", "bust_armpit"));
    EXPECT_FALSE(has_warning(base, "bust_right", "bust_armpit"));
    const Result r = measure_file(
        kBundled, o, write_overrides("low_bust.json", busts_lowered(base, "armpit", 0.10)));
    EXPECT_TRUE(has_warning(r, "bust_left", "bust_armpit"));
    EXPECT_TRUE(has_warning(r, "bust_right", "bust_armpit"));
}

// Bust points at the armpits' level: the bust tape runs around the arms as well as the chest (a
// thin male body of seed 20261207 had its bust points there by itself before the bust points of a
// chest without an apex went to the nipple level: bust girth 356 mm over MakeHuman's ruler, 1.42
// times the high bust girth, with no warning).
TEST(SelfChecks, BustTapeAroundTheArmsIsFarOverTheHighBust) {
    const BodyOptions o = body_options("mh_female_average.obj", LengthUnit::dm);
    const Result base = measure_file(kBundled, o);
    EXPECT_FALSE(has_warning(base, "bust_girth", "bust_high_bust"));
    const Result r = measure_file(
        kBundled, o, write_overrides("armpit_bust.json", busts_lowered(base, "armpit", 0)));
    const auto bust = r.measurements.value("bust_girth");
    const auto high = r.measurements.value("high_bust_girth");
    ASSERT_TRUE(bust && high);
    EXPECT_GT(*bust, 1.3 * *high);  // the tape does run around the arms
    EXPECT_TRUE(has_warning(r, "bust_girth", "bust_high_bust"));
}

// A thin, flat chest whose sternum is its front from the armpits down to the lower ribs
// (data/README.md): no level has a breast's or pectoral's apex, and the bust points go to the
// usual nipple level under the armpits. Taking the profile's nearest level instead put them on
// the lower ribs, 0.109 of the stature under the armpits, the bust girth 37 mm under MakeHuman's
// ruler, with no warning.
TEST(SelfChecks, FlatChestWithTheSternumInFrontHasItsBustUnderTheArmpits) {
    const BodyOptions o = body_options("mh_thin_flat_chest.ply", LengthUnit::dm);
    const Result r =
        measure_file(std::string(TAPELINE_DATA_DIR) + "/bodies/mh_thin_flat_chest.ply", o);
    const double h = r.frame.height;
    for (const char* side : {"left", "right"}) {
        const auto b = r.landmarks.point(std::string("bust_") + side);
        const auto ap = r.landmarks.point(std::string("armpit_") + side);
        ASSERT_TRUE(b && ap) << side;
        EXPECT_GT(((*ap)[1] - (*b)[1]) / h, 0.02) << side;
        EXPECT_LT(((*ap)[1] - (*b)[1]) / h, 0.06) << side;
        EXPECT_FALSE(has_warning(r, std::string("bust_") + side, "bust_armpit")) << side;
    }
    const auto bust = r.measurements.value("bust_girth");
    ASSERT_TRUE(bust);
    EXPECT_NEAR(*bust, 680.6, 25.0);  // MakeHuman's bust ruler
    EXPECT_FALSE(has_warning(r, "bust_girth", "bust_high_bust"));
}

// Shoulder points beside the neck (where a skinned T-pose's outline has its only corner): the
// straight distance between them is far under a quarter of the stature.
TEST(SelfChecks, ShoulderPointsBesideTheNeckBreakTheShoulderBreadth) {
    const BodyOptions o = body_options("mh_female_average.obj", LengthUnit::dm);
    const Result base = measure_file(kBundled, o);
    EXPECT_FALSE(has_warning(base, "acromion_left", "shoulder_breadth"));
    const double h = base.frame.height;
    std::string json;
    for (const char* side : {"left", "right"}) {
        const auto snp = base.landmarks.point(std::string("side_neck_") + side);
        const auto ac = base.landmarks.point(std::string("acromion_") + side);
        ASSERT_TRUE(snp && ac) << side;
        const double out = (*snp)[0] > (*ac)[0] ? -0.03 * h : 0.03 * h;
        const Vec3 p{(*snp)[0] + out, (*ac)[1], (*ac)[2]};
        json +=
            std::string(json.empty() ? "" : ", ") + "\"acromion_" + side + "\": " + point_json(p);
    }
    const Result r = measure_file(kBundled, o, write_overrides("shoulders.json", json));
    EXPECT_TRUE(has_warning(r, "acromion_left", "shoulder_breadth"));
}

// A front neck point taken well down the chest tilts the neck base plane so that it runs over
// the shoulders: the tape is then far longer than the neck's.
TEST(SelfChecks, NeckBasePlaneOverTheShouldersIsFlagged) {
    const BodyOptions o = body_options("mh_female_average.obj", LengthUnit::dm);
    const Result base = measure_file(kBundled, o);
    EXPECT_FALSE(has_warning(base, "neck_base_girth", "neck_base_wide"));
    const auto fn = base.landmarks.point("front_neck");
    const auto nb = base.measurements.value("neck_base_girth");
    const auto ng = base.measurements.value("neck_girth");
    ASSERT_TRUE(fn && nb && ng);
    EXPECT_LT(*nb, 1.5 * *ng);
    const Vec3 low{(*fn)[0], (*fn)[1] - 0.08 * base.frame.height, (*fn)[2]};
    const Result r = measure_file(
        kBundled, o, write_overrides("neck.json", "\"front_neck\": " + point_json(low)));
    const auto nb_low = r.measurements.value("neck_base_girth");
    ASSERT_TRUE(nb_low);
    EXPECT_GT(*nb_low, 1.5 * *ng);
    EXPECT_TRUE(has_warning(r, "neck_base_girth", "neck_base_wide"));
}

}  // namespace
