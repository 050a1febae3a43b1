// Sewing along geodesic strings, and welding the sewn seams.
//
// Every stitch pair of the pattern meshing (a seam vertex on one side, its partner on the other)
// is joined by a string that runs along the body: the geodesic between the body points nearest
// to the two vertices (geodesic curvature flow on the body mesh, GeodesicPathSolver), lifted off
// the skin along the outward direction of the body's signed distance. A straight chord between a
// front and a back shoulder vertex would cut through the shoulder; the string goes over it.
// While the seams are sewn, each vertex of a pair is pulled towards a point that slides along its
// string to the string's middle (at sewing fraction σ the targets are at arc σ·L/2 from either
// end), so the pieces are drawn round the body, never through it. Then the pairs are held
// together by zero-length stitches, and at the end the pairs are welded into one vertex.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/vec3.h>
#include <tapeline/garment/collider.h>
#include <tapeline/garment/garment_types.h>
#include <tapeline/geodesic/curvature_flow.h>
#include <tapeline/pattern/meshing_types.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <numeric>
#include <unordered_map>
#include <vector>

namespace tapeline::garment {

/// A polyline with its arc lengths (mm).
struct StringPath {
    /// The polyline's vertices, mm.
    std::vector<Vec3> points;
    std::vector<double> arc;  ///< arc.back(): the string's length

    /// The string's length, mm (0 when `arc` is empty).
    double length() const { return arc.empty() ? 0.0 : arc.back(); }
    /// The point at arc position `a` (clamped to the string).
    Vec3 at(double a) const {
        if (points.size() == 1) {
            return points[0];
        }
        a = std::clamp(a, 0.0, length());
        const auto it = std::upper_bound(arc.begin(), arc.end(), a);
        const std::size_t i = std::min<std::size_t>(
            std::size_t(std::max<std::ptrdiff_t>(it - arc.begin(), 1) - 1), points.size() - 2);
        const double len = arc[i + 1] - arc[i];
        const double t = len > 0 ? (a - arc[i]) / len : 0.0;
        return vec3::add(points[i], vec3::scale(vec3::sub(points[i + 1], points[i]), t));
    }
};

/// The stitch pairs of a whole cloth (global vertex indices) and their strings.
struct SewingPlan {
    std::vector<Stitch> pairs;              ///< a, b global; rest 0
    std::vector<std::size_t> seam_of_pair;  ///< index into Pattern::seams
    std::vector<StringPath> strings;        ///< per pair, from a's end to b's end
};

/// Global vertex index of the first vertex of each piece (pieces concatenated in order).
inline std::vector<std::uint32_t> piece_offsets(const pattern::PatternMesh& mesh) {
    std::vector<std::uint32_t> off(mesh.pieces.size() + 1, 0);
    for (std::size_t i = 0; i < mesh.pieces.size(); ++i) {
        off[i + 1] = off[i] + std::uint32_t(mesh.pieces[i].uv.size());
    }
    return off;
}

/// The pairs of every seam, in global indices.
inline SewingPlan sewing_pairs(const pattern::PatternMesh& mesh) {
    const auto off = piece_offsets(mesh);
    SewingPlan plan;
    for (const pattern::SeamStitch& s : mesh.seams) {
        for (const auto& [a, b] : s.pairs) {
            Stitch st;
            st.a = off[s.piece_a] + a;
            st.b = off[s.piece_b] + b;
            if (st.a == st.b) {
                continue;
            }
            plan.pairs.push_back(st);
            plan.seam_of_pair.push_back(s.seam);
        }
    }
    return plan;
}

/// Strings along the body for every pair of `plan` (see the file comment): from vertex a as
/// placed, down to the skin (lifted by `offset_mm`), along the geodesic, up to vertex b.
/// `body_limb` marks body vertices on limbs, `cloth_limb` cloth vertices of limb pieces
/// (sleeves); a pair with no end on a limb piece starts and ends its string on the trunk.
/// `body_points` and `body_triangles` are the body in the cloth's frame (mm); `positions` the
/// placed cloth. Pairs whose ends are nearest to the same body vertex get a straight string.
inline void compute_strings(SewingPlan& plan, const std::vector<Vec3>& positions,
                            const std::vector<Vec3>& body_points, const std::vector<Tri>& body_tris,
                            const Collider& collider, double offset_mm,
                            const std::vector<std::uint8_t>& body_limb = {},
                            const std::vector<std::uint8_t>& cloth_limb = {}) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Mesh = CGAL::Surface_mesh<K::Point_3>;
    using VD = Mesh::Vertex_index;
    Mesh sm;
    std::vector<VD> vd(body_points.size());
    for (std::size_t v = 0; v < body_points.size(); ++v) {
        vd[v] = sm.add_vertex(K::Point_3(body_points[v][0], body_points[v][1], body_points[v][2]));
    }
    std::vector<std::uint8_t> used(body_points.size(), 0);
    for (const Tri& t : body_tris) {
        if (sm.add_face(vd[t[0]], vd[t[1]], vd[t[2]]) == Mesh::null_face()) {
            throw TopologyError(
                "dress: the body mesh is not an oriented manifold (a face cannot "
                "be added to the mesh the strings run on)");
        }
        used[t[0]] = used[t[1]] = used[t[2]] = 1;
    }
    // Nearest used body vertex of each pair end: a uniform grid over the body points.
    const double cell = 20;
    std::unordered_map<long long, std::vector<std::uint32_t>> grid;
    const auto key = [&](long i, long j, long k) {
        return ((long long)(i + 1000000) * 2000003LL + (j + 1000000)) * 2000003LL + (k + 1000000);
    };
    for (std::size_t v = 0; v < body_points.size(); ++v) {
        if (!used[v]) {
            continue;
        }
        const auto& p = body_points[v];
        grid[key(long(std::floor(p[0] / cell)), long(std::floor(p[1] / cell)),
                 long(std::floor(p[2] / cell)))]
            .push_back(std::uint32_t(v));
    }
    // A pair of two body pieces (no sleeve) starts its string on the trunk: the arm hanging next
    // to a side seam is nearer to it than the trunk, and a string from the arm would go round
    // by the shoulder.
    const auto nearest = [&](const Vec3& p, bool trunk_only) {
        const long ci = long(std::floor(p[0] / cell)), cj = long(std::floor(p[1] / cell)),
                   ck = long(std::floor(p[2] / cell));
        std::uint32_t best = 0;
        double bd = 1e300;
        for (long r = 1; r < 200; ++r) {
            for (long i = ci - r; i <= ci + r; ++i) {
                for (long j = cj - r; j <= cj + r; ++j) {
                    for (long k = ck - r; k <= ck + r; ++k) {
                        const auto it = grid.find(key(i, j, k));
                        if (it == grid.end()) {
                            continue;
                        }
                        for (std::uint32_t v : it->second) {
                            if (trunk_only && v < body_limb.size() && body_limb[v]) {
                                continue;
                            }
                            const double d = vec3::norm(vec3::sub(body_points[v], p));
                            if (d < bd) {
                                bd = d;
                                best = v;
                            }
                        }
                    }
                }
            }
            // Every point within r·cell of p has been seen once the best is that close.
            if (bd < (r - 1) * cell) {
                break;
            }
        }
        return best;
    };
    geodesic::GeodesicPathSolver<Mesh> solver(sm);
    using PP = typename geodesic::GeodesicPathSolver<Mesh>::PointPair;
    std::vector<PP> queries;
    std::vector<std::size_t> query_of(plan.pairs.size(), std::size_t(-1));
    std::vector<std::pair<std::uint32_t, std::uint32_t>> ends(plan.pairs.size());
    for (std::size_t k = 0; k < plan.pairs.size(); ++k) {
        const auto on_limb = [&](std::uint32_t v) {
            return v < cloth_limb.size() && cloth_limb[v];
        };
        const bool trunk_only = !on_limb(plan.pairs[k].a) && !on_limb(plan.pairs[k].b);
        const std::uint32_t va = nearest(positions[plan.pairs[k].a], trunk_only);
        const std::uint32_t vb = nearest(positions[plan.pairs[k].b], trunk_only);
        ends[k] = {va, vb};
        if (va != vb) {
            query_of[k] = queries.size();
            queries.push_back({vd[va], vd[vb]});
        }
    }
    geodesic::CurvatureFlowOptions gopt;
    const auto paths = solver.paths(queries, gopt);
    const auto lift = [&](const Vec3& p) {
        Vec3 g{0, 0, 0};
        const double d = collider.signed_distance(p, &g);
        return vec3::add(p, vec3::scale(g, offset_mm - d));
    };
    plan.strings.assign(plan.pairs.size(), {});
    for (std::size_t k = 0; k < plan.pairs.size(); ++k) {
        // The string starts at vertex a as placed, drops to the lifted skin below it, follows
        // the lifted geodesic and rises to vertex b: the targets of sewing_targets() then start
        // where the vertices are.
        StringPath& s = plan.strings[k];
        s.points.push_back(positions[plan.pairs[k].a]);
        if (query_of[k] == std::size_t(-1) || paths[query_of[k]].on_mesh.points.size() < 2) {
            s.points.push_back(lift(body_points[ends[k].first]));
            s.points.push_back(lift(body_points[ends[k].second]));
        } else {
            for (const auto& q : paths[query_of[k]].on_mesh.points) {
                s.points.push_back(lift({q.x(), q.y(), q.z()}));
            }
        }
        s.points.push_back(positions[plan.pairs[k].b]);
        s.arc.assign(s.points.size(), 0.0);
        for (std::size_t i = 1; i < s.points.size(); ++i) {
            s.arc[i] = s.arc[i - 1] + vec3::norm(vec3::sub(s.points[i], s.points[i - 1]));
        }
    }
}

/// What sewing_targets() keeps from one frame to the next: each corner's mean of its string
/// points and the target it was given.
struct SewingTargetState {
    std::map<std::uint32_t, Vec3> mean;
    std::map<std::uint32_t, Vec3> target;
};

/// The pull targets at sewing fraction `sigma` ∈ [0, 1]: a towards arc σ·L/2, b towards
/// arc L − σ·L/2 of its string. A vertex in several pairs (a corner where seams meet) gets one
/// attachment, to the mean of its targets: two hard pulls to different points would fight. That
/// mean lies inside the body when the strings run over different sides of a limb or the neck;
/// given the `body`, a target closer to its skin than half `offset_mm` (the strings' offset) is
/// lifted back out to `offset_mm` along the normal of the skin nearest it (by the exact distance:
/// the grid's is a bound away from the skin).
///
/// Given a `state` (the same one every frame), a lifted target moves with its mean: where the
/// lift would take it farther from its last target than the mean moved plus `offset_mm` (the mean
/// passed the middle of a limb, and the skin nearest it changed sides), it is the last target
/// moved as the mean moved and put back at `offset_mm` from the skin nearest it. On a shirt's
/// shoulder corner whose two strings ran over the front and the back of the shoulder, the nearest
/// skin changed from the top of the shoulder to its side and the target jumped 64 mm in one frame:
/// the sewing blew up.
inline std::vector<Attachment> sewing_targets(const SewingPlan& plan, double sigma,
                                              double compliance,
                                              const SignedDistanceGrid* body = nullptr,
                                              double offset_mm = 0,
                                              SewingTargetState* state = nullptr) {
    std::map<std::uint32_t, std::pair<Vec3, int>> sum;
    const auto add_target = [&](std::uint32_t v, const Vec3& p) {
        auto& e = sum[v];
        e.first = vec3::add(e.first, p);
        ++e.second;
    };
    for (std::size_t k = 0; k < plan.pairs.size(); ++k) {
        const StringPath& s = plan.strings[k];
        const double half = 0.5 * s.length() * std::clamp(sigma, 0.0, 1.0);
        add_target(plan.pairs[k].a, s.at(half));
        add_target(plan.pairs[k].b, s.at(s.length() - half));
    }
    // To the offset along the normal of the nearest skin: always, or (lift) only when closer
    // than half of it.
    const auto to_offset = [&](const Vec3& p, bool only_below_half) {
        Vec3 n;
        const double d = body->exact_signed_distance(p, &n);
        return d < 0.5 * offset_mm || !only_below_half ? vec3::add(p, vec3::scale(n, offset_mm - d))
                                                       : p;
    };
    std::vector<Attachment> out;
    out.reserve(sum.size());
    for (const auto& [v, e] : sum) {
        const Vec3 mean = vec3::scale(e.first, 1.0 / e.second);
        Vec3 target = body ? to_offset(mean, true) : mean;
        if (body && state) {
            const auto last_mean = state->mean.find(v);
            const auto last_target = state->target.find(v);
            if (last_mean != state->mean.end() && last_target != state->target.end()) {
                const Vec3 moved = vec3::sub(mean, last_mean->second);
                if (vec3::norm(vec3::sub(target, last_target->second)) >
                    vec3::norm(moved) + offset_mm) {
                    target = to_offset(vec3::add(last_target->second, moved), false);
                }
            }
            state->mean[v] = mean;
            state->target[v] = target;
        }
        out.push_back({v, target, compliance});
    }
    return out;
}

}  // namespace tapeline::garment
