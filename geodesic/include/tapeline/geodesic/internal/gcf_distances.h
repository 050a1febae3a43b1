// Single-source distances by geodesic curvature flow (curvature_flow.h, gcf_distances): the
// ring-by-ring propagation of the thesis' Algorithms 1 and 2 on the plain arrays of gcf_engine.h.
// Reuses the flow of gcf_engine.h (flow_step, curvature); no CGAL.
#pragma once

#include <tapeline/geodesic/curvature_flow_types.h>
#include <tapeline/geodesic/internal/gcf_engine.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::geodesic::internal::gcf {

/// Flows s (endpoints fixed) until converged / stalled / max_iterations, as run_flow does.
/// Returns the iterations taken; `status` receives the outcome.
inline std::size_t flow_to_convergence(const Mesh& m, std::vector<Sample>& s,
                                       const CurvatureFlowOptions& o, std::string& status) {
    if (s.size() < 3) {
        status = "converged";
        return 0;
    }
    const double h = m.mean_edge > 0 ? m.mean_edge : 1.0;
    auto scaled = [&](double k) {
        double len = 0;
        for (std::size_t i = 1; i < s.size(); ++i)
            len += (s[i].p - s[i - 1].p).norm();
        const double dh = len / static_cast<double>(s.size() - 1);
        return dh > 0 ? k / (dh * dh) * h : 0.0;
    };
    double kmax = 0, res = 0;
    curvature(m, s, o.interpolate_normals, kmax, res);
    if (scaled(kmax) <= o.tolerance) {
        status = "converged";
        return 0;
    }
    status = "max_iterations";
    std::size_t it = 0;
    while (it < o.max_iterations) {
        double upd = 0;
        if (!flow_step(m, s, o, o.step, upd)) {
            status = "solver_failed";
            return it;
        }
        ++it;
        curvature(m, s, o.interpolate_normals, kmax, res);
        if (scaled(kmax) <= o.tolerance) {
            status = "converged";
            break;
        }
        if (upd <= o.update_tolerance * h) {
            status = "stalled";
            break;
        }
    }
    return it;
}

/// Result of the propagation, per vertex of the compact mesh.
struct DistanceField {
    std::vector<double> d;
    std::size_t iterations = 0;
    std::size_t flows = 0;
    std::size_t converged = 0;
    std::size_t stalled = 0;
    std::size_t max_iterations = 0;
    std::size_t failed = 0;
    std::size_t stored_samples = 0;  ///< samples kept at the end (memory)
};

/// Ring-by-ring propagation from vertex `src` (components: only its component is reached).
/// window = 0: Algorithm 1 (whole polyline flowed); else Algorithm 2 (last `window` samples).
/// d = length of the sample polyline, Phong-lifted if `smooth`.
inline DistanceField propagate(const Mesh& m, std::uint32_t src, std::size_t window, double spacing,
                               bool smooth, bool shortest_parent, const CurvatureFlowOptions& o) {
    const std::size_t n = m.vertex_count();
    const double inf = std::numeric_limits<double>::infinity();
    DistanceField out;
    out.d.assign(n, inf);
    // Per visited vertex: the kept tail of its polyline (last window + 1 samples, all for
    // window 0) and the (lifted) length of the fixed prefix before tail[0].
    std::vector<std::vector<Sample>> tail(n);
    std::vector<double> prefix(n, 0.0);
    std::vector<char> visited(n, 0);
    auto lifted = [&](const Sample& a) -> Vec3 {
        if (!smooth || a.face == kNone)
            return a.p;
        return phong_lift(m, a.face, a.p);
    };
    auto length_of = [&](const std::vector<Sample>& s, std::size_t from, std::size_t to) {
        double len = 0;
        Vec3 prev = lifted(s[from]);
        for (std::size_t i = from + 1; i <= to; ++i) {
            const Vec3 cur = lifted(s[i]);
            len += (cur - prev).norm();
            prev = cur;
        }
        return len;
    };
    auto vertex_sample = [&](std::uint32_t v) {
        Sample s;
        s.p = m.xyz[v];
        s.vertex = v;
        s.face = m.vf_start[v] < m.vf_start[v + 1] ? m.vf[m.vf_start[v]] : kNone;
        return s;
    };
    // Appends the chord from the last sample of c to vertex w, subdivided at `spacing`.
    auto append_edge = [&](std::vector<Sample>& c, std::uint32_t w) {
        const Sample a = c.back();
        const Vec3 q = m.xyz[w];
        const double len = (q - a.p).norm();
        const std::size_t pieces =
            std::max<std::size_t>(1, static_cast<std::size_t>(std::ceil(len / spacing - 1e-9)));
        std::uint32_t hint = a.vertex;
        for (std::size_t k = 1; k < pieces; ++k) {
            Sample s;
            s.p = a.p + (static_cast<double>(k) / static_cast<double>(pieces)) * (q - a.p);
            s.vertex = nearest_vertex_walk(m, s.p, hint);
            project_around(m, s);
            hint = s.vertex;
            c.push_back(s);
        }
        c.push_back(vertex_sample(w));
    };
    auto keep = [&](std::uint32_t w, std::vector<Sample>& c, double pre) {
        std::size_t first = 0;
        if (window > 0 && c.size() > window + 1)
            first = c.size() - (window + 1);
        prefix[w] = pre + (first > 0 ? length_of(c, 0, first) : 0.0);
        out.d[w] = prefix[w] + length_of(c, first, c.size() - 1);
        tail[w].assign(c.begin() + static_cast<std::ptrdiff_t>(first), c.end());
        tail[w].shrink_to_fit();
        visited[w] = 1;
    };

    using Item = std::pair<double, std::uint32_t>;
    std::priority_queue<Item, std::vector<Item>, std::greater<Item>> q;
    std::vector<double> tentative(n, inf);
    auto relax = [&](std::uint32_t u) {
        for (std::uint32_t k = m.vv_start[u]; k < m.vv_start[u + 1]; ++k) {
            const std::uint32_t w = m.vv[k];
            if (visited[w])
                continue;
            const double t = out.d[u] + (m.xyz[w] - m.xyz[u]).norm();
            if (t < tentative[w]) {
                tentative[w] = t;
                q.push({t, w});
            }
        }
    };
    // Source and its 1-ring: straight edges.
    visited[src] = 1;
    out.d[src] = 0;
    tail[src] = {vertex_sample(src)};
    for (std::uint32_t k = m.vv_start[src]; k < m.vv_start[src + 1]; ++k) {
        const std::uint32_t w = m.vv[k];
        if (visited[w])
            continue;
        std::vector<Sample> c{vertex_sample(src)};
        append_edge(c, w);
        keep(w, c, 0.0);
        out.d[w] = (m.xyz[w] - m.xyz[src]).norm();  // straight edge, exactly
    }
    relax(src);
    for (std::uint32_t k = m.vv_start[src]; k < m.vv_start[src + 1]; ++k)
        relax(m.vv[k]);

    std::vector<Sample> c;
    while (!q.empty()) {
        const auto [t, w] = q.top();
        q.pop();
        if (visited[w] || t > tentative[w])
            continue;
        // Candidate parents: the straightest continuation among the visited neighbours, or
        // (shortest_parent) every visited neighbour, keeping the shortest flowed result.
        std::uint32_t best_u = kNone;
        double best_cos = -inf;
        std::vector<std::uint32_t> parents;
        for (std::uint32_t k = m.vv_start[w]; k < m.vv_start[w + 1]; ++k) {
            const std::uint32_t u = m.vv[k];
            if (!visited[u] || u == src)
                continue;
            parents.push_back(u);
            const auto& tu = tail[u];
            const Vec3 e = (m.xyz[w] - m.xyz[u]).normalized();
            Vec3 dir = Vec3::Zero();
            for (std::size_t i = tu.size(); i-- > 1;) {
                dir = tu.back().p - tu[i - 1].p;
                if (dir.norm() > 0)
                    break;
            }
            const double cs = dir.norm() > 0 ? dir.normalized().dot(e) : -1.0;
            if (cs > best_cos) {
                best_cos = cs;
                best_u = u;
            }
        }
        if (best_u == kNone) {  // only the source is visited around w (cannot happen past ring 1)
            c.assign(1, vertex_sample(src));
            append_edge(c, w);
            keep(w, c, 0.0);
            relax(w);
            continue;
        }
        if (!shortest_parent)
            parents.assign(1, best_u);
        double best_len = inf;
        std::vector<Sample> best_c;
        std::uint32_t chosen = kNone;
        for (const std::uint32_t u : parents) {
            c = tail[u];
            append_edge(c, w);
            // Flow the last `window` samples (all for window 0); the sample before them is fixed.
            std::size_t start = 0;
            if (window > 0 && c.size() > window + 1)
                start = c.size() - (window + 1);
            std::vector<Sample> part(c.begin() + static_cast<std::ptrdiff_t>(start), c.end());
            std::string status;
            out.iterations += flow_to_convergence(m, part, o, status);
            ++out.flows;
            if (status == "converged")
                ++out.converged;
            else if (status == "stalled")
                ++out.stalled;
            else if (status == "max_iterations")
                ++out.max_iterations;
            else
                ++out.failed;
            std::copy(part.begin(), part.end(), c.begin() + static_cast<std::ptrdiff_t>(start));
            const double len = prefix[u] + length_of(c, 0, c.size() - 1);
            if (len < best_len) {
                best_len = len;
                best_c.swap(c);
                chosen = u;
            }
        }
        keep(w, best_c, prefix[chosen]);
        relax(w);
    }
    for (std::size_t v = 0; v < n; ++v)
        out.stored_samples += tail[v].size();
    return out;
}

}  // namespace tapeline::geodesic::internal::gcf
