// Bodies with holes, as scans have them: faces cut out around the soles' lowest points, the crown
// and one armpit (placed from the closed body's landmarks) are filled and measured against the
// closed body, on the A- and the T-pose: every value within ISO 20685-1's tolerances (4 mm small
// girths and heights, 9 mm the large torso and thigh girths, 5 mm lengths along the skin). Tapes
// crossing the armpit's patch are marked, and a hole too big
// to fill is refused naming its size, height and place. Oracle: the same body closed (the cut only
// removes faces, so everything the holes do not touch is the same surface). Skipped when the
// shared data is absent.
#include <tapeline/core/errors.h>
#include <tapeline_test/expect.h>
#include <tapeline_test/measurement.h>
#include <tapeline_test/measurement_holes.h>
#include <tapeline_test/measurement_landmarks.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <map>
#include <string>
#include <vector>

namespace {

using namespace tapeline_test::measurement;
using tapeline::TopologyError;
using tapeline_test::expect_error;

const std::string kDir = std::string(TAPELINE_SHARED_DATA_DIR) + "/bodies/";

bool have_data() {
    return std::ifstream(kDir + "mh_female_average.obj").good();
}

Soup soup_of(const std::string& file) {
    return canonical_soup(kDir + file, body_options(file, LengthUnit::dm));
}

// The hole sets: where the faces are cut out, from the closed body.
struct HoleSet {
    std::string name;
    std::vector<HoleCut> cuts;
    std::vector<std::string> regions;  // every hole's region is one of these
};

std::vector<HoleSet> hole_sets(const Soup& soup, const Result& closed) {
    const double h = closed.frame.height, r = 0.012 * h;
    // The crown and the armpit have coarser triangles than the feet: a smaller ball cuts a
    // hole of about the same size.
    const double r_coarse = 0.006 * h;
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& p : soup.points) {
        lo = std::min(lo, p[0]);
        hi = std::max(hi, p[0]);
    }
    const double mid = 0.5 * (lo + hi);
    // The lowest vertex on each side of the midline: the sole under the heel or the ball.
    Vec3 sole[2] = {{0, h, 0}, {0, h, 0}};
    for (const auto& p : soup.points) {
        Vec3& s = sole[p[0] >= mid ? 0 : 1];
        if (p[1] < s[1]) {
            s = p;
        }
    }
    const Vec3 crown = *closed.landmarks.point("top_of_head");
    const Vec3 armpit = *closed.landmarks.point("armpit_right");
    const HoleSet soles{"soles", {{sole[0], r}, {sole[1], r}}, {"the left sole", "the right sole"}};
    const HoleSet top{"crown", {{crown, r_coarse}}, {"the crown"}};
    // The right armpit: the side whose lengths (waist_to_armpit) are taken.
    const HoleSet pit{"armpit",
                      {{armpit, r_coarse}},
                      {"the right armpit", "the right arm", "the right side of the torso"}};
    HoleSet all{"all", {}, {}};
    for (const auto* s : {&soles, &top, &pit}) {
        all.cuts.insert(all.cuts.end(), s->cuts.begin(), s->cuts.end());
        all.regions.insert(all.regions.end(), s->regions.begin(), s->regions.end());
    }
    return {soles, top, pit, all};
}

// The largest |difference| to the closed body's value, per kind (girths; lengths and heights).
struct Figures {
    double girth = 0, length = 0;
    std::string worst_girth, worst_length;
    int marked = 0;
};

// Every measurement of the closed body within ISO 20685-1 on the holed one.
Figures compare(const Result& closed, const Result& holed, const HoleSet& set,
                const std::string& what) {
    Figures f;
    for (const auto& l : holed.landmarks.landmarks) {
        EXPECT_TRUE(l.available()) << what << ": " << l.reason;
    }
    for (const auto& m : closed.measurements.measurements) {
        if (m.kind == MeasurementKind::angle) {
            continue;
        }
        EXPECT_FALSE(m.crosses_filled_hole) << what << " closed " << m.name;
        const Measurement* v = holed.measurements.find(m.name);
        if (!v) {
            ADD_FAILURE() << what << ": " << m.name << " not measured with holes";
            continue;
        }
        const double d = v->value - m.value;
        EXPECT_LE(std::abs(d), iso20685_tolerance(m))
            << what << " " << m.name << ": " << m.value << " closed, " << v->value << " filled"
            << (v->crosses_filled_hole ? " (crosses a filled hole)" : "");
        double& worst = m.kind == MeasurementKind::girth ? f.girth : f.length;
        if (std::abs(d) > worst) {
            worst = std::abs(d);
            (m.kind == MeasurementKind::girth ? f.worst_girth : f.worst_length) = m.name;
        }
        if (v->crosses_filled_hole) {
            ++f.marked;
            // A marked tape passes near a hole: one of its points within the cut ball (plus
            // the tape's bridging of hollows, 3 % of the height) of a cut centre.
            double nearest = std::numeric_limits<double>::infinity();
            for (const auto& p : v->points) {
                for (const auto& c : set.cuts) {
                    nearest = std::min(nearest, std::hypot(p[0] - c.centre[0], p[1] - c.centre[1],
                                                           p[2] - c.centre[2]) -
                                                    c.radius);
                }
            }
            EXPECT_LE(nearest, 0.03 * closed.frame.height) << what << " " << m.name;
        }
    }
    return f;
}

void check_holes(const Result& holed, const HoleSet& set, const std::string& what) {
    ASSERT_FALSE(holed.report.holes.empty()) << what;
    EXPECT_GE(holed.report.holes.size(), set.cuts.size()) << what;
    for (const auto& hole : holed.report.holes) {
        std::printf("    hole %5.1f mm at %6.1f mm, %s, %s, %zu faces\n", hole.size, hole.height,
                    hole.region.c_str(), hole.filling.c_str(), hole.faces_added);
        EXPECT_LE(hole.size, 0.05 * holed.frame.height) << what;
        EXPECT_GT(hole.faces_added, 0u) << what;
        EXPECT_NE(std::find(set.regions.begin(), set.regions.end(), hole.region), set.regions.end())
            << what << ": a hole named '" << hole.region << "'";
        EXPECT_EQ(hole.filling, "faired") << what << " " << hole.region;
    }
}

// Two bundled bodies and two of the population, each with four hole sets.
TEST(BodyHoles, SmallHolesAreFilledAndMeasureLikeTheClosedBody) {
    if (!have_data()) {
        GTEST_SKIP() << "no " << kDir;
    }
    std::map<std::string, Figures> per_set;
    for (const char* file : {"mh_female_average.obj", "mh_male_average.obj",
                             "population/mh_pop_003.ply", "population/mh_pop_017.ply"}) {
        const Soup soup = soup_of(file);
        const Result closed = measure_soup_with_skin_lengths(soup, file);
        ASSERT_TRUE(closed.report.holes.empty()) << file;
        for (const HoleSet& set : hole_sets(soup, closed)) {
            const std::string what = std::string(file) + " " + set.name;
            const Soup cut = cut_holes(soup, set.cuts);
            ASSERT_LT(cut.triangles.size(), soup.triangles.size()) << what;
            std::printf("%s: %zu faces cut\n", what.c_str(),
                        soup.triangles.size() - cut.triangles.size());
            const Result holed = measure_soup_with_skin_lengths(cut, what);
            check_holes(holed, set, what);
            // Every set within ISO 20685-1. With CGAL's default patch density the crown and
            // armpit patches (6-11 faces) were nearly flat and the landmarks hung on them moved:
            // up to 10.5 mm on girths and 16 mm on lengths (measurement/README.md).
            const Figures f = compare(closed, holed, set, what);
            std::printf("  max |diff| girth %.2f mm (%s), length/height %.2f mm (%s), %d marked\n",
                        f.girth, f.worst_girth.c_str(), f.length, f.worst_length.c_str(), f.marked);
            Figures& s = per_set[set.name];
            s.girth = std::max(s.girth, f.girth);
            s.length = std::max(s.length, f.length);
            s.marked += f.marked;
            if (set.name == "armpit" || set.name == "all") {
                EXPECT_GT(f.marked, 0) << what << ": no tape marked as crossing the armpit's patch";
            }
            // The right armpit's patch is under the high bust tape or the waist-to-armpit path.
            for (const auto& m : holed.measurements.measurements) {
                std::printf("%s",
                            m.crosses_filled_hole ? ("    marked: " + m.name + "\n").c_str() : "");
            }
        }
    }
    std::printf("hole set   max |girth diff|   max |length diff|   marked\n");
    for (const auto& [name, f] : per_set) {
        std::printf("%-8s %12.2f mm %16.2f mm %8d\n", name.c_str(), f.girth, f.length, f.marked);
    }
}

// The T-pose path on a body with holes: the arms raised after the holes were cut.
TEST(BodyHoles, TPoseBodyWithHolesMeasuresLikeTheClosedTPose) {
    if (!have_data()) {
        GTEST_SKIP() << "no " << kDir;
    }
    const char* file = "mh_female_average.obj";
    const Soup soup = soup_of(file);
    const Result closed = measure_soup_with_skin_lengths(soup, file);
    const HoleSet set = hole_sets(soup, closed).back();  // all
    Soup posed = soup;
    posed.points = raise_arms_to_t_pose(soup.points, closed.landmarks, 0.02 * closed.frame.height);
    Soup holed = cut_holes(soup, set.cuts);
    holed.points = raise_arms_to_t_pose(holed.points, closed.landmarks, 0.02 * closed.frame.height);
    const Result t_closed = measure_soup_with_skin_lengths(posed, "T closed", Pose::t_pose);
    const Result t_holed = measure_soup_with_skin_lengths(holed, "T holes", Pose::t_pose);
    check_holes(t_holed, set, "T-pose");
    const Figures f = compare(t_closed, t_holed, set, "T-pose");
    std::printf(
        "T-pose all holes: max |diff| girth %.2f mm (%s), length/height %.2f mm (%s), "
        "%d marked\n",
        f.girth, f.worst_girth.c_str(), f.length, f.worst_length.c_str(), f.marked);
}

// A hole of 10 % of the stature on the left side of the waist, and a band around the torso.
TEST(BodyHoles, AHoleTooBigToFillIsRefusedNamingWhereItIs) {
    if (!have_data()) {
        GTEST_SKIP() << "no " << kDir;
    }
    const char* file = "mh_female_average.obj";
    const Soup soup = soup_of(file);
    const Result closed = measure_soup_with_skin_lengths(soup, file);
    const double h = closed.frame.height, yw = (*closed.landmarks.point("waist_front"))[1];
    // The torso's leftmost point at the waist (the hanging arm is further out than 0.15 H).
    double mid_x = 0;
    for (const char* n : {"waist_front", "waist_back"}) {
        mid_x += 0.5 * (*closed.landmarks.point(n))[0];
    }
    Vec3 side{mid_x, yw, 0};
    for (const auto& p : soup.points) {
        if (std::abs(p[1] - yw) < 5 && p[0] - mid_x < 0.15 * h && p[0] > side[0]) {
            side = p;
        }
    }
    ASSERT_GT(side[0] - mid_x, 0.04 * h);
    const Soup cut = cut_holes(soup, {{side, 0.05 * h}});
    char limit[64];
    std::snprintf(limit, sizeof limit, "(holes up to %.0f mm, 5 %% of the stature", 0.05 * h);
    try {
        fill_soup(cut, "side.obj");
        ADD_FAILURE() << "a hole 10 % of the stature across was filled";
    } catch (const TopologyError& e) {
        const std::string msg = e.what();
        std::printf("%s\n", msg.c_str());
        for (const std::string& part :
             std::vector<std::string>{"side.obj: a hole ", " mm across at ",
                                      " mm height, the left side of the torso", limit}) {
            EXPECT_NE(msg.find(part), std::string::npos) << msg << " lacks " << part;
        }
        // The size and the height of its centre, as written ("1,023" is 1023 mm).
        auto number_before = [&](const std::string& tail) {
            const std::size_t end = msg.find(tail);
            std::size_t begin = end;
            while (begin > 0 && (std::isdigit(static_cast<unsigned char>(msg[begin - 1])) ||
                                 msg[begin - 1] == ',')) {
                --begin;
            }
            std::string digits;
            for (std::size_t i = begin; i < end; ++i) {
                if (msg[i] != ',') {
                    digits += msg[i];
                }
            }
            return digits.empty() ? -1.0 : std::stod(digits);
        };
        const double size = number_before(" mm across"), height = number_before(" mm height");
        EXPECT_GT(size, 0.05 * h) << msg;
        EXPECT_LT(size, 0.15 * h) << msg;  // the ball's diameter plus the cut triangles
        EXPECT_NEAR(height, yw, 0.02 * h) << msg;
    }
    // A band of the torso (everything within 2 % of the height of the waist level, the arms
    // left): two loops around the torso.
    Soup band = soup;
    band.triangles.clear();
    for (const auto& t : soup.triangles) {
        bool in = false;
        for (std::uint32_t v : t) {
            const Vec3& p = soup.points[v];
            in = in || (std::abs(p[1] - yw) < 0.02 * h && std::abs(p[0] - mid_x) < 0.15 * h);
        }
        if (!in) {
            band.triangles.push_back(t);
        }
    }
    expect_error<TopologyError>([&] { fill_soup(band, "band.obj"); },
                                {"band.obj: a hole ", "around the torso", "1 more too big"},
                                "band");
}

// Non-manifold edges are refused as on a closed mesh, holes or not.
TEST(BodyHoles, NonManifoldOpenMeshIsRefusedNamingTheEdge) {
    Soup s;
    s.points = {{300, 850, 0}, {-300, 850, 0}, {0, 850, 300},   {0, 850, -300},
                {0, 1700, 0},  {0, 0, 0},      {100, 1200, 200}};
    s.triangles = {{4, 2, 0}, {4, 1, 2}, {4, 3, 1}, {4, 0, 3},
                   {5, 0, 2}, {5, 2, 1}, {5, 1, 3}, {4, 2, 6}};  // {5, 3, 0} removed, a fin added
    expect_error<TopologyError>([&] { fill_soup(s, "fin.obj"); },
                                {"fin.obj", "non-manifold edge between vertices 2 and 4"}, "fin");
}

}  // namespace
