// Machinery of unfold.h on the compact mesh of the curvature flow (gcf_engine.h); Eigen, no CGAL.
//
// A path on the faces (a polyline whose consecutive points lie on a common face) is turned into
// the sequence of faces it crosses, and those faces are laid into the plane one after another,
// each rotated about the edge it shares with the previous one (the development, or unfolding, of
// the face strip). The unfolding is an isometry on every face, so a polyhedral geodesic that passes
// no vertex becomes a straight segment in it (Mitchell, Mount, Papadimitriou, "The discrete
// geodesic problem", SIAM J. Comput. 16(4), 1987, Lemma 3.1); this is the check and picture (c)
// of the thesis' curvature-flow section.
//
// The funnel at the end finds the shortest path inside the unfolded strip between its two end
// points: the funnel algorithm for shortest paths in a triangulated simple polygon (D. T. Lee,
// F. P. Preparata, "Euclidean shortest paths in the presence of rectilinear barriers", Networks
// 14(3), 1984; B. Chazelle, "A theorem on polygon cutting with applications", FOCS 1982), run on
// the sequence of hinge edges ("portals"); only orientation tests are used, so a strip whose
// unfolding overlaps itself in the plane is handled as the sleeve it is.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/internal/gcf_engine.h>
#include <tapeline/geodesic/unfold_types.h>

#include <Eigen/Dense>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <deque>
#include <limits>
#include <sstream>
#include <string>
#include <vector>

namespace tapeline::geodesic::internal::unfold {

using gcf::kNone;
using gcf::Mesh;
using gcf::Vec3;
using Vec2 = Eigen::Vector2d;

/// Why a polyline could not be unfolded: the index of the first point that is not on a face
/// holding the previous one (kNone: fine).
struct FaceSequence {
    std::vector<std::uint32_t> faces;     ///< the strip: consecutive faces share an edge
    std::vector<std::uint32_t> point_at;  ///< per kept point: strip index of the face it maps by
    std::vector<Vec3> points;             ///< the polyline without repeated points
    std::size_t fan_faces = 0;            ///< faces added to go around a vertex the path touches
    std::size_t bad_point = kNone;        ///< index (in `points`) of a point off the strip
};

inline double distance_to_face(const Mesh& m, std::uint32_t f, const Vec3& p) {
    Vec3 bary;
    const Vec3 c = gcf::closest_on_triangle(p, m.xyz[m.corner[3 * f]], m.xyz[m.corner[3 * f + 1]],
                                            m.xyz[m.corner[3 * f + 2]], bary);
    return (c - p).norm();
}

inline int corner_of(const Mesh& m, std::uint32_t f, std::uint32_t v) {
    for (int k = 0; k < 3; ++k)
        if (m.corner[3 * f + k] == v)
            return k;
    return -1;
}

/// Faces passed when turning around vertex v from face a to face b (b included, a not) in one
/// direction: dir 0 crosses the edge of the current face that starts at v (edge k = (corner k,
/// corner k+1)), dir 1 the one that ends at v; on a consistently oriented mesh each keeps turning
/// the same way. Empty if b is not reached (a border edge, or a full turn).
inline std::vector<std::uint32_t> turn_walk(const Mesh& m, std::uint32_t a, std::uint32_t b,
                                            std::uint32_t v, int dir) {
    std::vector<std::uint32_t> walk;
    const std::uint32_t degree = m.vf_start[v + 1] - m.vf_start[v];
    std::uint32_t f = a;
    for (std::uint32_t step = 0; step < degree; ++step) {
        const int k = corner_of(m, f, v);
        if (k < 0)
            break;
        const std::uint32_t g = m.across[3 * f + (dir == 0 ? k : (k + 2) % 3)];
        if (g == kNone || g == a)
            break;
        walk.push_back(g);
        if (g == b)
            return walk;
        f = g;
    }
    return {};
}

/// The shorter of the two turns around the shared vertex v from face a to face b.
inline std::vector<std::uint32_t> fan_walk(const Mesh& m, std::uint32_t a, std::uint32_t b,
                                           std::uint32_t v) {
    auto w0 = turn_walk(m, a, b, v, 0);
    auto w1 = turn_walk(m, a, b, v, 1);
    if (w0.empty() || (!w1.empty() && w1.size() < w0.size()))
        return w1;
    return w0;
}

/// Faces from a to b: none if a == b, {b} across a shared edge, else around a shared vertex.
/// `ok` is false when they are not connected that way.
inline std::vector<std::uint32_t> connect(const Mesh& m, std::uint32_t a, std::uint32_t b,
                                          bool& ok) {
    ok = true;
    if (a == b)
        return {};
    for (int k = 0; k < 3; ++k)
        if (m.across[3 * a + k] == b)
            return {b};
    std::vector<std::uint32_t> best;
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = m.corner[3 * a + k];
        if (corner_of(m, b, v) < 0)
            continue;
        auto w = fan_walk(m, a, b, v);
        if (!w.empty() && (best.empty() || w.size() < best.size()))
            best = std::move(w);
    }
    ok = !best.empty();
    return best;
}

/// The faces crossed by an on-mesh polyline. Each segment (between consecutive distinct points)
/// must lie on one face, within `tol`; when several faces hold a segment (it runs along an edge) or
/// consecutive segments' faces meet only at a vertex, the choice that adds the fewest faces wins
/// (dynamic programming over the candidate faces of every segment). `start_face`: a face holding
/// the first point, or kNone to search all faces.
inline FaceSequence face_sequence(const Mesh& m, const std::vector<Vec3>& input, double tol,
                                  std::uint32_t start_face) {
    FaceSequence out;
    for (const Vec3& p : input)
        if (out.points.empty() || (p - out.points.back()).norm() > tol)
            out.points.push_back(p);
    if (out.points.size() < 2)
        return out;
    if ((input.back() - out.points.back()).norm() > 0)
        out.points.back() = input.back();  // keep the exact end point
    const std::size_t segs = out.points.size() - 1;
    auto holds = [&](std::uint32_t f, std::size_t k) {
        return distance_to_face(m, f, out.points[k]) <= tol &&
               distance_to_face(m, f, out.points[k + 1]) <= tol;
    };
    // cand[k]: faces holding segment k; cost/prev: fewest strip faces up to segment k.
    std::vector<std::vector<std::uint32_t>> cand(segs), prev(segs);
    std::vector<std::vector<std::size_t>> cost(segs);
    std::vector<std::uint32_t> pool;
    if (start_face != kNone) {
        for (int c = 0; c < 3; ++c) {
            const std::uint32_t v = m.corner[3 * start_face + c];
            pool.insert(pool.end(), m.vf.begin() + m.vf_start[v], m.vf.begin() + m.vf_start[v + 1]);
        }
    } else {
        for (std::uint32_t f = 0; f < m.face_count(); ++f)
            pool.push_back(f);
    }
    for (std::size_t k = 0; k < segs; ++k) {
        if (k > 0) {
            pool.clear();
            for (std::uint32_t f : cand[k - 1])
                for (int c = 0; c < 3; ++c) {
                    const std::uint32_t v = m.corner[3 * f + c];
                    pool.insert(pool.end(), m.vf.begin() + m.vf_start[v],
                                m.vf.begin() + m.vf_start[v + 1]);
                }
        }
        std::sort(pool.begin(), pool.end());
        pool.erase(std::unique(pool.begin(), pool.end()), pool.end());
        for (std::uint32_t f : pool) {
            if (!holds(f, k))
                continue;
            std::size_t best = k == 0 ? 1 : std::numeric_limits<std::size_t>::max();
            std::uint32_t from = kNone;
            for (std::size_t j = 0; k > 0 && j < cand[k - 1].size(); ++j) {
                if (cost[k - 1][j] == std::numeric_limits<std::size_t>::max())
                    continue;
                bool ok = false;
                const std::size_t add = connect(m, cand[k - 1][j], f, ok).size();
                if (ok && cost[k - 1][j] + add < best) {
                    best = cost[k - 1][j] + add;
                    from = static_cast<std::uint32_t>(j);
                }
            }
            if (best == std::numeric_limits<std::size_t>::max())
                continue;
            cand[k].push_back(f);
            cost[k].push_back(best);
            prev[k].push_back(from);
        }
        if (cand[k].empty()) {
            out.bad_point = k + 1;
            return out;
        }
    }
    // Back-trace the cheapest choice, then expand the connections into the strip.
    std::vector<std::uint32_t> pick(segs);
    std::size_t j = static_cast<std::size_t>(
        std::min_element(cost[segs - 1].begin(), cost[segs - 1].end()) - cost[segs - 1].begin());
    for (std::size_t k = segs; k-- > 0;) {
        pick[k] = cand[k][j];
        if (k > 0)
            j = prev[k][j];
    }
    out.faces.push_back(pick[0]);
    out.point_at.push_back(0);
    for (std::size_t k = 1; k < segs; ++k) {
        bool ok = false;
        const auto add = connect(m, pick[k - 1], pick[k], ok);
        if (add.size() > 1)
            out.fan_faces += add.size() - 1;
        out.faces.insert(out.faces.end(), add.begin(), add.end());
        out.point_at.push_back(static_cast<std::uint32_t>(out.faces.size() - 1));
    }
    out.point_at.push_back(static_cast<std::uint32_t>(out.faces.size() - 1));
    return out;
}

/// The strip laid into the plane.
struct Strip {
    std::vector<std::uint32_t> faces;
    std::vector<std::array<Vec2, 3>> corners;  ///< per strip face, in the face's corner order
    /// hinge i: the edge shared by faces i and i+1, as (corner of face i, corner of face i)
    std::vector<std::array<int, 2>> hinge;
    std::vector<Vec2> path;  ///< the polyline's points mapped into the strip
    std::vector<std::uint32_t> point_at;
};

/// Lays the faces of `seq` into the plane: the first face with its first corner at the origin and
/// its first edge along +x (counter-clockwise), every next face rotated about the hinge edge to the
/// side opposite the previous face. Then moves the whole strip rigidly so that the first path point
/// is at the origin and the last on the +x axis.
inline Strip unfold_strip(const Mesh& m, const FaceSequence& seq) {
    Strip s;
    s.faces = seq.faces;
    s.point_at = seq.point_at;
    const std::size_t n = s.faces.size();
    s.corners.resize(n);
    s.hinge.resize(n > 0 ? n - 1 : 0);
    if (n == 0)
        return s;
    auto xyz = [&](std::uint32_t f, int k) -> const Vec3& { return m.xyz[m.corner[3 * f + k]]; };
    {
        const std::uint32_t f = s.faces[0];
        const Vec3 e = xyz(f, 1) - xyz(f, 0);
        const double len = e.norm();
        const Vec3 u = len > 0 ? Vec3(e / len) : Vec3::UnitX();
        const Vec3 w = xyz(f, 2) - xyz(f, 0);
        const double t = w.dot(u);
        s.corners[0] = {Vec2(0, 0), Vec2(len, 0), Vec2(t, (w - t * u).norm())};
    }
    for (std::size_t i = 1; i < n; ++i) {
        const std::uint32_t a = s.faces[i - 1], b = s.faces[i];
        int ka = -1, kb0 = -1, kb1 = -1;
        for (int k = 0; k < 3 && ka < 0; ++k) {
            if (m.across[3 * a + k] != b)
                continue;
            const int i0 = corner_of(m, b, m.corner[3 * a + k]);
            const int i1 = corner_of(m, b, m.corner[3 * a + (k + 1) % 3]);
            if (i0 >= 0 && i1 >= 0) {
                ka = k;
                kb0 = i0;
                kb1 = i1;
            }
        }
        // face_sequence only produces edge-adjacent neighbours.
        const int ka1 = (ka + 1) % 3, kaf = (ka + 2) % 3, kbf = 3 - kb0 - kb1;
        s.hinge[i - 1] = {ka, ka1};
        const Vec2 p0 = s.corners[i - 1][ka], p1 = s.corners[i - 1][ka1];
        const Vec2 far = s.corners[i - 1][kaf];
        Vec2 d = p1 - p0;
        const double d_len = d.norm();
        d = d_len > 0 ? Vec2(d / d_len) : Vec2(1, 0);
        Vec2 perp(-d.y(), d.x());
        if (perp.dot(far - p0) > 0)
            perp = -perp;
        const Vec3 a0 = xyz(b, kb0), a1 = xyz(b, kb1), c = xyz(b, kbf);
        const Vec3 e = a1 - a0;
        const double len = e.norm();
        const Vec3 u = len > 0 ? Vec3(e / len) : Vec3::UnitX();
        const double t = (c - a0).dot(u);
        const double h = ((c - a0) - t * u).norm();
        s.corners[i][kb0] = p0;
        s.corners[i][kb1] = p1;
        s.corners[i][kbf] = p0 + t * d + h * perp;
    }
    // Points by their barycentric coordinates on the face they map by.
    s.path.resize(seq.points.size());
    for (std::size_t k = 0; k < seq.points.size(); ++k) {
        const std::size_t i = s.point_at[k];
        const std::uint32_t f = s.faces[i];
        Vec3 bary;
        gcf::closest_on_triangle(seq.points[k], xyz(f, 0), xyz(f, 1), xyz(f, 2), bary);
        s.path[k] =
            bary[0] * s.corners[i][0] + bary[1] * s.corners[i][1] + bary[2] * s.corners[i][2];
    }
    // Rigid motion: start at the origin, end on +x.
    const Vec2 origin = s.path.front();
    Vec2 dir = s.path.back() - origin;
    const double len = dir.norm();
    dir = len > 0 ? Vec2(dir / len) : Vec2(1, 0);
    Eigen::Matrix2d rot;
    rot << dir.x(), dir.y(), -dir.y(), dir.x();
    for (auto& tri : s.corners)
        for (auto& c : tri)
            c = rot * (c - origin);
    for (auto& p : s.path)
        p = rot * (p - origin);
    return s;
}

inline double cross2(const Vec2& a, const Vec2& b) {
    return a.x() * b.y() - a.y() * b.x();
}

/// Whether the straight segment between the strip's end points crosses every hinge edge (within
/// `tol`): it then stays inside the strip and is a path on the mesh.
inline bool straight_inside(const Strip& s, double tol) {
    const Vec2 a = s.path.front(), b = s.path.back();
    const Vec2 d = b - a;
    const double len = d.norm();
    if (!(len > 0))
        return true;
    for (std::size_t i = 0; i < s.hinge.size(); ++i) {
        const Vec2 p = s.corners[i][s.hinge[i][0]], q = s.corners[i][s.hinge[i][1]];
        // Signed distances of the hinge ends from the line a-b, and where the line meets it.
        const double sp = cross2(d, p - a) / len, sq = cross2(d, q - a) / len;
        if ((sp > tol && sq > tol) || (sp < -tol && sq < -tol))
            return false;
        const double u = (sp == sq) ? 0.5 : std::clamp(sp / (sp - sq), 0.0, 1.0);
        const double along = (p + u * (q - p) - a).dot(d) / len;
        if (along < -tol || along > len + tol)
            return false;
    }
    return true;
}

/// A hinge of the strip seen from the path: its end points on the left and on the right of the
/// walking direction (from face i into face i + 1), in the plane and as mesh vertices.
struct Portal {
    Vec2 left, right;
    std::uint32_t left_vertex = kNone, right_vertex = kNone;
};

inline std::vector<Portal> portals(const Mesh& m, const Strip& s) {
    std::vector<Portal> out(s.hinge.size());
    for (std::size_t i = 0; i < s.hinge.size(); ++i) {
        const int a = s.hinge[i][0], b = s.hinge[i][1];
        const Vec2 p = s.corners[i][a], q = s.corners[i][b];
        const Vec2 behind = s.corners[i][3 - a - b];
        const std::uint32_t vp = m.corner[3 * s.faces[i] + a], vq = m.corner[3 * s.faces[i] + b];
        // Walking away from `behind` across p-q: q is on the left when `behind` is on the left of
        // p -> q.
        if (cross2(q - p, behind - p) > 0)
            out[i] = {q, p, vq, vp};
        else
            out[i] = {p, q, vp, vq};
    }
    return out;
}

/// A turning point of the shortest path in the strip: the start, a strip vertex, or the goal.
struct Apex {
    Vec2 xy;
    std::uint32_t vertex = kNone;  ///< mesh vertex (kNone for the start and the goal)
    std::size_t portal = 0;        ///< 0 start; i + 1 at portal i; portals + 1 the goal
};

/// Shortest path from `start` to `goal` through the portals in order (the funnel algorithm): the
/// funnel is the apex and the last left and right portal points seen from it; a new portal point
/// that narrows one side is taken, one that crosses the other side makes that side's point the
/// next apex, and the scan restarts after the portal where that point was taken.
inline std::vector<Apex> funnel(const std::vector<Portal>& ports, const Vec2& start,
                                const Vec2& goal) {
    const std::size_t np = ports.size();
    auto left_of = [&](std::size_t i) { return i < np ? ports[i].left : goal; };
    auto right_of = [&](std::size_t i) { return i < np ? ports[i].right : goal; };
    std::vector<Apex> out{{start, kNone, 0}};
    Vec2 apex = start, left = left_of(0), right = right_of(0);
    std::size_t left_i = 0, right_i = 0;  // portals where left and right were taken
    auto restart = [&](const Vec2& p, std::size_t i, std::uint32_t v) {
        out.push_back({p, v, i + 1});
        apex = p;
        left_i = right_i = i;
        left = right = p;
    };
    for (std::size_t i = 1; i <= np; ++i) {
        const Vec2 nl = left_of(i), nr = right_of(i);
        // Right side: nr narrows the funnel when it is not right of apex -> right.
        if (cross2(right - apex, nr - apex) >= 0) {
            if (apex == right || cross2(left - apex, nr - apex) <= 0) {
                right = nr;
                right_i = i;
            } else {  // crosses the left side: the left point is the next turning point
                restart(left, left_i, left_i < np ? ports[left_i].left_vertex : kNone);
                i = left_i;
                continue;
            }
        }
        if (cross2(left - apex, nl - apex) <= 0) {
            if (apex == left || cross2(right - apex, nl - apex) >= 0) {
                left = nl;
                left_i = i;
            } else {
                restart(right, right_i, right_i < np ? ports[right_i].right_vertex : kNone);
                i = right_i;
                continue;
            }
        }
    }
    out.push_back({goal, kNone, np + 1});
    return out;
}

/// Total angle of the faces around vertex v, and whether v is on the border.
inline double vertex_angle(const Mesh& m, std::uint32_t v, bool& border) {
    double sum = 0;
    border = false;
    for (std::uint32_t k = m.vf_start[v]; k < m.vf_start[v + 1]; ++k) {
        const std::uint32_t f = m.vf[k];
        const int c = corner_of(m, f, v);
        const Vec3 a = m.xyz[m.corner[3 * f + (c + 1) % 3]] - m.xyz[v];
        const Vec3 b = m.xyz[m.corner[3 * f + (c + 2) % 3]] - m.xyz[v];
        sum += std::atan2(a.cross(b).norm(), a.dot(b));
        if (m.across[3 * f + c] == kNone || m.across[3 * f + (c + 2) % 3] == kNone)
            border = true;
    }
    return sum;
}

/// Result of straighten().
struct Straightened {
    std::vector<Vec3> points;  ///< start, hinge crossings (repeats merged), goal
    double length = 0;
    std::size_t flips = 0;       ///< vertices the strip was moved across
    std::size_t bends = 0;       ///< turning points left at vertices (saddles or borders)
    std::size_t unresolved = 0;  ///< turning points that could shorten but were not flipped
    std::size_t faces = 0;       ///< faces of the final strip
};

/// The shortest path through the strip's faces (funnel), then made locally shortest on the mesh:
/// where it turns at a vertex v with less than pi on the other side (total angle at v minus pi
/// minus the turn), the faces of the strip around v are replaced by those on the other side of v
/// and the funnel runs again. Each such move shortens the path strictly, so this ends; the result
/// is a polyhedral geodesic (straight in every unfolding, bending only at saddle or border vertices
/// by at most their excess angle). This is the "locally exact shortest path" idea of S.-Q. Xin,
/// G.-J. Wang, Computer-Aided Design 39(12), 2007, on the strip the flow found.
inline Straightened straighten(const Mesh& m, Strip strip, const Vec3& start3, const Vec3& goal3,
                               std::size_t max_flips) {
    Straightened out;
    const double pi = 3.14159265358979323846;
    std::vector<Apex> apexes;
    std::vector<Portal> ports;
    for (;;) {
        ports = portals(m, strip);
        apexes = funnel(ports, strip.path.front(), strip.path.back());
        if (out.flips >= max_flips)
            break;
        // The first turning point that can be shortened, with its run of strip faces around it.
        std::size_t a = 0, b = 0;
        std::uint32_t v = kNone;
        int other_dir = 0;
        for (std::size_t j = 1; j + 1 < apexes.size() && v == kNone; ++j) {
            const Vec2 d1 = apexes[j].xy - apexes[j - 1].xy, d2 = apexes[j + 1].xy - apexes[j].xy;
            const double turn = std::abs(std::atan2(cross2(d1, d2), d1.dot(d2)));
            bool border = false;
            const double total = vertex_angle(m, apexes[j].vertex, border);
            if (border || total - pi - turn >= pi - 1e-12)
                continue;
            const std::uint32_t w = apexes[j].vertex;
            const std::size_t pi_ = apexes[j].portal - 1;  // faces pi_ and pi_ + 1 hold w
            std::size_t lo = pi_, hi = pi_ + 1;
            while (lo > 0 && corner_of(m, strip.faces[lo - 1], w) >= 0)
                --lo;
            while (hi + 1 < strip.faces.size() && corner_of(m, strip.faces[hi + 1], w) >= 0)
                ++hi;
            // The run must turn around w one way, face after face.
            const int k = corner_of(m, strip.faces[lo], w);
            const int dir = m.across[3 * strip.faces[lo] + k] == strip.faces[lo + 1] ? 0 : 1;
            const auto run = turn_walk(m, strip.faces[lo], strip.faces[hi], w, dir);
            bool monotone = run.size() == hi - lo;
            for (std::size_t r = 0; monotone && r < run.size(); ++r)
                monotone = run[r] == strip.faces[lo + 1 + r];
            if (!monotone || turn_walk(m, strip.faces[lo], strip.faces[hi], w, 1 - dir).empty()) {
                ++out.unresolved;
                continue;
            }
            a = lo;
            b = hi;
            v = w;
            other_dir = 1 - dir;
        }
        if (v == kNone)
            break;
        FaceSequence seq;
        seq.faces.assign(strip.faces.begin(),
                         strip.faces.begin() + static_cast<std::ptrdiff_t>(a) + 1);
        const auto other = turn_walk(m, strip.faces[a], strip.faces[b], v, other_dir);
        seq.faces.insert(seq.faces.end(), other.begin(), other.end());
        seq.faces.insert(seq.faces.end(), strip.faces.begin() + static_cast<std::ptrdiff_t>(b) + 1,
                         strip.faces.end());
        seq.points = {start3, goal3};
        seq.point_at = {0, static_cast<std::uint32_t>(seq.faces.size() - 1)};
        strip = unfold_strip(m, seq);
        ++out.flips;
    }
    // Back to the mesh: each portal is crossed where the segment between the turning points
    // around it meets it (at the vertex itself for portals around a turning point).
    out.points.push_back(start3);
    std::size_t j = 0;
    for (std::size_t i = 0; i < ports.size(); ++i) {
        while (j + 1 < apexes.size() && apexes[j + 1].portal <= i + 1)
            ++j;
        Vec3 x;
        if (apexes[j].portal == i + 1) {
            x = m.xyz[apexes[j].vertex];
        } else {
            const Vec2 p = apexes[j].xy, q = apexes[j + 1].xy;
            const Portal& po = ports[i];
            const double den = cross2(q - p, po.right - po.left);
            const double t =
                den != 0 ? std::clamp(cross2(q - p, p - po.left) / den, 0.0, 1.0) : 0.5;
            x = m.xyz[po.left_vertex] + t * (m.xyz[po.right_vertex] - m.xyz[po.left_vertex]);
        }
        if ((x - out.points.back()).norm() > 0)
            out.points.push_back(x);
    }
    if ((goal3 - out.points.back()).norm() > 0 || out.points.size() == 1)
        out.points.push_back(goal3);
    else
        out.points.back() = goal3;
    for (std::size_t k = 1; k < out.points.size(); ++k)
        out.length += (out.points[k] - out.points[k - 1]).norm();
    out.bends = apexes.size() - 2;
    out.faces = strip.faces.size();
    return out;
}

/// The unfolding of an on-mesh polyline as the public result. `bad_point` is set to the index of
/// the first point (in `points`, repeats merged) that is not on a face next to the previous one,
/// the result is then empty; kNone if fine.
inline UnfoldedPath unfold_polyline(const Mesh& m, const std::vector<Vec3>& points,
                                    const UnfoldOptions& o, std::uint32_t start_face,
                                    std::size_t& bad_point, Strip* strip = nullptr) {
    UnfoldedPath out;
    const double h = m.mean_edge > 0 ? m.mean_edge : 1.0;
    const double tol = o.tolerance * h;
    const FaceSequence seq = face_sequence(m, points, tol, start_face);
    bad_point = seq.bad_point;
    if (bad_point != kNone || seq.points.size() < 2)
        return out;
    Strip s = unfold_strip(m, seq);
    out.faces.resize(s.faces.size());
    for (std::size_t i = 0; i < s.faces.size(); ++i) {
        auto& f = out.faces[i];
        f.face = s.faces[i];
        for (int k = 0; k < 3; ++k) {
            f.vertices[k] = m.corner[3 * s.faces[i] + k];
            f.corners[k] = {s.corners[i][k].x(), s.corners[i][k].y()};
        }
    }
    for (std::size_t k = 0; k < s.path.size(); ++k) {
        out.points.push_back({s.path[k].x(), s.path[k].y()});
        out.point_face.push_back(s.point_at[k]);
        if (k > 0) {
            out.traced_length += (seq.points[k] - seq.points[k - 1]).norm();
            out.unfolded_length += (s.path[k] - s.path[k - 1]).norm();
        }
        if (k > 0 && k + 1 < s.path.size()) {
            const std::uint32_t f = s.faces[s.point_at[k]];
            for (int c = 0; c < 3; ++c)
                if ((m.xyz[m.corner[3 * f + c]] - seq.points[k]).norm() <= tol) {
                    ++out.vertex_points;
                    break;
                }
        }
    }
    out.straight_length = (s.path.back() - s.path.front()).norm();
    out.straight_inside = straight_inside(s, tol);
    out.fan_faces = seq.fan_faces;
    if (strip)
        *strip = std::move(s);
    return out;
}

/// unfold_polyline with the user input checked: InvalidInput (naming `where`) for a bad
/// tolerance, a non-finite point, fewer than two distinct points or a point off the faces.
inline UnfoldedPath unfold_checked(const Mesh& m, const std::vector<Vec3>& pts,
                                   const UnfoldOptions& o, const char* where) {
    if (!std::isfinite(o.tolerance) || !(o.tolerance > 0))
        throw InvalidInput(std::string(where) + ": tolerance must be finite and > 0");
    for (std::size_t k = 0; k < pts.size(); ++k)
        if (!pts[k].allFinite())
            throw InvalidInput(std::string(where) + ": path point #" + std::to_string(k) +
                               " is not finite");
    std::size_t bad = kNone;
    UnfoldedPath out = unfold_polyline(m, pts, o, kNone, bad);
    if (bad != kNone) {
        std::ostringstream msg;
        msg << where << ": path point #" << bad << " (after merging repeats) is not on a face next "
            << "to the previous point's face; the path must run on the faces";
        throw InvalidInput(msg.str());
    }
    if (out.points.size() < 2)
        throw InvalidInput(std::string(where) + ": the path needs two distinct points");
    return out;
}

}  // namespace tapeline::geodesic::internal::unfold
