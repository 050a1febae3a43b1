// A minimal closed triangle mesh that models CGAL's FaceListGraph (hence HalfedgeListGraph,
// HalfedgeGraph), EdgeListGraph and Boost's IncidenceGraph with nothing else: its own descriptor
// types, boost::graph_traits, the free functions those concepts require and a readable
// vertex_point map. No index maps, no iterator tricks, no CGAL base class: an algorithm that
// compiles on it asks only for what its documentation's concepts promise. CGAL 5.5 ships no
// graph archetypes, so this plays their part.
//
// Halfedges come in pairs (2k and 2k + 1 are opposite), as in CGAL::Surface_mesh, so an edge is a
// halfedge compared by pair; the mesh must be closed (every halfedge has a face).
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/Iterator_range.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/property_map/property_map.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <stdexcept>
#include <type_traits>
#include <utility>
#include <vector>

namespace tapeline_test::minimal {

using Point = CGAL::Epick::Point_3;

template <int Tag>
struct Index {
    static constexpr std::uint32_t none = 0xffffffffu;
    std::uint32_t i = none;
    Index() = default;
    explicit Index(std::uint32_t k) : i(k) {}
    friend bool operator==(Index a, Index b) { return a.i == b.i; }
    friend bool operator!=(Index a, Index b) { return a.i != b.i; }
    friend bool operator<(Index a, Index b) { return a.i < b.i; }
};
using Vertex = Index<0>;
using Halfedge = Index<1>;
using Face = Index<2>;

/// An edge: one of its two halfedges, compared by pair (source and target follow that halfedge).
struct Edge {
    std::uint32_t h = Index<1>::none;
    Edge() = default;
    explicit Edge(Halfedge k) : h(k.i) {}
    friend bool operator==(Edge a, Edge b) { return (a.h >> 1) == (b.h >> 1); }
    friend bool operator!=(Edge a, Edge b) { return !(a == b); }
    friend bool operator<(Edge a, Edge b) { return (a.h >> 1) < (b.h >> 1); }
};

struct Mesh {
    std::vector<Point> points;
    std::vector<std::uint32_t> target, next, face;  // per halfedge
    std::vector<std::uint32_t> vertex_halfedge;     // a halfedge pointing to each vertex
    std::vector<std::uint32_t> face_halfedge;
    std::vector<Vertex> vertex_list;
    std::vector<Halfedge> halfedge_list;
    std::vector<Edge> edge_list;
    std::vector<Face> face_list;

    /// A closed, consistently oriented triangle soup.
    Mesh(std::vector<Point> pts, const std::vector<std::array<std::size_t, 3>>& triangles)
        : points(std::move(pts)) {
        std::map<std::pair<std::size_t, std::size_t>, std::uint32_t> directed;
        auto halfedge_of = [&](std::size_t a, std::size_t b) {
            const auto it = directed.find({a, b});
            if (it != directed.end()) {
                return it->second;
            }
            const auto k = static_cast<std::uint32_t>(target.size());
            target.push_back(static_cast<std::uint32_t>(b));
            target.push_back(static_cast<std::uint32_t>(a));
            next.resize(k + 2, Index<1>::none);
            face.resize(k + 2, Index<2>::none);
            directed[{a, b}] = k;
            directed[{b, a}] = k + 1;
            return k;
        };
        vertex_halfedge.assign(points.size(), Index<1>::none);
        for (std::size_t f = 0; f < triangles.size(); ++f) {
            std::uint32_t h[3];
            for (int c = 0; c < 3; ++c) {
                h[c] = halfedge_of(triangles[f][c], triangles[f][(c + 1) % 3]);
                if (face[h[c]] != Index<2>::none) {
                    throw std::invalid_argument("minimal mesh: inconsistent orientation");
                }
                face[h[c]] = static_cast<std::uint32_t>(f);
                vertex_halfedge[target[h[c]]] = h[c];
            }
            for (int c = 0; c < 3; ++c) {
                next[h[c]] = h[(c + 1) % 3];
            }
            face_halfedge.push_back(h[0]);
        }
        for (std::uint32_t f : face) {
            if (f == Index<2>::none) {
                throw std::invalid_argument("minimal mesh: not closed");
            }
        }
        for (std::uint32_t v = 0; v < points.size(); ++v) {
            vertex_list.emplace_back(v);
        }
        for (std::uint32_t h = 0; h < target.size(); ++h) {
            halfedge_list.emplace_back(h);
            if (h % 2 == 0) {
                edge_list.emplace_back(Halfedge(h));
            }
        }
        for (std::uint32_t f = 0; f < face_halfedge.size(); ++f) {
            face_list.emplace_back(f);
        }
    }
};

/// The vertex_point map: readable, by const reference.
struct PointMap {
    using key_type = Vertex;
    using value_type = Point;
    using reference = const Point&;
    using category = boost::readable_property_map_tag;
    const Mesh* mesh = nullptr;
    friend reference get(const PointMap& pm, Vertex v) { return pm.mesh->points[v.i]; }
};
}  // namespace tapeline_test::minimal

namespace std {
template <int Tag>
struct hash<tapeline_test::minimal::Index<Tag>> {
    std::size_t operator()(tapeline_test::minimal::Index<Tag> k) const { return k.i; }
};
template <>
struct hash<tapeline_test::minimal::Edge> {
    std::size_t operator()(tapeline_test::minimal::Edge e) const { return e.h >> 1; }
};
}  // namespace std

namespace CGAL {
template <>
struct graph_has_property<tapeline_test::minimal::Mesh, vertex_point_t> : CGAL::Tag_true {};
}  // namespace CGAL

namespace boost {
template <>
struct property_map<tapeline_test::minimal::Mesh, CGAL::vertex_point_t> {
    using type = tapeline_test::minimal::PointMap;
    using const_type = tapeline_test::minimal::PointMap;
};
template <>
struct graph_traits<tapeline_test::minimal::Mesh> {
    using M = tapeline_test::minimal::Mesh;
    using vertex_descriptor = tapeline_test::minimal::Vertex;
    using halfedge_descriptor = tapeline_test::minimal::Halfedge;
    using edge_descriptor = tapeline_test::minimal::Edge;
    using face_descriptor = tapeline_test::minimal::Face;
    using vertex_iterator = std::vector<vertex_descriptor>::const_iterator;
    using halfedge_iterator = std::vector<halfedge_descriptor>::const_iterator;
    using edge_iterator = std::vector<edge_descriptor>::const_iterator;
    using face_iterator = std::vector<face_descriptor>::const_iterator;
    using out_edge_iterator = CGAL::Out_edge_iterator<M>;
    using in_edge_iterator = CGAL::In_edge_iterator<M>;
    using directed_category = boost::undirected_tag;
    using edge_parallel_category = boost::disallow_parallel_edge_tag;
    struct traversal_category : boost::incidence_graph_tag,
                                boost::vertex_list_graph_tag,
                                boost::edge_list_graph_tag {};
    using vertices_size_type = std::size_t;
    using halfedges_size_type = std::size_t;
    using edges_size_type = std::size_t;
    using faces_size_type = std::size_t;
    using degree_size_type = std::size_t;
    static vertex_descriptor null_vertex() { return {}; }
    static halfedge_descriptor null_halfedge() { return {}; }
    static face_descriptor null_face() { return {}; }
};
}  // namespace boost

namespace tapeline_test::minimal {

using GT = boost::graph_traits<Mesh>;

// FaceListGraph, HalfedgeListGraph, EdgeListGraph, VertexListGraph.
inline CGAL::Iterator_range<GT::vertex_iterator> vertices(const Mesh& m) {
    return CGAL::make_range(m.vertex_list.begin(), m.vertex_list.end());
}
inline CGAL::Iterator_range<GT::halfedge_iterator> halfedges(const Mesh& m) {
    return CGAL::make_range(m.halfedge_list.begin(), m.halfedge_list.end());
}
inline CGAL::Iterator_range<GT::edge_iterator> edges(const Mesh& m) {
    return CGAL::make_range(m.edge_list.begin(), m.edge_list.end());
}
inline CGAL::Iterator_range<GT::face_iterator> faces(const Mesh& m) {
    return CGAL::make_range(m.face_list.begin(), m.face_list.end());
}
inline std::size_t num_vertices(const Mesh& m) {
    return m.vertex_list.size();
}
inline std::size_t num_halfedges(const Mesh& m) {
    return m.halfedge_list.size();
}
inline std::size_t num_edges(const Mesh& m) {
    return m.edge_list.size();
}
inline std::size_t num_faces(const Mesh& m) {
    return m.face_list.size();
}

// HalfedgeGraph, FaceGraph.
inline Vertex target(Halfedge h, const Mesh& m) {
    return Vertex(m.target[h.i]);
}
inline Vertex source(Halfedge h, const Mesh& m) {
    return Vertex(m.target[h.i ^ 1u]);
}
inline Halfedge opposite(Halfedge h, const Mesh&) {
    return Halfedge(h.i ^ 1u);
}
inline Halfedge next(Halfedge h, const Mesh& m) {
    return Halfedge(m.next[h.i]);
}
inline Halfedge prev(Halfedge h, const Mesh& m) {
    return Halfedge(m.next[m.next[h.i]]);  // triangles only
}
inline Edge edge(Halfedge h, const Mesh&) {
    return Edge(h);
}
inline Halfedge halfedge(Edge e, const Mesh&) {
    return Halfedge(e.h);
}
inline Vertex target(Edge e, const Mesh& m) {
    return target(Halfedge(e.h), m);
}
inline Vertex source(Edge e, const Mesh& m) {
    return source(Halfedge(e.h), m);
}
inline Halfedge halfedge(Vertex v, const Mesh& m) {
    return Halfedge(m.vertex_halfedge[v.i]);
}
inline Halfedge halfedge(Face f, const Mesh& m) {
    return Halfedge(m.face_halfedge[f.i]);
}
inline Face face(Halfedge h, const Mesh& m) {
    return Face(m.face[h.i]);
}
inline std::pair<Halfedge, bool> halfedge(Vertex u, Vertex v, const Mesh& m) {
    const Halfedge start = halfedge(v, m);
    Halfedge h = start;
    do {
        if (source(h, m) == u) {
            return {h, true};
        }
        h = opposite(next(h, m), m);
    } while (h != start);
    return {Halfedge(), false};
}
inline std::pair<Edge, bool> edge(Vertex u, Vertex v, const Mesh& m) {
    const auto h = halfedge(u, v, m);
    return {h.second ? Edge(h.first) : Edge(), h.second};
}

// IncidenceGraph (Boost's Dijkstra walks out-edges).
inline CGAL::Iterator_range<GT::out_edge_iterator> out_edges(Vertex v, const Mesh& m) {
    return CGAL::make_range(GT::out_edge_iterator(halfedge(v, m), m),
                            GT::out_edge_iterator(halfedge(v, m), m, 1));
}
inline CGAL::Iterator_range<GT::in_edge_iterator> in_edges(Vertex v, const Mesh& m) {
    return CGAL::make_range(GT::in_edge_iterator(halfedge(v, m), m),
                            GT::in_edge_iterator(halfedge(v, m), m, 1));
}
inline std::size_t out_degree(Vertex v, const Mesh& m) {
    std::size_t d = 0;
    for (auto e : out_edges(v, m)) {
        (void)e;
        ++d;
    }
    return d;
}
inline std::size_t in_degree(Vertex v, const Mesh& m) {
    return out_degree(v, m);
}
inline std::size_t degree(Vertex v, const Mesh& m) {
    return out_degree(v, m);
}

inline PointMap get(CGAL::vertex_point_t, const Mesh& m) {
    return PointMap{&m};
}

}  // namespace tapeline_test::minimal
