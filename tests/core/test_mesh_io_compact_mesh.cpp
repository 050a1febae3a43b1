// The compact mesh (core/compact_mesh.h) against what CGAL says about the mesh it was built from,
// on a Surface_mesh and a Polyhedron_3, closed and with a border; a quad face is refused.
#include <tapeline/core/errors.h>
#include <tapeline_test/compact_mesh.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>

namespace {

using tapeline::CompactMesh;
using tapeline_test::compact_mesh_of;
using tapeline_test::CompactMeshView;
using tapeline_test::Faces;
using tapeline_test::MeshKind;
using tapeline_test::Points;

// An octahedron (closed), and the same with two adjacent faces left out (a border of 4 edges).
const Points kOctahedron{{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
const Faces kOctahedronFaces{{0, 2, 4}, {2, 1, 4}, {1, 3, 4}, {3, 0, 4},
                             {2, 0, 5}, {1, 2, 5}, {3, 1, 5}, {0, 3, 5}};

void expect_consistent(const CompactMeshView& view, const Points& points, std::size_t faces) {
    const CompactMesh& m = view.mesh;
    ASSERT_EQ(m.vertex_count(), points.size());
    ASSERT_EQ(m.face_count(), faces);
    for (std::uint32_t v = 0; v < m.vertex_count(); ++v)
        for (int k = 0; k < 3; ++k)
            EXPECT_EQ(m.point(v)[k], points[v][k]);
    std::size_t border = 0;
    for (std::uint32_t f = 0; f < m.face_count(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t h = 3 * f + k;
            EXPECT_EQ(m.corner[h], view.face_vertices[f][k]) << "face " << f << " corner " << k;
            EXPECT_EQ(m.twin[h] == CompactMesh::kNone, view.border[f][k]) << "halfedge " << h;
            if (m.twin[h] == CompactMesh::kNone) {
                ++border;
                continue;
            }
            // The twin runs the same edge the other way, and its twin is h again.
            EXPECT_EQ(m.twin[m.twin[h]], h);
            EXPECT_EQ(m.corner[m.twin[h]], m.corner[CompactMesh::next_halfedge(h)]);
            EXPECT_EQ(m.corner[CompactMesh::next_halfedge(m.twin[h])], m.corner[h]);
        }
    }
    EXPECT_EQ(border, [&] {
        std::size_t n = 0;
        for (const auto& b : view.border)
            n += std::count(b.begin(), b.end(), true);
        return n;
    }());
    // Vertex -> corners: every corner once, ascending, at its vertex.
    ASSERT_EQ(m.vstart.size(), m.vertex_count() + 1);
    ASSERT_EQ(m.vcorners.size(), 3 * m.face_count());
    for (std::uint32_t v = 0; v < m.vertex_count(); ++v) {
        for (std::uint32_t k = m.vstart[v]; k < m.vstart[v + 1]; ++k) {
            EXPECT_EQ(m.corner[m.vcorners[k]], v);
            if (k > m.vstart[v]) {
                EXPECT_LT(m.vcorners[k - 1], m.vcorners[k]);
            }
        }
        // Neighbours in CGAL's order around the vertex.
        const std::vector<std::uint32_t> nb(m.neighbours.begin() + m.nstart[v],
                                            m.neighbours.begin() + m.nstart[v + 1]);
        ASSERT_EQ(nb.size(), view.neighbours[v].size()) << "vertex " << v;
        for (std::size_t k = 0; k < nb.size(); ++k)
            EXPECT_EQ(nb[k], view.neighbours[v][k]);
    }
}

TEST(CompactMesh, ClosedOctahedronMatchesCgalOnBothMeshTypes) {
    for (MeshKind kind : {MeshKind::surface_mesh, MeshKind::polyhedron}) {
        const auto view = compact_mesh_of(kOctahedron, kOctahedronFaces, kind);
        expect_consistent(view, kOctahedron, 8);
        EXPECT_EQ(std::count(view.mesh.twin.begin(), view.mesh.twin.end(), CompactMesh::kNone), 0);
        for (std::uint32_t v = 0; v < 6; ++v)
            EXPECT_EQ(view.mesh.nstart[v + 1] - view.mesh.nstart[v], 4u);
    }
}

TEST(CompactMeshWithBorder, OpenOctahedronHasFourBorderHalfedges) {
    const Faces open(kOctahedronFaces.begin(), kOctahedronFaces.end() - 2);
    for (MeshKind kind : {MeshKind::surface_mesh, MeshKind::polyhedron}) {
        const auto view = compact_mesh_of(kOctahedron, open, kind);
        expect_consistent(view, kOctahedron, 6);
        EXPECT_EQ(std::count(view.mesh.twin.begin(), view.mesh.twin.end(), CompactMesh::kNone), 4);
    }
}

TEST(CompactMeshRejects, AQuadFaceNamingIt) {
    const Points points{{0, 0, 0}, {1, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0.5, -1, 0}};
    const Faces faces{{1, 0, 4}, {0, 1, 2, 3}};  // a triangle, then a quad sharing edge 0-1
    try {
        (void)compact_mesh_of(points, faces, MeshKind::surface_mesh);
        ADD_FAILURE() << "a quad face was accepted";
    } catch (const tapeline::TopologyError& e) {
        EXPECT_NE(std::string(e.what()).find("face #1 is not a triangle"), std::string::npos)
            << e.what();
    }
}

}  // namespace
