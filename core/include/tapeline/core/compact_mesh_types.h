// A triangle mesh as flat arrays: positions, corners, twin halfedges, vertex-to-corner and
// vertex-to-vertex tables. Light header without CGAL; the builder from a CGAL FaceListGraph is
// make_compact_mesh (compact_mesh.h).
//
// Conventions: face f has corners 3f, 3f+1, 3f+2 in the order of
// CGAL::Polygon_mesh_processing::Face_location (source(halfedge(f)), target(halfedge(f)),
// target(next(halfedge(f))), so barycentric coordinates carry over); halfedge 3f+k runs from
// corner k to corner k+1 (mod 3); twin[3f+k] is the halfedge of the neighbouring face on the same
// edge, or kNone on the border.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace tapeline {

/// A triangle mesh as flat arrays (built by make_compact_mesh, compact_mesh.h). Halfedge h is
/// corner h % 3 of face h / 3, from that corner to the next one.
struct CompactMesh {
    static constexpr std::uint32_t kNone = 0xffffffffu;  ///< no element

    std::vector<double> xyz;            ///< 3 per vertex
    std::vector<std::uint32_t> corner;  ///< 3 per face: vertex index at each corner
    std::vector<std::uint32_t> twin;    ///< 3 per face: opposite halfedge, kNone on the border
    /// CSR vertex -> its corners (ascending; corner c is in face c / 3).
    ///@{
    std::vector<std::uint32_t> vstart, vcorners;
    ///@}
    /// CSR vertex -> the other ends of its edges, border edges included, in the order of
    /// CGAL::halfedges_around_target(halfedge(v)) (empty for an isolated vertex).
    ///@{
    std::vector<std::uint32_t> nstart, neighbours;
    ///@}

    std::size_t vertex_count() const { return xyz.size() / 3; }   ///< number of vertices
    std::size_t face_count() const { return corner.size() / 3; }  ///< number of faces
    std::array<double, 3> point(std::uint32_t v) const {          ///< position of vertex v
        return {xyz[3 * v], xyz[3 * v + 1], xyz[3 * v + 2]};
    }
    /// next halfedge in h's face
    static std::uint32_t next_halfedge(std::uint32_t h) { return h % 3 == 2 ? h - 2 : h + 1; }
    /// previous halfedge in h's face
    static std::uint32_t prev_halfedge(std::uint32_t h) { return h % 3 == 0 ? h + 2 : h - 1; }
};

}  // namespace tapeline
