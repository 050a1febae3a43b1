// Single-source shortest paths over a Steiner graph of the mesh: its nodes are the vertices and
// `per_edge` points evenly spaced inside every edge (more near the source), and every two nodes on
// the boundary of a face are joined by the straight segment across it (the fixed scheme of
// M. Lanthier, A. Maheshwari, J.-R. Sack, "Approximating shortest paths on weighted polyhedral
// surfaces", Algorithmica 30(4), 2001). Its paths lie on the faces, are never shorter than the
// polyhedral geodesic, and cross the faces close to it: started from one, the two-point flow and
// its straightening land in the geodesic's homotopy class where the edge-graph search does not (a
// coarse mesh whose geodesics run through saddle vertices). The repair pass of gcf_distances uses
// it as one more start, as an upper bound of every vertex's distance (a path length it may take)
// and, with a margin, as a check of distances far below it.
#pragma once

#include <tapeline/geodesic/internal/gcf_engine.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace tapeline::geodesic::internal::gcf {

class SteinerTree {
public:
    /// Dijkstra from vertex `source` over the whole graph (every vertex reachable in its component
    /// gets a finite distance). per_edge >= 1. Edges with an end within Euclidean distance
    /// near_radius of the source get near_per_edge points instead (when larger): a graph path
    /// loses up to a fraction of an edge at each crossing, which near the source is a large part
    /// of the path's length, so the graph's relative error is largest there (figures at
    /// CurvatureFlowDistanceOptions::repair_steiner_points). The geodesic ball of that radius lies
    /// inside the Euclidean one.
    SteinerTree(const Mesh& m, std::uint32_t source, std::uint32_t per_edge,
                std::uint32_t near_per_edge = 0, double near_radius = 0)
        : m_(m) {
        number_edges();
        const Vec3 s = m.xyz[source];
        start_.assign(ends_.size() + 1, 0);
        for (std::size_t e = 0; e < ends_.size(); ++e) {
            const bool near = near_per_edge > per_edge &&
                              std::min((m.xyz[ends_[e][0]] - s).norm(),
                                       (m.xyz[ends_[e][1]] - s).norm()) <= near_radius;
            start_[e + 1] = start_[e] + (near ? near_per_edge : per_edge);
        }
        edge_.resize(start_.back());
        for (std::uint32_t e = 0; e < ends_.size(); ++e)
            std::fill(edge_.begin() + start_[e], edge_.begin() + start_[e + 1], e);
        const std::size_t nodes = m.vertex_count() + edge_.size();
        dist_.assign(nodes, std::numeric_limits<double>::infinity());
        pred_.assign(nodes, kNone);
        using Item = std::pair<double, std::uint32_t>;
        std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
        dist_[source] = 0;
        q.push({0.0, source});
        std::vector<std::uint32_t> around;
        while (!q.empty()) {
            // Named copies, not a structured binding: lambdas may capture those only from C++20.
            const double d = q.top().first;
            const std::uint32_t x = q.top().second;
            q.pop();
            if (d > dist_[x])
                continue;
            const Vec3 px = position(x);
            auto relax_face = [&](std::uint32_t f) {
                face_nodes(f, around);
                for (const std::uint32_t y : around) {
                    if (y == x)
                        continue;
                    const double nd = d + (position(y) - px).norm();
                    if (nd < dist_[y]) {
                        dist_[y] = nd;
                        pred_[y] = x;
                        q.push({nd, y});
                    }
                }
            };
            if (x < m.vertex_count()) {
                for (std::uint32_t k = m.vf_start[x]; k < m.vf_start[x + 1]; ++k)
                    relax_face(m.vf[k]);
            } else {
                for (const std::uint32_t f : faces_[edge_[x - m.vertex_count()]])
                    if (f != kNone)
                        relax_face(f);
            }
        }
    }

    /// Length of the graph's shortest path from the source to vertex v (+infinity if none).
    double distance(std::uint32_t v) const { return dist_[v]; }

    /// The points of that path, source first (empty if none).
    std::vector<Vec3> path_to(std::uint32_t v) const {
        std::vector<Vec3> out;
        if (!(dist_[v] < std::numeric_limits<double>::infinity()))
            return out;
        for (std::uint32_t x = v; x != kNone; x = pred_[x])
            out.push_back(position(x));
        std::reverse(out.begin(), out.end());
        return out;
    }

private:
    // Edge ids: one per pair of faces sharing an edge (or per border edge), its two end vertices
    // and the faces on either side.
    void number_edges() {
        const std::size_t nf = m_.face_count();
        edge_of_.assign(3 * nf, kNone);
        for (std::uint32_t f = 0; f < nf; ++f) {
            for (int e = 0; e < 3; ++e) {
                const std::uint32_t a = m_.corner[3 * f + e], b = m_.corner[3 * f + (e + 1) % 3];
                const std::uint32_t g = m_.across[3 * f + e];
                if (g != kNone && g < f) {
                    for (int j = 0; j < 3; ++j) {
                        const std::uint32_t c = m_.corner[3 * g + j],
                                            d = m_.corner[3 * g + (j + 1) % 3];
                        if ((c == a && d == b) || (c == b && d == a))
                            edge_of_[3 * f + e] = edge_of_[3 * g + j];
                    }
                }
                if (edge_of_[3 * f + e] == kNone) {
                    edge_of_[3 * f + e] = static_cast<std::uint32_t>(ends_.size());
                    ends_.push_back({std::min(a, b), std::max(a, b)});
                    faces_.push_back({f, g});
                }
            }
        }
    }

    Vec3 position(std::uint32_t x) const {
        const std::size_t nv = m_.vertex_count();
        if (x < nv)
            return m_.xyz[x];
        const std::uint32_t e = edge_[x - nv];
        const double t = static_cast<double>(x - nv - start_[e] + 1) /
                         static_cast<double>(start_[e + 1] - start_[e] + 1);
        return (1 - t) * m_.xyz[ends_[e][0]] + t * m_.xyz[ends_[e][1]];
    }

    void face_nodes(std::uint32_t f, std::vector<std::uint32_t>& out) const {
        out.clear();
        const auto nv = static_cast<std::uint32_t>(m_.vertex_count());
        for (int c = 0; c < 3; ++c) {
            out.push_back(m_.corner[3 * f + c]);
            const std::uint32_t e = edge_of_[3 * f + c];
            for (std::uint32_t i = start_[e]; i < start_[e + 1]; ++i)
                out.push_back(nv + i);
        }
    }

    const Mesh& m_;
    std::vector<std::uint32_t> edge_of_;
    std::vector<std::uint32_t> start_;  // edge e's points are nodes nv + [start_[e], start_[e+1])
    std::vector<std::uint32_t> edge_;   // the edge of node nv + i
    std::vector<std::array<std::uint32_t, 2>> ends_;
    std::vector<std::array<std::uint32_t, 2>> faces_;
    std::vector<double> dist_;
    std::vector<std::uint32_t> pred_;
};

}  // namespace tapeline::geodesic::internal::gcf
