// The seven MakeHuman bodies and two proxy meshes in ../shared/data/bodies (decimetres, +Y up,
// +Z front, A-pose). MakeHuman's own "ruler" girths are polylines through fixed vertices, not a
// tape: they zig-zag through the mesh and follow hollows a tape bridges, so they are a sanity
// band, not truth. The proxies (other topology, same body) must agree with their base bodies
// within ISO 20685-1's tolerances. Skipped when the shared data is absent.
#include <tapeline_test/measurement.h>

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <map>
#include <string>

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
    BodyOptions o;
    o.unit = LengthUnit::dm;
    o.name = body + ".obj";
    return measure_file(kDir + body + ".obj", o);
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

const std::map<std::string, double> kKnownOutside = {{"neck_base_girth", 30},
                                                     {"mid_thigh_girth", 10}};

TEST(MakeHumanBodies, ProxyMeshesAgreeWithTheirBaseBodies) {
    if (!have_data()) {
        GTEST_SKIP() << "no " << kDir;
    }
    const std::pair<const char*, const char*> pairs[] = {
        {"mh_female_average", "mh_female_average_female_generic"},
        {"mh_male_average", "mh_male_average_male_generic"}};
    for (const auto& [base, proxy] : pairs) {
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
            // ISO 20685-1: 9 mm for the large torso girths, 4 mm for the others and heights.
            const bool large = m.name == "bust_girth" || m.name == "waist_girth" ||
                               m.name == "hip_girth" || m.name == "underbust_girth" ||
                               m.name == "high_bust_girth" || m.name == "high_hip_girth";
            const double tol = large ? 9 : 4;
            const double diff = *v - m.value;
            // Known to miss ISO (see measurement/README.md): the neck base plane follows the
            // cervicale and front neck point, whose heights are ill-conditioned on smooth necks;
            // mid-thigh follows the knee level (a flat minimum of the leg's girth). Guarded by
            // looser bounds so that regressions still show.
            const auto known = kKnownOutside.find(m.name);
            const bool out = std::abs(diff) > tol;
            std::printf("  %-18s %9.1f %9.1f %+8.1f %5.0f%s\n", m.name.c_str(), m.value, *v, diff,
                        tol,
                        !out                           ? ""
                        : known != kKnownOutside.end() ? "  OUTSIDE (known)"
                                                       : "  OUTSIDE");
            if (known != kKnownOutside.end()) {
                EXPECT_LT(std::abs(diff), known->second) << proxy << " " << m.name;
                continue;
            }
            outside += out ? 1 : 0;
        }
        std::printf("  %d outside the ISO tolerance\n", outside);
        EXPECT_EQ(outside, 0) << proxy;
    }
}

}  // namespace
