// A minimal triangle mesh written for the genericity test: flat arrays, integer descriptors,
// boost::graph_traits and the free functions of the concepts the algorithms' documentation names,
// nothing else. No CGAL base class and no internal vertex, halfedge or face index maps (CGAL's
// get_initialized_*_index_map falls back on dynamic property maps, keyed by std::hash): an
// algorithm that compiles and runs on it asks only for what its concepts promise. CGAL 5.5 ships
// no graph archetypes; this plays their part.
//
// The base: HalfedgeListGraph (hence HalfedgeGraph, which refines Boost's IncidenceGraph:
// out_edges, out_degree, source(e), target(e)), FaceListGraph (hence FaceGraph), descriptors that
// are DefaultConstructible, Assignable, EqualityComparable and Hashable (std::hash), and a
// readable vertex_point map with its CGAL::graph_has_property specialization.
//
// Beyond the base, the algorithms need (each named in their \tparam, as does the test's own
// run_algorithms):
//  - VertexListGraph: vertices(g), num_vertices(g), vertex_iterator, vertices_size_type.
//    vertices_size_type and vertices(g): CGAL::get_initialized_vertex_index_map (the dynamic
//    index map's value type, and its initialisation), called by every algorithm through
//    geodesic/internal/named_parameters.h and by run_algorithms. vertices(g) and num_vertices(g):
//    geodesic::internal::MeshIndex (mesh_checks.h), built by every algorithm, and
//    boost::dijkstra_shortest_paths_no_init (its heap index map) in geodesic::dijkstra_distances.
//  - EdgeListGraph: edges(g), edge_iterator. geodesic::internal::connected_components
//    (mesh_checks.h), called by dijkstra_distances, exact_mmp_distances, exact_mmp_path,
//    heat_distances, fast_marching_distances, gcf_distances, geodesic_path and unfold_path.
//    num_edges(g), edges_size_type and the traversal tags complete the two concepts; no call uses
//    them.
// Nothing else: no operator< on descriptors, no in_edges, no index maps. (copy_of reads a
// Surface_mesh to build the arrays; the algorithms see only the functions below.)
// One semantic requirement the types do not show: an edge descriptor keeps the halfedge it was
// made from, so that source(e) of an out-edge of v is v (Boost's IncidenceGraph;
// dijkstra_distances walks out_edges and takes target(e) as the neighbour). An edge reduced to
// its smaller halfedge compiles and gives wrong Dijkstra distances.
#pragma once

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Iterator_range.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <boost/graph/graph_traits.hpp>
#include <boost/iterator/iterator_facade.hpp>
#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <iterator>
#include <stdexcept>
#include <utility>
#include <vector>

namespace tapeline_test::minimal {

using Point = CGAL::Epick::Point_3;

constexpr std::uint32_t kNone = 0xffffffffu;

/// A descriptor: an index into the mesh's arrays, kNone for the null element.
template <int Kind>
struct Index {
    std::uint32_t i = kNone;
    Index() = default;
    explicit Index(std::uint32_t k) : i(k) {}
    friend bool operator==(Index a, Index b) { return a.i == b.i; }
    friend bool operator!=(Index a, Index b) { return a.i != b.i; }
};
using Vertex = Index<0>;
using Halfedge = Index<1>;
using Face = Index<2>;

/// An edge: one of its two halfedges, `h`, which gives it a direction (source(e) and target(e)
/// are those of h, so that an out-edge of v starts at v, as Boost's IncidenceGraph requires), and
/// the smaller of the two, `key`, by which edges compare and hash.
struct Edge {
    std::uint32_t h = kNone, key = kNone;
    Edge() = default;
    Edge(std::uint32_t halfedge, std::uint32_t smaller) : h(halfedge), key(smaller) {}
    friend bool operator==(Edge a, Edge b) { return a.key == b.key; }
    friend bool operator!=(Edge a, Edge b) { return a.key != b.key; }
};

/// Walks the indices 0, 1, ... as descriptors of type D.
template <class D>
class IndexIterator
    : public boost::iterator_facade<IndexIterator<D>, D, std::random_access_iterator_tag, D> {
public:
    IndexIterator() = default;
    explicit IndexIterator(std::uint32_t i) : i_(i) {}

private:
    friend class boost::iterator_core_access;
    D dereference() const { return D(i_); }
    bool equal(const IndexIterator& o) const { return i_ == o.i_; }
    void increment() { ++i_; }
    void decrement() { --i_; }
    void advance(std::ptrdiff_t n) { i_ = static_cast<std::uint32_t>(i_ + n); }
    std::ptrdiff_t distance_to(const IndexIterator& o) const {
        return static_cast<std::ptrdiff_t>(o.i_) - static_cast<std::ptrdiff_t>(i_);
    }
    std::uint32_t i_ = 0;
};

/// The arrays. Halfedge h goes from target[opposite[h]] to target[h]; next[h] follows it around
/// face[h] (kNone on a border halfedge). vertex_halfedge[v] has target v (kNone if v is
/// isolated); face_halfedge[f] lies on f.
struct Mesh {
    std::vector<Point> positions;
    std::vector<std::uint32_t> next, opposite, target, face;
    std::vector<std::uint32_t> vertex_halfedge, face_halfedge;
};

/// Walks the edges: the halfedges smaller than their opposite.
class EdgeIterator
    : public boost::iterator_facade<EdgeIterator, Edge, std::forward_iterator_tag, Edge> {
public:
    EdgeIterator() = default;
    EdgeIterator(const Mesh& m, std::uint32_t h) : m_(&m), h_(h) { skip(); }

private:
    friend class boost::iterator_core_access;
    void skip() {
        while (h_ < m_->opposite.size() && m_->opposite[h_] < h_)
            ++h_;
    }
    Edge dereference() const { return Edge(h_, h_); }
    bool equal(const EdgeIterator& o) const { return h_ == o.h_; }
    void increment() {
        ++h_;
        skip();
    }
    const Mesh* m_ = nullptr;
    std::uint32_t h_ = 0;
};

/// The same mesh as `sm` (which has no removed elements), element for element: vertex, halfedge
/// and face i of the copy are those of index i in `sm`, and every incidence is the same.
inline Mesh copy_of(const CGAL::Surface_mesh<Point>& sm) {
    if (sm.has_garbage())
        throw std::invalid_argument("minimal mesh: the Surface_mesh has removed elements");
    using SM = CGAL::Surface_mesh<Point>;
    auto index = [](auto d) {
        return d == decltype(d)() ? kNone : static_cast<std::uint32_t>(d.idx());
    };
    Mesh m;
    for (SM::Vertex_index v : sm.vertices()) {
        m.positions.push_back(sm.point(v));
        m.vertex_halfedge.push_back(index(sm.halfedge(v)));
    }
    for (SM::Halfedge_index h : sm.halfedges()) {
        m.next.push_back(index(sm.next(h)));
        m.opposite.push_back(index(sm.opposite(h)));
        m.target.push_back(index(sm.target(h)));
        m.face.push_back(index(sm.face(h)));
    }
    for (SM::Face_index f : sm.faces())
        m.face_halfedge.push_back(index(sm.halfedge(f)));
    return m;
}

/// The vertex_point map: readable, by const reference.
struct PointMap {
    using key_type = Vertex;
    using value_type = Point;
    using reference = const Point&;
    using category = boost::readable_property_map_tag;
    const Mesh* mesh = nullptr;
    friend reference get(const PointMap& map, Vertex v) { return map.mesh->positions[v.i]; }
};

}  // namespace tapeline_test::minimal

namespace std {
template <int Kind>
struct hash<tapeline_test::minimal::Index<Kind>> {
    std::size_t operator()(tapeline_test::minimal::Index<Kind> d) const { return d.i; }
};
template <>
struct hash<tapeline_test::minimal::Edge> {
    std::size_t operator()(tapeline_test::minimal::Edge e) const { return e.key; }
};
}  // namespace std

namespace boost {

template <>
struct graph_traits<tapeline_test::minimal::Mesh> {
    using Mesh = tapeline_test::minimal::Mesh;
    // Boost's Graph and IncidenceGraph.
    using vertex_descriptor = tapeline_test::minimal::Vertex;
    using edge_descriptor = tapeline_test::minimal::Edge;
    using directed_category = boost::undirected_tag;
    using edge_parallel_category = boost::disallow_parallel_edge_tag;
    // The traversal tags of IncidenceGraph, VertexListGraph and EdgeListGraph.
    struct traversal_category : boost::incidence_graph_tag,
                                boost::vertex_list_graph_tag,
                                boost::edge_list_graph_tag {};
    using out_edge_iterator = CGAL::Out_edge_iterator<Mesh>;
    using degree_size_type = std::size_t;
    static vertex_descriptor null_vertex() { return {}; }
    // HalfedgeGraph, HalfedgeListGraph.
    using halfedge_descriptor = tapeline_test::minimal::Halfedge;
    using halfedge_iterator = tapeline_test::minimal::IndexIterator<halfedge_descriptor>;
    using halfedges_size_type = std::size_t;
    static halfedge_descriptor null_halfedge() { return {}; }
    // FaceGraph, FaceListGraph.
    using face_descriptor = tapeline_test::minimal::Face;
    using face_iterator = tapeline_test::minimal::IndexIterator<face_descriptor>;
    using faces_size_type = std::size_t;
    static face_descriptor null_face() { return {}; }
    // VertexListGraph.
    using vertex_iterator = tapeline_test::minimal::IndexIterator<vertex_descriptor>;
    using vertices_size_type = std::size_t;
    // EdgeListGraph.
    using edge_iterator = tapeline_test::minimal::EdgeIterator;
    using edges_size_type = std::size_t;
};

template <>
struct property_map<tapeline_test::minimal::Mesh, CGAL::vertex_point_t> {
    using type = tapeline_test::minimal::PointMap;
    using const_type = tapeline_test::minimal::PointMap;
};

}  // namespace boost

namespace CGAL {
template <>
struct graph_has_property<tapeline_test::minimal::Mesh, vertex_point_t> : CGAL::Tag_true {};
}  // namespace CGAL

namespace tapeline_test::minimal {

using GT = boost::graph_traits<Mesh>;

// HalfedgeGraph.
inline Vertex target(Halfedge h, const Mesh& m) {
    return Vertex(m.target[h.i]);
}
inline Vertex source(Halfedge h, const Mesh& m) {
    return Vertex(m.target[m.opposite[h.i]]);
}
inline Halfedge opposite(Halfedge h, const Mesh& m) {
    return Halfedge(m.opposite[h.i]);
}
inline Halfedge next(Halfedge h, const Mesh& m) {
    return Halfedge(m.next[h.i]);
}
inline Halfedge prev(Halfedge h, const Mesh& m) {
    Halfedge p = h;
    while (next(p, m) != h)
        p = next(p, m);
    return p;
}
inline Edge edge(Halfedge h, const Mesh& m) {
    return Edge(h.i, std::min(h.i, m.opposite[h.i]));
}
inline Halfedge halfedge(Edge e, const Mesh&) {
    return Halfedge(e.h);
}
inline Halfedge halfedge(Vertex v, const Mesh& m) {
    return Halfedge(m.vertex_halfedge[v.i]);
}
inline std::pair<Halfedge, bool> halfedge(Vertex u, Vertex v, const Mesh& m) {
    const Halfedge start = halfedge(v, m);
    if (start == GT::null_halfedge())
        return {Halfedge(), false};
    Halfedge h = start;
    do {
        if (source(h, m) == u)
            return {h, true};
        h = opposite(next(h, m), m);
    } while (h != start);
    return {Halfedge(), false};
}

// IncidenceGraph (HalfedgeGraph refines it).
inline Vertex source(Edge e, const Mesh& m) {
    return source(Halfedge(e.h), m);
}
inline Vertex target(Edge e, const Mesh& m) {
    return target(Halfedge(e.h), m);
}
inline CGAL::Iterator_range<GT::out_edge_iterator> out_edges(Vertex v, const Mesh& m) {
    return CGAL::make_range(GT::out_edge_iterator(halfedge(v, m), m),
                            GT::out_edge_iterator(halfedge(v, m), m, 1));
}
inline std::size_t out_degree(Vertex v, const Mesh& m) {
    std::size_t d = 0;
    for (auto e : out_edges(v, m)) {
        (void)e;
        ++d;
    }
    return d;
}

// HalfedgeListGraph.
inline CGAL::Iterator_range<GT::halfedge_iterator> halfedges(const Mesh& m) {
    return CGAL::make_range(GT::halfedge_iterator(0),
                            GT::halfedge_iterator(static_cast<std::uint32_t>(m.next.size())));
}
inline std::size_t num_halfedges(const Mesh& m) {
    return m.next.size();
}

// FaceGraph, FaceListGraph.
inline Face face(Halfedge h, const Mesh& m) {
    return Face(m.face[h.i]);
}
inline Halfedge halfedge(Face f, const Mesh& m) {
    return Halfedge(m.face_halfedge[f.i]);
}
inline CGAL::Iterator_range<GT::face_iterator> faces(const Mesh& m) {
    return CGAL::make_range(GT::face_iterator(0),
                            GT::face_iterator(static_cast<std::uint32_t>(m.face_halfedge.size())));
}
inline std::size_t num_faces(const Mesh& m) {
    return m.face_halfedge.size();
}

// VertexListGraph.
inline CGAL::Iterator_range<GT::vertex_iterator> vertices(const Mesh& m) {
    return CGAL::make_range(GT::vertex_iterator(0),
                            GT::vertex_iterator(static_cast<std::uint32_t>(m.positions.size())));
}
inline std::size_t num_vertices(const Mesh& m) {
    return m.positions.size();
}

// EdgeListGraph.
inline CGAL::Iterator_range<GT::edge_iterator> edges(const Mesh& m) {
    return CGAL::make_range(GT::edge_iterator(m, 0),
                            GT::edge_iterator(m, static_cast<std::uint32_t>(m.opposite.size())));
}
inline std::size_t num_edges(const Mesh& m) {
    return m.opposite.size() / 2;
}

// The vertex_point property.
inline PointMap get(CGAL::vertex_point_t, const Mesh& m) {
    return PointMap{&m};
}

}  // namespace tapeline_test::minimal
