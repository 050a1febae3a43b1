// Quality figures of a draped garment, each measured independently of the solver that made it:
// body penetration by an exact inside test (CGAL::Side_of_triangle_mesh) and distances (CGAL AABB
// tree), cloth edges crossing body triangles (GarmentCode's measure of a failed drape), cloth
// edges crossing cloth triangles, and the principal stretches of every 3D triangle against its 2D
// pattern triangle. Crossings are decided by exact predicates (CGAL's Epick kernel): with plain
// double arithmetic an edge lying in the plane of a flat patch of cloth was counted as crossing
// triangles it only lies beside (6 such false crossings on one placed shirt, 368 on a flat grid).
#pragma once

#include <tapeline/core/vec3.h>
#include <tapeline/garment/crossings.h>
#include <tapeline/garment/deformation.h>
#include <tapeline/garment/garment_types.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Side_of_triangle_mesh.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::garment {

/// Largest principal stretch of each triangle: the larger singular value of the map from its
/// pattern triangle to its 3D triangle (1: unstretched; 1 for a degenerate pattern triangle).
inline std::vector<double> triangle_stretch(const std::vector<Vec3>& x, const std::vector<Tri>& t,
                                            const std::vector<std::array<UV, 3>>& uv) {
    std::vector<double> out(t.size(), 1.0);
    for (std::size_t f = 0; f < t.size(); ++f) {
        Vec3 f1, f2;
        if (!deformation_gradient(x[t[f][0]], x[t[f][1]], x[t[f][2]], uv[f], f1, f2)) {
            continue;
        }
        // Singular values of F: square roots of the eigenvalues of FᵀF.
        const double p = vec3::dot(f1, f1), q = vec3::dot(f1, f2), r = vec3::dot(f2, f2);
        const double mean = 0.5 * (p + r), dev = std::sqrt(0.25 * (p - r) * (p - r) + q * q);
        out[f] = std::sqrt(mean + dev);
    }
    return out;
}

namespace internal {

inline double percentile(std::vector<double> v, double q) {
    if (v.empty()) {
        return 0;
    }
    const std::size_t k = std::min(v.size() - 1, std::size_t(q * double(v.size() - 1) + 0.5));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
}

}  // namespace internal

/// Penetration, crossings and stretch of `g` on the closed body (`body_points`, `body_tris`, the
/// garment's frame, mm). `moving_fraction` and `stitch_gap_max_mm` are copied in. A triangle
/// whose centroid lies within `contact_band_mm` of the skin counts as lying on the body for the
/// split of the stretch (QualityFigures::stretch_p95_on_body); 0 leaves the split out.
inline QualityFigures garment_quality(const std::vector<Vec3>& body_points,
                                      const std::vector<Tri>& body_tris, const GarmentMesh& g,
                                      double moving_fraction, double stitch_gap_max_mm,
                                      double contact_band_mm = 0) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Mesh = CGAL::Surface_mesh<K::Point_3>;
    using P = K::Point_3;
    QualityFigures q;
    q.moving_fraction = moving_fraction;
    q.stitch_gap_max_mm = stitch_gap_max_mm;
    // Body: a Surface_mesh for the inside test, a triangle AABB tree for distances and crossings.
    Mesh body;
    std::vector<Mesh::Vertex_index> vd;
    for (const Vec3& p : body_points) {
        vd.push_back(body.add_vertex(P(p[0], p[1], p[2])));
    }
    for (const Tri& t : body_tris) {
        body.add_face(vd[t[0]], vd[t[1]], vd[t[2]]);
    }
    using BodyPrimitive = CGAL::AABB_face_graph_triangle_primitive<Mesh>;
    using BodyTree = CGAL::AABB_tree<CGAL::AABB_traits<K, BodyPrimitive>>;
    BodyTree body_tree(faces(body).first, faces(body).second, body);
    body_tree.accelerate_distance_queries();
    const CGAL::Side_of_triangle_mesh<Mesh, K> inside(body_tree);
    for (const Vec3& x : g.positions) {
        const P p(x[0], x[1], x[2]);
        if (inside(p) == CGAL::ON_BOUNDED_SIDE) {
            ++q.vertices_inside_body;
            q.max_depth_mm = std::max(q.max_depth_mm, std::sqrt(body_tree.squared_distance(p)));
        }
    }
    const auto edges = internal::unique_edges(g.triangles);
    for (const auto& [a, b] : edges) {
        const K::Segment_3 s(P(g.positions[a][0], g.positions[a][1], g.positions[a][2]),
                             P(g.positions[b][0], g.positions[b][1], g.positions[b][2]));
        if (body_tree.do_intersect(s)) {
            ++q.edges_crossing_body;
            if (q.body_crossing_points.size() < 100) {
                q.body_crossing_points.push_back(
                    vec3::scale(vec3::add(g.positions[a], g.positions[b]), 0.5));
            }
        }
    }
    // Cloth self-intersections: an edge crossing a triangle it does not share a vertex with.
    {
        // The piece of an edge: that of a triangle holding it (a seam edge may be in two).
        std::map<std::pair<std::uint32_t, std::uint32_t>, std::uint32_t> edge_piece;
        const bool pieces = g.triangle_piece.size() == g.triangles.size();
        if (pieces) {
            for (std::size_t f = 0; f < g.triangles.size(); ++f) {
                for (int k = 0; k < 3; ++k) {
                    const std::uint32_t a = g.triangles[f][k], b = g.triangles[f][(k + 1) % 3];
                    edge_piece.emplace(std::make_pair(std::min(a, b), std::max(a, b)),
                                       g.triangle_piece[f]);
                }
            }
        }
        std::map<std::string, std::size_t> by_pieces;
        const auto piece_name = [&](std::uint32_t i) {
            return i < g.piece_names.size() ? g.piece_names[i] : std::to_string(i);
        };
        internal::for_each_edge_triangle_crossing(
            g.positions, g.triangles, [&](std::uint32_t a, std::uint32_t b, std::size_t t) {
                ++q.self_intersections;
                if (q.self_crossing_points.size() < 100) {
                    q.self_crossing_points.push_back(
                        vec3::scale(vec3::add(g.positions[a], g.positions[b]), 0.5));
                }
                if (pieces) {
                    const std::string pe = piece_name(edge_piece.at({a, b}));
                    const std::string pt = piece_name(g.triangle_piece[t]);
                    ++by_pieces[pe == pt ? pe : std::min(pe, pt) + " / " + std::max(pe, pt)];
                }
            });
        q.self_crossings_by_pieces.assign(by_pieces.begin(), by_pieces.end());
        std::stable_sort(q.self_crossings_by_pieces.begin(), q.self_crossings_by_pieces.end(),
                         [](const auto& x, const auto& y) { return x.second > y.second; });
    }
    const auto st = triangle_stretch(g.positions, g.triangles, g.uv);
    if (!st.empty()) {
        q.stretch_median = internal::percentile(st, 0.5);
        q.stretch_p95 = internal::percentile(st, 0.95);
        q.stretch_max = *std::max_element(st.begin(), st.end());
        q.stretch_above_105_percent =
            100.0 * double(std::count_if(st.begin(), st.end(), [](double s) { return s > 1.05; })) /
            double(st.size());
    }
    if (contact_band_mm > 0 && !st.empty()) {
        std::vector<double> on, off;
        for (std::size_t f = 0; f < g.triangles.size(); ++f) {
            const Tri& t = g.triangles[f];
            const Vec3 c = vec3::scale(
                vec3::add(vec3::add(g.positions[t[0]], g.positions[t[1]]), g.positions[t[2]]),
                1.0 / 3.0);
            const double d2 = body_tree.squared_distance(P(c[0], c[1], c[2]));
            (d2 <= contact_band_mm * contact_band_mm ? on : off).push_back(st[f]);
        }
        q.triangles_on_body_percent = 100.0 * double(on.size()) / double(st.size());
        q.stretch_p95_on_body = on.empty() ? 1.0 : internal::percentile(on, 0.95);
        q.stretch_p95_off_body = off.empty() ? 1.0 : internal::percentile(off, 0.95);
    }
    return q;
}

/// How far the highest of the `draped` vertices lies below the highest of the `placed` ones
/// (the same vertices, canonical frame, y up), mm; 0 when there are none.
inline double top_drop_mm(const std::vector<Vec3>& placed, const std::vector<Vec3>& draped) {
    if (placed.empty() || draped.empty()) {
        return 0;
    }
    const auto higher = [](const Vec3& a, const Vec3& b) { return a[1] < b[1]; };
    return (*std::max_element(placed.begin(), placed.end(), higher))[1] -
           (*std::max_element(draped.begin(), draped.end(), higher))[1];
}

/// Largest drop of the garment's highest point from its placement that a drape passes with, mm.
/// Garments that came to hang from the body dropped 10–78 mm (four tops on the nine bundled
/// bodies at 20 mm, placed 15 mm off the skin: docs/garment.md); ones that slid off the
/// shoulders 208 mm, and one that fell off the body 1362 mm. A shirt whose neckline slid only
/// partly over the shoulders (by less than the limit) passes: this gate catches a garment that
/// left its place, not one that sits badly.
inline constexpr double kMaxTopDropMm = 100;

/// The gates of a successful drape (issue figures): stitch gap ≤ 1 mm, no cloth edge crossing
/// the body, no vertex deeper than 1 mm, no self-intersection, p95 stretch ≤ 1.05, static (at
/// most 1 % of the vertices moved more than 0.3 mm in the last frame); and a self-check of ours:
/// the garment still hangs where it was placed (its top came down at most kMaxTopDropMm).
inline std::vector<Gate> quality_gates(const QualityFigures& q) {
    return {
        {"stitch_gap_max_mm", q.stitch_gap_max_mm, 1.0, q.stitch_gap_max_mm <= 1.0},
        {"edges_crossing_body", double(q.edges_crossing_body), 0, q.edges_crossing_body == 0},
        {"max_depth_mm", q.max_depth_mm, 1.0, q.max_depth_mm <= 1.0},
        {"self_intersections", double(q.self_intersections), 0, q.self_intersections == 0},
        {"stretch_p95", q.stretch_p95, 1.05, q.stretch_p95 <= 1.05},
        {"moving_fraction", q.moving_fraction, 0.01, q.moving_fraction <= 0.01},
        {"top_drop_mm", q.top_drop_mm, kMaxTopDropMm, q.top_drop_mm <= kMaxTopDropMm},
    };
}

}  // namespace tapeline::garment
