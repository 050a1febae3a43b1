// Reading every supported format and variant; repairs with their counts and warnings; the map back
// to input vertices; real meshes (spot.obj in the project data, shared meshes when present).
#include <tapeline_test/io.h>
#include <tapeline_test/io_bytes.h>
#include <tapeline_test/io_fixture.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <limits>
#include <string>
#include <vector>

namespace {

using tapeline::MeshLoadOptions;
using tapeline_test::load;
using tapeline_test::load_soup;
using tapeline_test::LoadedView;
using tapeline_test::MeshKind;

using Read = tapeline_test::TempFileTest;

/// Checks shared by every successful load: a valid triangle mesh whose counts match the report.
void expect_valid(const LoadedView& m) {
    EXPECT_TRUE(m.valid_polygon_mesh);
    EXPECT_TRUE(m.triangle_mesh);
    EXPECT_EQ(m.report.vertices, m.points.size());
    EXPECT_EQ(m.report.faces, m.triangles.size());
    EXPECT_EQ(m.input_index.size(), m.points.size());
    EXPECT_EQ(m.face_input_index.size(), m.triangles.size());
}

bool has_warning(const LoadedView& m, const std::string& part) {
    for (const std::string& w : m.report.warnings) {
        if (w.find(part) != std::string::npos && w.find(m.report.file + ": ") == 0) {
            return true;
        }
    }
    return false;
}

std::string warnings(const LoadedView& m) {
    return m.report.summary();
}

/// The tetrahedron of the reject tests, closed and consistently oriented (outward normals).
using tapeline_test::kTetraFaces;
using tapeline_test::kTetraPoints;

/// `file_order`: vertices keep the file's order (not so for STL, numbered by first appearance).
void expect_clean_tetrahedron(const LoadedView& m, bool file_order = true) {
    expect_valid(m);
    EXPECT_EQ(m.report.input_vertices, 4u);
    EXPECT_EQ(m.report.input_faces, 4u);
    EXPECT_EQ(m.report.vertices, 4u);
    EXPECT_EQ(m.report.faces, 4u);
    EXPECT_EQ(m.report.components, 1u);
    EXPECT_EQ(m.report.boundary_loops, 0u);
    EXPECT_TRUE(m.closed);
    EXPECT_TRUE(m.report.warnings.empty()) << warnings(m);
    // Vertex order and positions are those of the file.
    tapeline_test::Points sorted = m.points;
    std::sort(sorted.begin(), sorted.end());
    tapeline_test::Points expected = kTetraPoints;
    std::sort(expected.begin(), expected.end());
    EXPECT_EQ(sorted, expected);
    for (std::size_t i = 0; i < 4; ++i) {
        if (file_order) {
            EXPECT_EQ(m.points[i], kTetraPoints[i]);
        }
        EXPECT_EQ(m.input_index[i], i);
    }
    // Surface area of the unit corner tetrahedron: 3 * 1/2 + sqrt(3)/2.
    EXPECT_NEAR(m.area, 1.5 + std::sqrt(3.0) / 2, 1e-12);
}

// --- format variants
// --------------------------------------------------------------------------------

TEST_F(Read, OffPlain) {
    const LoadedView m = load(file("t.off",
                                   "OFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n"
                                   "3 0 3 2\n3 1 2 3\n"));
    expect_clean_tetrahedron(m);
    EXPECT_EQ(m.report.format, "off");
}

TEST_F(Read, OffVariantsCommentsCrlfAndCountsOnKeywordLine) {
    // COFF colours (4 values), counts on the keyword line, comments, CRLF, face colours.
    expect_clean_tetrahedron(
        load(file("c.off",
                  "COFF 4 4 6 # counts here\r\n# comment line\r\n0 0 0 255 0 0 255\r\n"
                  "1 0 0 0 255 0 255\r\n\r\n0 1 0 0 0 255 255\r\n0 0 1 9 9 9 255\r\n"
                  "3 0 2 1 255 0 0\r\n3 0 1 3\r\n3 0 3 2\r\n3 1 2 3 # last\r\n")));
    // NOFF normals, counts on their own line, leading '+' and exponents.
    expect_clean_tetrahedron(load(file("n.off",
                                       "NOFF\n4 4 0\n0 0 0 0 0 1\n+1e0 0 0 0 0 1\n0 1.0 0 0 0 1\n"
                                       "0 0 10E-1 0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n")));
    // STCNOFF: texture, colour and normal prefixes together; upper-case extension.
    expect_clean_tetrahedron(load(file("s.OFF",
                                       "STCNOFF\n4 4 0\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n"
                                       "3 0 1 3\n3 0 3 2\n3 1 2 3\n")));
}

TEST_F(Read, ObjIndexFormsAndIgnoredRecords) {
    const LoadedView m = load(file("t.obj",
                                   "# tetrahedron\nmtllib none.mtl\no tetra\nv 0 0 0\nv 1 0 0\n"
                                   "vt 0 0\nvt 1 0\nvn 0 0 1\nv 0 1 0 1.0\nv 0 0 1 0.5 0.5 0.5\n"
                                   "g side\nusemtl skin\ns 1\nf 1/1 3/2 2/1\nf 1/1/1 2/2/1 4/1/1\n"
                                   "f 1//1 4//1 3//1\nf -3 -2 -1\nl 1 2\n"));
    expect_clean_tetrahedron(m);
    EXPECT_EQ(m.report.format, "obj");
}

TEST_F(Read, ObjForwardReferences) {
    // Faces may refer to vertices defined further down.
    expect_clean_tetrahedron(load(file("f.obj",
                                       "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\nv 0 0 0\nv 1 0 0\n"
                                       "v 0 1 0\nv 0 0 1\n")));
}

const char* const kPlyTetraAscii =
    "ply\nformat ascii 1.0\ncomment made by hand\nobj_info nothing\nelement vertex 4\n"
    "property double x\nproperty float y\nproperty float z\nproperty uchar red\n"
    "property list uchar float texture\nproperty float quality\nelement edge 1\n"
    "property int vertex1\nproperty int vertex2\nelement face 4\n"
    "property list uint8 int32 vertex_indices\nproperty uchar flags\nend_header\n"
    "0 0 0 1 2 0.5 0.5 7\n1 0 0 2 0 8\n0 1 0 3 1 0.25 9\n0 0 1 4 0 10\n0 1\n"
    "3 0 2 1 0\n3 0 1 3 0\n3 0 3 2 0\n3 1 2 3 0\n";

TEST_F(Read, PlyAsciiWithExtraPropertiesAndElements) {
    const std::string path = file("t.ply", kPlyTetraAscii);
    const LoadedView m = load(path);
    expect_clean_tetrahedron(m);
    EXPECT_EQ(m.report.format, "ply-ascii");
    const tapeline::PolygonSoup soup = tapeline_test::read_soup(path);
    ASSERT_EQ(soup.vertex_properties.count("quality"), 1u);
    EXPECT_EQ(soup.vertex_properties.at("quality"), (std::vector<double>{7, 8, 9, 10}));
    EXPECT_EQ(soup.vertex_properties.at("red"), (std::vector<double>{1, 2, 3, 4}));
}

using tapeline_test::put;

/// Binary PLY with mixed types: double x, float y, short z (scaled), an extra int property,
/// an edge element, ushort/uint face lists, written in either byte order.
std::string mixed_binary_ply(bool big_endian) {
    std::string out = std::string("ply\nformat ") +
                      (big_endian ? "binary_big_endian" : "binary_little_endian") +
                      " 1.0\nelement vertex 4\nproperty double x\nproperty float y\n"
                      "property int id\nproperty short z\nelement edge 1\nproperty list uchar int "
                      "pair\nelement face 4\nproperty uchar flag\nproperty list ushort uint "
                      "vertex_indices\nend_header\n";
    for (std::size_t i = 0; i < 4; ++i) {
        put(out, kTetraPoints[i][0], big_endian);
        put(out, static_cast<float>(kTetraPoints[i][1]), big_endian);
        put(out, static_cast<std::int32_t>(100 + i), big_endian);
        put(out, static_cast<std::int16_t>(kTetraPoints[i][2]), big_endian);
    }
    put(out, std::uint8_t{2}, big_endian);
    put(out, std::int32_t{0}, big_endian);
    put(out, std::int32_t{1}, big_endian);
    for (const auto& f : kTetraFaces) {
        put(out, std::uint8_t{1}, big_endian);
        put(out, static_cast<std::uint16_t>(f.size()), big_endian);
        for (std::size_t v : f) {
            put(out, static_cast<std::uint32_t>(v), big_endian);
        }
    }
    return out;
}

TEST_F(Read, PlyBinaryLittleEndian) {
    const std::string path = file("le.ply", mixed_binary_ply(false));
    const LoadedView m = load(path);
    expect_clean_tetrahedron(m);
    EXPECT_EQ(m.report.format, "ply-binary-le");
    EXPECT_EQ(tapeline_test::read_soup(path).vertex_properties.at("id"),
              (std::vector<double>{100, 101, 102, 103}));
}

TEST_F(Read, PlyBinaryBigEndian) {
    const std::string path = file("be.ply", mixed_binary_ply(true));
    const LoadedView m = load(path);
    expect_clean_tetrahedron(m);
    EXPECT_EQ(m.report.format, "ply-binary-be");
    EXPECT_EQ(tapeline_test::read_soup(path).vertex_properties.at("id"),
              (std::vector<double>{100, 101, 102, 103}));
}

const char* const kStlTetraAscii =
    "solid tetra\n"
    "facet normal 0 0 -1\n outer loop\n  vertex 0 0 0\n  vertex 0 1 0\n  vertex 1 0 0\n endloop\n"
    "endfacet\n"
    "facet normal 0 -1 0\n outer loop\n  vertex 0 0 0\n  vertex 1 0 0\n  vertex 0 0 1\n endloop\n"
    "endfacet\n"
    "facet normal -1 0 0\n outer loop\n  vertex 0 0 0\n  vertex 0 0 1\n  vertex 0 1 0\n endloop\n"
    "endfacet\n"
    "facet normal 1 1 1\n outer loop\n  vertex 1 0 0\n  vertex 0 1 0\n  vertex 0 0 1\n endloop\n"
    "endfacet\n"
    "endsolid tetra\n";

TEST_F(Read, StlAsciiSharesEqualCorners) {
    const LoadedView m = load(file("t.stl", kStlTetraAscii));
    expect_clean_tetrahedron(m, false);  // 12 corners become 4 vertices, in order of appearance
    EXPECT_EQ(m.report.format, "stl-ascii");
}

TEST_F(Read, StlBinaryEvenIfHeaderSaysSolid) {
    std::string out = "solid but actually binary";
    out.resize(80, ' ');
    put(out, std::uint32_t{4}, false);
    for (const auto& f : kTetraFaces) {
        for (int k = 0; k < 3; ++k) {
            put(out, 0.0f, false);
        }
        for (std::size_t v : f) {
            for (double x : kTetraPoints[v]) {
                put(out, static_cast<float>(x), false);
            }
        }
        put(out, std::uint16_t{0}, false);
    }
    const LoadedView m = load(file("t.stl", out));
    expect_clean_tetrahedron(m, false);
    EXPECT_EQ(m.report.format, "stl-binary");
}

// --- repairs
// ----------------------------------------------------------------------------------------

TEST_F(Read, PolygonsAreTriangulated) {
    // A unit cube of 6 quads.
    const LoadedView m = load(file("cube.off",
                                   "OFF\n8 6 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n"
                                   "0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n4 1 2 6 5\n4 2 3 7 6\n"
                                   "4 3 0 4 7\n"));
    expect_valid(m);
    EXPECT_EQ(m.report.polygons_triangulated, 6u);
    EXPECT_EQ(m.report.faces, 12u);
    EXPECT_EQ(m.report.vertices, 8u);
    EXPECT_TRUE(m.closed);
    EXPECT_EQ(m.report.degenerate_faces, 0u);
    EXPECT_NEAR(m.area, 6.0, 1e-12);
    EXPECT_TRUE(
        has_warning(m, "6 polygon faces triangulated (first: line 11: face 0 with 4 vertices)"))
        << warnings(m);
    // Each triangle remembers its quad: two triangles per input face.
    std::vector<int> per_face(6, 0);
    for (std::size_t f : m.face_input_index) {
        ++per_face.at(f);
    }
    EXPECT_EQ(per_face, std::vector<int>(6, 2));
}

TEST(ReadSoup, NonConvexPolygon) {
    // An L-shaped hexagon (area 3): a fan from vertex 0 would leave the polygon; CDT does not.
    const LoadedView m =
        load_soup({{0, 0, 0}, {2, 0, 0}, {2, 1, 0}, {1, 1, 0}, {1, 2, 0}, {0, 2, 0}},
                  {{0, 1, 2, 3, 4, 5}}, "L");
    expect_valid(m);
    EXPECT_EQ(m.report.format, "soup");
    EXPECT_EQ(m.report.faces, 4u);
    EXPECT_NEAR(m.area, 3.0, 1e-12);
    EXPECT_EQ(m.report.boundary_loops, 1u);
}

TEST(ReadSoup, PolygonWithCollinearCornersIsCutIntoDegenerateTriangles) {
    // CGAL cannot triangulate a polygon without a normal; the fallback fan keeps the mesh valid
    // and the triangles are reported as degenerate.
    const LoadedView m =
        load_soup({{0, 0, 0}, {1, 0, 0}, {2, 0, 0}, {3, 0, 0}}, {{0, 1, 2, 3}}, "line");
    expect_valid(m);
    EXPECT_EQ(m.report.faces, 2u);
    EXPECT_EQ(m.report.degenerate_faces, 2u);
    EXPECT_TRUE(has_warning(m, "2 degenerate (zero-area) triangles (first: in input face 0)"))
        << warnings(m);
}

TEST_F(Read, DuplicateVerticesAreMerged) {
    // Two triangles of a square; the second repeats the coordinates of vertices 0 and 2.
    const std::string path = file("dup.obj",
                                  "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 0 0\nv 1 1 0\nv 0 1 0\n"
                                  "f 1 2 3\nf 4 5 6\n");
    const LoadedView m = load(path);
    expect_valid(m);
    EXPECT_EQ(m.report.duplicate_vertices_merged, 2u);
    EXPECT_EQ(m.report.vertices, 4u);
    EXPECT_EQ(m.report.boundary_loops, 1u);
    EXPECT_EQ(m.report.components, 1u);
    EXPECT_TRUE(has_warning(m,
                            "2 duplicate vertices merged (first: line 4: vertex 3 has the same "
                            "coordinates as vertex 0)"))
        << warnings(m);
    // Input vertex 3 is represented by the mesh vertex of input vertex 0.
    EXPECT_EQ(m.copies[3], m.copies[0]);
    EXPECT_EQ(m.copies[4], m.copies[2]);
    EXPECT_EQ(m.x_in_input_order[3], 0.0);
    EXPECT_EQ(m.x_in_input_order[4], 1.0);
}

TEST_F(Read, UnreferencedVerticesAreDropped) {
    const LoadedView m = load(file("unref.off",
                                   "OFF\n6 4 0\n0 0 0\n1 0 0\n7 7 7\n0 1 0\n0 0 1\n8 8 8\n"
                                   "3 0 3 1\n3 0 1 4\n3 0 4 3\n3 1 3 4\n"));
    expect_valid(m);
    EXPECT_EQ(m.report.unreferenced_vertices, 2u);
    EXPECT_EQ(m.report.vertices, 4u);
    EXPECT_EQ(m.input_vertex_count, 6u);
    EXPECT_TRUE(m.copies[2].empty());
    EXPECT_TRUE(m.copies[5].empty());
    EXPECT_EQ(m.copies[3].size(), 1u);
    EXPECT_EQ(m.points[m.copies[3][0]], (std::array<double, 3>{0, 1, 0}));
    EXPECT_EQ(m.x_in_input_order[2], std::numeric_limits<double>::infinity());
    EXPECT_TRUE(m.closed);
    EXPECT_TRUE(has_warning(m, "2 unreferenced vertices dropped (first: line 5: vertex 2)"))
        << warnings(m);
}

TEST(ReadSoup, NonManifoldEdgeIsSplit) {
    // Three triangles share the edge 0-1.
    const LoadedView m = load_soup({{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}},
                                   {{0, 1, 2}, {1, 0, 3}, {0, 1, 4}}, "book");
    expect_valid(m);
    EXPECT_EQ(m.report.non_manifold_edges, 1u);
    EXPECT_GE(m.report.vertices_split, 1u);
    EXPECT_EQ(m.report.faces, 3u);
    EXPECT_EQ(m.report.vertices, 5u + m.report.vertices_split);
    EXPECT_TRUE(has_warning(m,
                            "1 non-manifold edge split (first: edge between vertices 0 and 1, "
                            "shared by 3 faces: 0 1 2)"))
        << warnings(m);
    // Every copy maps back to an input vertex; the edge's ends have several copies.
    EXPECT_GE(m.copies[0].size() + m.copies[1].size(), 3u);
    for (std::size_t i = 0; i < 5; ++i) {
        for (std::size_t k : m.copies[i]) {
            EXPECT_EQ(m.input_index[k], i);
        }
    }
}

TEST(ReadSoup, NonManifoldVertexIsSplitOnEveryMeshType) {
    // Two triangles touching at vertex 2 only (a bow tie).
    const tapeline_test::Points points = {{0, 0, 0}, {1, 0, 0}, {0.5, 1, 0}, {0, 2, 0}, {1, 2, 0}};
    const tapeline_test::Faces faces = {{0, 1, 2}, {2, 4, 3}};
    for (MeshKind kind :
         {MeshKind::surface_mesh, MeshKind::surface_mesh_simple, MeshKind::polyhedron}) {
        const LoadedView m = load_soup(points, faces, "bowtie", {}, kind);
        expect_valid(m);
        EXPECT_EQ(m.report.non_manifold_vertices, 1u);
        EXPECT_EQ(m.report.vertices_split, 1u);
        EXPECT_EQ(m.report.vertices, 6u);
        EXPECT_EQ(m.report.components, 2u);
        EXPECT_EQ(m.report.boundary_loops, 2u);
        ASSERT_EQ(m.copies[2].size(), 2u);
        EXPECT_EQ(m.points[m.copies[2][0]], m.points[m.copies[2][1]]);
        EXPECT_EQ(m.x_in_input_order[2], 0.5);
        EXPECT_TRUE(has_warning(m,
                                "1 non-manifold vertex split (first: vertex 2, where 2 separate "
                                "fans of faces meet)"))
            << warnings(m);
        EXPECT_TRUE(has_warning(m,
                                "2 connected components of 1, 1 triangles (first: the second "
                                "component contains input face 1)"))
            << warnings(m);
    }
}

TEST(ReadSoup, InconsistentOrientationIsFixed) {
    // The second triangle of the square runs the shared edge in the same direction as the first.
    const LoadedView m =
        load_soup({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 2, 3}}, "square");
    const LoadedView flipped =
        load_soup({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2}, {0, 3, 2}}, "square");
    expect_valid(m);
    expect_valid(flipped);
    EXPECT_EQ(m.report.faces_reoriented, 0u);
    EXPECT_EQ(flipped.report.faces_reoriented, 1u);
    EXPECT_EQ(flipped.report.vertices_split, 0u);
    EXPECT_EQ(flipped.report.boundary_loops, 1u);
    EXPECT_TRUE(has_warning(flipped, "1 face reversed to agree with their neighbours' orientation"))
        << warnings(flipped);
}

TEST(ReadSoup, MobiusStripIsCutOpen) {
    tapeline_test::Points points;
    const double pi = 3.14159265358979323846;
    for (int i = 0; i < 3; ++i) {
        const double a = 2 * pi * i / 3, t = a / 2;
        for (double s : {-0.3, 0.3}) {
            points.push_back({(1 + s * std::cos(t)) * std::cos(a),
                              (1 + s * std::cos(t)) * std::sin(a), s * std::sin(t)});
        }
    }
    const LoadedView m = load_soup(
        points, {{0, 1, 3}, {0, 3, 2}, {2, 3, 5}, {2, 5, 4}, {4, 5, 0}, {4, 0, 1}}, "strip");
    expect_valid(m);
    EXPECT_GE(m.report.vertices_split, 1u);
    EXPECT_EQ(m.report.faces, 6u);
    EXPECT_TRUE(has_warning(m, "added to make the mesh manifold and orientable")) << warnings(m);
}

TEST(ReadSoup, CollapsedAndDuplicateFacesAreDropped) {
    // Tetrahedron plus: a face whose corners 4 and 0 coincide (collapses after merging), and a
    // repeat of face 0 in the other orientation.
    tapeline_test::Points points = kTetraPoints;
    points.push_back({0, 0, 0});
    tapeline_test::Faces faces = kTetraFaces;
    faces.push_back({4, 0, 1});
    faces.push_back({1, 2, 0});
    const LoadedView m = load_soup(points, faces, "tetra");
    expect_valid(m);
    EXPECT_EQ(m.report.collapsed_faces_dropped, 1u);
    EXPECT_EQ(m.report.duplicate_faces_dropped, 1u);
    EXPECT_EQ(m.report.faces, 4u);
    EXPECT_TRUE(m.closed);
    EXPECT_TRUE(has_warning(m,
                            "1 face left with fewer than 3 distinct vertices by merging "
                            "duplicates, dropped (first: face 4)"))
        << warnings(m);
    EXPECT_TRUE(has_warning(m,
                            "1 duplicate face dropped (first: face 5 repeats face 0 (same "
                            "vertices))"))
        << warnings(m);
}

TEST(ReadSoup, DegenerateAndNeedleFacesAreReportedNotRejected) {
    // Face 1 is flat (collinear corners); face 2 has a 0.1 degree angle at vertex 6.
    const double t = std::tan(0.1 * 3.14159265358979323846 / 180);
    const LoadedView m = load_soup({{0, 0, 0},
                                    {1, 0, 0},
                                    {0, 1, 0},
                                    {5, 0, 0},
                                    {6, 0, 0},
                                    {7, 0, 0},
                                    {0, 3, 0},
                                    {10, 3, 0},
                                    {10, 3 + 10 * t, 0}},
                                   {{0, 1, 2}, {3, 4, 5}, {6, 7, 8}}, "thin");
    expect_valid(m);
    EXPECT_EQ(m.report.degenerate_faces, 1u);
    EXPECT_EQ(m.report.needle_faces, 1u);
    EXPECT_EQ(m.report.components, 3u);
    EXPECT_TRUE(has_warning(m, "1 degenerate (zero-area) triangle (first: in input face 1)"))
        << warnings(m);
    EXPECT_TRUE(has_warning(m,
                            "1 needle triangle with an angle below 1 degrees (first: in input "
                            "face 2, smallest angle 0.1 degrees)"))
        << warnings(m);
    MeshLoadOptions options;
    options.needle_angle_degrees = 0.05;
    EXPECT_EQ(load_soup({{0, 0, 0}, {10, 10 * t, 0}, {10, 20, 0}}, {{0, 1, 2}}, "thin", options)
                  .report.needle_faces,
              0u);
}

TEST(ReadSoup, BoundariesOfAnAnnulus) {
    // A square with a square hole: 8 vertices, 8 triangles, 2 boundary loops.
    const tapeline_test::Points points = {{0, 0, 0}, {3, 0, 0}, {3, 3, 0}, {0, 3, 0},
                                          {1, 1, 0}, {2, 1, 0}, {2, 2, 0}, {1, 2, 0}};
    tapeline_test::Faces faces;
    for (std::size_t i = 0; i < 4; ++i) {
        const std::size_t j = (i + 1) % 4;
        faces.push_back({i, j, 4 + j});
        faces.push_back({i, 4 + j, 4 + i});
    }
    const LoadedView m = load_soup(points, faces, "annulus");
    expect_valid(m);
    EXPECT_EQ(m.report.boundary_loops, 2u);
    EXPECT_EQ(m.report.components, 1u);
    EXPECT_NEAR(m.area, 8.0, 1e-12);
    EXPECT_TRUE(has_warning(m, "2 boundary loops (first: the loop through vertex 0, 4 edges)"))
        << warnings(m);
}

TEST(ReadSoup, StrictAcceptsACleanMesh) {
    MeshLoadOptions options;
    options.strict = true;
    const LoadedView m = load_soup(kTetraPoints, kTetraFaces, "tetra", options);
    expect_valid(m);
    EXPECT_TRUE(m.report.warnings.empty());
}

TEST(ReadSoup, SummaryMentionsCountsAndWarnings) {
    const LoadedView m =
        load_soup({{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}}, {{0, 1, 2, 3}}, "quad");
    const std::string s = m.report.summary();
    EXPECT_NE(s.find("quad (soup): 4 vertices, 1 faces read; mesh has 4 vertices, 2 triangles"),
              std::string::npos)
        << s;
    EXPECT_NE(s.find("polygons triangulated: 1"), std::string::npos) << s;
    EXPECT_NE(s.find("warning: quad: 1 polygon face triangulated"), std::string::npos) << s;
}

// --- real meshes
// ------------------------------------------------------------------------------------

TEST(ReadData, SpotObj) {
    const std::string path = std::string(TAPELINE_DATA_DIR) + "/spot.obj";
    for (MeshKind kind : {MeshKind::surface_mesh, MeshKind::polyhedron}) {
        const LoadedView m = load(path, {}, kind);
        expect_valid(m);
        EXPECT_EQ(m.report.vertices, 2930u);
        EXPECT_EQ(m.report.faces, 5856u);
        EXPECT_EQ(m.report.components, 1u);
        EXPECT_EQ(m.report.boundary_loops, 0u);
        EXPECT_TRUE(m.closed);
        // Euler characteristic of a closed genus-0 surface: V - E + F = V - F/2 = 2.
        EXPECT_EQ(2 * m.report.vertices - m.report.faces, 4u);
        for (std::size_t i = 0; i < m.points.size(); ++i) {
            ASSERT_EQ(m.input_index[i], i);
        }
    }
}

std::string shared_mesh(const std::string& name) {
    return std::string(TAPELINE_SHARED_DATA_DIR) + "/meshes/" + name;
}

TEST(ReadData, SharedBinaryPly) {
    const std::string path = shared_mesh("bob_loop3.ply");
    if (!std::filesystem::exists(path)) {
        GTEST_SKIP() << path << " not present";
    }
    const LoadedView m = load(path);
    expect_valid(m);
    EXPECT_EQ(m.report.format, "ply-binary-le");
    EXPECT_EQ(m.report.input_vertices, 342016u);
    EXPECT_EQ(m.report.input_faces, 684032u);
    EXPECT_EQ(m.report.faces, 684032u);
    EXPECT_EQ(m.report.components, 1u);
}

TEST(ReadData, EverySharedMeshLoadsAsAValidTriangleMesh) {
    const std::string dir = std::string(TAPELINE_SHARED_DATA_DIR) + "/meshes";
    if (!std::filesystem::is_directory(dir)) {
        GTEST_SKIP() << dir << " not present";
    }
    for (const auto& entry : std::filesystem::directory_iterator(dir)) {
        const std::string path = entry.path().string();
        const std::string ext = entry.path().extension().string();
        if (ext != ".off" && ext != ".obj" && ext != ".ply" && ext != ".stl") {
            continue;
        }
        SCOPED_TRACE(path);
        const LoadedView m = load(path);
        expect_valid(m);
        EXPECT_GT(m.report.faces, 0u);
        // Every mesh vertex comes from an input vertex and lists itself among its copies.
        for (std::size_t k = 0; k < m.input_index.size(); ++k) {
            const auto& c = m.copies.at(m.input_index[k]);
            ASSERT_NE(std::find(c.begin(), c.end(), k), c.end());
        }
    }
}

}  // namespace
