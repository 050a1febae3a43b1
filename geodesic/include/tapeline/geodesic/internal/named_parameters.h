// Resolution of the CGAL named parameters shared by the baseline geodesic methods:
// vertex_point_map, vertex_index_map, halfedge_index_map, face_index_map, geom_traits.
#pragma once

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/named_params_helper.h>

namespace tapeline::geodesic::internal {

template <class TriangleMesh, class NamedParameters>
struct MeshParameters {
    using VertexPointMap =
        typename CGAL::GetVertexPointMap<TriangleMesh, NamedParameters>::const_type;
    using GeomTraits = typename CGAL::GetGeomTraits<TriangleMesh, NamedParameters>::type;
    using VertexIndexMap =
        typename CGAL::GetInitializedVertexIndexMap<TriangleMesh, NamedParameters>::const_type;
    using HalfedgeIndexMap =
        typename CGAL::GetInitializedHalfedgeIndexMap<TriangleMesh, NamedParameters>::const_type;
    using FaceIndexMap =
        typename CGAL::GetInitializedFaceIndexMap<TriangleMesh, NamedParameters>::const_type;
    using Point_3 = typename GeomTraits::Point_3;

    static VertexPointMap vertex_point_map(const TriangleMesh& tm, const NamedParameters& np) {
        using CGAL::parameters::choose_parameter;
        using CGAL::parameters::get_parameter;
        return choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                CGAL::get_const_property_map(CGAL::vertex_point, tm));
    }
    static GeomTraits geom_traits(const NamedParameters& np) {
        using CGAL::parameters::choose_parameter;
        using CGAL::parameters::get_parameter;
        return choose_parameter<GeomTraits>(get_parameter(np, CGAL::internal_np::geom_traits));
    }
    static VertexIndexMap vertex_index_map(const TriangleMesh& tm, const NamedParameters& np) {
        return CGAL::get_initialized_vertex_index_map(tm, np);
    }
    static HalfedgeIndexMap halfedge_index_map(const TriangleMesh& tm, const NamedParameters& np) {
        return CGAL::get_initialized_halfedge_index_map(tm, np);
    }
    static FaceIndexMap face_index_map(const TriangleMesh& tm, const NamedParameters& np) {
        return CGAL::get_initialized_face_index_map(tm, np);
    }
};

}  // namespace tapeline::geodesic::internal
