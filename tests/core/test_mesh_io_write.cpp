// Writers: every format round-trips through our own reader with the same geometry and
// connectivity; the scalar PLY carries the values and colours a viewer needs.
#include <tapeline/core/errors.h>
#include <tapeline_test/io.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <vector>

namespace {

using tapeline_test::LoadedView;

class Write : public ::testing::Test {
protected:
    void SetUp() override {
        dir_ = tapeline_test::temp_dir(
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
        spot_ = tapeline_test::load(std::string(TAPELINE_DATA_DIR) + "/spot.obj");
        for (const auto& t : spot_.triangles) {
            faces_.push_back({t[0], t[1], t[2]});
        }
    }
    std::string dir_;
    LoadedView spot_;
    tapeline_test::Faces faces_;
};

/// Triangles with each one rotated to start at its smallest index (orientation kept).
std::vector<std::array<std::size_t, 3>> canonical(std::vector<std::array<std::size_t, 3>> ts) {
    for (auto& t : ts) {
        std::rotate(t.begin(), std::min_element(t.begin(), t.end()), t.end());
    }
    return ts;
}

/// x rounded to float. Through a volatile: g++ 12.2 at -O2/-O3 drops a plain (and a
/// memcpy-based) double->float->double round trip when the results initialise a
/// std::array<double, 3> (seen here; reduced case: SLP-vectorised push_back of three casts).
double to_float(double x) {
    volatile float f = static_cast<float>(x);
    return f;
}

std::string slurp(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

TEST_F(Write, ExactFormatsRoundTrip) {
    for (const std::string ext : {".off", ".obj", ".ply", ".OFF"}) {
        SCOPED_TRACE(ext);
        const std::string path = dir_ + "/spot" + ext;
        tapeline_test::write_mesh_from_soup(path, spot_.points, faces_);
        const LoadedView back = tapeline_test::load(path);
        EXPECT_TRUE(back.valid_polygon_mesh);
        EXPECT_TRUE(back.report.warnings.empty()) << back.report.summary();
        // 17 significant digits (text) or doubles (PLY): bit-identical coordinates, same order.
        EXPECT_EQ(back.points, spot_.points);
        EXPECT_EQ(canonical(back.triangles), canonical(spot_.triangles));
    }
}

TEST_F(Write, StlRoundTripInFloat) {
    const std::string path = dir_ + "/spot.stl";
    tapeline_test::write_mesh_from_soup(path, spot_.points, faces_);
    EXPECT_EQ(slurp(path).size(), 84u + 50u * spot_.triangles.size());
    const LoadedView back = tapeline_test::load(path);
    EXPECT_EQ(back.report.format, "stl-binary");
    EXPECT_TRUE(back.report.warnings.empty()) << back.report.summary();
    EXPECT_EQ(back.report.vertices, spot_.points.size());
    EXPECT_EQ(back.report.faces, spot_.triangles.size());
    EXPECT_TRUE(back.closed);
    // STL stores floats: every point comes back as its float rounding (STL numbers vertices by
    // first appearance, so compare as sorted sets).
    tapeline_test::Points expected;
    for (const auto& p : spot_.points) {
        expected.push_back({to_float(p[0]), to_float(p[1]), to_float(p[2])});
    }
    tapeline_test::Points got = back.points;
    std::sort(expected.begin(), expected.end());
    std::sort(got.begin(), got.end());
    ASSERT_EQ(got.size(), expected.size());
    for (std::size_t i = 0; i < got.size(); ++i) {
        ASSERT_EQ(got[i], expected[i]) << i;
    }
    // Same surface: the area agrees to float precision (relative 1e-6 covers the rounding of
    // coordinates of magnitude ~1 by 2^-24 ~ 6e-8 per coordinate, accumulated over the sum).
    EXPECT_NEAR(back.area, spot_.area, 1e-6 * spot_.area);
}

TEST_F(Write, RewriteLoadedFile) {
    const std::string path = dir_ + "/spot.ply";
    tapeline_test::rewrite_mesh(std::string(TAPELINE_DATA_DIR) + "/spot.obj", path);
    const LoadedView back = tapeline_test::load(path);
    EXPECT_EQ(back.report.format, "ply-binary-le");
    EXPECT_EQ(back.points, spot_.points);
}

/// A distance-like field on spot with a hole of non-finite values.
std::vector<double> field(const LoadedView& m) {
    std::vector<double> values;
    for (const auto& p : m.points) {
        values.push_back(std::sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]));
    }
    values[3] = std::numeric_limits<double>::infinity();
    values[5] = std::numeric_limits<double>::quiet_NaN();
    return values;
}

void expect_scalar_ply(const std::string& path, const LoadedView& spot,
                       const std::vector<double>& values, const std::string& property) {
    const tapeline::PolygonSoup soup = tapeline_test::read_soup(path);
    ASSERT_EQ(soup.points.size(), spot.points.size());
    EXPECT_EQ(soup.faces.size(), spot.triangles.size());
    ASSERT_EQ(soup.vertex_properties.count(property), 1u);
    const auto& got = soup.vertex_properties.at(property);
    const auto& red = soup.vertex_properties.at("red");
    const auto& green = soup.vertex_properties.at("green");
    const auto& blue = soup.vertex_properties.at("blue");
    std::size_t lo = 0, hi = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        for (int k = 0; k < 3; ++k) {
            ASSERT_EQ(soup.points[i][k], to_float(spot.points[i][k]));
        }
        if (std::isnan(values[i])) {
            EXPECT_TRUE(std::isnan(got[i]));
        } else {
            EXPECT_EQ(got[i], to_float(values[i])) << i;  // float property, exact
        }
        if (!std::isfinite(values[i])) {
            EXPECT_EQ(red[i], 128);
            EXPECT_EQ(green[i], 128);
            EXPECT_EQ(blue[i], 128);
            continue;
        }
        if (!std::isfinite(values[lo]) || values[i] < values[lo]) {
            lo = i;
        }
        if (!std::isfinite(values[hi]) || values[i] > values[hi]) {
            hi = i;
        }
    }
    // Ends of the finite range get the ends of viridis.
    EXPECT_EQ((std::array<double, 3>{red[lo], green[lo], blue[lo]}),
              (std::array<double, 3>{68, 1, 84}));
    EXPECT_EQ((std::array<double, 3>{red[hi], green[hi], blue[hi]}),
              (std::array<double, 3>{253, 231, 37}));
    for (std::size_t f = 0; f < soup.faces.size(); ++f) {
        ASSERT_EQ(soup.faces[f].size(), 3u);
    }
}

TEST_F(Write, ScalarPlyBinaryReadsBackWithTheSameValues) {
    const std::vector<double> values = field(spot_);
    const std::string path = dir_ + "/distance.ply";
    tapeline_test::write_scalar_from_soup(path, spot_.points, faces_, values);
    const std::string bytes = slurp(path);
    const std::string header = bytes.substr(0, bytes.find("end_header"));
    EXPECT_NE(header.find("format binary_little_endian 1.0"), std::string::npos);
    EXPECT_NE(header.find("property float distance\nproperty uchar red\nproperty uchar green\n"
                          "property uchar blue\n"),
              std::string::npos)
        << header;
    expect_scalar_ply(path, spot_, values, "distance");
    // And it is an ordinary mesh file for the loader too.
    const LoadedView back = tapeline_test::load(path);
    EXPECT_EQ(back.report.format, "ply-binary-le");
    EXPECT_EQ(back.report.vertices, spot_.points.size());
}

TEST_F(Write, ScalarPlyAscii) {
    const std::vector<double> values = field(spot_);
    tapeline::ScalarPlyOptions options;
    options.binary = false;
    options.property = "geodesic_distance";
    const std::string path = dir_ + "/distance_ascii.ply";
    tapeline_test::write_scalar_from_soup(path, spot_.points, faces_, values, options);
    EXPECT_EQ(tapeline_test::read_soup(path).format, "ply-ascii");
    expect_scalar_ply(path, spot_, values, "geodesic_distance");
}

TEST_F(Write, ScalarPlyConstantAndAllNonFiniteFields) {
    const std::string path = dir_ + "/flat.ply";
    tapeline_test::write_scalar_from_soup(path, spot_.points, faces_,
                                          std::vector<double>(spot_.points.size(), 2.5));
    const auto soup = tapeline_test::read_soup(path);
    EXPECT_EQ(soup.vertex_properties.at("distance").front(), 2.5);
    EXPECT_EQ(soup.vertex_properties.at("red").front(), 68);  // bottom of the map, not NaN
    tapeline_test::write_scalar_from_soup(
        path, spot_.points, faces_,
        std::vector<double>(spot_.points.size(), std::numeric_limits<double>::infinity()));
    EXPECT_EQ(tapeline_test::read_soup(path).vertex_properties.at("green").back(), 128);
}

TEST_F(Write, FailedWriteLeavesExistingFileUntouched) {
    const std::string path = dir_ + "/keep.ply";
    tapeline_test::write_scalar_from_soup(path, spot_.points, faces_, field(spot_));
    const std::string before = slurp(path);
    EXPECT_THROW(tapeline_test::write_scalar_from_soup(path, spot_.points, faces_, {1.0}),
                 tapeline::InvalidInput);
    EXPECT_EQ(slurp(path), before);
}

}  // namespace
