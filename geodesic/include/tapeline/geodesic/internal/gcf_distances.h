// Single-source distances by geodesic curvature flow (curvature_flow.h, gcf_distances): the
// ring-by-ring propagation of the thesis' Algorithms 1 and 2 over the vertices of the mesh arrays
// of gcf_engine.h (the propagation of gcf_wavefront.h with the flow of gcf_engine.h); no CGAL.
#pragma once

#include <tapeline/geodesic/curvature_flow_types.h>
#include <tapeline/geodesic/internal/gcf_batches.h>
#include <tapeline/geodesic/internal/gcf_engine.h>
#include <tapeline/geodesic/internal/gcf_trace.h>
#include <tapeline/geodesic/internal/gcf_wavefront.h>
#include <tapeline/geodesic/internal/unfold_engine.h>

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
    FlowCounts counts;
    std::size_t stored_samples = 0;  ///< samples kept at the end (memory)
    double epsilon = 0;              ///< largest anchor kink excess / mean edge (windowed flows)
    std::size_t max_faces = 0;       ///< largest number of faces holding samples of one path
    // Diagnostics (PropagateParams::diagnostics): per vertex its parent (kNone: from the source),
    // the outcome bits of its flows (1 whole path, 2 some flow hit the iteration cap) and the
    // kept tail of its polyline.
    std::vector<std::uint32_t> parent;
    std::vector<unsigned char> flags;
    std::vector<std::vector<Sample>> tails;
};

/// Interpolated distance at x on face f from the visited corners: sum_i l_i (d_i + g_i.(x - v_i)/2)
/// with barycentric weights l_i, exact for a quadratic field (the averaged linear interpolation
/// and first-order Taylor extrapolation cancel their second-order errors). Unvisited corners are
/// left out (weights renormalised, first-order). Returns +inf when no corner is visited.
inline double field_at(const Mesh& m, std::uint32_t f, const Vec3& x, const std::vector<double>& d,
                       const std::vector<Vec3>& g, const std::vector<char>& visited,
                       Vec3* gradient = nullptr) {
    Vec3 bary;
    closest_on_triangle(x, m.xyz[m.corner[3 * f]], m.xyz[m.corner[3 * f + 1]],
                        m.xyz[m.corner[3 * f + 2]], bary);
    double sum = 0, wsum = 0;
    Vec3 gsum = Vec3::Zero();
    int seen = 0;
    for (int k = 0; k < 3; ++k) {
        const std::uint32_t v = m.corner[3 * f + k];
        if (!visited[v] || !std::isfinite(d[v]))
            continue;
        ++seen;
        const Vec3 dx = x - m.xyz[v];
        sum += bary[k] * (d[v] + 0.5 * g[v].dot(dx));
        wsum += bary[k];
        gsum += bary[k] * g[v];
    }
    if (seen == 0)
        return std::numeric_limits<double>::infinity();
    if (seen < 3 || !(wsum > 1e-12)) {  // partial face: plain first-order extrapolation
        sum = 0;
        gsum = Vec3::Zero();
        for (int k = 0; k < 3; ++k) {
            const std::uint32_t v = m.corner[3 * f + k];
            if (!visited[v] || !std::isfinite(d[v]))
                continue;
            sum += d[v] + g[v].dot(x - m.xyz[v]);
            gsum += g[v];
        }
        sum /= seen;
    } else {
        sum /= wsum;
    }
    if (gradient)
        *gradient = gsum;
    return sum;
}

/// Length on the faces of the segment between consecutive samples a and b: its on-face trace
/// (trace_on_faces, as the on-mesh output of the two-point flow), a polyhedral length like the
/// exact distance's; the chord |ab| cuts through the solid at a fold or crease (measured: fandisk,
/// a 90-degree crease, chords up to 0.36 mean edge lengths short). A piece without a plane cut is
/// its chord, and *failed is set (the caller falls back to its unflowed path). `points` (optional,
/// ending with a.p) receives the traced points after a.
inline double traced_length(const Mesh& m, const Sample& a, const Sample& b,
                            std::vector<Vec3>* points = nullptr, bool* failed = nullptr) {
    thread_local std::vector<Vec3> own;
    if (!points) {
        own.assign(1, a.p);
        points = &own;
    }
    const std::size_t first = points->size() - 1;
    auto chord = [](const Sample&, const Sample& q, std::vector<Vec3>& out) { out.push_back(q.p); };
    if (trace_on_faces(m, a, b, *points, chord) > 0 && failed)
        *failed = true;
    double len = 0;
    for (std::size_t i = first + 1; i < points->size(); ++i)
        len += ((*points)[i] - (*points)[i - 1]).norm();
    return len;
}

/// Polyhedral length of samples s[from..to]: their traces on the faces (traced_length), then the
/// shortest path through the faces those traces cross, moved across vertices where it can be
/// shortened (unfold::straighten, the on-mesh output of the two-point flow): a polyhedral
/// geodesic between s[from] and s[to] near the flowed samples, whose length is what the exact
/// distance measures. The traced length when the strip cannot be unfolded.
inline double polyhedral_length(const Mesh& m, const std::vector<Sample>& s, std::size_t from,
                                std::size_t to, bool* failed = nullptr) {
    thread_local std::vector<Vec3> pts;
    pts.assign(1, s[from].p);
    double traced = 0;
    for (std::size_t i = from + 1; i <= to; ++i)
        traced += traced_length(m, s[i - 1], s[i], &pts, failed);
    if (to <= from + 1 || s[from].face == kNone)
        return traced;
    std::size_t bad = kNone;
    unfold::Strip strip;
    unfold::unfold_polyline(m, pts, UnfoldOptions{}, s[from].face, bad, &strip);
    if (bad != kNone || strip.faces.empty())
        return traced;
    const std::size_t cap = 4 * strip.faces.size() + 16;
    const auto st = unfold::straighten(m, std::move(strip), pts.front(), pts.back(), cap);
    return std::isfinite(st.length) && st.length <= traced ? st.length : traced;
}

/// Parameters of propagate (see CurvatureFlowDistanceOptions).
struct PropagateParams {
    std::size_t window = 0;
    double spacing = 0;
    bool smooth = true;
    bool shortest_parent = false;
    bool field_anchor = true;
    std::size_t near_source_samples = 0;
    std::size_t anchor_slides = 1;
    bool cut_locus_guard = true;
    bool traced = true;        ///< with smooth = false: traced_length instead of chords
    bool straighten = true;    ///< with smooth = false: polyhedral_length (implies traced)
    bool diagnostics = false;  ///< fill DistanceField::parent, flags, tails
    /// Flow steps of a window that does not reach back to the source (a fixed sample before it),
    /// at most; 0: `o.max_iterations`. Paths flowed whole keep `o.max_iterations`.
    std::size_t window_max_iterations = 0;
};

/// Ring-by-ring propagation from vertex `src` (components: only its component is reached).
/// window = 0: Algorithm 1 (whole polyline flowed); else Algorithm 2 (last `window` samples).
/// d = length of the sample polyline, Phong-lifted if `smooth`.
inline DistanceField propagate(const Mesh& m, std::uint32_t src, const PropagateParams& pp,
                               const CurvatureFlowOptions& o) {
    const std::size_t n = m.vertex_count();
    const std::size_t window = pp.window;
    const double spacing = pp.spacing;
    const bool field_anchor = window > 0 && pp.field_anchor;
    const std::size_t near_source =
        pp.near_source_samples > 0 ? pp.near_source_samples : 2 * window + 1;
    const double inf = std::numeric_limits<double>::infinity();
    DistanceField out;
    // Per visited vertex: the kept tail of its polyline (last window + 1 samples, all for
    // window 0 or near the source with a field anchor), the (lifted) length of the fixed prefix
    // before tail[0] (prefix anchor) and the unit direction the path arrives in (field anchor).
    auto position = [&m](std::uint32_t v) -> const Vec3& { return m.xyz[v]; };
    Wavefront<Sample, Vec3, decltype(position)> wf(m.vv_start, m.vv, position, Vec3::Zero());
    std::vector<double>& d = wf.d;
    std::vector<std::vector<Sample>>& tail = wf.tail;
    std::vector<double>& prefix = wf.prefix;
    std::vector<Vec3>& arrival = wf.arrival;
    std::vector<char>& visited = wf.visited;
    std::vector<char>& whole_path = wf.whole_path;
    // Faces holding samples of the path before tail[0] (runs of one face counted once), for m.
    std::vector<std::uint32_t> faces_before(n, 0);
    auto face_runs = [](const std::vector<Sample>& c, std::size_t from, std::size_t to) {
        std::size_t runs = 0;
        for (std::size_t i = from; i < to; ++i)
            if (i == from || c[i].face != c[i - 1].face)
                ++runs;
        return runs;
    };
    auto lifted = [&](const Sample& a) -> Vec3 {
        if (!pp.smooth || a.face == kNone)
            return a.p;
        return phong_lift(m, a.face, a.p);
    };
    auto length_of = [&](const std::vector<Sample>& s, std::size_t from, std::size_t to) {
        double len = 0;
        if (!pp.smooth && pp.traced) {
            for (std::size_t i = from + 1; i <= to; ++i)
                len += traced_length(m, s[i - 1], s[i]);
            return len;
        }
        Vec3 prev = lifted(s[from]);
        for (std::size_t i = from + 1; i <= to; ++i) {
            const Vec3 cur = lifted(s[i]);
            len += (cur - prev).norm();
            prev = cur;
        }
        return len;
    };
    // The length a distance is read from: with the on-face length, the straightened polyhedral
    // length (the traced one, cheaper, steers the anchor slides and the prefix rule).
    auto measure = [&](const std::vector<Sample>& s, std::size_t from, std::size_t to,
                       bool* failed = nullptr) {
        if (!pp.smooth && pp.straighten)
            return polyhedral_length(m, s, from, to, failed);
        return length_of(s, from, to);
    };
    auto vertex_sample = [&](std::uint32_t v) {
        Sample s;
        s.p = m.xyz[v];
        s.vertex = v;
        s.face = m.vf_start[v] < m.vf_start[v + 1] ? m.vf[m.vf_start[v]] : kNone;
        return s;
    };
    auto tangent = [&](std::uint32_t v, const Vec3& x) -> Vec3 {
        const Vec3 nrm = m.frame(v).col(2);
        const Vec3 t = x - x.dot(nrm) * nrm;
        const double len = t.norm();
        return len > 0 ? Vec3(t / len) : Vec3::Zero();
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
    // Stores c as the path of w. dist: its distance when already known (field anchor), else the
    // prefix `pre` before c[0] plus the length of c.
    auto keep = [&](std::uint32_t w, std::vector<Sample>& c, double pre, double dist, bool whole,
                    std::size_t faces_pre) {
        whole = whole && field_anchor;
        whole_path[w] = whole ? 1 : 0;
        const std::size_t first = window_start(c.size(), window, whole);
        prefix[w] = pre + (first > 0 ? length_of(c, 0, first) : 0.0);
        faces_before[w] = static_cast<std::uint32_t>(faces_pre + face_runs(c, 0, first));
        out.max_faces = std::max(out.max_faces, faces_pre + face_runs(c, 0, c.size()));
        d[w] = std::isfinite(dist) ? dist : prefix[w] + measure(c, first, c.size() - 1);
        if (c.size() >= 2)
            arrival[w] = tangent(w, c.back().p - c[c.size() - 2].p);
        wf.store(w, c, first);
    };

    // Source and its 1-ring: straight edges.
    visited[src] = 1;
    d[src] = 0;
    tail[src] = {vertex_sample(src)};
    for (std::uint32_t k = m.vv_start[src]; k < m.vv_start[src + 1]; ++k) {
        const std::uint32_t w = m.vv[k];
        if (visited[w])
            continue;
        std::vector<Sample> c{vertex_sample(src)};
        append_edge(c, w);
        keep(w, c, 0.0, (m.xyz[w] - m.xyz[src]).norm(), true, 0);  // straight edge, exactly
    }
    wf.relax(src);
    for (std::uint32_t k = m.vv_start[src]; k < m.vv_start[src + 1]; ++k)
        wf.relax(m.vv[k]);

    // A truncated window's flow stops after window_max_iterations steps; a whole path's does not.
    CurvatureFlowOptions window_o = o;
    if (pp.window_max_iterations > 0)
        window_o.max_iterations = std::min(o.max_iterations, pp.window_max_iterations);
    // Flows the part of c from `start` on (c[start] and c.back() fixed).
    auto flow_part = [&](std::vector<Sample>& c, std::size_t start, FlowCounts& counts) {
        std::vector<Sample> part(c.begin() + static_cast<std::ptrdiff_t>(start), c.end());
        std::string status;
        const std::size_t its = flow_to_convergence(m, part, start > 0 ? window_o : o, status);
        counts.add(status, its);
        std::copy(part.begin(), part.end(), c.begin() + static_cast<std::ptrdiff_t>(start));
    };
    // Field anchor: the anchor c[start] is slid sideways so that the flowed window leaves it in
    // the direction the field arrives in; returns the anchor's interpolated distance (+inf when
    // its face has no visited corner).
    auto slide_anchor = [&](std::vector<Sample>& c, std::size_t start, FlowCounts& counts) {
        Vec3 grad;
        double da = field_at(m, c[start].face, c[start].p, d, arrival, visited, &grad);
        if (!std::isfinite(da))
            return da;
        // Every anchor A gives d(w) <= D(A) + |window|: a slide is kept only when it lowers that
        // sum; otherwise the best state is restored and the next slide is half as long. (The
        // plain Newton-like slide oscillated on coarse, curved meshes: spot max error 6.9 %
        // with 3 slides, 19 % with 2.)
        double best = da + length_of(c, start, c.size() - 1);
        std::vector<Sample> best_part(c.begin() + static_cast<std::ptrdiff_t>(start), c.end());
        double scale = 1;
        for (std::size_t it = 0; it < pp.anchor_slides; ++it) {
            Sample& a = c[start];
            const Vec3 t_in = tangent(a.vertex, grad);
            const Vec3 t_out = tangent(a.vertex, c[start + 1].p - a.p);
            if (t_in.squaredNorm() == 0 || t_out.squaredNorm() == 0)
                break;
            const double len = length_of(c, start, c.size() - 1);
            // Flat-plane model: a lateral offset delta of the anchor from the geodesic through w
            // kinks the path by delta (1/s + 1/L); undo that offset.
            const Vec3 shift = (t_out - t_out.dot(t_in) * t_in) * (scale * da * len / (da + len));
            if (shift.norm() <= 1e-9 * m.mean_edge)
                break;
            a.p += shift;
            a.vertex = nearest_vertex_walk(m, a.p, a.vertex);
            project_around(m, a);
            flow_part(c, start, counts);
            Vec3 g2;
            const double d2 = field_at(m, c[start].face, c[start].p, d, arrival, visited, &g2);
            const double total = d2 + length_of(c, start, c.size() - 1);
            if (std::isfinite(d2) && total < best) {
                best = total;
                best_part.assign(c.begin() + static_cast<std::ptrdiff_t>(start), c.end());
                da = d2;
                grad = g2;
            } else {
                std::copy(best_part.begin(), best_part.end(),
                          c.begin() + static_cast<std::ptrdiff_t>(start));
                scale *= 0.5;
            }
        }
        return da;
    };

    // epsilon of the thesis' O(epsilon m) bound: the length a fixed anchor c[start] adds over the
    // chord from the sample before it to the one after it, |PA| + |AB| - |PB|. P is the path's
    // own previous sample (prefix anchor) or a point one spacing back along the field's arrival
    // direction (field anchor).
    auto kink_excess = [&](const std::vector<Sample>& c, std::size_t start) {
        const Vec3 a = c[start].p, b = c[start + 1].p;
        Vec3 p = c[start - 1].p;
        if (field_anchor) {
            Vec3 grad;
            const double da = field_at(m, c[start].face, a, d, arrival, visited, &grad);
            const Vec3 t_in = tangent(c[start].vertex, grad);
            if (!std::isfinite(da) || t_in.squaredNorm() == 0)
                return 0.0;
            p = a - (a - c[start - 1].p).norm() * t_in;
        }
        return (a - p).norm() + (b - a).norm() - (b - p).norm();
    };

    // The path of one vertex from the visited set as it stands; reads shared state only, so
    // the vertices of a batch (below) are solved in parallel.
    struct Solved {
        std::vector<Sample> c;
        double len = 0;
        std::uint32_t chosen = kNone;  // parent; kNone: straight from the source
        bool whole = false;
        std::size_t start = 0;
        double excess = 0;
        FlowCounts counts;
    };
    auto solve = [&](std::uint32_t w, Solved& r) {
        // Candidate parents: the straightest continuation among the visited neighbours (with
        // the cut-locus guard's), or (shortest_parent) every visited neighbour, keeping the
        // shortest flowed result.
        std::vector<std::uint32_t> parents = wf.visited_neighbours(w, src);
        const std::uint32_t best_u = wf.straightest(w, parents);
        if (best_u == kNone) {  // only the source is visited around w (cannot happen past ring 1)
            r.c.assign(1, vertex_sample(src));
            append_edge(r.c, w);
            r.chosen = kNone;
            return;
        }
        if (!pp.shortest_parent)
            parents = pp.cut_locus_guard ? wf.guarded(w, best_u, parents)
                                         : std::vector<std::uint32_t>{best_u};
        r.len = inf;
        std::vector<Sample> c;
        for (const std::uint32_t u : parents) {
            c = tail[u];
            append_edge(c, w);
            // With the polyhedral length: the path before the flow, kept in case the flowed one
            // leaves the surface (below).
            std::vector<Sample> unflowed;
            if (!pp.smooth && pp.straighten)
                unflowed = c;
            // Flow the last `window` samples (all for window 0); the sample before them is fixed.
            const bool whole = field_anchor && whole_path[u] && c.size() <= near_source;
            const std::size_t start = window_start(c.size(), window, whole);
            flow_part(c, start, r.counts);
            double len;
            double excess = 0;
            bool failed = false;
            if (field_anchor && start > 0) {
                const double da = slide_anchor(c, start, r.counts);
                excess = kink_excess(c, start);
                len = std::isfinite(da) ? da + measure(c, start, c.size() - 1, &failed)
                                        : prefix[u] + measure(c, 0, c.size() - 1, &failed);
            } else {
                len = prefix[u] + measure(c, 0, c.size() - 1, &failed);
                if (start > 0)
                    excess = kink_excess(c, start);
            }
            if (failed && !unflowed.empty()) {
                // A flowed segment has no trace on the faces even when split: samples on two
                // sheets of a narrow fold, whose chord cuts through the solid (armadillo: up to
                // 3 mean edges short, 47 %). The parent's path with the edge to w appended lies on
                // the surface; its straightened length is an upper bound.
                c.swap(unflowed);
                const double da = field_anchor && start > 0
                                      ? field_at(m, c[start].face, c[start].p, d, arrival, visited)
                                      : inf;
                len = std::isfinite(da) ? da + measure(c, start, c.size() - 1)
                                        : prefix[u] + measure(c, 0, c.size() - 1);
                excess = start > 0 ? kink_excess(c, start) : 0.0;
            }
            if (len < r.len) {
                r.len = len;
                r.c.swap(c);
                r.chosen = u;
                r.whole = whole;
                r.start = start;
                r.excess = excess;
            }
        }
    };
    if (pp.diagnostics) {
        out.parent.assign(n, kNone);
        out.flags.assign(n, 0);
    }
    auto commit = [&](std::uint32_t w, Solved& r) {
        if (pp.diagnostics) {
            out.parent[w] = r.chosen;
            out.flags[w] = static_cast<unsigned char>((r.whole ? 1 : 0) |
                                                      (r.counts.max_iterations > 0 ? 2 : 0));
        }
        if (r.chosen == kNone) {
            keep(w, r.c, 0.0, inf, true, 0);
        } else {
            keep(w, r.c, prefix[r.chosen], field_anchor ? r.len : inf, r.whole,
                 faces_before[r.chosen]);
            if (r.start > 0)
                out.epsilon = std::max(out.epsilon, r.excess / m.mean_edge);
        }
        out.counts.add(r.counts);
        wf.relax(w);
    };

    for (std::size_t v = 0; v < n; ++v)  // fill the frame cache before threads read it
        m.frame(static_cast<std::uint32_t>(v));
    Progress progress("gcf distances: vertices", n);
    wf.run<Solved>(solve, commit, progress);
    for (std::size_t v = 0; v < n; ++v)
        out.stored_samples += tail[v].size();
    if (pp.diagnostics)
        out.tails = std::move(tail);
    out.d = std::move(d);
    return out;
}

}  // namespace tapeline::geodesic::internal::gcf
