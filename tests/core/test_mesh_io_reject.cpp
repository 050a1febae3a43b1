// Every input the mesh reader rejects, fed from a file written by the test itself; each test checks
// the exception type and that the one-line message names the file and the element (DESIGN.md §6).
#include <tapeline/core/errors.h>
#include <tapeline_test/io.h>
#include <tapeline_test/io_bytes.h>
#include <tapeline_test/io_fixture.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <functional>
#include <limits>
#include <string>
#include <vector>

namespace {

using tapeline::InvalidInput;
using tapeline::MeshLoadOptions;
using tapeline::TopologyError;
using tapeline_test::load;
using tapeline_test::load_soup;

/// Runs `action`, expects exception E whose message contains every part and is a single line.
template <class E>
void expect_error(const std::function<void()>& action, const std::vector<std::string>& parts) {
    try {
        action();
        ADD_FAILURE() << "no exception; expected one containing '" << parts.front() << "'";
    } catch (const E& e) {
        const std::string message = e.what();
        for (const std::string& part : parts) {
            EXPECT_NE(message.find(part), std::string::npos)
                << "message: " << message << "\nexpected to contain: " << part;
        }
        EXPECT_EQ(message.find('\n'), std::string::npos) << "not one line: " << message;
    } catch (const std::exception& e) {
        ADD_FAILURE() << "wrong exception type, message: " << e.what();
    }
}

class Reject : public tapeline_test::TempFileTest {
protected:
    /// Loading `path` throws E with a message naming the path and containing `parts`.
    template <class E>
    void expect_load_error(const std::string& path, std::vector<std::string> parts,
                           const MeshLoadOptions& options = {}) {
        parts.insert(parts.begin(), path + ": ");
        expect_error<E>([&] { load(path, options); }, parts);
    }
};

const char* const kTetraOff =
    "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n";

// --- binary helpers -----------------------------------------------------------------------------

using tapeline_test::put;

/// Binary PLY (float xyz, uchar/int lists) of the given soup.
std::string binary_ply(const tapeline_test::Points& points, const tapeline_test::Faces& faces,
                       bool big_endian = false) {
    std::string out =
        std::string("ply\nformat ") + (big_endian ? "binary_big_endian" : "binary_little_endian") +
        " 1.0\nelement vertex " + std::to_string(points.size()) +
        "\nproperty float x\nproperty float y\nproperty float z\nelement face " +
        std::to_string(faces.size()) + "\nproperty list uchar int vertex_indices\nend_header\n";
    for (const auto& p : points) {
        for (double x : p) {
            put(out, static_cast<float>(x), big_endian);
        }
    }
    for (const auto& f : faces) {
        put(out, static_cast<std::uint8_t>(f.size()), big_endian);
        for (std::size_t v : f) {
            put(out, static_cast<std::int32_t>(v), big_endian);
        }
    }
    return out;
}

/// Binary STL of triangles given by corner coordinates.
std::string binary_stl(const std::vector<std::array<float, 9>>& triangles) {
    std::string out(80, ' ');
    put(out, static_cast<std::uint32_t>(triangles.size()), false);
    for (const auto& t : triangles) {
        for (int k = 0; k < 3; ++k) {
            put(out, 0.0f, false);
        }
        for (float x : t) {
            put(out, x, false);
        }
        put(out, std::uint16_t{0}, false);
    }
    return out;
}

using tapeline_test::kTetraFaces;
using tapeline_test::kTetraPoints;

// --- any format
// -----------------------------------------------------------------------------------

TEST_F(Reject, MissingFile) {
    expect_load_error<InvalidInput>(dir_ + "/nothing.off", {"cannot open file"});
}

TEST_F(Reject, UnknownExtension) {
    expect_load_error<InvalidInput>(file("mesh.xyz", kTetraOff), {"unknown mesh format '.xyz'"});
}

TEST_F(Reject, EmptyFile) {
    expect_load_error<InvalidInput>(file("mesh.off", ""), {"file is empty"});
}

TEST_F(Reject, NeedleAngleOutOfRange) {
    MeshLoadOptions options;
    options.needle_angle_degrees = std::numeric_limits<double>::quiet_NaN();
    expect_load_error<InvalidInput>(file("mesh.off", kTetraOff), {"needle_angle_degrees"}, options);
}

// --- OFF
// ------------------------------------------------------------------------------------------

TEST_F(Reject, OffTruncatedVertices) {
    expect_load_error<InvalidInput>(file("mesh.off", "OFF\n5 1 0\n0 0 0\n1 0 0\n0 1 0\n"),
                                    {"truncated: header announces 5 vertices, file ends after 3"});
}

TEST_F(Reject, OffTruncatedFaces) {
    expect_load_error<InvalidInput>(
        file("mesh.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n"),
        {"truncated: header announces 3 faces, file ends after 1"});
}

TEST_F(Reject, OffMissingCounts) {
    expect_load_error<InvalidInput>(file("mesh.off", "OFF\n# only a comment\n"),
                                    {"truncated: file ends before the vertex and face counts"});
}

TEST_F(Reject, OffNaNCoordinate) {
    expect_load_error<InvalidInput>(
        file("mesh.off", "OFF\n# comment\n4 1 0\n0 0 0\n1 nan 0\n0 1 0\n0 0 1\n3 0 1 2\n"),
        {"line 5: vertex 1 has a NaN coordinate"});
}

TEST_F(Reject, OffInfiniteCoordinate) {
    expect_load_error<InvalidInput>(
        file("mesh.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 -inf\n3 0 1 2\n"),
        {"line 6: vertex 3 has an infinite coordinate"});
}

TEST_F(Reject, OffOverflowingCoordinateIsInfinite) {
    expect_load_error<InvalidInput>(
        file("mesh.off", "OFF\n4 1 0\n0 0 0\n1e999 0 0\n0 1 0\n0 0 1\n3 0 1 2\n"),
        {"line 4: vertex 1 has an infinite coordinate"});
}

TEST_F(Reject, OffUnparsableCoordinate) {
    expect_load_error<InvalidInput>(
        file("mesh.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 abc 0\n0 0 1\n3 0 1 2\n"),
        {"line 5: vertex 2: cannot parse 'abc' as a number"});
}

TEST_F(Reject, OffTooFewCoordinates) {
    expect_load_error<InvalidInput>(
        file("mesh.off", "OFF\n4 1 0\n0 0 0\n1 0\n0 1 0\n0 0 1\n3 0 1 2\n"),
        {"line 4: vertex 1 has 2 coordinates, expected 3"});
}

TEST_F(Reject, OffBadKeyword) {
    expect_load_error<InvalidInput>(file("mesh.off", "PLY\n4 1 0\n"),
                                    {"line 1: expected the OFF header keyword, found 'PLY'"});
}

TEST_F(Reject, OffUnsupportedVariant) {
    expect_load_error<InvalidInput>(file("mesh.off", "4OFF\n4 1 0\n"), {"'4OFF'", "not supported"});
}

TEST_F(Reject, OffBadCount) {
    expect_load_error<InvalidInput>(file("mesh.off", "OFF\n4 x 0\n"),
                                    {"line 2: cannot parse 'x' as a vertex, face or edge count"});
}

TEST_F(Reject, OffIndexOutOfRange) {
    expect_load_error<InvalidInput>(
        file("mesh.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 9001 3\n"),
        {"line 8: face 1 references vertex 9001 but there are 4 vertices"});
}

TEST_F(Reject, OffNegativeIndex) {
    expect_load_error<InvalidInput>(
        file("mesh.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 -1 2\n"),
        {"line 7: face 0 references vertex -1 but there are 4 vertices"});
}

TEST_F(Reject, OffFaceWithTwoVertices) {
    expect_load_error<InvalidInput>(
        file("mesh.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n2 0 1\n"),
        {"line 7: face 0 has only 2 vertices"});
}

TEST_F(Reject, OffFaceShorterThanAnnounced) {
    expect_load_error<InvalidInput>(
        file("mesh.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n4 0 1 2\n"),
        {"line 7: face 0 announces 4 vertices but lists 3"});
}

TEST_F(Reject, OffFaceRepeatsVertex) {
    expect_load_error<InvalidInput>(
        file("mesh.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 1 3 1\n"),
        {"line 8: face 1 uses vertex 1 more than once"});
}

TEST_F(Reject, OffNoFaces) {
    expect_load_error<InvalidInput>(file("mesh.off", "OFF\n3 0 0\n0 0 0\n1 0 0\n0 1 0\n"),
                                    {"empty mesh: no faces (3 vertices)"});
}

TEST_F(Reject, OffBinaryUnsupported) {
    expect_load_error<InvalidInput>(file("mesh.off", "OFF BINARY\n"),
                                    {"binary OFF is not supported"});
}

// --- OBJ
// ------------------------------------------------------------------------------------------

TEST_F(Reject, ObjIndexOutOfRange) {
    expect_load_error<InvalidInput>(
        file("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 2 3\nf 1 9001 4\n"),
        {"line 6: face 1 references vertex 9001 but the file defines 4 vertices"});
}

TEST_F(Reject, ObjRelativeIndexBeforeFirstVertex) {
    expect_load_error<InvalidInput>(
        file("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf -1 -2 -7\nv 0 0 1\n"),
        {"line 4: face 0 references vertex -7 but only 3 vertices are defined before it"});
}

TEST_F(Reject, ObjIndexZero) {
    expect_load_error<InvalidInput>(
        file("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n"),
        {"line 4: face 0 references vertex 0 (OBJ vertex numbers start at 1)"});
}

TEST_F(Reject, ObjUnparsableIndex) {
    expect_load_error<InvalidInput>(file("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 two 3\n"),
                                    {"line 4: face 0: cannot parse 'two' as a vertex reference"});
}

TEST_F(Reject, ObjNaNCoordinate) {
    expect_load_error<InvalidInput>(file("mesh.obj", "# c\nv 0 0 0\nv NaN 0 0\nv 0 1 0\nf 1 2 3\n"),
                                    {"line 3: vertex 1 has a NaN coordinate"});
}

TEST_F(Reject, ObjUnparsableCoordinate) {
    expect_load_error<InvalidInput>(file("mesh.obj", "v 0 0 0\nv 1 0 0,5\nv 0 1 0\nf 1 2 3\n"),
                                    {"line 2: vertex 1: cannot parse '0,5' as a number"});
}

TEST_F(Reject, ObjFaceWithTwoVertices) {
    expect_load_error<InvalidInput>(file("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2\n"),
                                    {"line 4: face 0 has only 2 vertices"});
}

TEST_F(Reject, ObjNoFaces) {
    expect_load_error<InvalidInput>(file("mesh.obj", "v 0 0 0\nv 1 0 0\nl 1 2\n"),
                                    {"empty mesh: no faces (2 vertices)"});
}

// --- PLY
// ------------------------------------------------------------------------------------------

TEST_F(Reject, PlyNotPly) {
    expect_load_error<InvalidInput>(file("mesh.ply", "OFF\n"), {"not a PLY file"});
}

TEST_F(Reject, PlyNoEndHeader) {
    expect_load_error<InvalidInput>(
        file("mesh.ply", "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\n"),
        {"truncated: the PLY header has no 'end_header' line"});
}

TEST_F(Reject, PlyUnknownFormat) {
    expect_load_error<InvalidInput>(file("mesh.ply", "ply\nformat binary_middle_endian 1.0\n"),
                                    {"line 2: unknown PLY format 'binary_middle_endian'"});
}

TEST_F(Reject, PlyUnknownType) {
    expect_load_error<InvalidInput>(
        file("mesh.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float128 x\nend_header\n"),
        {"line 4: unknown property type 'float128'"});
}

TEST_F(Reject, PlyNoX) {
    expect_load_error<InvalidInput>(
        file("mesh.ply",
             "ply\nformat ascii 1.0\nelement vertex 1\nproperty float y\nproperty float z\n"
             "end_header\n0 0\n"),
        {"the PLY vertex element has no scalar 'x' property"});
}

TEST_F(Reject, PlyFaceWithoutIndexList) {
    expect_load_error<InvalidInput>(
        file("mesh.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nelement face 1\nproperty list uchar int corners\nend_header\n"),
        {"the PLY face element has no 'vertex_indices' list property"});
}

TEST_F(Reject, PlyAsciiIndexOutOfRange) {
    expect_load_error<InvalidInput>(
        file("mesh.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nelement face 2\nproperty list uchar int vertex_indices\n"
             "end_header\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 9001\n"),
        {"line 14: face 1 references vertex 9001 but there are 3 vertices"});
}

TEST_F(Reject, PlyAsciiUnparsable) {
    expect_load_error<InvalidInput>(
        file("mesh.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
             "end_header\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n"),
        {"line 11: vertex 1: cannot parse 'zero' as a number"});
}

TEST_F(Reject, PlyAsciiTruncated) {
    expect_load_error<InvalidInput>(
        file("mesh.ply",
             "ply\nformat ascii 1.0\nelement vertex 3\nproperty float x\nproperty float y\n"
             "property float z\nelement face 1\nproperty list uchar int vertex_indices\n"
             "end_header\n0 0 0\n1 0 0\n"),
        {"truncated: header announces 3 vertices, file ends after 2"});
}

TEST_F(Reject, PlyBinaryTruncatedVertices) {
    std::string bytes = binary_ply(kTetraPoints, kTetraFaces);
    const std::size_t header = bytes.find("end_header\n") + 11;
    bytes.resize(header + 2 * 12 + 5);  // two whole vertices and part of the third
    expect_load_error<InvalidInput>(file("mesh.ply", bytes),
                                    {"truncated: header announces 4 vertices, file ends after 2"});
}

TEST_F(Reject, PlyBinaryTruncatedFaces) {
    std::string bytes = binary_ply(kTetraPoints, kTetraFaces);
    bytes.resize(bytes.size() - 3);
    expect_load_error<InvalidInput>(file("mesh.ply", bytes),
                                    {"truncated: header announces 4 faces, file ends after 3"});
}

TEST_F(Reject, PlyBinaryIndexOutOfRange) {
    tapeline_test::Faces faces = kTetraFaces;
    faces[2][1] = 9001;
    expect_load_error<InvalidInput>(file("mesh.ply", binary_ply(kTetraPoints, faces, true)),
                                    {"face 2 references vertex 9001 but there are 4 vertices"});
}

TEST_F(Reject, PlyBinaryNaN) {
    tapeline_test::Points points = kTetraPoints;
    points[2][2] = std::numeric_limits<double>::quiet_NaN();
    expect_load_error<InvalidInput>(file("mesh.ply", binary_ply(points, kTetraFaces)),
                                    {"vertex 2 has a NaN coordinate"});
}

TEST_F(Reject, PlyBinaryFaceWithTwoVertices) {
    tapeline_test::Faces faces = kTetraFaces;
    faces[3] = {1, 2};
    expect_load_error<InvalidInput>(file("mesh.ply", binary_ply(kTetraPoints, faces)),
                                    {"face 3 has only 2 vertices"});
}

TEST_F(Reject, PlyNoVertexElement) {
    expect_load_error<InvalidInput>(file("mesh.ply", "ply\nformat ascii 1.0\nend_header\n"),
                                    {"the PLY header declares no vertex element"});
}

// --- STL
// ------------------------------------------------------------------------------------------

TEST_F(Reject, StlBinaryTruncated) {
    std::string bytes = binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 0, 1, 1, 0, 0}});
    bytes.resize(bytes.size() - 20);
    expect_load_error<InvalidInput>(
        file("mesh.stl", bytes),
        {"truncated: header announces 2 triangles (184 bytes), file ends after 1"});
}

TEST_F(Reject, StlBinaryTrailingBytes) {
    std::string bytes = binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}});
    bytes += "xyz";
    expect_load_error<InvalidInput>(file("mesh.stl", bytes),
                                    {"binary STL header announces 1 triangles (134 bytes) but the "
                                     "file has 137 bytes"});
}

TEST_F(Reject, StlTooShort) {
    expect_load_error<InvalidInput>(file("mesh.stl", "abc"), {"too short for a binary STL"});
}

TEST_F(Reject, StlBinaryNaN) {
    const float nan = std::numeric_limits<float>::quiet_NaN();
    expect_load_error<InvalidInput>(
        file("mesh.stl", binary_stl({{0, 0, 0, 1, 0, 0, 0, 1, 0}, {0, 0, 0, 0, 0, 1, 1, 0, nan}})),
        {"facet 1, corner 2 has a NaN coordinate"});
}

TEST_F(Reject, StlAsciiTruncatedInsideFacet) {
    expect_load_error<InvalidInput>(
        file("mesh.stl",
             "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
             "endloop\nendfacet\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\n"),
        {"truncated: file ends inside facet 1 (started on line 9)"});
}

TEST_F(Reject, StlAsciiMissingEndsolid) {
    expect_load_error<InvalidInput>(
        file("mesh.stl",
             "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex 0 1 0\n"
             "endloop\nendfacet\n"),
        {"truncated: file ends without 'endsolid' after 1 facets"});
}

TEST_F(Reject, StlAsciiUnparsable) {
    expect_load_error<InvalidInput>(
        file("mesh.stl",
             "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 x\nvertex 0 1 0\n"
             "endloop\nendfacet\nendsolid t\n"),
        {"line 5: facet 0, corner 1: cannot parse 'x' as a number"});
}

TEST_F(Reject, StlAsciiInfinite) {
    expect_load_error<InvalidInput>(
        file("mesh.stl",
             "solid t\nfacet normal 0 0 1\nouter loop\nvertex 0 0 0\nvertex 1 0 0\nvertex inf 1 0\n"
             "endloop\nendfacet\nendsolid t\n"),
        {"line 6: facet 0, corner 2 has an infinite coordinate"});
}

TEST_F(Reject, StlAsciiUnknownKeyword) {
    expect_load_error<InvalidInput>(file("mesh.stl", "solid t\nfacet normal 0 0 1\nvortex 0 0 0\n"),
                                    {"line 3: unexpected 'vortex' in ASCII STL"});
}

// --- in-memory soup
// -------------------------------------------------------------------------------

TEST(RejectSoup, NaN) {
    tapeline_test::Points points = kTetraPoints;
    points[3][0] = std::numeric_limits<double>::quiet_NaN();
    expect_error<InvalidInput>([&] { load_soup(points, kTetraFaces, "body"); },
                               {"body: vertex 3 has a NaN coordinate"});
}

TEST(RejectSoup, IndexOutOfRange) {
    tapeline_test::Faces faces = kTetraFaces;
    faces[1][2] = 4;
    expect_error<InvalidInput>([&] { load_soup(kTetraPoints, faces, "body"); },
                               {"body: face 1 references vertex 4 but there are 4 vertices"});
}

TEST(RejectSoup, FaceWithTwoVertices) {
    expect_error<InvalidInput>(
        [&] {
            load_soup(kTetraPoints, {{0, 1}}, "body");
        },
        {"body: face 0 has only 2 vertices"});
}

TEST(RejectSoup, Empty) {
    expect_error<InvalidInput>([&] { load_soup({}, {}, "body"); },
                               {"body: empty mesh: no faces (0 vertices)"});
}

TEST(RejectSoup, AllFacesCollapse) {
    // Vertices 0 and 1 coincide, so the only face has two distinct corners once they merge.
    expect_error<InvalidInput>(
        [&] {
            load_soup({{0, 0, 0}, {0, 0, 0}, {1, 0, 0}}, {{0, 1, 2}}, "body");
        },
        {"body: empty mesh: no face is left after merging duplicates"});
}

// --- strict mode: repairs become rejections ------------------------------------------------------

MeshLoadOptions strict() {
    MeshLoadOptions options;
    options.strict = true;
    return options;
}

TEST_F(Reject, StrictPolygon) {
    expect_load_error<TopologyError>(
        file("mesh.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n4 0 1 2 3\n"),
        {"line 7: face 0 with 4 vertices; strict mode accepts triangles only"}, strict());
}

TEST_F(Reject, StrictDuplicateVertex) {
    expect_load_error<TopologyError>(
        file("mesh.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\nf 4 5 3\n"),
        {"line 4: vertex 3 has the same coordinates as vertex 1; strict mode rejects duplicate "
         "vertices"},
        strict());
}

TEST_F(Reject, StrictUnreferencedVertex) {
    expect_load_error<TopologyError>(
        file("mesh.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n5 5 5\n3 0 1 2\n"),
        {"line 6: vertex 3 is not used by any face; strict mode rejects unreferenced vertices"},
        strict());
}

TEST_F(Reject, StrictNonManifoldEdge) {
    // Three triangles share the edge 0-1 (a "book").
    expect_load_error<TopologyError>(
        file("mesh.off",
             "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 1 0 3\n3 0 1 4\n"),
        {"edge between vertices 0 and 1, shared by 3 faces: 0 1 2; strict mode rejects "
         "non-manifold edges"},
        strict());
}

TEST_F(Reject, StrictNonManifoldVertex) {
    // Two triangles touching at vertex 2 only (a bow tie).
    expect_load_error<TopologyError>(
        file("mesh.off", "OFF\n5 2 0\n0 0 0\n1 0 0\n0.5 1 0\n0 2 0\n1 2 0\n3 0 1 2\n3 2 4 3\n"),
        {"line 5: vertex 2, where 2 separate fans of faces meet; strict mode rejects non-manifold "
         "vertices"},
        strict());
}

TEST_F(Reject, StrictDuplicateFace) {
    expect_load_error<TopologyError>(
        file("mesh.off", "OFF\n4 3 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 2 1 0\n"),
        {"line 9: face 2 repeats face 0 (same vertices); strict mode rejects duplicate faces"},
        strict());
}

TEST(RejectSoup, StrictNonOrientable) {
    // A Möbius strip: 3 quads (6 triangles) with a half twist; no consistent orientation exists.
    tapeline_test::Points points;
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < 3; ++i) {
        const double a = 2 * pi * i / 3, t = a / 2;
        for (double s : {-0.3, 0.3}) {
            points.push_back({(1 + s * std::cos(t)) * std::cos(a),
                              (1 + s * std::cos(t)) * std::sin(a), s * std::sin(t)});
        }
    }
    // Strip i joins the pair (2i, 2i+1) to the next pair; the last joins crosswise.
    const tapeline_test::Faces faces = {{0, 1, 3}, {0, 3, 2}, {2, 3, 5},
                                        {2, 5, 4}, {4, 5, 0}, {4, 0, 1}};
    expect_error<TopologyError>(
        [&] { load_soup(points, faces, "strip", strict()); },
        {"strip: the faces cannot be oriented consistently", "non-orientable"});
}

// --- LoadedMesh and writers
// ------------------------------------------------------------------------

TEST_F(Reject, MeshVerticesOfOutOfRange) {
    const std::string path = file("mesh.off", kTetraOff);
    expect_error<InvalidInput>([&] { tapeline_test::count_mesh_vertices_of(path, 4); },
                               {path + ": vertex 4 does not exist (the input has 4 vertices)"});
}

TEST_F(Reject, WriteUnknownExtension) {
    const std::string path = dir_ + "/out.xyz";
    expect_error<InvalidInput>(
        [&] { tapeline_test::write_mesh_from_soup(path, kTetraPoints, kTetraFaces); },
        {path + ": unknown mesh format '.xyz' for writing"});
    EXPECT_FALSE(tapeline_test::file_exists(path));
}

TEST_F(Reject, WriteIntoMissingDirectory) {
    const std::string path = dir_ + "/no/such/dir/out.ply";
    expect_error<InvalidInput>(
        [&] { tapeline_test::write_mesh_from_soup(path, kTetraPoints, kTetraFaces); },
        {path + ": cannot open for writing"});
}

TEST_F(Reject, ScalarPlyWrongValueCount) {
    const std::string path = dir_ + "/field.ply";
    expect_error<InvalidInput>(
        [&] {
            tapeline_test::write_scalar_from_soup(path, kTetraPoints, kTetraFaces, {1, 2, 3});
        },
        {path + ": 3 values for a mesh of 4 vertices"});
    EXPECT_FALSE(tapeline_test::file_exists(path));
}

TEST_F(Reject, ScalarPlyBadPropertyName) {
    tapeline::ScalarPlyOptions options;
    options.property = "geodesic distance";
    const std::string path = dir_ + "/field.ply";
    expect_error<InvalidInput>(
        [&] {
            tapeline_test::write_scalar_from_soup(path, kTetraPoints, kTetraFaces, {0, 1, 2, 3},
                                                  options);
        },
        {path + ": invalid PLY property name 'geodesic distance'"});
}

}  // namespace

// --- coordinate range and hostile paths ---------------------------------------------------------

TEST_F(Reject, CoordinateBeyondRange) {
    expect_load_error<InvalidInput>(
        file("huge.off",
             "OFF\n4 4 0\n0 0 0\n1e300 0 0\n0 1e300 0\n0 0 1e300\n"
             "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"),
        {"vertex 1 has coordinate 1e+300, outside the supported range |x| <= 1e+15",
         "rescale or re-centre"});
}

TEST_F(Reject, CoordinatesSpanTooLittle) {
    expect_load_error<InvalidInput>(
        file("tiny.off",
             "OFF\n4 4 0\n0 0 0\n1e-300 0 0\n0 1e-300 0\n0 0 1e-300\n"
             "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"),
        {"the 4 points span only 1.73e-300 (bounding-box diagonal)", "at least 1e-12"});
}

TEST_F(Reject, CoordinatesSpanTooLittleForTheirOffset) {
    // A unit tetrahedron 1e11 away from the origin keeps only 5 digits of its shape.
    expect_load_error<InvalidInput>(
        file("far.off",
             "OFF\n4 4 0\n1e11 1e11 1e11\n100000000001 1e11 1e11\n1e11 100000000001 1e11\n"
             "1e11 1e11 100000000001\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"),
        {"span only 1.73", "at coordinates up to 1e+11", "1e-09 of the largest coordinate"});
}

TEST_F(Reject, CoordinatesAtTheLimitsLoad) {
    // 1e14 (inside |x| <= 1e15) with a spread of 1e14, and a spread of 1e-11 near the origin.
    EXPECT_NO_THROW(load(file("big.off",
                              "OFF\n4 4 0\n0 0 0\n1e14 0 0\n0 1e14 0\n0 0 1e14\n"
                              "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")));
    EXPECT_NO_THROW(load(file("small.off",
                              "OFF\n4 4 0\n0 0 0\n1e-11 0 0\n0 1e-11 0\n0 0 1e-11\n"
                              "3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")));
}

TEST_F(Reject, DirectoryGivenAsMesh) {
    const std::string dir = dir_ + "/mesh.obj";
    std::filesystem::create_directories(dir);
    expect_error<InvalidInput>([&] { load(dir); }, {dir + ": is a directory, not a file"});
}
