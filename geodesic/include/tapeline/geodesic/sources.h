// Source sets and surface points for the geodesic distance functions.
//
// A point on the surface is either a mesh vertex or a
// `CGAL::Polygon_mesh_processing::Face_location` (face + barycentric coordinates with respect to
// source(halfedge(f)), target(halfedge(f)), target(next(halfedge(f))), the PMP convention, which
// is also the one of `Surface_mesh_shortest_path`).
#pragma once

#include <CGAL/Polygon_mesh_processing/locate.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <cstddef>
#include <variant>
#include <vector>

namespace tapeline::geodesic {

/// A point inside a face: the face and its barycentric coordinates (PMP convention).
template <class TriangleMesh>
using FaceLocation = CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>;

/// A vertex or a face location.
template <class TriangleMesh>
using SurfacePoint = std::variant<typename boost::graph_traits<TriangleMesh>::vertex_descriptor,
                                  FaceLocation<TriangleMesh>>;

/// The sources of a distance field: vertices and face locations (the field is the minimum of the
/// single-source fields). Duplicates are harmless. The solvers check every source against the
/// mesh when they start (InvalidInput on a stale descriptor or bad barycentric coordinates).
///
/// \tparam TriangleMesh a model of `FaceGraph`; its vertex_descriptor and face_descriptor name
///         the sources.
template <class TriangleMesh>
struct SourceSet {
    /// A vertex of the mesh.
    using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
    using Location = FaceLocation<TriangleMesh>;  ///< a face and barycentric coordinates

    std::vector<vertex_descriptor> vertices;  ///< vertex sources
    std::vector<Location> locations;          ///< sources inside faces

    /// An empty set (the solvers reject it: add at least one source).
    SourceSet() = default;
    /// One vertex source.
    explicit SourceSet(vertex_descriptor v) { vertices.push_back(v); }
    /// One face-location source.
    explicit SourceSet(const Location& l) { locations.push_back(l); }
    /// One source, vertex or face location.
    explicit SourceSet(const SurfacePoint<TriangleMesh>& p) { add(p); }

    /// Adds a vertex source; returns `*this` for chaining.
    SourceSet& add(vertex_descriptor v) {
        vertices.push_back(v);
        return *this;
    }
    /// Adds a face-location source; returns `*this` for chaining.
    SourceSet& add(const Location& l) {
        locations.push_back(l);
        return *this;
    }
    /// Adds a vertex or face-location source; returns `*this` for chaining.
    SourceSet& add(const SurfacePoint<TriangleMesh>& p) {
        if (const auto* v = std::get_if<vertex_descriptor>(&p))
            vertices.push_back(*v);
        else
            locations.push_back(std::get<Location>(p));
        return *this;
    }

    /// Number of sources (vertices and face locations).
    std::size_t size() const { return vertices.size() + locations.size(); }
    /// True when the set holds no source.
    bool empty() const { return size() == 0; }
};

}  // namespace tapeline::geodesic
