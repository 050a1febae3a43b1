// A fine drape seen from a coarse drape of the same pattern: every fine vertex located in the
// coarse mesh through the shared pattern coordinates, and its displacement from the coarse
// surface split into the height along the coarse normal and a tangential rest. The ground truth
// that wrinkle synthesis learns from and is measured against (issue: "the coarse one embedded in
// the fine one, barycentric map through the shared UVs").
//
// Location. Both meshes carry per-corner pattern coordinates (mm) and a piece per triangle
// (garment/garment_types.h, GarmentMesh). A fine vertex takes the pattern point and piece of the
// first triangle corner that names it (a vertex welded across a seam lies on both pieces' edges;
// either side gives the same coarse surface point up to the coarse seam's own gap). It is located
// in the coarse triangles of its piece by the closest point in the pattern plane, found with a
// CGAL AABB tree over the coarse pattern triangles lifted to z = piece index · 10⁷ mm (pieces
// never see each other): inside a coarse triangle that is the point itself; outside (the fine
// outline follows the pattern's curves more closely than the coarse one) it is the nearest point
// of the coarse outline, and its distance is reported.
//
// Displacement. At the barycentric coordinates b of the located point: the coarse surface point
// x_c and normal n_c = normalised Σ b_i·N_i (area-weighted vertex normals of the coarse drape);
// the fine vertex x_f gives d = x_f − x_c, the height h = d·n_c and the tangential part d − h·n_c.
// The coarse surface is the smooth one its vertices and normals stand for, not its flat facets: a
// fine drape that follows a curve the coarse one cuts across with 20 mm chords lies above the
// facets' middles by the sagitta (L²/(8R): 0.5 mm on a 100 mm radius), which repeats with the
// coarse edges and reads as a wave of about their length. So x_c is the Phong tessellation
// (T. Boubekeur, M. Alexa, "Phong Tessellation", SIGGRAPH Asia 2008) of the flat point
// p = Σ b_i·X_i, p* = Σ b_i·(p − ((p − X_i)·N_i)·N_i), blended as x_c = (p + p*)/2: with that
// shape factor of 1/2 the middle of a chord of a circle, between two vertices with radial
// normals, lands on the circle up to fourth order in the chord's angle (smooth_coarse_point()).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/phong.h>
#include <tapeline/draw/mesh_render.h>
#include <tapeline/garment/garment_types.h>

#include <CGAL/AABB_traits.h>
#include <CGAL/AABB_tree.h>
#include <CGAL/AABB_triangle_primitive.h>
#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>

#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace tapeline::wrinkles {

using garment::Vec3;

/// Where one fine vertex lies on the coarse drape, and how far from it.
struct EmbeddedVertex {
    std::uint32_t coarse_triangle = 0;    ///< coarse triangle holding the located point
    std::array<double, 3> barycentric{};  ///< of the located point in that triangle
    double outside_mm = 0;  ///< pattern distance from the fine vertex's point to the coarse piece
    double height_mm = 0;   ///< h: displacement along the coarse normal
    double tangential_mm = 0;  ///< length of the displacement's tangential part
};

/// The embedding of a fine drape in a coarse one, with totals.
struct Embedding {
    std::vector<EmbeddedVertex> vertices;  ///< per fine vertex (unused vertices: zero)
    double rms_height_mm = 0;              ///< root mean square of h over the used vertices
    double max_abs_height_mm = 0;
    double rms_tangential_mm = 0;
    double max_outside_mm = 0;  ///< largest pattern distance outside the coarse pieces
    std::size_t used = 0;       ///< fine vertices named by a triangle
};

namespace internal {

/// Pieces are lifted apart in the pattern plane by this many mm per piece index (embedding and
/// comparison search one piece at a time this way).
inline constexpr double kPieceGap = 1e7;

/// The point of the smooth coarse surface at barycentric `b` of triangle `t` (see the file
/// comment): Phong tessellation with shape factor 1/2 over the vertex normals `n`.
inline Vec3 smooth_coarse_point(const std::vector<Vec3>& x, const garment::Tri& t,
                                const std::vector<Vec3>& n, const std::array<double, 3>& b) {
    return phong_point(x, t, n, b, 0.5);
}

/// The interpolated coarse normal at barycentric `b` of triangle `t` (unit; zero when the
/// normals cancel).
inline Vec3 smooth_coarse_normal(const garment::Tri& t, const std::vector<Vec3>& n,
                                 const std::array<double, 3>& b) {
    Vec3 nc{0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        nc = vec3::add(nc, vec3::scale(n[t[std::size_t(i)]], b[std::size_t(i)]));
    }
    const double l = vec3::norm(nc);
    return l > 0 ? vec3::scale(nc, 1 / l) : Vec3{0, 0, 0};
}

/// Per vertex of a garment: the pattern point and piece of the first triangle corner that names
/// it, whether any triangle does, and whether triangles of two pieces do (a welded seam).
struct VertexPattern {
    std::vector<garment::UV> uv;
    std::vector<std::uint32_t> piece;
    std::vector<std::uint8_t> used, seam;
};

inline VertexPattern vertex_pattern(const garment::GarmentMesh& g) {
    VertexPattern p;
    const std::size_t n = g.positions.size();
    p.uv.assign(n, {0, 0});
    p.piece.assign(n, 0);
    p.used.assign(n, 0);
    p.seam.assign(n, 0);
    for (std::size_t f = 0; f < g.triangles.size(); ++f) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = g.triangles[f][std::size_t(k)];
            if (!p.used[v]) {
                p.used[v] = 1;
                p.uv[v] = g.uv[f][std::size_t(k)];
                p.piece[v] = g.triangle_piece[f];
            } else if (p.piece[v] != g.triangle_piece[f]) {
                p.seam[v] = 1;
            }
        }
    }
    return p;
}

inline void check_garment(const garment::GarmentMesh& g, const char* which) {
    const std::string w = std::string("embedding: ") + which + " mesh";
    if (g.uv.size() != g.triangles.size() || g.triangle_piece.size() != g.triangles.size()) {
        throw InvalidInput(w + ": " + std::to_string(g.triangles.size()) + " triangles, " +
                           std::to_string(g.uv.size()) + " pattern triangles and " +
                           std::to_string(g.triangle_piece.size()) + " piece indices");
    }
    for (std::size_t f = 0; f < g.triangles.size(); ++f) {
        for (std::uint32_t v : g.triangles[f]) {
            if (v >= g.positions.size()) {
                throw InvalidInput(w + ": triangle " + std::to_string(f) + " names vertex " +
                                   std::to_string(v) + " of " + std::to_string(g.positions.size()));
            }
        }
        for (const garment::UV& t : g.uv[f]) {
            if (!(std::isfinite(t[0]) && std::isfinite(t[1]))) {
                throw InvalidInput(w + ": triangle " + std::to_string(f) +
                                   " has a pattern coordinate that is not finite");
            }
        }
    }
    for (std::size_t v = 0; v < g.positions.size(); ++v) {
        for (double c : g.positions[v]) {
            if (!std::isfinite(c)) {
                throw InvalidInput(w + ": vertex " + std::to_string(v) +
                                   " has a coordinate that is not finite");
            }
        }
    }
}

}  // namespace internal

/// Embeds `fine` in `coarse` (see the file comment); positions of both in mm, pattern
/// coordinates in mm, the same pieces by index.
///
/// \throws InvalidInput naming the mesh and the triangle or vertex: arrays of different sizes,
///         an index out of range, a value that is not finite, a fine triangle on a piece the
///         coarse mesh does not have, a coarse mesh without a non-degenerate pattern triangle.
inline Embedding embed_fine_in_coarse(const garment::GarmentMesh& coarse,
                                      const garment::GarmentMesh& fine) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Iterator = std::vector<K::Triangle_3>::const_iterator;
    using Primitive = CGAL::AABB_triangle_primitive<K, Iterator>;
    using Tree = CGAL::AABB_tree<CGAL::AABB_traits<K, Primitive>>;
    internal::check_garment(coarse, "coarse");
    internal::check_garment(fine, "fine");
    std::vector<K::Triangle_3> tris;
    std::vector<std::uint32_t> tri_of;  // tree triangle -> coarse triangle
    std::uint32_t pieces = 0;
    for (std::size_t f = 0; f < coarse.triangles.size(); ++f) {
        const auto& u = coarse.uv[f];
        const double z = internal::kPieceGap * double(coarse.triangle_piece[f]);
        const K::Triangle_3 t(K::Point_3(u[0][0], u[0][1], z), K::Point_3(u[1][0], u[1][1], z),
                              K::Point_3(u[2][0], u[2][1], z));
        pieces = std::max(pieces, coarse.triangle_piece[f] + 1);
        if (!t.is_degenerate()) {
            tris.push_back(t);
            tri_of.push_back(std::uint32_t(f));
        }
    }
    if (tris.empty()) {
        throw InvalidInput("embedding: the coarse mesh has no pattern triangle of non-zero area");
    }
    Tree tree(tris.begin(), tris.end());
    tree.accelerate_distance_queries();
    const std::vector<Vec3> normals = draw::vertex_normals(coarse.positions, coarse.triangles);

    Embedding out;
    out.vertices.resize(fine.positions.size());
    std::vector<std::uint8_t> done(fine.positions.size(), 0);
    double sum_h2 = 0, sum_t2 = 0;
    for (std::size_t f = 0; f < fine.triangles.size(); ++f) {
        const std::uint32_t piece = fine.triangle_piece[f];
        if (piece >= pieces) {
            throw InvalidInput("embedding: fine triangle " + std::to_string(f) + " lies on piece " +
                               std::to_string(piece) + ", the coarse mesh has " +
                               std::to_string(pieces));
        }
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = fine.triangles[f][std::size_t(k)];
            if (done[v]) {
                continue;
            }
            done[v] = 1;
            const garment::UV& p = fine.uv[f][std::size_t(k)];
            const K::Point_3 q(p[0], p[1], internal::kPieceGap * double(piece));
            const auto hit = tree.closest_point_and_primitive(q);
            const std::size_t ti = std::size_t(hit.second - tris.cbegin());
            const std::uint32_t ct = tri_of[ti];
            const K::Triangle_3& t = tris[ti];
            EmbeddedVertex& e = out.vertices[v];
            e.coarse_triangle = ct;
            e.outside_mm = std::sqrt(CGAL::squared_distance(q, hit.first));
            // Barycentric coordinates of the closest point in the pattern triangle.
            const double x = hit.first.x(), y = hit.first.y();
            const double x0 = t[0].x(), y0 = t[0].y(), x1 = t[1].x(), y1 = t[1].y(), x2 = t[2].x(),
                         y2 = t[2].y();
            const double det = (x1 - x0) * (y2 - y0) - (x2 - x0) * (y1 - y0);
            const double b1 = ((x - x0) * (y2 - y0) - (x2 - x0) * (y - y0)) / det;
            const double b2 = ((x1 - x0) * (y - y0) - (x - x0) * (y1 - y0)) / det;
            e.barycentric = {1 - b1 - b2, b1, b2};
            const Vec3 xc = internal::smooth_coarse_point(coarse.positions, coarse.triangles[ct],
                                                          normals, e.barycentric);
            const Vec3 nc =
                internal::smooth_coarse_normal(coarse.triangles[ct], normals, e.barycentric);
            const Vec3 d = vec3::sub(fine.positions[v], xc);
            e.height_mm = vec3::dot(d, nc);
            e.tangential_mm = vec3::norm(vec3::sub(d, vec3::scale(nc, e.height_mm)));
            ++out.used;
            sum_h2 += e.height_mm * e.height_mm;
            sum_t2 += e.tangential_mm * e.tangential_mm;
            out.max_abs_height_mm = std::max(out.max_abs_height_mm, std::abs(e.height_mm));
            out.max_outside_mm = std::max(out.max_outside_mm, e.outside_mm);
        }
    }
    if (out.used > 0) {
        out.rms_height_mm = std::sqrt(sum_h2 / double(out.used));
        out.rms_tangential_mm = std::sqrt(sum_t2 / double(out.used));
    }
    return out;
}

}  // namespace tapeline::wrinkles
