// Cloth edges crossing cloth triangles, decided by exact predicates (CGAL's Epick kernel): the
// quality report counts them, the placement checks them, the drape solver untangles them. With
// plain double arithmetic an edge lying in the plane of a flat patch of cloth was counted as
// crossing triangles it only lies beside (368 false crossings on a flat 60 × 60 grid).
#pragma once

#include <tapeline/garment/drape_types.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <cstdint>
#include <iterator>
#include <utility>
#include <vector>

namespace tapeline::garment::internal {

/// The garment's edges, each once as (a, b) with a < b.
inline std::vector<std::pair<std::uint32_t, std::uint32_t>> unique_edges(
    const std::vector<Tri>& triangles) {
    std::vector<std::pair<std::uint32_t, std::uint32_t>> edges;
    edges.reserve(3 * triangles.size());
    for (const Tri& t : triangles) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[k], b = t[(k + 1) % 3];
            edges.push_back({std::min(a, b), std::max(a, b)});
        }
    }
    std::sort(edges.begin(), edges.end());
    edges.erase(std::unique(edges.begin(), edges.end()), edges.end());
    return edges;
}

/// Calls f(a, b, t) for every edge (a, b) of the mesh (each once, a < b) and every triangle t
/// it crosses or touches that has neither a nor b as a corner: exact predicates, so an edge
/// beside a coplanar triangle is not counted. A triangle whose corners are collinear (or
/// coincide) has no inside to cross and is never reported, nor is an edge of zero length: CGAL's
/// segment–triangle test is undefined for them, and with its checks compiled out it reported
/// edges passing near a collapsed triangle as crossing it.
template <typename F>
void for_each_edge_triangle_crossing(const std::vector<Vec3>& x, const std::vector<Tri>& tris,
                                     F&& f) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using P = K::Point_3;
    using Triangle = K::Triangle_3;
    const auto pt = [&](std::uint32_t v) { return P(x[v][0], x[v][1], x[v][2]); };
    std::vector<Triangle> ts;
    std::vector<std::size_t> index;  // of each triangle of `ts` in `tris`
    ts.reserve(tris.size());
    index.reserve(tris.size());
    for (std::size_t t = 0; t < tris.size(); ++t) {
        const Triangle tri(pt(tris[t][0]), pt(tris[t][1]), pt(tris[t][2]));
        if (!tri.is_degenerate()) {
            ts.push_back(tri);
            index.push_back(t);
        }
    }
    using Iterator = std::vector<Triangle>::const_iterator;
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, CGAL::AABB_triangle_primitive<K, Iterator>>>;
    const Tree tree(ts.cbegin(), ts.cend());
    std::vector<Tree::Primitive_id> hits;
    for (const auto& [a, b] : unique_edges(tris)) {
        const K::Segment_3 edge(pt(a), pt(b));
        if (edge.is_degenerate()) {
            continue;
        }
        hits.clear();
        tree.all_intersected_primitives(edge, std::back_inserter(hits));
        std::sort(hits.begin(), hits.end());  // in triangle order, whatever the tree's
        for (const auto& h : hits) {
            const std::size_t t = index[std::size_t(h - ts.cbegin())];
            const Tri& tv = tris[t];
            if (tv[0] != a && tv[1] != a && tv[2] != a && tv[0] != b && tv[1] != b && tv[2] != b) {
                f(a, b, t);
            }
        }
    }
}

}  // namespace tapeline::garment::internal
