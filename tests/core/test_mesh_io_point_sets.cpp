// Point sets without faces (core/point_io.h): the three formats read back the coordinates
// written, and each rejection names the file, the line and what is wrong.
#include <tapeline/core/errors.h>
#include <tapeline_test/expect.h>
#include <tapeline_test/io_fixture.h>

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace {

using tapeline_test::expect_error;
using tapeline_test::read_points;

class PointSets : public tapeline_test::TempFileTest {};

TEST_F(PointSets, XyzWithCommentsBlankLinesAndAnyDimension) {
    const std::string p3 = file("a.xyz", "# unit points\n1 2 3\n\n  -4.5\t5e-1 6 # trailing\n");
    const auto a = read_points(p3);
    EXPECT_EQ(a.format, "xyz");
    EXPECT_EQ(a.file, p3);
    EXPECT_EQ(a.dimension, 3u);
    EXPECT_EQ(a.coordinates, (std::vector<double>{1, 2, 3, -4.5, 0.5, 6}));
    EXPECT_TRUE(a.normals.empty());
    const auto b = read_points(file("b.XYZ", "0.25 1\n2 3\n4 5\n"));  // D = 2, upper-case
    EXPECT_EQ(b.dimension, 2u);
    EXPECT_EQ(b.coordinates, (std::vector<double>{0.25, 1, 2, 3, 4, 5}));
}

TEST_F(PointSets, CsvWithAndWithoutAHeader) {
    const auto a = read_points(file("a.csv", "x,y,z,w,v\n1, 2, 3, 4, 5\n6,7,8,9,10\n"));
    EXPECT_EQ(a.format, "csv");
    EXPECT_EQ(a.dimension, 5u);
    EXPECT_EQ(a.coordinates, (std::vector<double>{1, 2, 3, 4, 5, 6, 7, 8, 9, 10}));
    const auto b = read_points(file("b.csv", "1,2,3\n-1e3,0,7.5\n"));
    EXPECT_EQ(b.dimension, 3u);
    EXPECT_EQ(b.coordinates, (std::vector<double>{1, 2, 3, -1000, 0, 7.5}));
}

TEST_F(PointSets, PlyVerticesAndNormalsFacesIgnored) {
    const auto a = read_points(file("a.ply",
                                    "ply\nformat ascii 1.0\nelement vertex 3\nproperty double x\n"
                                    "property double y\nproperty double z\nproperty float nx\n"
                                    "property float ny\nproperty float nz\nelement face 1\n"
                                    "property list uchar int vertex_indices\nend_header\n"
                                    "0 0 0 0 0 1\n1 0 0 0 0 1\n0 2 0 0 1 0\n3 0 1 2\n"));
    EXPECT_EQ(a.format, "ply");
    EXPECT_EQ(a.dimension, 3u);
    EXPECT_EQ(a.coordinates, (std::vector<double>{0, 0, 0, 1, 0, 0, 0, 2, 0}));
    EXPECT_EQ(a.normals, (std::vector<double>{0, 0, 1, 0, 0, 1, 0, 1, 0}));
    const auto b = read_points(file("b.ply",
                                    "ply\nformat ascii 1.0\nelement vertex 2\nproperty float x\n"
                                    "property float y\nproperty float z\nend_header\n"
                                    "1 2 3\n4 5 6\n"));
    EXPECT_EQ(b.coordinates, (std::vector<double>{1, 2, 3, 4, 5, 6}));
    EXPECT_TRUE(b.normals.empty());
}

TEST_F(PointSets, RejectionsNameTheFileTheLineAndTheFault) {
    using tapeline::InvalidInput;
    const std::string rows = file("rows.xyz", "1 2 3\n4 5 6\n7 8\n");
    expect_error<InvalidInput>([&] { read_points(rows); },
                               {rows, "line 3: 2 coordinates, but line 1 has 3"}, "row length");
    const std::string text = file("text.csv", "x,y,z\n1,2,3\n4,abc,6\n");
    expect_error<InvalidInput>([&] { read_points(text); },
                               {text, "line 3: coordinate 2 'abc' is not a number"},
                               "not a number");
    const std::string nan = file("nan.xyz", "1 2 3\n4 nan 6\n");
    expect_error<InvalidInput>([&] { read_points(nan); }, {nan, "line 2: coordinate 2 is NaN"},
                               "NaN");
    const std::string inf = file("inf.csv", "1,2,3\n4,5,inf\n");
    expect_error<InvalidInput>([&] { read_points(inf); }, {inf, "line 2: coordinate 3 is infinite"},
                               "infinite");
    const std::string ext = file("points.txt", "1 2 3\n");
    expect_error<InvalidInput>(
        [&] { read_points(ext); },
        {ext, "unknown point-set format '.txt' (expected .xyz, .csv or .ply)"}, "extension");
    const std::string one = file("one.xyz", "1\n2\n");
    expect_error<InvalidInput>([&] { read_points(one); },
                               {one, "line 1: a point needs at least 2 coordinates, found 1"},
                               "one coordinate");
    const std::string empty = file("empty.csv", "x,y,z\n\n");
    expect_error<InvalidInput>([&] { read_points(empty); }, {empty, "no points"}, "no points");
    const std::string missing = dir_ + "/missing.xyz";
    expect_error<InvalidInput>([&] { read_points(missing); }, {missing}, "missing file");
}

}  // namespace
