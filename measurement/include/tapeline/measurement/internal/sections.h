// The body as a plain indexed triangle mesh in the canonical frame, its plane sections and the
// tape around each section (convex hull in the plane, CGAL::convex_hull_2).
//
// Plane sections are cut here rather than with CGAL::Polygon_mesh_slicer because the landmark
// search cuts many hundreds of planes: this cut is one pass over precomputed edge/face adjacency
// (no AABB tree, no per-call graph), and deciding each vertex's side once (a vertex on the plane
// counts as above) makes every section of a closed manifold a set of closed loops, even when the
// plane passes exactly through vertices or edges. The tests check it against the slicer.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/phong.h>
#include <tapeline/core/vec3.h>
#include <tapeline/measurement/body_types.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numeric>
#include <string>
#include <vector>

namespace tapeline::measurement::internal {

using Vec2 = std::array<double, 2>;

using vec3::add;
using vec3::cross;
using vec3::dot;
using vec3::norm;
using vec3::normalized;
using vec3::sub;
inline Vec3 mul(const Vec3& a, double s) {
    return vec3::scale(a, s);
}
inline double dist(const Vec3& a, const Vec3& b) {
    return norm(sub(a, b));
}
inline double dist2d(const Vec2& a, const Vec2& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1]);
}

/// Sorts the edges into spatially coherent chunks with bounding boxes (BodyMesh::chunk_edges).
inline void build_edge_chunks(BodyMesh& m) {
    Vec3 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
            std::numeric_limits<double>::infinity()};
    Vec3 hi{-lo[0], -lo[1], -lo[2]};
    for (const auto& p : m.points) {
        for (int k = 0; k < 3; ++k) {
            lo[k] = std::min(lo[k], p[k]);
            hi[k] = std::max(hi[k], p[k]);
        }
    }
    auto spread = [](std::uint64_t v) {  // 21 bits -> every third bit
        v &= 0x1fffff;
        v = (v | v << 32) & 0x1f00000000ffffULL;
        v = (v | v << 16) & 0x1f0000ff0000ffULL;
        v = (v | v << 8) & 0x100f00f00f00f00fULL;
        v = (v | v << 4) & 0x10c30c30c30c30c3ULL;
        v = (v | v << 2) & 0x1249249249249249ULL;
        return v;
    };
    std::vector<std::pair<std::uint64_t, std::uint32_t>> keyed(m.edges.size());
    for (std::uint32_t e = 0; e < m.edges.size(); ++e) {
        const Vec3& a = m.points[m.edges[e][0]];
        const Vec3& b = m.points[m.edges[e][1]];
        std::uint64_t code = 0;
        for (int k = 0; k < 3; ++k) {
            const double t = hi[k] > lo[k] ? (0.5 * (a[k] + b[k]) - lo[k]) / (hi[k] - lo[k]) : 0;
            code |= spread(static_cast<std::uint64_t>(std::clamp(t, 0.0, 1.0) * 2097151.0)) << k;
        }
        keyed[e] = {code, e};
    }
    std::sort(keyed.begin(), keyed.end());
    m.chunk_edges.resize(keyed.size());
    m.chunk_ends.resize(keyed.size());
    m.chunk_box.clear();
    for (std::size_t i = 0; i < keyed.size(); ++i) {
        m.chunk_edges[i] = keyed[i].second;
        m.chunk_ends[i] = {m.points[m.edges[keyed[i].second][0]],
                           m.points[m.edges[keyed[i].second][1]]};
        if (i % BodyMesh::kChunk == 0) {
            m.chunk_box.push_back(
                {m.points[m.edges[keyed[i].second][0]], m.points[m.edges[keyed[i].second][0]]});
        }
        auto& box = m.chunk_box.back();
        for (std::uint32_t v : m.edges[keyed[i].second]) {
            for (int k = 0; k < 3; ++k) {
                box[0][k] = std::min(box[0][k], m.points[v][k]);
                box[1][k] = std::max(box[1][k], m.points[v][k]);
            }
        }
    }
}

/// Fills edges, edge_faces, face_edges and components. Rejects (TopologyError, naming the mesh
/// and the first offending edge) edges with more than two faces, then boundary edges (make_body
/// fills the holes first, holes.h).
inline void build_adjacency(BodyMesh& m) {
    const std::size_t nf = m.triangles.size();
    struct HalfEdge {
        std::uint64_t key;
        std::uint32_t face, corner;
    };
    std::vector<HalfEdge> hes;
    hes.reserve(3 * nf);
    for (std::uint32_t f = 0; f < nf; ++f) {
        for (std::uint32_t k = 0; k < 3; ++k) {
            std::uint64_t a = m.triangles[f][k], b = m.triangles[f][(k + 1) % 3];
            if (a > b) {
                std::swap(a, b);
            }
            hes.push_back({(a << 32) | b, f, k});
        }
    }
    std::sort(hes.begin(), hes.end(), [](const HalfEdge& x, const HalfEdge& y) {
        return x.key < y.key || (x.key == y.key && x.face < y.face);
    });
    m.edges.clear();
    m.edge_faces.clear();
    m.face_edges.assign(nf, {0, 0, 0});
    std::size_t boundary = 0, non_manifold = 0;
    std::uint64_t first_boundary = 0, first_non_manifold = 0;
    for (std::size_t i = 0; i < hes.size();) {
        std::size_t j = i;
        while (j < hes.size() && hes[j].key == hes[i].key) {
            ++j;
        }
        const std::size_t count = j - i;
        if (count == 1 && boundary++ == 0) {
            first_boundary = hes[i].key;
        }
        if (count > 2 && non_manifold++ == 0) {
            first_non_manifold = hes[i].key;
        }
        const auto e = static_cast<std::uint32_t>(m.edges.size());
        m.edges.push_back({static_cast<std::uint32_t>(hes[i].key >> 32),
                           static_cast<std::uint32_t>(hes[i].key & 0xffffffffu)});
        m.edge_faces.push_back({hes[i].face, hes[count > 1 ? i + 1 : i].face});
        for (std::size_t k = i; k < j; ++k) {
            m.face_edges[hes[k].face][hes[k].corner] = e;
        }
        i = j;
    }
    auto edge_name = [](std::uint64_t key) {
        return "edge between vertices " + std::to_string(key >> 32) + " and " +
               std::to_string(key & 0xffffffffu);
    };
    if (non_manifold > 0) {
        throw TopologyError(m.name + ": non-manifold " + edge_name(first_non_manifold) + " (" +
                            std::to_string(non_manifold) + " edges with more than two faces)");
    }
    if (boundary > 0) {
        throw TopologyError(m.name + ": the body mesh is not closed: " + edge_name(first_boundary) +
                            " has one face (" + std::to_string(boundary) +
                            " boundary edges); measuring needs a closed surface");
    }
    // Components: union-find over faces sharing an edge.
    std::vector<std::uint32_t> parent(nf);
    std::iota(parent.begin(), parent.end(), 0u);
    auto root = [&parent](std::uint32_t x) {
        while (parent[x] != x) {
            x = parent[x] = parent[parent[x]];
        }
        return x;
    };
    for (const auto& ef : m.edge_faces) {
        parent[root(ef[0])] = root(ef[1]);
    }
    m.components = 0;
    for (std::uint32_t f = 0; f < nf; ++f) {
        m.components += root(f) == f ? 1 : 0;
    }
    m.min_y = std::numeric_limits<double>::infinity();
    m.max_y = -m.min_y;
    for (const auto& p : m.points) {
        m.min_y = std::min(m.min_y, p[1]);
        m.max_y = std::max(m.max_y, p[1]);
    }
    build_edge_chunks(m);
}

/// A plane with an in-plane orthonormal frame (u, w); 2D coordinates are along u and w.
struct Plane {
    Vec3 origin{0, 0, 0}, normal{0, 1, 0}, u{1, 0, 0}, w{0, 0, 1};

    /// `u_hint` is projected into the plane (a fallback is used when it is parallel to normal).
    static Plane make(const Vec3& origin, const Vec3& normal, const Vec3& u_hint) {
        Plane p;
        p.origin = origin;
        p.normal = normalized(normal);
        Vec3 u = sub(u_hint, mul(p.normal, dot(u_hint, p.normal)));
        if (norm(u) < 1e-9) {
            const Vec3 alt = std::abs(p.normal[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
            u = sub(alt, mul(p.normal, dot(alt, p.normal)));
        }
        p.u = normalized(u);
        p.w = cross(p.normal, p.u);
        return p;
    }
    /// Horizontal plane at height y: u = x (left), w = -z (back), so that u × w = y.
    static Plane horizontal(double y) { return make({0, y, 0}, {0, 1, 0}, {1, 0, 0}); }

    Vec2 to2(const Vec3& p) const {
        const Vec3 d = sub(p, origin);
        return {dot(d, u), dot(d, w)};
    }
    Vec3 to3(const Vec2& q) const { return add(origin, add(mul(u, q[0]), mul(w, q[1]))); }
    double side(const Vec3& p) const { return dot(sub(p, origin), normal); }
};

/// One closed polyline of a plane section, in 3D and in the plane's 2D frame.
struct Loop {
    std::vector<Vec3> points;
    std::vector<Vec2> uv;
    /// Per point: the mesh edge it lies on and where (points[i] = end 0 + params[i] (end 1 −
    /// end 0)); the face the loop crosses from point i to point i + 1 (cyclically).
    std::vector<std::uint32_t> edges, faces;
    std::vector<double> params;
    Vec2 lo{0, 0}, hi{0, 0};      // 2D bounding box
    bool crosses_filled = false;  // passes through a face that fills a hole (BodyMesh::filled)
};

/// Scratch buffers reused between cuts of the same mesh.
struct CutWorkspace {
    std::vector<std::int32_t> crossing;  // per edge: index of its crossing point, or -1
    std::vector<std::uint32_t> crossing_edges;
    std::vector<Vec3> crossing_points;
    std::vector<double> crossing_params;
    std::vector<char> visited;
    std::size_t cuts = 0;
};

/// The section of the mesh by the plane, as closed loops (see the top of this file). Only the
/// edge chunks whose bounding box the plane meets are visited (a box strictly on one side holds
/// no crossing edge), so a cut costs the chunks plus the edges near the plane, not the mesh.
inline std::vector<Loop> cut(const BodyMesh& m, const Plane& plane, CutWorkspace& ws) {
    ++ws.cuts;
    const std::size_t ne = m.edges.size();
    if (ws.crossing.size() != ne) {
        ws.crossing.assign(ne, -1);
    }
    for (std::uint32_t e : ws.crossing_edges) {  // reset what the previous cut marked
        ws.crossing[e] = -1;
    }
    ws.crossing_edges.clear();
    ws.crossing_points.clear();
    ws.crossing_params.clear();
    const Vec3 an{std::abs(plane.normal[0]), std::abs(plane.normal[1]), std::abs(plane.normal[2])};
    for (std::size_t c = 0; c < m.chunk_box.size(); ++c) {
        const auto& box = m.chunk_box[c];
        const Vec3 centre = mul(add(box[0], box[1]), 0.5), half = mul(sub(box[1], box[0]), 0.5);
        const double d = plane.side(centre), r = dot(an, half);
        const double slack = 1e-9 * (1 + std::abs(d) + r);
        if (d - r > slack || d + r < -slack) {
            continue;
        }
        const std::size_t end = std::min(m.chunk_edges.size(), (c + 1) * BodyMesh::kChunk);
        for (std::size_t i = c * BodyMesh::kChunk; i < end; ++i) {
            // The same vertex always gets the same side: same coordinates, same arithmetic.
            const Vec3& a = m.chunk_ends[i][0];
            const Vec3& b = m.chunk_ends[i][1];
            const double sa = plane.side(a), sb = plane.side(b);
            if ((sa >= 0) != (sb >= 0)) {
                const std::uint32_t e = m.chunk_edges[i];
                const double t = sa / (sa - sb);
                ws.crossing[e] = static_cast<std::int32_t>(ws.crossing_points.size());
                ws.crossing_points.push_back(add(a, mul(sub(b, a), t)));
                ws.crossing_params.push_back(t);
                ws.crossing_edges.push_back(e);
            }
        }
    }
    ws.visited.assign(ws.crossing_points.size(), 0);
    std::vector<Loop> loops;
    for (std::uint32_t start : ws.crossing_edges) {
        if (ws.visited[static_cast<std::size_t>(ws.crossing[start])]) {
            continue;
        }
        Loop loop;
        std::uint32_t e = start;
        std::uint32_t f = m.edge_faces[e][0];
        do {
            ws.visited[static_cast<std::size_t>(ws.crossing[e])] = 1;
            loop.crosses_filled = loop.crosses_filled || m.is_filled(f);
            const auto c = static_cast<std::size_t>(ws.crossing[e]);
            loop.points.push_back(ws.crossing_points[c]);
            loop.params.push_back(ws.crossing_params[c]);
            loop.edges.push_back(e);
            loop.faces.push_back(f);
            // The other crossing edge of face f (a face is crossed by 0 or 2 edges).
            std::uint32_t next = e;
            for (std::uint32_t fe : m.face_edges[f]) {
                if (fe != e && ws.crossing[fe] >= 0) {
                    next = fe;
                    break;
                }
            }
            if (next == e) {
                break;  // cannot happen on a closed manifold; guards against a bad adjacency
            }
            e = next;
            f = m.edge_faces[e][0] == f ? m.edge_faces[e][1] : m.edge_faces[e][0];
        } while (e != start && loop.points.size() <= ws.crossing_points.size());
        if (loop.points.size() < 3 || loop.points.size() != loop.faces.size()) {
            continue;
        }
        loop.uv.reserve(loop.points.size());
        loop.lo = {std::numeric_limits<double>::infinity(),
                   std::numeric_limits<double>::infinity()};
        loop.hi = {-loop.lo[0], -loop.lo[1]};
        for (const auto& p : loop.points) {
            const Vec2 q = plane.to2(p);
            loop.uv.push_back(q);
            for (int k = 0; k < 2; ++k) {
                loop.lo[k] = std::min(loop.lo[k], q[k]);
                loop.hi[k] = std::max(loop.hi[k], q[k]);
            }
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

/// Even-odd point-in-polygon test.
inline bool inside(const std::vector<Vec2>& poly, const Vec2& p) {
    bool in = false;
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        const Vec2& a = poly[i];
        const Vec2& b = poly[j];
        if ((a[1] > p[1]) != (b[1] > p[1]) &&
            p[0] < (b[0] - a[0]) * (p[1] - a[1]) / (b[1] - a[1]) + a[0]) {
            in = !in;
        }
    }
    return in;
}

inline double segment_distance(const Vec2& p, const Vec2& a, const Vec2& b) {
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double l2 = dx * dx + dy * dy;
    double t = l2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / l2 : 0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(p[0] - a[0] - t * dx, p[1] - a[1] - t * dy);
}

/// Distance from p to a closed polygon's boundary.
inline double boundary_distance(const std::vector<Vec2>& poly, const Vec2& p) {
    double d = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0, j = poly.size() - 1; i < poly.size(); j = i++) {
        d = std::min(d, segment_distance(p, poly[j], poly[i]));
    }
    return d;
}

/// One body part in a plane: the loops that are nested in or overlap one another (a body given
/// as a union of overlapping closed parts has such loops), with the tape around them.
struct Section {
    std::vector<std::size_t> loops;  // indices into the cut's loops
    std::vector<Vec2> hull;          // convex hull, counter-clockwise in (u, w)
    double perimeter = 0;            // tape length: the hull's perimeter
    double area = 0;                 // hull area
    Vec2 centroid{0, 0};             // hull centroid
    Vec2 lo{0, 0}, hi{0, 0};         // bounding box
    bool crosses_filled = false;     // one of its loops crosses a filled hole
};

/// A plane's loops grouped into sections, each with its tape.
struct PlaneSection {
    Plane plane;
    std::vector<Loop> loops;
    std::vector<Section> sections;

    /// Index of the section whose region (any of its loops) contains p, else of the section
    /// whose hull is nearest to p; -1 when there is none.
    int locate(const Vec2& p, double* distance = nullptr) const {
        int best = -1;
        double best_d = std::numeric_limits<double>::infinity();
        for (std::size_t s = 0; s < sections.size(); ++s) {
            const Section& sec = sections[s];
            bool in = false;
            if (p[0] >= sec.lo[0] && p[0] <= sec.hi[0] && p[1] >= sec.lo[1] && p[1] <= sec.hi[1]) {
                for (std::size_t l : sec.loops) {
                    if (inside(loops[l].uv, p)) {
                        in = true;
                        break;
                    }
                }
            }
            const double d = in ? 0.0 : boundary_distance(sec.hull, p);
            if (d < best_d) {
                best_d = d;
                best = static_cast<int>(s);
            }
        }
        if (distance) {
            *distance = best_d;
        }
        return best;
    }
    /// 3D points of a section's tape (its hull).
    std::vector<Vec3> tape(std::size_t s) const {
        std::vector<Vec3> out;
        for (const auto& q : sections[s].hull) {
            out.push_back(plane.to3(q));
        }
        return out;
    }
};

/// Convex hull (CGAL::convex_hull_2, exact predicates), its perimeter, area and centroid.
inline void compute_tape(const std::vector<Vec2>& points, Section& s) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<K::Point_2> in, out;
    in.reserve(points.size());
    for (const auto& p : points) {
        in.emplace_back(p[0], p[1]);
    }
    CGAL::convex_hull_2(in.begin(), in.end(), std::back_inserter(out));
    s.hull.clear();
    for (const auto& p : out) {
        s.hull.push_back({p.x(), p.y()});
    }
    s.perimeter = 0;
    s.area = 0;
    double cx = 0, cy = 0;
    for (std::size_t i = 0, j = s.hull.size() - 1; i < s.hull.size(); j = i++) {
        const Vec2& a = s.hull[j];
        const Vec2& b = s.hull[i];
        s.perimeter += dist2d(a, b);
        const double c = a[0] * b[1] - b[0] * a[1];
        s.area += c;
        cx += (a[0] + b[0]) * c;
        cy += (a[1] + b[1]) * c;
    }
    s.area *= 0.5;
    if (std::abs(s.area) > 1e-12) {
        s.centroid = {cx / (6 * s.area), cy / (6 * s.area)};
    } else {
        s.centroid = {0, 0};
        for (const auto& p : s.hull) {
            s.centroid[0] += p[0] / static_cast<double>(s.hull.size());
            s.centroid[1] += p[1] / static_cast<double>(s.hull.size());
        }
    }
    s.area = std::abs(s.area);
}

/// Points of section `s`'s loops on the smooth surface the mesh stands for (Phong tessellation,
/// shape factor 1/2, over the vertex normals `normals`: tapeline/core/phong.h), in the plane's
/// frame: every crossing point and `per_segment` − 1 points between it and the next, each the
/// Phong image of its flat point moved across the face (along the barycentric gradient of the
/// plane's side, two Newton steps) until it lies in the plane: a point of the smooth surface's
/// section, where the lift alone would leave the plane when the normals are not in it (a tilted
/// cut). The flat section's chords cut inside a convex body by their sagitta (a 30 mm tube of 10
/// vertices around: 1.6 % of its girth); these points lie on the curve the vertices sample
/// (0.3 % short there).
inline std::vector<Vec2> smooth_points(const BodyMesh& m, const std::vector<Vec3>& normals,
                                       const PlaneSection& ps, const Section& s, int per_segment) {
    std::vector<Vec2> out;
    for (std::size_t l : s.loops) {
        const Loop& loop = ps.loops[l];
        const std::size_t n = loop.points.size();
        for (std::size_t i = 0; i < n; ++i) {
            const auto& tri = m.triangles[loop.faces[i]];
            // Barycentric coordinates in the face of this crossing and the next.
            auto bary = [&](std::size_t k, std::array<double, 3>& b) {
                const auto& e = m.edges[loop.edges[k]];
                b = {0, 0, 0};
                double sum = 0;
                for (std::size_t c = 0; c < 3; ++c) {
                    if (tri[c] == e[0]) {
                        b[c] += 1 - loop.params[k];
                        sum += 1 - loop.params[k];
                    }
                    if (tri[c] == e[1]) {
                        b[c] += loop.params[k];
                        sum += loop.params[k];
                    }
                }
                return std::abs(sum - 1) < 1e-9;  // the edge is one of the face's
            };
            std::array<double, 3> b0, b1;
            if (!bary(i, b0) || !bary((i + 1) % n, b1)) {
                out.push_back(loop.uv[i]);  // cannot happen on the cut's own adjacency
                continue;
            }
            const std::array<Vec3, 3> x{m.points[tri[0]], m.points[tri[1]], m.points[tri[2]]};
            const std::array<Vec3, 3> nv{normals[tri[0]], normals[tri[1]], normals[tri[2]]};
            // The plane's side is linear over the flat face: Σ b_i s_i. Moving b along s − s̄
            // (which keeps Σ b_i = 1) changes it at the rate g.
            const std::array<double, 3> sc{ps.plane.side(x[0]), ps.plane.side(x[1]),
                                           ps.plane.side(x[2])};
            const double mean = (sc[0] + sc[1] + sc[2]) / 3;
            const std::array<double, 3> grad{sc[0] - mean, sc[1] - mean, sc[2] - mean};
            const double g = grad[0] * sc[0] + grad[1] * sc[1] + grad[2] * sc[2];
            for (int j = 0; j < per_segment; ++j) {
                const double a = static_cast<double>(j) / per_segment;
                std::array<double, 3> b{(1 - a) * b0[0] + a * b1[0], (1 - a) * b0[1] + a * b1[1],
                                        (1 - a) * b0[2] + a * b1[2]};
                Vec3 p = phong_point(x, nv, b);
                for (int k = 0; k < 2 && g > 0; ++k) {
                    const double step = -ps.plane.side(p) / g;
                    for (std::size_t c = 0; c < 3; ++c) {
                        b[c] += step * grad[c];
                    }
                    p = phong_point(x, nv, b);
                }
                out.push_back(ps.plane.to2(p));
            }
        }
    }
    return out;
}

/// Whether two loops overlap: one has a vertex inside the other (nested or crossing).
inline bool overlap(const Loop& a, const Loop& b) {
    if (a.hi[0] < b.lo[0] || b.hi[0] < a.lo[0] || a.hi[1] < b.lo[1] || b.hi[1] < a.lo[1]) {
        return false;
    }
    for (const auto& p : a.uv) {
        if (inside(b.uv, p)) {
            return true;
        }
    }
    for (const auto& p : b.uv) {
        if (inside(a.uv, p)) {
            return true;
        }
    }
    return false;
}

/// Cuts the mesh and groups the loops into sections.
inline PlaneSection section(const BodyMesh& m, const Plane& plane, CutWorkspace& ws) {
    PlaneSection ps;
    ps.plane = plane;
    ps.loops = cut(m, plane, ws);
    const std::size_t n = ps.loops.size();
    std::vector<std::size_t> group(n);
    std::iota(group.begin(), group.end(), std::size_t{0});
    auto root = [&group](std::size_t x) {
        while (group[x] != x) {
            x = group[x] = group[group[x]];
        }
        return x;
    };
    for (std::size_t i = 0; i < n; ++i) {
        for (std::size_t j = i + 1; j < n; ++j) {
            if (root(i) != root(j) && overlap(ps.loops[i], ps.loops[j])) {
                group[root(i)] = root(j);
            }
        }
    }
    for (std::size_t i = 0; i < n; ++i) {
        if (root(i) != i) {
            continue;
        }
        Section s;
        std::vector<Vec2> pts;
        for (std::size_t j = 0; j < n; ++j) {
            if (root(j) == i) {
                s.loops.push_back(j);
                s.crosses_filled = s.crosses_filled || ps.loops[j].crosses_filled;
                pts.insert(pts.end(), ps.loops[j].uv.begin(), ps.loops[j].uv.end());
            }
        }
        compute_tape(pts, s);
        s.lo = {std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
        s.hi = {-s.lo[0], -s.lo[1]};
        for (const auto& q : s.hull) {
            for (int k = 0; k < 2; ++k) {
                s.lo[k] = std::min(s.lo[k], q[k]);
                s.hi[k] = std::max(s.hi[k], q[k]);
            }
        }
        ps.sections.push_back(std::move(s));
    }
    return ps;
}

}  // namespace tapeline::measurement::internal
