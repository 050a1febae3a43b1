// The single-source propagation of the curvature-flow distances over a graph of positioned nodes:
// mesh vertices joined by the mesh edges (gcf_distances.h) or the grid nodes of a point set joined
// to the neighbouring cells (gcf_points.h). What the two share lives here: the per-node state
// (distance, kept tail of the path, fixed prefix length, arrival direction), the tentative
// distances over the edges, the choice of the parents a new node continues (the straightest
// continuation and the cut-locus guard), the causal batches (gcf_batches.h) with their progress,
// and the shortest edge path that starts a two-point flow. How a path is flowed and measured is
// the caller's (solve and commit). No CGAL.
#pragma once

#include <tapeline/core/progress.h>
#include <tapeline/geodesic/internal/gcf_batches.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::geodesic::internal::gcf {

/// Outcomes of flows, summed.
struct FlowCounts {
    std::size_t iterations = 0, flows = 0, converged = 0, stalled = 0, max_iterations = 0,
                failed = 0;
    void add(const std::string& status, std::size_t its) {
        iterations += its;
        ++flows;
        if (status == "converged")
            ++converged;
        else if (status == "stalled")
            ++stalled;
        else if (status == "max_iterations")
            ++max_iterations;
        else
            ++failed;
    }
    void add(const FlowCounts& c) {
        iterations += c.iterations;
        flows += c.flows;
        converged += c.converged;
        stalled += c.stalled;
        max_iterations += c.max_iterations;
        failed += c.failed;
    }
    /// Into a report's fields of the same names (failed: solver_failures).
    template <class Report>
    void write(Report& r) const {
        r.flows = flows;
        r.iterations = iterations;
        r.converged = converged;
        r.stalled = stalled;
        r.max_iterations = max_iterations;
        r.solver_failures = failed;
    }
};

/// Dijkstra over a CSR graph from a, stopped once b is settled: dist (+inf where not reached) and
/// pred (kNone at a and where not reached). length(v, w) is the length of edge (v, w).
template <class Length>
void dijkstra_to(const std::vector<std::uint32_t>& adj_start, const std::vector<std::uint32_t>& adj,
                 std::uint32_t a, std::uint32_t b, const Length& length, std::vector<double>& dist,
                 std::vector<std::uint32_t>& pred) {
    const std::size_t n = adj_start.size() - 1;
    dist.assign(n, std::numeric_limits<double>::infinity());
    pred.assign(n, std::numeric_limits<std::uint32_t>::max());
    MinQueue q;
    dist[a] = 0;
    q.push({0.0, a});
    while (!q.empty()) {
        const auto [dv, v] = q.top();
        q.pop();
        if (dv > dist[v])
            continue;
        if (v == b)
            break;
        for (std::uint32_t k = adj_start[v]; k < adj_start[v + 1]; ++k) {
            const std::uint32_t w = adj[k];
            const double nd = dv + length(v, w);
            if (nd < dist[w]) {
                dist[w] = nd;
                pred[w] = v;
                q.push({nd, w});
            }
        }
    }
}

/// Index of the first sample a window of `window` samples flows in a path of `size` samples
/// (the sample there is held fixed): 0 for the whole path (window 0, `whole`, or a short path).
inline std::size_t window_start(std::size_t size, std::size_t window, bool whole) {
    return window > 0 && !whole && size > window + 1 ? size - (window + 1) : 0;
}

/// State of a propagation over nodes 0..n-1 joined by a CSR adjacency; position(v) gives the
/// point of node v (an Eigen vector, compared by value, so a vector type of any size works).
template <class Sample, class Vec, class Position>
class Wavefront {
public:
    Wavefront(const std::vector<std::uint32_t>& adj_start, const std::vector<std::uint32_t>& adj,
              Position position, const Vec& zero)
        : adj_start_(adj_start), adj_(adj), position_(position), zero_(zero) {
        const std::size_t n = adj_start.size() - 1;
        const double inf = std::numeric_limits<double>::infinity();
        d.assign(n, inf);
        prefix.assign(n, 0.0);
        tentative.assign(n, inf);
        arrival.assign(n, zero);
        tail.resize(n);
        visited.assign(n, 0);
        whole_path.assign(n, 0);
    }

    std::size_t size() const { return d.size(); }

    /// Lowers the tentative distance d(u) + |uw| of the unvisited neighbours w of u.
    void relax(std::uint32_t u) {
        for (std::uint32_t k = adj_start_[u]; k < adj_start_[u + 1]; ++k) {
            const std::uint32_t w = adj_[k];
            if (visited[w])
                continue;
            const double t = d[u] + (position_(w) - position_(u)).norm();
            if (t < tentative[w]) {
                tentative[w] = t;
                queue_.push({t, w});
            }
        }
    }

    /// The visited neighbours of w other than src, in adjacency order; *next_to_source tells
    /// whether src is a neighbour.
    std::vector<std::uint32_t> visited_neighbours(std::uint32_t w, std::uint32_t src,
                                                  bool* next_to_source = nullptr) const {
        std::vector<std::uint32_t> out;
        for (std::uint32_t k = adj_start_[w]; k < adj_start_[w + 1]; ++k) {
            const std::uint32_t u = adj_[k];
            if (u == src) {
                if (next_to_source)
                    *next_to_source = true;
            } else if (visited[u]) {
                out.push_back(u);
            }
        }
        return out;
    }

    /// The candidate u whose path (its last non-zero step) continues most straightly into the
    /// edge (u, w): the thesis' parent rule. The first on ties; kNone without candidates.
    std::uint32_t straightest(std::uint32_t w, const std::vector<std::uint32_t>& candidates) const {
        std::uint32_t best_u = std::numeric_limits<std::uint32_t>::max();
        double best_cos = -std::numeric_limits<double>::infinity();
        for (const std::uint32_t u : candidates) {
            const auto& tu = tail[u];
            const Vec e = (position_(w) - position_(u)).normalized();
            Vec dir = zero_;
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
        return best_u;
    }

    /// Cut-locus guard: where two wavefronts meet, the straightest continuation may come from the
    /// longer side (or the wrong side of a handle); the candidate that gives the smallest
    /// tentative distance and those whose paths arrive from a clearly different direction (over
    /// 60 degrees) are continued too. Returns best first, then those others.
    std::vector<std::uint32_t> guarded(std::uint32_t w, std::uint32_t best,
                                       const std::vector<std::uint32_t>& candidates) const {
        std::vector<std::uint32_t> out{best};
        std::uint32_t nearest = std::numeric_limits<std::uint32_t>::max();
        double nearest_t = std::numeric_limits<double>::infinity();
        for (const std::uint32_t u : candidates) {
            const double t = d[u] + (position_(w) - position_(u)).norm();
            if (t < nearest_t) {
                nearest_t = t;
                nearest = u;
            }
            if (u != best && arrival[u].dot(arrival[best]) < 0.5)
                out.push_back(u);
        }
        if (std::find(out.begin(), out.end(), nearest) == out.end())
            out.push_back(nearest);
        return out;
    }

    /// Keeps c[first..] as the tail of w's path and marks w visited.
    void store(std::uint32_t w, const std::vector<Sample>& c, std::size_t first) {
        tail[w].assign(c.begin() + static_cast<std::ptrdiff_t>(first), c.end());
        tail[w].shrink_to_fit();
        visited[w] = 1;
    }

    /// Visits the queued nodes in causal batches (propagate_in_batches; band = the shortest
    /// edge): solve(node, Solved&) in parallel against the visited set as it stands, then
    /// commit(node, Solved&) in queue order, which stores the node and relaxes its neighbours.
    /// `progress` counts the nodes.
    template <class Solved, class Solve, class Commit>
    void run(const Solve& solve, const Commit& commit, Progress& progress) {
        const double band = shortest_edge(adj_start_, adj_, [&](std::uint32_t v, std::uint32_t u) {
            return (position_(u) - position_(v)).norm();
        });
        progress.advance(static_cast<std::size_t>(std::count(visited.begin(), visited.end(), 1)));
        propagate_in_batches<Solved>(queue_, tentative, visited, adj_start_, adj_, band, solve,
                                     commit, &progress);
    }

    std::vector<double> d;       ///< distance of the visited nodes (+inf elsewhere)
    std::vector<double> prefix;  ///< length of the path before tail[v][0]
    std::vector<double> tentative;
    std::vector<Vec> arrival;  ///< unit direction the path of v arrives in
    std::vector<std::vector<Sample>> tail;
    std::vector<char> visited;
    std::vector<char> whole_path;  ///< tail[v] starts at the source

private:
    const std::vector<std::uint32_t>& adj_start_;
    const std::vector<std::uint32_t>& adj_;
    Position position_;
    Vec zero_;
    MinQueue queue_;
};

}  // namespace tapeline::geodesic::internal::gcf
