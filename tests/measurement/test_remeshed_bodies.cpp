// A body measures the same whatever its triangles: bodies re-meshed by CGAL (isotropic remeshing
// for 5 mm edges, a Garland–Heckbert decimation to 5,000 vertices; tapeline/core/remesh.h) against
// the original mesh: every landmark found, no self-check warning, every measurement of the
// original found again and within ISO 20685-1 (girths 4 mm, 9 mm the large torso and thigh
// girths; heights 4 mm; lengths along the skin 5 mm). Oracle: the original mesh, measured the same
// way. Two measurements still move more with the triangles on the population
// (docs/bench_measure/remeshed.md, measurement/README.md): the cross seam and the inseam (they
// hang on the crotch point's level) and waist to knee (on the knee's); they get the slack below.
// The 20 mm re-meshing is left to the benchmark: its chords cut small girths by more than ISO
// allows (a 108 mm wrist drawn with 18.5 mm chords loses about 5 mm). One bundled body, one of the
// hold-out population, and two whose elbow (mh_pop_032: shoulder to elbow +29 / +31 mm) and wrist
// (mh_pop_022: shoulder to wrist +7 mm decimated) followed the triangles when they were taken at
// the farthest bend and the narrowest section. Skipped without the data.
#include <tapeline_test/measurement.h>
#include <tapeline_test/measurement_holes.h>
#include <tapeline_test/measurement_remesh.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

namespace {

using namespace tapeline_test::measurement;

const std::string kDir = std::string(TAPELINE_SHARED_DATA_DIR) + "/bodies/";

struct Variant {
    const char* name;
    double edge_mm;        // isotropic remeshing; 0: decimation
    std::size_t vertices;  // decimation target
};

// How many measurements fall outside ISO 20685-1, and the worst excess.
struct Outcome {
    int compared = 0, outside = 0;
    double worst = -std::numeric_limits<double>::infinity();  ///< max |diff| - tolerance, mm
    std::string worst_name;
};

// Slack beyond ISO 20685-1 for the measurements that still move with the triangles (mm): the
// cross seam and the inseam hang on the crotch point's level and are held to ISO + 8 mm. The
// neck base girth and the front neck to waist length, which hang on the front neck point, are
// held to ISO itself (before the front neck point's depth was smoothed, a 9.6 mm drop of that
// point gave +38 mm on mh_pop_036's decimated copy).
double slack(const Measurement& m) {
    if (m.name.rfind("cross_seam", 0) == 0 || m.name == "inseam") {
        return 8;
    }
    // Waist to knee ends at the knee landmark's level: outside ISO on 2 of the 49 bodies' 5 mm
    // copies and 3 of their 5k copies (docs/bench_measure/remeshed.md); mh_pop_036's 5k copy
    // -5.4 mm.
    if (m.name == "waist_to_knee") {
        return 3;
    }
    return 0;
}

Outcome compare(const Result& original, const Result& variant, const std::string& what) {
    Outcome o;
    for (const auto& l : variant.landmarks.landmarks) {
        EXPECT_TRUE(l.available()) << what << ": " << l.reason;
    }
    EXPECT_TRUE(variant.warnings.empty())
        << what << ": " << variant.warnings.size() << " self-check warning(s), the first: "
        << (variant.warnings.empty() ? "" : variant.warnings.front().message);
    for (const auto& m : original.measurements.measurements) {
        if (m.kind == MeasurementKind::angle) {
            continue;
        }
        const Measurement* v = variant.measurements.find(m.name);
        if (!v) {
            ADD_FAILURE() << what << ": " << m.name << " not measured";
            continue;
        }
        ++o.compared;
        const double d = v->value - m.value, tol = iso20685_tolerance(m) + slack(m);
        if (std::abs(d) > tol) {
            ++o.outside;
            std::printf("  %-28s %9.1f %9.1f %+7.1f  tol %.0f  OUTSIDE\n", m.name.c_str(), m.value,
                        v->value, d, tol);
        }
        if (std::abs(d) - tol > o.worst) {
            o.worst = std::abs(d) - tol;
            o.worst_name = m.name;
        }
    }
    std::printf("%s: %d compared, %d outside their bound, worst |diff| - bound %+.2f mm (%s)\n",
                what.c_str(), o.compared, o.outside, o.worst, o.worst_name.c_str());
    return o;
}

TEST(RemeshedBodies, MeasureLikeTheOriginalMesh) {
    if (!std::ifstream(kDir + "mh_female_average.obj").good()) {
        GTEST_SKIP() << "no " << kDir;
    }
    const Variant variants[] = {{"isotropic 5 mm", 5, 0}, {"decimated to 5k vertices", 0, 5000}};
    for (const char* file : {"mh_female_average.obj", "population/mh_pop_036.ply",
                             "population/mh_pop_032.ply", "population/mh_pop_022.ply"}) {
        const Soup soup = canonical_soup(kDir + file, body_options(file, LengthUnit::dm));
        const Result original = measure_soup_with_skin_lengths(soup, file);
        ASSERT_TRUE(original.warnings.empty()) << file;
        for (const Variant& v : variants) {
            const std::string what = std::string(file) + ", " + v.name;
            const Soup other =
                v.edge_mm > 0 ? remeshed_soup(soup, v.edge_mm) : simplified_soup(soup, v.vertices);
            std::printf("%s: %zu vertices (original %zu)\n", what.c_str(), other.points.size(),
                        soup.points.size());
            if (v.edge_mm == 0) {
                EXPECT_NEAR(static_cast<double>(other.points.size()), 5000.0, 50.0) << what;
            }
            const Result r = measure_soup_with_skin_lengths(other, what);
            const Outcome o = compare(original, r, what);
            EXPECT_GT(o.compared, 40) << what;
            EXPECT_EQ(o.outside, 0) << what;
        }
    }
}

}  // namespace
