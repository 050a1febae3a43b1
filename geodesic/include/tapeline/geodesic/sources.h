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

template <class TriangleMesh>
using FaceLocation = CGAL::Polygon_mesh_processing::Face_location<TriangleMesh, double>;

/// A vertex or a face location.
template <class TriangleMesh>
using SurfacePoint = std::variant<typename boost::graph_traits<TriangleMesh>::vertex_descriptor,
                                  FaceLocation<TriangleMesh>>;

/// The sources of a distance field: vertices and face locations (the field is the minimum of the
/// single-source fields). Duplicates are harmless.
template <class TriangleMesh>
struct SourceSet {
    using vertex_descriptor = typename boost::graph_traits<TriangleMesh>::vertex_descriptor;
    using Location = FaceLocation<TriangleMesh>;

    std::vector<vertex_descriptor> vertices;
    std::vector<Location> locations;

    SourceSet() = default;
    explicit SourceSet(vertex_descriptor v) { vertices.push_back(v); }
    explicit SourceSet(const Location& l) { locations.push_back(l); }
    explicit SourceSet(const SurfacePoint<TriangleMesh>& p) { add(p); }

    SourceSet& add(vertex_descriptor v) {
        vertices.push_back(v);
        return *this;
    }
    SourceSet& add(const Location& l) {
        locations.push_back(l);
        return *this;
    }
    SourceSet& add(const SurfacePoint<TriangleMesh>& p) {
        if (const auto* v = std::get_if<vertex_descriptor>(&p))
            vertices.push_back(*v);
        else
            locations.push_back(std::get<Location>(p));
        return *this;
    }

    std::size_t size() const { return vertices.size() + locations.size(); }
    bool empty() const { return size() == 0; }
};

}  // namespace tapeline::geodesic
