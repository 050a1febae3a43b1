// Causal batches of the ring propagation shared by the curvature-flow distances on meshes
// (gcf_distances.h) and on point clouds (gcf_points.h); no CGAL.
#pragma once

#include <tapeline/core/progress.h>

#include <algorithm>
#include <cstdint>
#include <functional>
#include <limits>
#include <queue>
#include <utility>
#include <vector>

#ifdef CGAL_LINKED_WITH_TBB
#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#endif

namespace tapeline::geodesic::internal::gcf {

/// (tentative distance, node) and the min-queue of the propagation.
using QueueItem = std::pair<double, std::uint32_t>;
using MinQueue = std::priority_queue<QueueItem, std::vector<QueueItem>, std::greater<QueueItem>>;

/// The shortest positive length(v, u) over the edges of a CSR adjacency (+inf if none).
template <class Length>
double shortest_edge(const std::vector<std::uint32_t>& adj_start,
                     const std::vector<std::uint32_t>& adj, const Length& length) {
    double band = std::numeric_limits<double>::infinity();
    for (std::size_t v = 0; v + 1 < adj_start.size(); ++v)
        for (std::uint32_t k = adj_start[v]; k < adj_start[v + 1]; ++k) {
            const double e = length(static_cast<std::uint32_t>(v), adj[k]);
            if (e > 0)
                band = std::min(band, e);
        }
    return band;
}

/// Empties q in batches: the queue's next nodes within `band` of its minimum, none adjacent to
/// another of the batch. With band the shortest edge, they are the ones the one-at-a-time order
/// would visit next (relaxing one cannot lower another's tentative distance below the band), and
/// none can be the parent of another. solve(node, Solved&) runs on all of them against the same
/// visited set, in parallel (TBB), and may only read shared state; commit(node, Solved&) then
/// runs one after another in queue order, marks the node visited and relaxes its neighbours. So
/// the result does not depend on the number of threads. Stale entries (visited, or above the
/// node's current tentative distance) are skipped. `progress` (optional) advances per batch.
template <class Solved, class Solve, class Commit>
void propagate_in_batches(MinQueue& q, const std::vector<double>& tentative,
                          const std::vector<char>& visited,
                          const std::vector<std::uint32_t>& adj_start,
                          const std::vector<std::uint32_t>& adj, double band, const Solve& solve,
                          const Commit& commit, Progress* progress = nullptr) {
    std::vector<char> in_batch(tentative.size(), 0);
    std::vector<std::uint32_t> batch;
    std::vector<QueueItem> deferred;
    std::vector<Solved> solved;
    while (!q.empty()) {
        batch.clear();
        deferred.clear();
        double t0 = std::numeric_limits<double>::infinity();
        while (!q.empty()) {
            const auto [t, w] = q.top();
            if (!batch.empty() && t > t0 + band)
                break;
            q.pop();
            if (visited[w] || in_batch[w] || t > tentative[w])
                continue;
            bool adjacent = false;
            for (std::uint32_t k = adj_start[w]; k < adj_start[w + 1] && !adjacent; ++k)
                adjacent = in_batch[adj[k]] != 0;
            if (adjacent) {
                deferred.push_back({t, w});
                continue;
            }
            if (batch.empty())
                t0 = t;
            batch.push_back(w);
            in_batch[w] = 1;
        }
        for (const QueueItem& it : deferred)
            q.push(it);
        solved.assign(batch.size(), Solved{});
#ifdef CGAL_LINKED_WITH_TBB
        if (batch.size() > 1) {
            tbb::parallel_for(tbb::blocked_range<std::size_t>(0, batch.size(), 1),
                              [&](const tbb::blocked_range<std::size_t>& range) {
                                  for (std::size_t i = range.begin(); i != range.end(); ++i)
                                      solve(batch[i], solved[i]);
                              });
        } else
#endif
        {
            for (std::size_t i = 0; i < batch.size(); ++i)
                solve(batch[i], solved[i]);
        }
        for (std::size_t i = 0; i < batch.size(); ++i) {
            in_batch[batch[i]] = 0;
            commit(batch[i], solved[i]);
        }
        if (progress)
            progress->advance(batch.size());
    }
}

}  // namespace tapeline::geodesic::internal::gcf
