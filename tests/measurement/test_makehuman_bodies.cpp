// The seven MakeHuman bodies and two proxy meshes in ../shared/data/bodies (decimetres, +Y up,
// +Z front, A-pose). MakeHuman's own "ruler" girths are polylines through fixed vertices, not a
// tape: they zig-zag through the mesh and follow hollows a tape bridges, so they are a sanity
// band, not truth. The proxies (other topology, same body) must agree with their base bodies
// within ISO 20685-1's tolerances. Skipped when the shared data is absent.
#include <tapeline_test/measurement.h>
#include <tapeline_test/measurement_landmarks.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace tapeline_test::measurement;

const std::string kDir = std::string(TAPELINE_SHARED_DATA_DIR) + "/bodies/";
const char* kBodies[] = {"mh_default_neutral",    "mh_female_average", "mh_male_average",
                         "mh_female_heavy_short", "mh_male_thin_tall", "mh_male_muscular_heavy",
                         "mh_child_10y"};

bool have_data() {
    return std::ifstream(kDir + "measurements.json").good();
}

Result measure(const std::string& body) {
    return measure_file(kDir + body + ".obj", body_options(body + ".obj", LengthUnit::dm));
}

// MakeHuman ruler name -> our girth.
const std::map<std::string, std::string> kRulers = {{"neck_circ", "neck_girth"},
                                                    {"upperarm_circ", "upper_arm_girth"},
                                                    {"wrist_circ", "wrist_girth"},
                                                    {"bust_circ", "bust_girth"},
                                                    {"underbust_circ", "underbust_girth"},
                                                    {"waist_circ", "waist_girth"},
                                                    {"hips_circ", "hip_girth"},
                                                    {"thigh_circ", "thigh_girth"},
                                                    {"knee_circ", "knee_girth"},
                                                    {"calf_circ", "calf_girth"},
                                                    {"ankle_circ", "ankle_girth"}};

TEST(MakeHumanBodies, EveryLandmarkFoundAndGirthsNearTheRulers) {
    if (!have_data()) {
        GTEST_SKIP() << "no " << kDir;
    }
    const auto doc = nlohmann::json::parse(std::ifstream(kDir + "measurements.json"));
    std::map<std::string, std::pair<double, int>> sums;  // ruler -> (sum of |relative|, n)
    for (const char* body : kBodies) {
        const Result r = measure(body);
        for (const auto& l : r.landmarks.landmarks) {
            EXPECT_TRUE(l.available()) << body << ": " << l.reason;
        }
        EXPECT_TRUE(r.measurements.missing.empty()) << body;
        EXPECT_EQ(r.frame.unit, LengthUnit::dm);
        std::printf(
            "%s: stature %.1f mm (MakeHuman %.1f), landmarks %.3f s, girths %.3f s, "
            "%zu sections\n",
            body, r.measurements.value("stature").value_or(0),
            10 * doc["bodies"][body]["height_cm"].get<double>(), r.report.landmark_seconds,
            r.report.girth_seconds, r.report.sections);
        EXPECT_NEAR(r.measurements.value("stature").value_or(0),
                    10 * doc["bodies"][body]["height_cm"].get<double>(), 1.0);
        std::printf("  %-16s %9s %9s %8s\n", "ruler", "ruler mm", "tape mm", "diff %");
        for (const auto& [ruler, ours] : kRulers) {
            const double ruler_mm =
                10 * doc["bodies"][body]["makehuman_ruler_cm"][ruler].get<double>();
            const auto tape = r.measurements.value(ours);
            ASSERT_TRUE(tape) << body << " " << ours;
            const double rel = 100 * (*tape - ruler_mm) / ruler_mm;
            std::printf("  %-16s %9.1f %9.1f %+8.1f\n", ruler.c_str(), ruler_mm, *tape, rel);
            sums[ruler].first += std::abs(rel);
            sums[ruler].second += 1;
            // A sanity band: a different level definition or a bridged hollow, not a blunder.
            EXPECT_LT(std::abs(rel), 15.0) << body << " " << ours;
        }
    }
    std::printf("mean |tape - ruler| / ruler:\n");
    for (const auto& [ruler, s] : sums) {
        std::printf("  %-16s %5.1f %%\n", ruler.c_str(), s.first / s.second);
    }
}

// The two proxy meshes (other topology, same body) and their base bodies.
const std::pair<const char*, const char*> kProxyPairs[] = {
    {"mh_female_average", "mh_female_average_female_generic"},
    {"mh_male_average", "mh_male_average_male_generic"}};

TEST(MakeHumanBodies, ProxyMeshesAgreeWithTheirBaseBodies) {
    if (!have_data()) {
        GTEST_SKIP() << "no " << kDir;
    }
    for (const auto& [base, proxy] : kProxyPairs) {
        const Result a = measure(base), b = measure(proxy);
        for (const auto& l : b.landmarks.landmarks) {
            EXPECT_TRUE(l.available()) << proxy << ": " << l.reason;
        }
        std::printf("%s vs %s\n  %-18s %9s %9s %8s %5s\n", proxy, base, "girth", "base", "proxy",
                    "diff", "tol");
        int outside = 0;
        for (const auto& m : a.measurements.measurements) {
            if (m.name.find("_left") != std::string::npos ||
                m.name.find("_right") != std::string::npos) {
                continue;
            }
            const auto v = b.measurements.value(m.name);
            ASSERT_TRUE(v) << proxy << " " << m.name;
            const double tol = iso20685_tolerance(m);
            const double diff = *v - m.value;
            // Every girth, neck base and mid-thigh included: their levels (side neck points,
            // knee) are defined to move with the surface, not with its triangles.
            const bool out = std::abs(diff) > tol;
            std::printf("  %-18s %9.1f %9.1f %+8.1f %5.0f%s\n", m.name.c_str(), m.value, *v, diff,
                        tol, out ? "  OUTSIDE" : "");
            EXPECT_LE(std::abs(diff), tol) << proxy << " " << m.name;
            outside += out ? 1 : 0;
        }
        std::printf("  %d outside the ISO tolerance\n", outside);
        EXPECT_EQ(outside, 0) << proxy;
    }
}

// The lengths along the skin must agree too (ISO 20685-1: 5 mm for segment lengths, 4 mm for
// heights). They hang on single landmarks, not on levels: a landmark that is the extreme of a flat
// function (the lateral extreme of a round neck section, the corner of a round shoulder) moves
// with the triangles and takes the length with it. Before the side neck point was the crossing
// of the neck's outline with the line through its centre and the acromion the vertex of a
// parabola fitted to the chord distances, hps_to_waist_back differed by 6.5 mm (female) and the
// back shoulder widths by 9-11 mm (male).
TEST(MakeHumanBodies, ProxyMeshLengthsAgreeWithTheirBaseBodies) {
    if (!have_data()) {
        GTEST_SKIP() << "no " << kDir;
    }
    for (const auto& [base, proxy] : kProxyPairs) {
        auto skin = [](const std::string& body) {
            BodyOptions o;
            o.unit = LengthUnit::dm;
            o.name = body + ".obj";
            return measure_file_with_skin_lengths(kDir + body + ".obj", o);
        };
        const Result a = skin(base), b = skin(proxy);
        std::printf("%s vs %s\n  %-28s %9s %9s %8s %5s\n", proxy, base, "length", "base", "proxy",
                    "diff", "tol");
        int outside = 0, compared = 0;
        for (const auto& m : a.measurements.measurements) {
            if (m.kind != MeasurementKind::length && m.kind != MeasurementKind::height) {
                continue;
            }
            const auto v = b.measurements.value(m.name);
            ASSERT_TRUE(v) << proxy << " " << m.name;
            const double tol = m.kind == MeasurementKind::height ? 4 : 5;
            const double diff = *v - m.value;
            const bool out = std::abs(diff) > tol;
            std::printf("  %-28s %9.1f %9.1f %+8.1f %5.0f%s\n", m.name.c_str(), m.value, *v, diff,
                        tol, out ? "  OUTSIDE" : "");
            EXPECT_LE(std::abs(diff), tol) << proxy << " " << m.name;
            outside += out ? 1 : 0;
            compared += m.kind == MeasurementKind::length ? 1 : 0;
        }
        std::printf("  %d outside the ISO tolerance\n", outside);
        EXPECT_GT(compared, 10) << proxy << ": the skin lengths were not measured";
        EXPECT_EQ(outside, 0) << proxy;
    }
}

// MakeHuman's arm rulers are straight lines between fixed vertices: upperarm_length from its
// shoulder vertex (on the back of the shoulder's top, 25-50 mm inside our acromion, the lateral
// tip) to the olecranon, lowerarm_length from the elbow's front to the wrist. Our lengths follow
// the skin from the acromion over the olecranon to the wrist. Before the elbow was the bend of
// the arm's centre line (it was the narrowest section, on the lateral side), both came out
// 10-13% short. Bands: the whole arm within 5%, the upper arm within 10% (the different shoulder
// point), both as relative errors since the bodies span 131-195 cm.
TEST(MakeHumanBodies, ArmLengthsNearTheMakeHumanRulers) {
    if (!have_data()) {
        GTEST_SKIP() << "no " << kDir;
    }
    const auto doc = nlohmann::json::parse(std::ifstream(kDir + "measurements.json"));
    std::printf("  %-24s %8s %8s %7s %8s %8s %7s\n", "body", "upper MH", "ours", "diff %", "arm MH",
                "ours", "diff %");
    for (const char* body : kBodies) {
        BodyOptions o;
        o.unit = LengthUnit::dm;
        o.name = std::string(body) + ".obj";
        const Result r = measure_file_with_skin_lengths(kDir + body + ".obj", o);
        const auto& ruler = doc["bodies"][body]["makehuman_ruler_cm"];
        const double upper = 10 * ruler["upperarm_length"].get<double>();
        const double arm = upper + 10 * ruler["lowerarm_length"].get<double>();
        const auto se = r.measurements.value("shoulder_to_elbow");
        const auto sw = r.measurements.value("shoulder_to_wrist");
        ASSERT_TRUE(se && sw) << body;
        const double du = 100 * (*se - upper) / upper, da = 100 * (*sw - arm) / arm;
        std::printf("  %-24s %8.1f %8.1f %+7.1f %8.1f %8.1f %+7.1f\n", body, upper, *se, du, arm,
                    *sw, da);
        EXPECT_LT(std::abs(du), 10.0) << body;
        EXPECT_LT(std::abs(da), 5.0) << body;
    }
}

// mh_male_muscular_heavy's neck is as wide as its jaw: the smallest horizontal section below the
// head is the jaw's, the side neck points are found at the jaw and the neck girth goes around the
// mouth (seen in its picture; +27 mm against MakeHuman's ruler). The neck_below_chin self-check
// must say so, and only there: on the six other bodies the side neck points lie below the chin's
// underside. neck_base_narrow, which needs no chin, says so too: the neck base tape (over the
// four neck points, below the jaw) is shorter than the neck girth round the jaw.
TEST(MakeHumanBodies, NeckTakenAtTheJawIsFlagged) {
    if (!have_data()) {
        GTEST_SKIP() << "no " << kDir;
    }
    for (const char* body : kBodies) {
        const Result r = measure(body);
        int flagged = 0, narrow = 0;
        for (const auto& w : r.warnings) {
            flagged += w.rule == "neck_below_chin";
            narrow += w.rule == "neck_base_narrow";
            if (w.rule == "neck_below_chin" || w.rule == "neck_base_narrow") {
                std::printf("%s: %s\n", body, w.message.c_str());
            }
        }
        const bool jaw = std::string(body) == "mh_male_muscular_heavy";
        EXPECT_EQ(flagged, jaw ? 2 : 0) << body;
        EXPECT_EQ(narrow, jaw ? 1 : 0) << body;
        const auto nb = r.measurements.value("neck_base_girth");
        const auto ng = r.measurements.value("neck_girth");
        ASSERT_TRUE(nb && ng) << body;
        EXPECT_EQ(narrow == 1, *nb < 1.05 * *ng) << body << ": " << *nb << " and " << *ng;
    }
}

// No T-pose body is in the shared data: each body (the bundled ones and five of the population,
// three of them from the hold-out) is measured as it is and again with its arms raised to
// horizontal about the shoulder (tapeline_test/measurement_landmarks.h: a one-joint
// skinning that moves nothing on the torso side below the armpit, nor the neck and head). Every
// landmark must be found on the T-pose, the armpits near the A-pose's (raising the arm turns the
// armpit's skin but keeps its height within 1% of the stature, the junction's corner lies up to
// 30 mm further out), and every girth that involves no arm must stay the same (the waist and
// high hip girths: see below). Bust, high bust
// and underbust are left out: their tape passes just below the armpit, where raising the arm
// changes the chest, or their level follows the bust point, searched below the armpit.
TEST(MakeHumanBodies, TPoseArmpitsFoundAndArmFreeGirthsUnchanged) {
    if (!have_data()) {
        GTEST_SKIP() << "no " << kDir;
    }
    const char* arm_free[] = {"stature",    "head_girth",  "neck_girth",      "neck_base_girth",
                              "hip_girth",  "thigh_girth", "mid_thigh_girth", "knee_girth",
                              "calf_girth", "ankle_girth"};
    std::vector<std::string> files;
    for (const char* body : kBodies) {
        files.push_back(std::string(body) + ".obj");
    }
    for (const char* body :
         {"mh_pop_004", "mh_pop_019", "mh_pop_031", "mh_pop_035", "mh_pop_038"}) {
        files.push_back("population/" + std::string(body) + ".ply");
    }
    for (const std::string& file : files) {
        const char* body = file.c_str();
        BodyOptions o;
        o.unit = LengthUnit::dm;
        o.name = file;
        const PosePair p = measure_file_a_and_t_pose(kDir + file, o);
        for (const auto& l : p.t_pose.landmarks.landmarks) {
            EXPECT_TRUE(l.available()) << body << " T-pose: " << l.reason;
        }
        EXPECT_TRUE(p.t_pose.measurements.missing.empty()) << body;
        // Raising the arms adds no warning (the arm girths' loops are not taken for loops
        // around the midline, the shoulder points stay at the shoulders).
        for (const auto& w : p.t_pose.warnings) {
            bool in_a = false;
            for (const auto& v : p.a_pose.warnings) {
                in_a = in_a || (v.rule == w.rule && v.measurement == w.measurement);
            }
            EXPECT_TRUE(in_a) << body << " T-pose only: " << w.rule << ": " << w.message;
        }
        const double h = p.a_pose.measurements.value("stature").value_or(0);
        for (const char* side : {"acromion_left", "acromion_right"}) {
            const auto a = p.a_pose.landmarks.point(side), t = p.t_pose.landmarks.point(side);
            if (a && t) {
                std::printf("%s %s: A-pose (%.0f, %.0f, %.0f), T-pose (%.0f, %.0f, %.0f) mm\n",
                            body, side, (*a)[0], (*a)[1], (*a)[2], (*t)[0], (*t)[1], (*t)[2]);
            }
        }
        for (const char* side : {"armpit_left", "armpit_right"}) {
            const auto a = p.a_pose.landmarks.point(side), t = p.t_pose.landmarks.point(side);
            ASSERT_TRUE(a && t) << body << " " << side;
            std::printf("%s %s: A-pose (%.0f, %.0f, %.0f), T-pose (%.0f, %.0f, %.0f) mm\n", body,
                        side, (*a)[0], (*a)[1], (*a)[2], (*t)[0], (*t)[1], (*t)[2]);
            EXPECT_NEAR((*t)[1], (*a)[1], 0.01 * h) << body << " " << side;
            EXPECT_NEAR(std::abs((*t)[0]), std::abs((*a)[0]), 35.0) << body << " " << side;
        }
        for (const char* name : arm_free) {
            const auto a = p.a_pose.measurements.value(name), t = p.t_pose.measurements.value(name);
            ASSERT_TRUE(a && t) << body << " " << name;
            // The posed mesh is rewritten in millimetres (rounding far below 0.01 mm).
            EXPECT_NEAR(*t, *a, 0.05) << body << " " << name;
        }
        // The waist: a narrowest girth stays where it is. On a torso without a waist indentation
        // (or only the fold under the chest) the waist is placed 0.57 of the way from crotch to
        // armpit and follows the armpits, which move when the arms are raised: its level moves
        // by no more than 0.57 of theirs, and its girth and the high hip's (halfway down to the
        // hip level) stay within ISO 20685-1's 9 mm; where the level did not move, they do not.
        auto armpit_level = [](const Result& r) {
            return std::min((*r.landmarks.point("armpit_left"))[1],
                            (*r.landmarks.point("armpit_right"))[1]);
        };
        const auto wa = p.a_pose.landmarks.point("waist_front");
        const auto wt = p.t_pose.landmarks.point("waist_front");
        ASSERT_TRUE(wa && wt) << body;
        const double moved = std::abs((*wt)[1] - (*wa)[1]);
        EXPECT_LE(moved, 0.57 * std::abs(armpit_level(p.t_pose) - armpit_level(p.a_pose)) + 0.1)
            << body << ": the waist moved " << moved << " mm";
        for (const char* name : {"waist_girth", "high_hip_girth"}) {
            const auto a = p.a_pose.measurements.value(name), t = p.t_pose.measurements.value(name);
            ASSERT_TRUE(a && t) << body << " " << name;
            EXPECT_NEAR(*t, *a, moved < 0.1 ? 0.05 : 9.0)
                << body << " " << name << " (the waist moved " << moved << " mm)";
        }
    }
}

}  // namespace
