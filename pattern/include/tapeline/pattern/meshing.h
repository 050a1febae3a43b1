// Triangle meshes of pattern pieces for cloth simulation: a constrained Delaunay triangulation of
// each piece's outline refined by Ruppert/Shewchuk-style Delaunay refinement (CGAL 2D Mesh_2:
// Constrained_Delaunay_triangulation_2 + Delaunay_mesher_no_edge_refinement_2 with
// Delaunay_mesh_size_criteria_2; Shewchuk, "Delaunay refinement algorithms for triangular mesh
// generation", CGTA 22, 2002).
//
// Boundary. Each outline edge is cut into n segments of equal arc length, n large enough that the
// segments are at most `target_edge_mm` long and the chords within `curve_tolerance_mm` of the
// curve. The two sides of a seam get the same counts (per edge when both sides have as many
// edges, else by adding segments to the shorter-count side), so their vertices pair one to one,
// start to start or start to end as the seam's direction says — what GarmentCode's box mesh does
// before merging stitch vertices. The refinement never splits a boundary segment: the
// no-edge-refinement mesher drops any circumcentre that would encroach on one, so the outline
// vertices are exactly the sampled points (checked after refinement; a violation would be a
// SolverFailure). The price: a triangle whose circumcentre encroaches stays unrefined, so the
// size bound holds inside the piece but not strictly at the boundary (measured in the report).
//
// This header pulls in CGAL; include meshing_types.h where only the types are needed.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/pattern/io_garmentcode.h>  // placed_point
#include <tapeline/pattern/meshing_types.h>
#include <tapeline/pattern/pattern.h>

#include <CGAL/Constrained_Delaunay_triangulation_2.h>
#include <CGAL/Delaunay_mesh_face_base_2.h>
#include <CGAL/Delaunay_mesh_size_criteria_2.h>
#include <CGAL/Delaunay_mesh_vertex_base_2.h>
#include <CGAL/Delaunay_mesher_no_edge_refinement_2.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <string>
#include <vector>

namespace tapeline::pattern {

namespace internal {

struct MeshCgal {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Vb = CGAL::Delaunay_mesh_vertex_base_2<K>;
    using Fb = CGAL::Delaunay_mesh_face_base_2<K>;
    using Tds = CGAL::Triangulation_data_structure_2<Vb, Fb>;
    using Cdt = CGAL::Constrained_Delaunay_triangulation_2<K, Tds>;
    using Criteria = CGAL::Delaunay_mesh_size_criteria_2<Cdt>;
    using Mesher = CGAL::Delaunay_mesher_no_edge_refinement_2<Cdt, Criteria>;
};

/// The outline edges of a seam side in range order.
inline std::vector<std::size_t> range_edges(const Pattern& p, const EdgeRange& r,
                                            std::size_t& piece_index, const std::string& seam) {
    piece_index = p.pieces.size();
    for (std::size_t i = 0; i < p.pieces.size(); ++i) {
        if (p.pieces[i].name == r.piece) {
            piece_index = i;
        }
    }
    if (piece_index == p.pieces.size()) {
        throw InvalidInput("meshing '" + p.name + "': seam '" + seam + "' names missing piece '" +
                           r.piece + "'");
    }
    const std::size_t n = p.pieces[piece_index].outline.edges.size();
    if (r.first_edge >= n || r.count < 1 || r.count > n) {
        throw InvalidInput("meshing '" + p.name + "': seam '" + seam + "' names edges " +
                           std::to_string(r.first_edge) + " (+" + std::to_string(r.count) +
                           ") of piece '" + r.piece + "', which has " + std::to_string(n));
    }
    std::vector<std::size_t> out;
    for (std::size_t k = 0; k < r.count; ++k) {
        out.push_back((r.first_edge + k) % n);
    }
    return out;
}

/// Segments per outline edge, equal along both sides of every seam.
inline std::vector<std::vector<std::size_t>> boundary_counts(const Pattern& p,
                                                             const MeshingOptions& o) {
    std::vector<std::vector<std::size_t>> counts(p.pieces.size());
    std::vector<std::vector<double>> lengths(p.pieces.size());
    double total = 0;
    for (std::size_t i = 0; i < p.pieces.size(); ++i) {
        for (const Edge& e : p.pieces[i].outline.edges) {
            const double len = length(e);
            lengths[i].push_back(len);
            std::size_t n = 0;
            if (len >= 1e-6) {
                n = std::max<std::size_t>({1, std::size_t(std::ceil(len / o.target_edge_mm - 1e-9)),
                                           sample(e.curve, o.curve_tolerance_mm).size() - 1});
            }
            counts[i].push_back(n);
            total += double(n);
        }
    }
    if (total > 2e7) {
        throw InvalidInput("meshing '" + p.name + "': a target edge of " +
                           std::to_string(o.target_edge_mm) + " mm would put " +
                           std::to_string(std::size_t(total)) + " points on the outlines");
    }
    struct Side {
        std::size_t piece;
        std::vector<std::size_t> edges;
    };
    std::vector<std::pair<Side, Side>> seams;
    for (std::size_t s = 0; s < p.seams.size(); ++s) {
        const Seam& seam = p.seams[s];
        const std::string name = seam.name.empty() ? "#" + std::to_string(s) : seam.name;
        Side a, b;
        a.edges = range_edges(p, seam.a, a.piece, name);
        b.edges = range_edges(p, seam.b, b.piece, name);
        if (seam.direction == SeamDirection::opposite) {
            std::reverse(b.edges.begin(), b.edges.end());
        }
        for (const Side* side : {&a, &b}) {
            for (std::size_t e : side->edges) {
                counts[side->piece][e] = std::max<std::size_t>(counts[side->piece][e], 1);
            }
        }
        seams.push_back({a, b});
    }
    auto sum = [&](const Side& s) {
        std::size_t t = 0;
        for (std::size_t e : s.edges) {
            t += counts[s.piece][e];
        }
        return t;
    };
    // Counts only grow, so this reaches a fixed point unless seams overlap in contradictory ways.
    for (int iter = 0; iter < 1000; ++iter) {
        bool changed = false;
        for (auto& [a, b] : seams) {
            if (a.edges.size() == b.edges.size()) {
                for (std::size_t k = 0; k < a.edges.size(); ++k) {
                    std::size_t& ca = counts[a.piece][a.edges[k]];
                    std::size_t& cb = counts[b.piece][b.edges[k]];
                    if (ca != cb) {
                        ca = cb = std::max(ca, cb);
                        changed = true;
                    }
                }
            } else {
                std::size_t sa = sum(a), sb = sum(b);
                Side& low = sa < sb ? a : b;
                for (std::size_t need = std::max(sa, sb) - std::min(sa, sb); need > 0; --need) {
                    // One more segment on the edge with the longest segments.
                    std::size_t best = low.edges[0];
                    double best_len = -1;
                    for (std::size_t e : low.edges) {
                        const double l = lengths[low.piece][e] /
                                         double(std::max<std::size_t>(counts[low.piece][e], 1));
                        if (l > best_len) {
                            best_len = l;
                            best = e;
                        }
                    }
                    ++counts[low.piece][best];
                    changed = true;
                }
            }
        }
        if (!changed) {
            return counts;
        }
    }
    throw SolverFailure("meshing '" + p.name +
                        "': overlapping seams ask for different vertex counts on the same edges");
}

inline PieceMesh mesh_piece(const Pattern& pat, const Piece& piece,
                            const std::vector<std::size_t>& counts, const MeshingOptions& o,
                            MeshingReport& rep) {
    using C = MeshCgal;
    const std::string where = "meshing '" + pat.name + "': piece '" + piece.name + "'";
    PieceMesh out;
    out.piece = piece.name;
    const std::size_t ne = piece.outline.edges.size();
    std::vector<std::size_t> first(ne);
    for (std::size_t e = 0; e < ne; ++e) {
        const Curve& c = piece.outline.edges[e].curve;
        if (!is_finite(c)) {
            throw InvalidInput(where + ": edge " + std::to_string(e) +
                               " has a non-finite coordinate");
        }
        first[e] = out.uv.size();
        const double len = length(c);
        for (std::size_t k = 0; k < counts[e]; ++k) {
            const double t =
                k == 0 ? 0.0 : parameter_at_length(c, len * double(k) / double(counts[e]));
            out.boundary_params.push_back({e, t});
            out.uv.push_back(point_at(c, t));
        }
    }
    const std::size_t m = out.uv.size();
    if (m < 3) {
        throw InvalidInput(where + ": the outline has fewer than 3 points");
    }
    out.boundary_count = m;
    for (std::size_t e = 0; e < ne; ++e) {
        std::vector<std::uint32_t> ids;
        for (std::size_t k = 0; k <= counts[e]; ++k) {
            ids.push_back(std::uint32_t((first[e] + k) % m));
        }
        out.edge_vertices.push_back(std::move(ids));
    }

    C::Cdt cdt;
    std::vector<C::Cdt::Vertex_handle> vh;
    std::map<C::Cdt::Vertex_handle, std::uint32_t> id;
    for (std::size_t i = 0; i < m; ++i) {
        vh.push_back(cdt.insert(C::K::Point_2(out.uv[i].x, out.uv[i].y)));
        if (!id.emplace(vh.back(), std::uint32_t(i)).second) {
            const BoundaryParam& bp = out.boundary_params[i];
            throw InvalidInput(where + ": the outline passes twice through (" +
                               std::to_string(out.uv[i].x) + ", " + std::to_string(out.uv[i].y) +
                               ") (edge " + std::to_string(bp.edge) + ")");
        }
    }
    try {
        for (std::size_t i = 0; i < m; ++i) {
            cdt.insert_constraint(vh[i], vh[(i + 1) % m]);
        }
    } catch (const C::Cdt::Intersection_of_constraints_exception&) {
        throw InvalidInput(where + ": the outline sampled every " +
                           std::to_string(o.target_edge_mm) +
                           " mm intersects itself (validate the pattern, or lower the target "
                           "edge length)");
    }
    C::Mesher mesher(cdt, C::Criteria(o.aspect_bound, o.target_edge_mm));
    // CGAL 5.5's constructor leaves the seeds' mark uninitialised and refine_mesh() reads it
    // (UBSan: "load of value 135 ... type 'bool'"); with no seeds the value is not used, and
    // clear_seeds() gives it one.
    mesher.clear_seeds();
    mesher.refine_mesh();

    // The outline must come out as it went in: m constrained edges between consecutive points.
    std::size_t constrained = 0;
    for (auto e = cdt.finite_edges_begin(); e != cdt.finite_edges_end(); ++e) {
        if (!cdt.is_constrained(*e)) {
            continue;
        }
        ++constrained;
        const auto a = id.find(e->first->vertex(cdt.cw(e->second)));
        const auto b = id.find(e->first->vertex(cdt.ccw(e->second)));
        if (a == id.end() || b == id.end()) {
            ++rep.boundary_steiner_points;
            continue;
        }
        const std::size_t d = (a->second + m - b->second) % m;
        if (d != 1 && d != m - 1) {
            ++rep.boundary_steiner_points;
        }
    }
    if (constrained != m || rep.boundary_steiner_points > 0) {
        throw SolverFailure(where + ": the refinement changed the outline (" +
                            std::to_string(constrained) + " boundary segments for " +
                            std::to_string(m) + " points)");
    }
    for (auto f = cdt.finite_faces_begin(); f != cdt.finite_faces_end(); ++f) {
        if (!f->is_in_domain()) {
            continue;
        }
        std::array<std::uint32_t, 3> tri{};
        for (int k = 0; k < 3; ++k) {
            const auto v = f->vertex(k);
            auto it = id.find(v);
            if (it == id.end()) {
                it = id.emplace(v, std::uint32_t(out.uv.size())).first;
                out.uv.push_back({v->point().x(), v->point().y()});
            }
            tri[k] = it->second;
        }
        out.triangles.push_back(tri);
    }
    for (const Point2& p : out.uv) {
        if (o.use_placement && piece.placement) {
            out.xyz.push_back(placed_point(*piece.placement, p));
        } else {
            out.xyz.push_back({p.x, p.y, 0.0});
        }
    }
    // Quality figures.
    for (const auto& t : out.triangles) {
        const Point2 a = out.uv[t[0]], b = out.uv[t[1]], c = out.uv[t[2]];
        const double la = distance(b, c), lb = distance(c, a), lc = distance(a, b);
        rep.max_edge_mm = std::max({rep.max_edge_mm, la, lb, lc});
        rep.area_mm2 += 0.5 * cross(b - a, c - a);
        auto angle = [](double opp, double s1, double s2) {
            return std::acos(
                       std::clamp((s1 * s1 + s2 * s2 - opp * opp) / (2 * s1 * s2), -1.0, 1.0)) *
                   180.0 / M_PI;
        };
        rep.min_angle_deg =
            std::min({rep.min_angle_deg, angle(la, lb, lc), angle(lb, lc, la), angle(lc, la, lb)});
    }
    for (std::size_t i = 0; i < m; ++i) {
        rep.max_boundary_edge_mm =
            std::max(rep.max_boundary_edge_mm, distance(out.uv[i], out.uv[(i + 1) % m]));
    }
    rep.vertices += out.uv.size();
    rep.triangles += out.triangles.size();
    rep.boundary_vertices += m;
    return out;
}

/// The vertices along a seam side, start to end of the range.
inline std::vector<std::uint32_t> side_vertices(const PieceMesh& mesh,
                                                const std::vector<std::size_t>& edges) {
    std::vector<std::uint32_t> out;
    for (std::size_t e : edges) {
        const auto& ids = mesh.edge_vertices[e];
        out.insert(out.end(), ids.begin(), ids.end() - 1);
    }
    out.push_back(mesh.edge_vertices[edges.back()].back());
    return out;
}

}  // namespace internal

/// Meshes every piece (see the file comment) and pairs the vertices of every seam.
/// Throws InvalidInput for bad options, seams naming missing pieces or edges, and outlines whose
/// sampling intersects itself.
///
/// \throws InvalidInput for a non-positive target edge length or curve tolerance, an aspect
///         bound out of range, a seam naming a missing piece or edges, an outline with fewer
///         than 3 points, passing twice through a point, or whose sampling intersects itself.
/// \throws SolverFailure when overlapping seams ask for different vertex counts on one edge,
///         the refinement changes an outline, or the two sides of a seam get different vertex
///         counts.
inline PatternMesh mesh_pattern(const Pattern& pattern, const MeshingOptions& options = {},
                                MeshingReport* report = nullptr) {
    using namespace internal;
    const auto t0 = std::chrono::steady_clock::now();
    if (!(options.target_edge_mm > 0) || !std::isfinite(options.target_edge_mm)) {
        throw InvalidInput("meshing '" + pattern.name + "': target edge length must be positive (" +
                           std::to_string(options.target_edge_mm) + " mm)");
    }
    if (!(options.curve_tolerance_mm > 0)) {
        throw InvalidInput("meshing '" + pattern.name + "': curve tolerance must be positive");
    }
    if (!(options.aspect_bound >= 0 && options.aspect_bound <= 0.125)) {
        throw InvalidInput("meshing '" + pattern.name + "': aspect bound " +
                           std::to_string(options.aspect_bound) +
                           " outside [0, 0.125] (above, Delaunay refinement may not terminate)");
    }
    MeshingReport rep;
    const auto counts = boundary_counts(pattern, options);
    PatternMesh mesh;
    for (std::size_t i = 0; i < pattern.pieces.size(); ++i) {
        mesh.pieces.push_back(mesh_piece(pattern, pattern.pieces[i], counts[i], options, rep));
    }
    for (std::size_t s = 0; s < pattern.seams.size(); ++s) {
        const Seam& seam = pattern.seams[s];
        SeamStitch st;
        st.seam = s;
        const std::vector<std::size_t> ea = range_edges(pattern, seam.a, st.piece_a, seam.name);
        const std::vector<std::size_t> eb = range_edges(pattern, seam.b, st.piece_b, seam.name);
        const std::vector<std::uint32_t> va = side_vertices(mesh.pieces[st.piece_a], ea);
        std::vector<std::uint32_t> vb = side_vertices(mesh.pieces[st.piece_b], eb);
        if (seam.direction == SeamDirection::opposite) {
            std::reverse(vb.begin(), vb.end());
        }
        if (va.size() != vb.size()) {
            throw SolverFailure("meshing '" + pattern.name + "': seam '" + seam.name + "' has " +
                                std::to_string(va.size()) + " and " + std::to_string(vb.size()) +
                                " vertices on its sides");
        }
        for (std::size_t k = 0; k < va.size(); ++k) {
            st.pairs.push_back({va[k], vb[k]});
        }
        mesh.seams.push_back(std::move(st));
    }
    rep.pieces = mesh.pieces.size();
    rep.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (report) {
        *report = rep;
    }
    return mesh;
}

}  // namespace tapeline::pattern
