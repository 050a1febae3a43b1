// Test facade for the compact mesh (core/compact_mesh.h): plain types only; the CGAL meshes are
// built and the builder instantiated in tests/support/io_compact_mesh.cpp.
#pragma once

#include <tapeline/core/compact_mesh_types.h>
#include <tapeline_test/io.h>

#include <array>
#include <cstddef>
#include <vector>

namespace tapeline_test {

/// The compact mesh of a polygon soup turned into a CGAL mesh of `kind`, with what CGAL itself
/// says about that mesh: per face its vertices from halfedge(f) on (source first, the
/// Face_location order), per vertex its neighbours (halfedges_around_target), per halfedge of a
/// face whether its opposite is a border halfedge.
struct CompactMeshView {
    tapeline::CompactMesh mesh;
    std::vector<std::array<std::size_t, 3>> face_vertices;
    std::vector<std::vector<std::size_t>> neighbours;
    std::vector<std::array<bool, 3>> border;
};
CompactMeshView compact_mesh_of(const Points& points, const Faces& faces, MeshKind kind);

}  // namespace tapeline_test
