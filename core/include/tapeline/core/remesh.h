// Another tessellation of the same surface, from CGAL: isotropic remeshing to a target edge
// length (Polygon_mesh_processing::isotropic_remeshing, borders split first and kept) and
// decimation to a vertex count (Surface_mesh_simplification::edge_collapse with Garland–Heckbert
// plane quadrics). A measurement that depends on how a body is triangulated is wrong: these make
// the re-meshed copies its tests and benchmark compare against (measurement/README.md), and
// `tapeline mesh remesh` / `tapeline mesh simplify` make them for a user's own meshes.
#pragma once

#include <tapeline/core/errors.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/measure.h>
#include <CGAL/Polygon_mesh_processing/remesh.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/Count_stop_predicate.h>
#include <CGAL/Surface_mesh_simplification/Policies/Edge_collapse/GarlandHeckbert_plane_policies.h>
#include <CGAL/Surface_mesh_simplification/edge_collapse.h>
#include <CGAL/boost/graph/helpers.h>

#include <cmath>
#include <cstddef>
#include <iterator>
#include <string>
#include <vector>

namespace tapeline {

/// At most this many faces come out of `remesh_isotropic` (estimated from the area before any
/// work): a slip of the unit (an edge of 0.005 on a millimetre mesh) would otherwise run for
/// hours and fill the memory.
inline constexpr double kMaxRemeshedFaces = 20e6;

struct RemeshReport {
    std::size_t vertices_before = 0, faces_before = 0;
    std::size_t vertices_after = 0, faces_after = 0;
};

namespace internal {

template <class TriangleMesh>
void check_remesh_input(const TriangleMesh& tm, const std::string& name) {
    if (num_faces(tm) == 0) {
        throw InvalidInput(name + ": the mesh has no faces");
    }
    if (!CGAL::is_triangle_mesh(tm)) {
        throw InvalidInput(name + ": the mesh has faces that are not triangles");
    }
}

/// The mesh without its removed elements (Surface_mesh keeps them until collected); a no-op for
/// graphs that free them at once.
template <class TriangleMesh>
auto collect_garbage(TriangleMesh& tm, int) -> decltype(tm.collect_garbage(), void()) {
    tm.collect_garbage();
}
template <class TriangleMesh>
void collect_garbage(TriangleMesh&, long) {}

}  // namespace internal

/// Re-meshes `tm` in place to near-equilateral triangles for a target edge length `edge_length`
/// (the mesh's unit): `iterations` rounds of split / collapse / flip / tangential relaxation with
/// every vertex projected back onto the input surface (CGAL's isotropic_remeshing). CGAL splits
/// edges longer than 4/3 of the target and collapses those shorter than 4/5 of it, so the mean
/// edge comes out under the target (0.77 of it on a fine icosphere, 0.93 on the bodies). Border
/// edges are split to the length and kept, so an open mesh keeps its holes where they were.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` with an internal vertex point map (the tool
///         and the tests use CGAL::Surface_mesh; other graphs are not tested).
/// \throws InvalidInput naming `name` when `edge_length` is not a positive finite number, when
///         `iterations` is 0, when the mesh has no faces or faces that are not triangles, or when
///         the result would have more than kMaxRemeshedFaces faces.
template <class TriangleMesh>
RemeshReport remesh_isotropic(TriangleMesh& tm, double edge_length, unsigned iterations = 3,
                              const std::string& name = "mesh") {
    namespace PMP = CGAL::Polygon_mesh_processing;
    if (!(std::isfinite(edge_length) && edge_length > 0)) {
        throw InvalidInput(name + ": the target edge length must be a positive number, not " +
                           std::to_string(edge_length));
    }
    if (iterations == 0) {
        throw InvalidInput(name + ": remeshing needs at least one iteration");
    }
    internal::check_remesh_input(tm, name);
    RemeshReport r{num_vertices(tm), num_faces(tm), 0, 0};
    // An equilateral triangle of side L has area sqrt(3)/4 L².
    const double area = CGAL::to_double(PMP::area(tm));
    const double estimate = area / (std::sqrt(3.0) / 4.0 * edge_length * edge_length);
    if (!(estimate <= kMaxRemeshedFaces)) {
        throw InvalidInput(name + ": an edge length of " + std::to_string(edge_length) +
                           " (the mesh's unit) would give about " +
                           std::to_string(static_cast<long long>(estimate)) +
                           " faces, more than 20 million; is the unit right?");
    }
    using halfedge_descriptor = typename boost::graph_traits<TriangleMesh>::halfedge_descriptor;
    using edge_descriptor = typename boost::graph_traits<TriangleMesh>::edge_descriptor;
    std::vector<halfedge_descriptor> border_halfedges;
    PMP::border_halfedges(faces(tm), tm, std::back_inserter(border_halfedges));
    std::vector<edge_descriptor> border;
    border.reserve(border_halfedges.size());
    for (halfedge_descriptor h : border_halfedges) {
        border.push_back(edge(h, tm));
    }
    if (!border.empty()) {
        PMP::split_long_edges(border, edge_length, tm);
    }
    PMP::isotropic_remeshing(
        faces(tm), edge_length, tm,
        CGAL::parameters::number_of_iterations(iterations).protect_constraints(true));
    internal::collect_garbage(tm, 0);
    r.vertices_after = num_vertices(tm);
    r.faces_after = num_faces(tm);
    return r;
}

/// Decimates `tm` in place to about `vertices` vertices by edge collapses ordered and placed by
/// Garland–Heckbert plane quadrics (CGAL's edge_collapse); the count is reached within a few
/// vertices (collapses are counted in edges, about three per vertex). The removed elements are
/// collected before it returns.
///
/// \tparam TriangleMesh a model of `MutableFaceGraph` with an internal vertex point map.
/// \throws InvalidInput naming `name` when `vertices` is below 4 or not below the mesh's vertex
///         count, or when the mesh has no faces or faces that are not triangles.
template <class TriangleMesh>
RemeshReport simplify_to_vertices(TriangleMesh& tm, std::size_t vertices,
                                  const std::string& name = "mesh") {
    namespace SMS = CGAL::Surface_mesh_simplification;
    internal::check_remesh_input(tm, name);
    RemeshReport r{num_vertices(tm), num_faces(tm), 0, 0};
    if (vertices < 4 || vertices >= r.vertices_before) {
        throw InvalidInput(name + ": cannot simplify " + std::to_string(r.vertices_before) +
                           " vertices to " + std::to_string(vertices) +
                           " (the target must be at least 4 and below the vertex count)");
    }
    using Kernel =
        typename CGAL::Kernel_traits<typename boost::property_traits<typename boost::property_map<
            TriangleMesh, CGAL::vertex_point_t>::type>::value_type>::Kernel;
    // Edges in proportion to vertices (E ≈ 3V on a closed mesh, whatever its genus and borders).
    const double edges_per_vertex =
        static_cast<double>(num_edges(tm)) / static_cast<double>(r.vertices_before);
    const auto target_edges =
        static_cast<std::size_t>(std::llround(edges_per_vertex * static_cast<double>(vertices)));
    SMS::Count_stop_predicate<TriangleMesh> stop(target_edges);
    SMS::GarlandHeckbert_plane_policies<TriangleMesh, Kernel> policies(tm);
    SMS::edge_collapse(
        tm, stop,
        CGAL::parameters::get_cost(policies.get_cost()).get_placement(policies.get_placement()));
    internal::collect_garbage(tm, 0);
    r.vertices_after = num_vertices(tm);
    r.faces_after = num_faces(tm);
    return r;
}

}  // namespace tapeline
