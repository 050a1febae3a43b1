// A body mesh brought into the canonical measuring frame (body_types.h): millimetres, y up,
// z front, x to the body's left, floor at y = 0.
//
// Input is any CGAL FaceListGraph triangle mesh (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...)
// through boost::graph_traits, with the `vertex_point_map` named parameter; read files with
// tapeline::read_triangle_mesh (core), which triangulates polygons. The body keeps the mesh's
// vertex and face order: points[i] is the i-th vertex of vertices(tm), triangles[j] the j-th face
// of faces(tm), so a landmark can be located on the caller's mesh again.
#pragma once

#include <tapeline/core/compact_mesh.h>
#include <tapeline/core/errors.h>
#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/holes.h>
#include <tapeline/measurement/internal/sections.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/named_params_helper.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::measurement {

/// Builds a Body from points (input coordinates and unit) and triangles. Holes up to 5 % of the
/// stature across are filled (holes.h; Body::holes, BodyMesh::filled). Rejects NaN/infinite
/// coordinates, out-of-range indices and a bad frame (InvalidInput), and bigger holes and
/// non-manifold meshes (TopologyError), each with a message naming options.name and the element.
inline Body make_body(std::vector<Vec3> points, std::vector<std::array<std::uint32_t, 3>> tris,
                      const BodyOptions& options) {
    const std::string& name = options.name;
    if (options.up.index == options.front.index) {
        throw InvalidInput(name + ": up axis " + options.up.to_string() + " and front axis " +
                           options.front.to_string() +
                           " must be perpendicular (two different coordinate axes)");
    }
    if (points.empty() || tris.empty()) {
        throw InvalidInput(name + ": empty body mesh (" + std::to_string(points.size()) +
                           " vertices, " + std::to_string(tris.size()) + " triangles)");
    }
    for (std::size_t v = 0; v < points.size(); ++v) {
        for (double c : points[v]) {
            if (!std::isfinite(c)) {
                throw InvalidInput(name + ": vertex " + std::to_string(v) + " has a" +
                                   (std::isnan(c) ? " NaN" : "n infinite") + " coordinate");
            }
        }
    }
    for (std::size_t f = 0; f < tris.size(); ++f) {
        for (std::uint32_t v : tris[f]) {
            if (v >= points.size()) {
                throw InvalidInput(name + ": face " + std::to_string(f) + " references vertex " +
                                   std::to_string(v) + " but there are " +
                                   std::to_string(points.size()) + " vertices");
            }
        }
    }
    Body body;
    BodyFrame& fr = body.frame;
    fr.up = options.up;
    fr.front = options.front;
    fr.pose = options.pose;
    const Vec3 up = options.up.vector(), front = options.front.vector();
    fr.rows = {internal::cross(up, front), up, front};
    double lo = std::numeric_limits<double>::infinity(), hi = -lo;
    for (const auto& p : points) {
        const double h = internal::dot(up, p);
        lo = std::min(lo, h);
        hi = std::max(hi, h);
    }
    const double input_height = hi - lo;
    if (!(input_height > 0)) {
        throw InvalidInput(name + ": the body has zero height along the up axis " +
                           options.up.to_string());
    }
    if (options.unit) {
        fr.unit = *options.unit;
    } else {
        fr.unit = infer_length_unit(input_height, name);
        fr.unit_inferred = true;
    }
    fr.scale = millimetres_per(fr.unit);
    fr.floor = lo * fr.scale;
    fr.height = input_height * fr.scale;
    for (auto& p : points) {
        p = fr.to_canonical(p);
    }
    body.holes = fill_body_holes(points, tris, body.mesh.filled, fr.height, name);
    if (!body.holes.empty()) {
        // A patch may reach below the input's lowest vertex (a sole) or above its highest.
        double y0 = std::numeric_limits<double>::infinity(), y1 = -y0;
        for (const auto& p : points) {
            y0 = std::min(y0, p[1]);
            y1 = std::max(y1, p[1]);
        }
        for (auto& p : points) {
            p[1] -= y0;
        }
        for (auto& hole : body.holes) {
            hole.centre[1] -= y0;
            hole.height = hole.centre[1];
        }
        fr.floor += y0;
        fr.height = y1 - y0;
    }
    body.mesh.name = name;
    body.mesh.points = std::move(points);
    body.mesh.triangles = std::move(tris);
    internal::build_adjacency(body.mesh);
    return body;
}

namespace internal {

/// The vertices (input coordinates, as doubles) and triangles of a CGAL triangle mesh
/// (FaceListGraph; named parameter vertex_point_map), read through the compact mesh
/// (core/compact_mesh.h) in the order of vertices(tm) and faces(tm). A triangle's corners start at
/// target(halfedge(f)). A face with other than three vertices is a TopologyError naming `what`
/// and the face.
template <class TriangleMesh, class NamedParameters>
std::pair<std::vector<Vec3>, std::vector<std::array<std::uint32_t, 3>>> triangle_soup(
    const TriangleMesh& tm, const std::string& what, const NamedParameters& np) {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    const auto vpm = choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                      CGAL::get_const_property_map(CGAL::vertex_point, tm));
    // Enumeration order whatever index maps the mesh carries (a Surface_mesh with removed
    // elements included), so that points[i] is the i-th vertex of vertices(tm).
    auto vertex_index = get(CGAL::dynamic_vertex_property_t<std::uint32_t>(), tm);
    std::uint32_t i = 0;
    for (auto v : vertices(tm))
        put(vertex_index, v, i++);
    auto face_index = get(CGAL::dynamic_face_property_t<std::uint32_t>(), tm);
    i = 0;
    for (auto f : faces(tm))
        put(face_index, f, i++);
    CompactMesh c;
    try {
        c = make_compact_mesh(tm, vpm, vertex_index, face_index, what);
    } catch (const TopologyError& e) {
        throw TopologyError(std::string(e.what()) +
                            "; tapeline::read_triangle_mesh triangulates polygons");
    }
    std::vector<Vec3> points(c.vertex_count());
    for (std::uint32_t v = 0; v < points.size(); ++v)
        points[v] = c.point(v);
    std::vector<std::array<std::uint32_t, 3>> tris(c.face_count());
    for (std::size_t f = 0; f < tris.size(); ++f)
        tris[f] = {c.corner[3 * f + 1], c.corner[3 * f + 2], c.corner[3 * f]};
    return {std::move(points), std::move(tris)};
}

}  // namespace internal

/// Builds a Body from a CGAL triangle mesh (FaceListGraph); named parameter: vertex_point_map.
/// A face with other than three vertices is a TopologyError naming it.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
Body make_body(const TriangleMesh& tm, const BodyOptions& options,
               const NamedParameters& np = CGAL::parameters::default_values()) {
    auto [points, tris] = internal::triangle_soup(tm, options.name, np);
    return make_body(std::move(points), std::move(tris), options);
}

}  // namespace tapeline::measurement
