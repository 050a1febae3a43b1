// Analytic test surfaces (sphere, ellipsoid, torus, open cylinder) as CGAL triangle meshes.
//
// Ground truth for geodesic tests and benchmarks: each surface has a spec string (see SurfaceSpec
// in <tapeline/surfaces/analytic_surface_types.h>), a polygon soup generator and, in
// <tapeline/surfaces/analytic_geodesics.h>, the exact smooth geodesic distance where one is known.
// The icosphere is the classical midpoint subdivision of the icosahedron with vertices pushed to
// the sphere; nothing here implements a paper.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/surfaces/analytic_surface_types.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <string>
#include <vector>

namespace tapeline {

/// Clears `tm` and fills it with the surface of `spec`: vertex i of the soup becomes the i-th
/// vertex of `tm` (in vertices(tm) order), face j the j-th face.
///
/// Named parameters: `vertex_point_map` (default: boost::get(CGAL::vertex_point, tm)); its value
/// type must be constructible from three doubles.
/// Throws InvalidInput for a bad spec, TopologyError if the mesh refuses a face (cannot happen for
/// the generated surfaces; the check stays in Release builds).
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` and `VertexListGraph`.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `WritablePropertyMap` vertex_descriptor -> a point constructible from three
///         doubles).
/// \throws InvalidInput when a field of `spec` is out of range.
/// \throws TopologyError when the mesh refuses a face.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
void make_surface_mesh(const SurfaceSpec& spec, TriangleMesh& tm,
                       const NamedParameters& np = CGAL::parameters::default_values()) {
    using GT = boost::graph_traits<TriangleMesh>;
    using vertex_descriptor = typename GT::vertex_descriptor;
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                CGAL::get_property_map(CGAL::vertex_point, tm));
    using Point = typename boost::property_traits<decltype(vpm)>::value_type;

    const SurfaceSoup soup = generate_surface(spec);
    CGAL::clear(tm);
    // reserve() is found by argument-dependent lookup, as in CGAL::copy_face_graph.
    reserve(tm, static_cast<typename GT::vertices_size_type>(soup.points.size()),
            static_cast<typename GT::edges_size_type>(soup.points.size() + soup.triangles.size()),
            static_cast<typename GT::faces_size_type>(soup.triangles.size()));
    std::vector<vertex_descriptor> vertex(soup.points.size());
    for (std::size_t i = 0; i < soup.points.size(); ++i) {
        vertex[i] = add_vertex(tm);
        const auto& p = soup.points[i];
        put(vpm, vertex[i], Point(p[0], p[1], p[2]));
    }
    std::vector<vertex_descriptor> face(3);
    for (std::size_t f = 0; f < soup.triangles.size(); ++f) {
        for (int k = 0; k < 3; ++k)
            face[k] = vertex[soup.triangles[f][k]];
        if (CGAL::Euler::add_face(face, tm) == GT::null_face())
            throw TopologyError("make_surface_mesh(" + spec.to_string() + "): face " +
                                std::to_string(f) + " was refused by the mesh");
    }
}

}  // namespace tapeline
