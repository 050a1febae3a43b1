// make_compact_mesh: the flat arrays of compact_mesh_types.h from any CGAL FaceListGraph, built
// once so that the algorithms working on them (exact MMP geodesics, the curvature flow, path
// unfolding, body sections) compile their inner loops once, whatever the input mesh type, and
// share one convention.
#pragma once

#include <tapeline/core/compact_mesh_types.h>
#include <tapeline/core/errors.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/named_params_helper.h>

#include <boost/graph/graph_traits.hpp>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tapeline {

/// Builds the compact mesh of a triangle mesh.
///
/// \tparam FaceListGraph a model of `FaceListGraph` and `HalfedgeGraph` (CGAL::Surface_mesh,
///         CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam VertexPointMap a readable property map from vertex descriptors to points with x(), y(),
///         z() convertible by CGAL::to_double.
/// \tparam VertexIndexMap, FaceIndexMap readable property maps onto [0, number of vertices) and
///         [0, number of faces): vertex i and face j of the compact mesh are those with index i
///         and j.
/// \throws InvalidInput when an index map leaves its range or maps two elements to one index,
///         TopologyError when a face is not a triangle; `where` starts both messages.
template <class FaceListGraph, class VertexPointMap, class VertexIndexMap, class FaceIndexMap>
CompactMesh make_compact_mesh(const FaceListGraph& g, VertexPointMap vpm, VertexIndexMap vim,
                              FaceIndexMap fim, const std::string& where = "compact mesh") {
    using GT = boost::graph_traits<FaceListGraph>;
    constexpr std::uint32_t kNone = CompactMesh::kNone;
    std::size_t nv = 0, nf = 0;
    for (auto v : vertices(g)) {
        (void)v;
        ++nv;
    }
    for (auto f : faces(g)) {
        (void)f;
        ++nf;
    }
    if (nv >= kNone / 2 || 3 * nf >= kNone / 2)
        throw InvalidInput(where + ": the mesh is too large (32-bit element indices)");
    auto bad_index = [&](const char* what, std::size_t i, std::size_t n) {
        throw InvalidInput(where + ": the " + what + " index map is not a bijection onto [0, " +
                           std::to_string(n) + ") (index " + std::to_string(i) + ")");
    };
    CompactMesh m;
    m.xyz.resize(3 * nv);
    std::vector<typename GT::vertex_descriptor> vertex_of(nv, GT::null_vertex());
    for (auto v : vertices(g)) {
        const std::size_t i = static_cast<std::size_t>(get(vim, v));
        if (i >= nv || vertex_of[i] != GT::null_vertex())
            bad_index("vertex", i, nv);
        vertex_of[i] = v;
        const auto& p = get(vpm, v);
        m.xyz[3 * i] = CGAL::to_double(p.x());
        m.xyz[3 * i + 1] = CGAL::to_double(p.y());
        m.xyz[3 * i + 2] = CGAL::to_double(p.z());
    }
    m.corner.resize(3 * nf);
    m.twin.assign(3 * nf, kNone);
    std::vector<char> face_seen(nf, 0);
    for (auto f : faces(g)) {
        const std::size_t fi = static_cast<std::size_t>(get(fim, f));
        if (fi >= nf || face_seen[fi])
            bad_index("face", fi, nf);
        face_seen[fi] = 1;
        const auto h0 = halfedge(f, g);
        if (next(next(next(h0, g), g), g) != h0)
            throw TopologyError(where + ": face #" + std::to_string(fi) +
                                " is not a triangle (a triangle mesh is needed)");
        auto h = h0;
        for (int k = 0; k < 3; ++k, h = next(h, g)) {
            m.corner[3 * fi + k] = static_cast<std::uint32_t>(get(vim, source(h, g)));
            const auto o = opposite(h, g);
            if (CGAL::is_border(o, g))
                continue;
            const auto nb = face(o, g);
            auto c = halfedge(nb, g);
            int j = 0;
            while (c != o && j < 3) {
                c = next(c, g);
                ++j;
            }
            m.twin[3 * fi + k] = static_cast<std::uint32_t>(3 * get(fim, nb) + j);
        }
    }
    m.vstart.assign(nv + 1, 0);
    for (std::uint32_t v : m.corner)
        ++m.vstart[v + 1];
    for (std::size_t v = 0; v < nv; ++v)
        m.vstart[v + 1] += m.vstart[v];
    m.vcorners.assign(m.corner.size(), 0);
    std::vector<std::uint32_t> fill(m.vstart.begin(), m.vstart.end() - 1);
    for (std::size_t c = 0; c < m.corner.size(); ++c)
        m.vcorners[fill[m.corner[c]]++] = static_cast<std::uint32_t>(c);
    m.nstart.assign(nv + 1, 0);
    for (std::size_t i = 0; i < nv; ++i) {
        std::uint32_t degree = 0;
        if (halfedge(vertex_of[i], g) != GT::null_halfedge())
            for (auto h : CGAL::halfedges_around_target(vertex_of[i], g)) {
                (void)h;
                ++degree;
            }
        m.nstart[i + 1] = m.nstart[i] + degree;
    }
    m.neighbours.resize(m.nstart[nv]);
    for (std::size_t i = 0; i < nv; ++i) {
        std::uint32_t k = m.nstart[i];
        if (halfedge(vertex_of[i], g) != GT::null_halfedge())
            for (auto h : CGAL::halfedges_around_target(vertex_of[i], g))
                m.neighbours[k++] = static_cast<std::uint32_t>(get(vim, source(h, g)));
    }
    return m;
}

/// make_compact_mesh with the maps given as CGAL named parameters (`vertex_point_map`,
/// `vertex_index_map`, `face_index_map`; the mesh's own maps by default).
template <class FaceListGraph, class NamedParameters = CGAL::parameters::Default_named_parameters>
CompactMesh make_compact_mesh(const FaceListGraph& g,
                              const NamedParameters& np = CGAL::parameters::default_values()) {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    return make_compact_mesh(g,
                             choose_parameter(get_parameter(np, CGAL::internal_np::vertex_point),
                                              CGAL::get_const_property_map(CGAL::vertex_point, g)),
                             CGAL::get_initialized_vertex_index_map(g, np),
                             CGAL::get_initialized_face_index_map(g, np));
}

}  // namespace tapeline
