// Bad input is rejected with one line naming what and where (DESIGN.md §4); landmark override
// files replace found landmarks.
#include <tapeline/core/errors.h>
#include <tapeline_test/expect.h>
#include <tapeline_test/measurement.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>

namespace {

using namespace tapeline_test::measurement;
using tapeline::InvalidInput;
using tapeline::TopologyError;
using tapeline_test::expect_error;

// A closed octahedron 1.7 units tall (as a tiny "body"), and the same with one face removed.
std::vector<Vec3> octahedron() {
    return {{0.3, 0.85, 0},  {-0.3, 0.85, 0}, {0, 0.85, 0.3},
            {0, 0.85, -0.3}, {0, 1.7, 0},     {0, 0, 0}};
}
Triangles octahedron_faces() {
    return {{4, 2, 0}, {4, 1, 2}, {4, 3, 1}, {4, 0, 3}, {5, 0, 2}, {5, 2, 1}, {5, 1, 3}, {5, 3, 0}};
}

// The hole left by one face is 0.90 m across (from (0, 0, 0) to (0.3, 0.85, 0)), far more than
// the 85 mm (5 % of 1.7 m) make_body fills; its centre (the corners' mean) is 567 mm high.
TEST(MeasurementInput, OpenMeshWithABigHoleIsRejectedNamingTheHole) {
    Triangles open = octahedron_faces();
    open.pop_back();
    BodyOptions o;
    o.name = "open.obj";
    expect_error<TopologyError>(
        [&] { measure_mesh(octahedron(), open, o); },
        {"open.obj: a hole 901 mm across at 567 mm height", "(holes up to 85 mm, 5 % of the"},
        "open mesh");
}

TEST(MeasurementInput, UnknownUnitAxisAndPoseStrings) {
    expect_error<InvalidInput>([] { parse_length_unit("inch", "--units"); },
                               {"--units", "unknown length unit 'inch'", "m, dm, cm or mm"},
                               "unit");
    expect_error<InvalidInput>([] { Axis::parse("Q", "--up"); },
                               {"--up", "unknown axis 'Q'", "+X, -X, +Y, -Y, +Z or -Z"}, "axis");
    expect_error<InvalidInput>([] { Axis::parse("+XY", "--front"); }, {"--front", "'+XY'"}, "axis");
    expect_error<InvalidInput>([] { parse_pose("Y", "--pose"); }, {"--pose", "'Y'", "A or T"},
                               "pose");
    EXPECT_EQ(parse_length_unit("dm", "--units"), LengthUnit::dm);
    EXPECT_EQ(Axis::parse("-z", "--front").to_string(), "-Z");
}

TEST(MeasurementInput, UpAndFrontOnTheSameAxisAreRejected) {
    BodyOptions o;
    o.name = "body.obj";
    o.front = Axis::parse("-Y", "--front");
    expect_error<InvalidInput>([&] { measure_mesh(octahedron(), octahedron_faces(), o); },
                               {"body.obj", "up axis +Y", "front axis -Y", "perpendicular"},
                               "axes");
}

TEST(MeasurementInput, NanCoordinateIsRejectedNamingTheVertex) {
    auto pts = octahedron();
    pts[3][2] = std::numeric_limits<double>::quiet_NaN();
    BodyOptions o;
    o.name = "nan.obj";
    expect_error<InvalidInput>([&] { measure_mesh(pts, octahedron_faces(), o); },
                               {"nan.obj", "vertex 3", "NaN"}, "nan");
}

TEST(MeasurementInput, UnitsAreInferredOnlyWhenTheHeightIsUnambiguous) {
    EXPECT_EQ(infer_length_unit(1.7, "b"), LengthUnit::m);
    EXPECT_EQ(infer_length_unit(13.1, "b"), LengthUnit::dm);
    EXPECT_EQ(infer_length_unit(165, "b"), LengthUnit::cm);
    EXPECT_EQ(infer_length_unit(1800, "b"), LengthUnit::mm);
    for (double h : {0.3, 3.7, 40.0, 400.0, 9000.0}) {
        char text[32];
        std::snprintf(text, sizeof text, "%g", h);
        expect_error<InvalidInput>(
            [&] { infer_length_unit(h, "body.obj"); },
            {"body.obj", std::string("units cannot be inferred from height ") + text,
             "pass --units"},
            text);
    }
    // Through the whole pipeline: a body 40 units tall.
    auto pts = octahedron();
    for (auto& p : pts) {
        p[1] *= 40 / 1.7;
    }
    BodyOptions o;
    o.name = "tall.obj";
    expect_error<InvalidInput>([&] { measure_mesh(pts, octahedron_faces(), o); },
                               {"tall.obj", "height 40", "pass --units"}, "pipeline");
}

TEST(MeasurementInput, ShapeWithoutLegsArmsOrNeckIsNotABody) {
    // A human height, upright, but nothing of a body: refused, naming what was looked for.
    BodyOptions o;
    o.unit = LengthUnit::m;
    o.name = "octa.obj";
    expect_error<InvalidInput>([&] { measure_mesh(octahedron(), octahedron_faces(), o); },
                               {"octa.obj", "does not look like a body", "crotch", "armpits"},
                               "octahedron");
}

TEST(MeasurementInput, BadOverrideFilesAreRejected) {
    expect_error<InvalidInput>([] { parse_overrides("{"); }, {"L.json", "malformed JSON"}, "json");
    expect_error<InvalidInput>([] { parse_overrides("[]"); }, {"L.json", "\"landmarks\""}, "shape");
    expect_error<InvalidInput>([] { parse_overrides(R"({"landmarks": {"navel": [0, 0, 0]}})"); },
                               {"L.json", "unknown landmark 'navel'", "crotch"}, "name");
    expect_error<InvalidInput>([] { parse_overrides(R"({"landmarks": {"crotch": [0, 0]}})"); },
                               {"L.json", "landmarks.crotch", "3 finite numbers"}, "value");
    expect_error<InvalidInput>([] { parse_overrides(R"({"frame": "world", "landmarks": {}})"); },
                               {"L.json", "\"frame\"", "\"input\" or \"canonical\""}, "frame");
    EXPECT_EQ(parse_overrides(R"({"landmarks": {"crotch": [0, 1, 2], "knee_left": [1, 2, 3]}})"),
              2u);
}

TEST(MeasurementInput, OverriddenLandmarksAreUsedDownstream) {
    const std::string path = ::testing::TempDir() + "tapeline_overrides.json";
    {
        // The waist moved 60 mm up (canonical frame): the waist girth follows it.
        std::ofstream f(path);
        f << R"({"frame": "canonical", "landmarks": {"waist_front": [0, 1100, 90]}})";
    }
    const SyntheticBody body({40, 10, 40});
    const Result r = measure_synthetic({40, 10, 40}, {}, path);
    std::remove(path.c_str());
    const Landmark* w = r.landmarks.find("waist_front");
    EXPECT_EQ(w->status, LandmarkStatus::overridden);
    EXPECT_NEAR(w->point[1], 1100, 1e-9);
    EXPECT_NEAR(r.measurements.value("waist_girth").value(), body.torso_girth(1100), 4.0);
    EXPECT_NEAR(r.landmarks.find("waist_back")->point[1], 1100, 1e-9);
}

}  // namespace
