// Fast marching on the compact mesh (core/compact_mesh_types.h): the first-order upwind scheme
// of R. Kimmel and J. A. Sethian, "Computing geodesic paths on manifolds", PNAS 95(15), 1998,
// with their splitting of obtuse corners by unfolding. No CGAL here: the loops compile once per
// translation unit whatever the input mesh type.
//
// The update of corner C from the final values a, b at the other corners A, B of a face is the
// plane wave d(x) = t + n·(x − C), |n| = 1, through (A, a) and (B, b), written with the Gram
// matrix G of the edge vectors CA, CB only (no planar layout): with u = (a − t, b − t),
// uᵀ G⁻¹ u = 1 is a quadratic in t, of which the larger root is taken. It is accepted when the
// wave comes through the face (−G⁻¹u ≥ 0: the characteristic reaching C crosses the segment AB)
// and t ≥ max(a, b) (the order of acceptance stays monotone); otherwise the corner takes the
// one-vertex updates a + |CA|, b + |CB|. At an obtuse corner that condition fails for the waves
// that come from inside its wide angle; the faces beyond AB are unfolded into the corner's plane
// until a vertex D lies in the corner's acute section (both angles ACD and DCB at most 90°), and
// the corner is also updated from the virtual faces (C, A, D) and (C, D, B) and along the virtual
// edge CD (a path on the surface: the segment stays inside the unfolded faces).
#pragma once

#include <tapeline/core/compact_mesh_types.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

namespace tapeline::geodesic::internal::fmm {

constexpr std::uint32_t kNone = tapeline::CompactMesh::kNone;
constexpr double kInf = std::numeric_limits<double>::infinity();

inline std::uint32_t next_he(std::uint32_t h) {
    return tapeline::CompactMesh::next_halfedge(h);
}
inline std::uint32_t prev_he(std::uint32_t h) {
    return tapeline::CompactMesh::prev_halfedge(h);
}

/// The plane-wave value at C from final values a at A and b at B, |CA| = la, |CB| = lb and
/// cos(ACB) = c; +infinity when the wave does not come through the face, the face has no area,
/// or the value would be below max(a, b).
inline double plane_wave(double la, double lb, double c, double a, double b) {
    const double s2 = 1 - c * c;
    if (!(la > 0) || !(lb > 0) || !(s2 > 1e-12)) {
        return kInf;
    }
    // det(G)·G⁻¹ = [[lb², −la·lb·c], [−la·lb·c, la²]]; the quadratic multiplied by det(G).
    const double g12 = la * lb * c;
    const double qa = la * la + lb * lb - 2 * g12;  // |AB|²
    const double qb = a * (lb * lb - g12) + b * (la * la - g12);
    const double qc = a * a * lb * lb - 2 * a * b * g12 + b * b * la * la - la * la * lb * lb * s2;
    const double disc = qb * qb - qa * qc;
    if (!(disc >= 0) || !(qa > 0)) {
        return kInf;
    }
    const double t = (qb + std::sqrt(disc)) / qa;
    if (!(t >= std::max(a, b))) {
        return kInf;
    }
    // Causality: −G⁻¹u ≥ 0 (up to rounding of the size of the terms).
    const double ua = a - t, ub = b - t;
    const double ca = lb * lb * ua - g12 * ub, cb = la * la * ub - g12 * ua;
    const double tol = 1e-12 * (la * la + lb * lb) * t;
    if (ca > tol || cb > tol) {
        return kInf;
    }
    return t;
}

/// An obtuse corner split by a virtual edge to the vertex `d` of the unfolded faces.
struct VirtualEdge {
    std::uint32_t corner;  ///< halfedge id 3f+k of the obtuse corner
    std::uint32_t d;       ///< the vertex in the corner's acute section
    double length;         ///< |CD| in the unfolding
    double cos_a, cos_b;   ///< cos(ACD), cos(DCB)
};

/// The source-independent part: edge lengths, corner cosines and the virtual edges.
class Mesh {
public:
    Mesh(const tapeline::CompactMesh& m, bool unfold_obtuse, std::size_t max_unfold_faces) : m_(m) {
        const std::size_t nf = m.face_count(), nv = m.vertex_count();
        len_.assign(3 * nf, 0.0);
        for (std::uint32_t h = 0; h < 3 * nf; ++h) {
            const auto p = m.point(m.corner[h]);
            const auto q = m.point(m.corner[next_he(h)]);
            len_[h] = std::sqrt((p[0] - q[0]) * (p[0] - q[0]) + (p[1] - q[1]) * (p[1] - q[1]) +
                                (p[2] - q[2]) * (p[2] - q[2]));
        }
        cos_.assign(3 * nf, 1.0);
        for (std::uint32_t h = 0; h < 3 * nf; ++h) {
            // At corner h: edges to the next corner (halfedge h) and to the previous one.
            const double a = len_[h], b = len_[prev_he(h)], c = len_[next_he(h)];
            cos_[h] =
                a > 0 && b > 0 ? std::clamp((a * a + b * b - c * c) / (2 * a * b), -1.0, 1.0) : 1.0;
        }
        virtual_of_.assign(unfold_obtuse ? 3 * nf : 0, kNone);
        for (std::uint32_t h = 0; h < 3 * nf; ++h) {
            // Right angles (a flat grid's, up to the rounding of the law of cosines) need no
            // split: the plane wave through a right corner's face is causal where it should be.
            if (!(cos_[h] < -1e-9)) {
                continue;
            }
            ++obtuse_;
            if (!unfold_obtuse) {
                continue;
            }
            VirtualEdge e;
            if (unfold(h, max_unfold_faces, e)) {
                virtual_of_[h] = static_cast<std::uint32_t>(virtuals_.size());
                virtuals_.push_back(e);
            }
        }
        // Vertex D -> the virtual edges that end at it (a CSR table).
        dstart_.assign(nv + 1, 0);
        for (const VirtualEdge& e : virtuals_) {
            ++dstart_[e.d + 1];
        }
        for (std::size_t v = 0; v < nv; ++v) {
            dstart_[v + 1] += dstart_[v];
        }
        dlist_.resize(virtuals_.size());
        std::vector<std::uint32_t> fill(dstart_.begin(), dstart_.end() - 1);
        for (std::uint32_t i = 0; i < virtuals_.size(); ++i) {
            dlist_[fill[virtuals_[i].d]++] = i;
        }
    }

    const tapeline::CompactMesh& compact() const { return m_; }
    std::size_t obtuse_corners() const { return obtuse_; }
    std::size_t virtual_edges() const { return virtuals_.size(); }
    double length(std::uint32_t h) const { return len_[h]; }
    double cosine(std::uint32_t h) const { return cos_[h]; }
    const VirtualEdge* virtual_edge(std::uint32_t h) const {
        return virtual_of_.empty() || virtual_of_[h] == kNone ? nullptr
                                                              : &virtuals_[virtual_of_[h]];
    }
    /// The virtual edges ending at vertex v.
    template <class F>
    void for_each_virtual_ending_at(std::uint32_t v, F&& f) const {
        for (std::uint32_t i = dstart_[v]; i < dstart_[v + 1]; ++i) {
            f(virtuals_[dlist_[i]]);
        }
    }

private:
    struct P2 {
        double x, y;
    };

    // Unfolds the faces beyond the edge opposite corner h until a vertex falls in the corner's
    // acute section; false when the border, a cap of faces or the corner itself comes first.
    bool unfold(std::uint32_t h, std::size_t max_faces, VirtualEdge& out) const {
        const std::uint32_t c = m_.corner[h];
        const double la = len_[h], lb = len_[prev_he(h)], co = cos_[h];
        const double si = std::sqrt(std::max(0.0, 1 - co * co));
        const P2 a0{la, 0}, b0{lb * co, lb * si};
        // The edge being crossed: its A-side and B-side ends (vertex, position), the halfedge
        // of the current face on it and the current face's third corner.
        std::uint32_t u = m_.corner[next_he(h)], w = m_.corner[prev_he(h)];
        P2 pu = a0, pw = b0, third{0, 0};
        std::uint32_t edge = next_he(h);
        for (std::size_t step = 0; step < max_faces; ++step) {
            const std::uint32_t t = m_.twin[edge];
            if (t == kNone) {
                return false;
            }
            const std::uint32_t p = m_.corner[prev_he(t)];
            const std::uint32_t first = m_.corner[next_he(t)];  // the end nearer to P along t
            if (p == c || p == u || p == w ||
                !((first == u && m_.corner[t] == w) || (first == w && m_.corner[t] == u))) {
                return false;
            }
            const double l_first = len_[next_he(t)], l_second = len_[prev_he(t)];
            const double lu = first == u ? l_first : l_second;  // |uP|
            const double lw = first == u ? l_second : l_first;  // |wP|
            const P2 e{pw.x - pu.x, pw.y - pu.y};
            const double el = std::sqrt(e.x * e.x + e.y * e.y);
            if (!(el > 0)) {
                return false;
            }
            const double x = (lu * lu - lw * lw + el * el) / (2 * el);
            const double y = std::sqrt(std::max(0.0, lu * lu - x * x));
            P2 n{-e.y / el, e.x / el};
            if (n.x * (third.x - pu.x) + n.y * (third.y - pu.y) > 0) {
                n = {-n.x, -n.y};
            }
            const P2 pp{pu.x + x * e.x / el + y * n.x, pu.y + x * e.y / el + y * n.y};
            const double sa = pp.x * a0.x + pp.y * a0.y, sb = pp.x * b0.x + pp.y * b0.y;
            // The section is closed, up to the rounding of the unfolding: a vertex at a right
            // angle to one edge (a sheared grid's vertex straight below the corner) splits it
            // into a right and an acute corner.
            const double tol = 1e-9 * (pp.x * pp.x + pp.y * pp.y + la * la + lb * lb);
            if (sa >= -tol && sb >= -tol) {
                const double lp = std::sqrt(pp.x * pp.x + pp.y * pp.y);
                out.corner = h;
                out.d = p;
                out.length = lp;
                out.cos_a = std::clamp(sa / (lp * la), -1.0, 1.0);
                out.cos_b = std::clamp(sb / (lp * lb), -1.0, 1.0);
                return true;
            }
            // The section lies between u and P (P beyond it on the B side) or between P and w.
            const bool keep_u = sa < -tol;
            const std::uint32_t hu = first == u ? next_he(t) : prev_he(t);  // on u–P
            const std::uint32_t hw = first == u ? prev_he(t) : next_he(t);  // on P–w
            if (keep_u) {
                third = pw;
                w = p;
                pw = pp;
                edge = hu;
            } else {
                third = pu;
                u = p;
                pu = pp;
                edge = hw;
            }
        }
        return false;
    }

    const tapeline::CompactMesh& m_;
    std::vector<double> len_;  // 3 per face: |corner k, corner k+1|
    std::vector<double> cos_;  // 3 per face: cosine of the angle at corner k
    std::vector<std::uint32_t> virtual_of_;
    std::vector<VirtualEdge> virtuals_;
    std::vector<std::uint32_t> dstart_, dlist_;
    std::size_t obtuse_ = 0;
};

/// What one run did.
struct RunStats {
    std::size_t face_updates = 0;
    std::size_t edge_updates = 0;
};

/// Runs the fast marching from seeded distances (`d`: the seeds' values, +infinity elsewhere)
/// and writes the final distances into `d` (+infinity where the front never came).
inline RunStats run(const Mesh& mesh, std::vector<double>& d) {
    const tapeline::CompactMesh& m = mesh.compact();
    const std::size_t nv = m.vertex_count();
    std::vector<std::uint8_t> done(nv, 0);
    // Per vertex, where its value came from: an edge (0) or face (1) update, or a seed (2).
    std::vector<std::uint8_t> from(nv, 2);
    using Item = std::pair<double, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> queue;
    for (std::uint32_t v = 0; v < nv; ++v) {
        if (d[v] < kInf) {
            queue.push({d[v], v});
        }
    }
    auto value = [&](std::uint32_t v) { return done[v] ? d[v] : kInf; };
    // The best update of corner h (halfedge id) from the final values around it.
    auto update = [&](std::uint32_t h) {
        const std::uint32_t a = m.corner[next_he(h)], b = m.corner[prev_he(h)];
        const double la = mesh.length(h), lb = mesh.length(prev_he(h));
        const double va = value(a), vb = value(b);
        double best = std::min(va + la, vb + lb);
        bool face = false;
        auto consider = [&](double t) {
            if (t < best) {
                best = t;
                face = true;
            }
        };
        if (va < kInf && vb < kInf) {
            consider(plane_wave(la, lb, mesh.cosine(h), va, vb));
        }
        if (const VirtualEdge* e = mesh.virtual_edge(h)) {
            const double vd = value(e->d);
            if (vd < kInf) {
                // The virtual edge is a path on the surface: the section's rays cross every
                // unfolded edge, so the segment CD stays inside the unfolded faces.
                if (vd + e->length < best) {
                    best = vd + e->length;
                    face = false;
                }
                if (va < kInf) {
                    consider(plane_wave(la, e->length, e->cos_a, va, vd));
                }
                if (vb < kInf) {
                    consider(plane_wave(e->length, lb, e->cos_b, vd, vb));
                }
            }
        }
        return std::make_pair(best, face);
    };
    auto relax = [&](std::uint32_t h) {
        const std::uint32_t c = m.corner[h];
        if (done[c]) {
            return;
        }
        const auto [t, face] = update(h);
        if (t < d[c]) {
            d[c] = t;
            from[c] = face ? 1 : 0;
            queue.push({t, c});
        }
    };
    RunStats stats;
    while (!queue.empty()) {
        const auto [dv, v] = queue.top();
        queue.pop();
        if (done[v] || dv != d[v]) {
            continue;
        }
        done[v] = 1;
        stats.face_updates += from[v] == 1;
        stats.edge_updates += from[v] == 0;
        // Every corner of v's faces other than v's own, then the obtuse corners whose virtual
        // edge ends at v.
        for (std::uint32_t i = m.vstart[v]; i < m.vstart[v + 1]; ++i) {
            const std::uint32_t h = m.vcorners[i];
            relax(next_he(h));
            relax(prev_he(h));
        }
        mesh.for_each_virtual_ending_at(v, [&](const VirtualEdge& e) { relax(e.corner); });
    }
    return stats;
}

}  // namespace tapeline::geodesic::internal::fmm
