// Unfolding of the faces crossed by a path on a triangle mesh: the faces are laid into the plane
// one after another, each rotated rigidly about the edge it shares with the previous one, and the
// path is mapped into that plane. A polyhedral geodesic that passes no vertex is a straight segment
// in its unfolding (Mitchell, Mount, Papadimitriou, "The discrete geodesic problem", SIAM J.
// Comput. 16(4), 1987): the straightness of the unfolded path is a check of any on-mesh path, and
// the unfolded straight segment (when it stays inside the strip) is the shortest path through that
// face sequence. This is output (c) of the thesis' geodesic-curvature-flow section.
//
// Works for any polyline whose consecutive points lie on a common face: the on-mesh path of the
// curvature flow (CurvatureFlowPath::on_mesh), exact_mmp_path, exact_cgal_path.
#pragma once

#include <tapeline/geodesic/curvature_flow.h>
#include <tapeline/geodesic/unfold_types.h>

namespace tapeline::geodesic {

/// Unfolds the faces crossed by `path` (a range of points with x(), y(), z(), lying on the faces
/// of `tm`). Named parameters: vertex_point_map, vertex_index_map, face_index_map, geom_traits;
/// the indices in the result are those of the index maps. InvalidInput when the mesh is not a
/// triangle mesh, the tolerance is not > 0, a point is not finite, the path has fewer than two
/// distinct points, or a point is not on a face next to the previous point's face.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
///         (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam PointRange a range of points with x(), y(), z() convertible by CGAL::to_double.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map` and `face_index_map` (`ReadablePropertyMap`s onto [0, n)),
///         `geom_traits` (a CGAL kernel).
/// \throws TopologyError when a face is not a triangle.
/// \throws InvalidInput on a non-finite coordinate or an index map that is not a bijection
///         onto [0, n) (a Surface_mesh with removed elements needs collect_garbage()).
/// \throws InvalidInput also when the mesh has no faces or is beyond 32-bit indices, on a
///         tolerance not > 0, a non-finite point, fewer than two distinct points, or a point
///         not on a face next to the previous point's face.
template <class TriangleMesh, class PointRange,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
UnfoldedPath unfold_path(const TriangleMesh& tm, const PointRange& path,
                         const UnfoldOptions& options = {},
                         const NamedParameters& np = CGAL::parameters::default_values()) {
    const internal::GcfSetup<TriangleMesh, NamedParameters> setup(tm, np);
    return internal::unfold::unfold_checked(setup.mesh(), internal::to_vec3s(path), options,
                                            "unfold_path");
}

}  // namespace tapeline::geodesic
