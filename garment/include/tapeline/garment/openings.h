// The openings of a garment (hem, neckline, sleeve ends, ...): the boundary loops of its welded
// mesh, in order, and what a tailor reads off each: its height, its length, its width and depth,
// the perimeter of its convex hull and the folds that cut into that hull.
//
// Folds: the loop is projected on its own plane (Newell's normal, so a sleeve end is seen along
// the sleeve and a hem from above); every vertex's depth is its distance inside the convex hull
// of the projection (CGAL::convex_hull_2). A hem that hangs smooth hugs its hull (depth 0 all
// round, whatever the body's section, as long as that is convex); each fold that turns the cloth
// inwards and out again is a peak of the depth. Folds are the peaks that rise and fall by at least
// `fold_depth_mm` (closed_peaks(), the same count as the Cusick test's nodes). A section of the
// body that is itself concave (the small of the back) would read as a fold: the count is of the
// loop's shape, not of its cause.
#pragma once

#include <tapeline/core/vec3.h>
#include <tapeline/garment/garment_types.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/convex_hull_2.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>
#include <utility>
#include <vector>

namespace tapeline::garment {

namespace internal {

/// Peaks of a closed sequence that rise and fall by at least `hysteresis` on both sides, counted
/// from its lowest value: a fold of a hem, a node of a Cusick shadow. 0 for a sequence that
/// varies less.
inline int closed_peaks(const std::vector<double>& v, double hysteresis) {
    if (v.empty()) {
        return 0;
    }
    const std::size_t n = v.size();
    const std::size_t kmin = std::size_t(std::min_element(v.begin(), v.end()) - v.begin());
    double low = v[kmin], high = low;
    bool rising = true;
    int peaks = 0;
    for (std::size_t k = 1; k <= n; ++k) {
        const double x = v[(kmin + k) % n];
        if (rising) {
            high = std::max(high, x);
            if (high - x >= hysteresis && high - low >= hysteresis) {
                ++peaks;
                rising = false;
                low = x;
            }
        } else {
            low = std::min(low, x);
            if (x - low >= hysteresis) {
                rising = true;
                high = x;
            }
        }
    }
    return peaks;
}

}  // namespace internal

/// The boundary loops of a triangle mesh, each as its vertices in order (edges used by one
/// triangle, walked around). A vertex where two loops touch is walked once per loop. Loops come
/// in the order of their smallest edge.
inline std::vector<std::vector<std::uint32_t>> boundary_loop_vertices(
    const std::vector<Tri>& tris) {
    std::map<std::pair<std::uint32_t, std::uint32_t>, int> count;
    for (const Tri& t : tris) {
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t a = t[k], b = t[(k + 1) % 3];
            ++count[{std::min(a, b), std::max(a, b)}];
        }
    }
    // Boundary edges as a multimap vertex → neighbour; each edge used once per loop.
    std::multimap<std::uint32_t, std::uint32_t> next;
    for (const auto& [e, c] : count) {
        if (c == 1) {
            next.emplace(e.first, e.second);
            next.emplace(e.second, e.first);
        }
    }
    const auto take = [&](std::uint32_t a, std::uint32_t b) {
        for (auto [it, end] = next.equal_range(a); it != end; ++it) {
            if (it->second == b) {
                next.erase(it);
                break;
            }
        }
    };
    std::vector<std::vector<std::uint32_t>> loops;
    while (!next.empty()) {
        const std::uint32_t start = next.begin()->first;
        std::vector<std::uint32_t> loop{start};
        std::uint32_t prev = start, cur = next.begin()->second;
        take(start, cur);
        take(cur, start);
        while (cur != start) {
            loop.push_back(cur);
            const auto it = next.find(cur);
            if (it == next.end()) {
                break;  // an open chain (a non-manifold boundary): keep what was walked
            }
            prev = cur;
            cur = it->second;
            take(prev, cur);
            take(cur, prev);
        }
        loops.push_back(std::move(loop));
    }
    return loops;
}

/// The openings of the mesh (positions `x`, triangles `tris`, canonical mm), with their figures
/// (see Opening and the file comment); `fold_depth_mm` is the rise and fall a fold must have.
inline std::vector<Opening> garment_openings(const std::vector<Vec3>& x,
                                             const std::vector<Tri>& tris,
                                             double fold_depth_mm = 2) {
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    std::vector<Opening> out;
    for (auto& loop : boundary_loop_vertices(tris)) {
        Opening o;
        o.loop = std::move(loop);
        const std::size_t n = o.loop.size();
        Vec3 c{0, 0, 0}, nn{0, 0, 0};
        double xmin = 1e300, xmax = -1e300, zmin = 1e300, zmax = -1e300;
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3& p = x[o.loop[i]];
            const Vec3& q = x[o.loop[(i + 1) % n]];
            o.points.push_back(p);
            c = vec3::add(c, p);
            o.length_mm += vec3::norm(vec3::sub(q, p));
            // Newell's normal of the closed polygon.
            nn[0] += (p[1] - q[1]) * (p[2] + q[2]);
            nn[1] += (p[2] - q[2]) * (p[0] + q[0]);
            nn[2] += (p[0] - q[0]) * (p[1] + q[1]);
            xmin = std::min(xmin, p[0]);
            xmax = std::max(xmax, p[0]);
            zmin = std::min(zmin, p[2]);
            zmax = std::max(zmax, p[2]);
        }
        c = vec3::scale(c, 1.0 / double(n));
        o.height_mm = c[1];
        o.width_mm = xmax - xmin;
        o.depth_mm = zmax - zmin;
        const double nl = vec3::norm(nn);
        o.normal = nl > 0 ? vec3::scale(nn, (nn[1] < 0 ? -1.0 : 1.0) / nl) : Vec3{0, 1, 0};
        // A basis of the loop's plane.
        const Vec3 helper = std::abs(o.normal[0]) < 0.9 ? Vec3{1, 0, 0} : Vec3{0, 0, 1};
        const Vec3 u = vec3::normalized(vec3::cross(helper, o.normal));
        const Vec3 v = vec3::cross(o.normal, u);
        std::vector<K::Point_2> pts;
        for (std::size_t i = 0; i < n; ++i) {
            const Vec3 d = vec3::sub(x[o.loop[i]], c);
            pts.emplace_back(vec3::dot(d, u), vec3::dot(d, v));
        }
        std::vector<K::Point_2> hull;
        CGAL::convex_hull_2(pts.begin(), pts.end(), std::back_inserter(hull));
        std::vector<K::Segment_2> sides;
        for (std::size_t i = 0; i < hull.size(); ++i) {
            sides.emplace_back(hull[i], hull[(i + 1) % hull.size()]);
            o.hull_perimeter_mm += std::sqrt(sides.back().squared_length());
        }
        // Depth: distance to the hull's sides (every point lies inside or on the hull).
        std::vector<double> depth(n, 0);
        if (hull.size() >= 3) {
            for (std::size_t i = 0; i < n; ++i) {
                double best = std::numeric_limits<double>::infinity();
                for (const K::Segment_2& side : sides) {
                    best = std::min(best, CGAL::squared_distance(pts[i], side));
                }
                depth[i] = std::sqrt(best);
            }
        }
        o.deepest_fold_mm = n ? *std::max_element(depth.begin(), depth.end()) : 0;
        o.folds = internal::closed_peaks(depth, fold_depth_mm);
        out.push_back(std::move(o));
    }
    return out;
}

}  // namespace tapeline::garment
