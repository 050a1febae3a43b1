// Options and report of the exact window-propagation method (exact_mmp.h).
//
// Light header without CGAL (DESIGN.md §3): loggers, benchmark drivers and test facades include it
// to read and print what the algorithm did without paying for the CGAL templates.
#pragma once

#include <tapeline/geodesic/geodesic_types.h>

#include <cstddef>
#include <limits>
#include <vector>

namespace tapeline::geodesic {

/// Behaviour of the exact MMP window propagation (Mitchell, Mount, Papadimitriou 1987, in the form
/// of Surazhsky et al. 2005). Every knob only limits the work; none changes an exact value.
struct ExactMmpOptions {
    /// Propagation stops once the wavefront passes this distance; vertices farther away get
    /// +infinity (counted in report.unreachable), vertices within it get their exact distance.
    double max_distance = std::numeric_limits<double>::infinity();
    /// Vertex indices (vertex_index_map numbering). When non-empty, propagation stops as soon as
    /// all of them are final; every vertex farther than the farthest of them gets +infinity.
    std::vector<std::size_t> target_vertices;
    /// Drop a window when the distances that its edge's end vertices already certify are shorter
    /// on the whole window (Qin et al. 2016 style pruning; never changes a value). Kept as a knob
    /// to measure what it saves.
    bool prune_with_vertex_distances = true;
    /// Keep every window after the propagation (ExactMmpSolver: face-location distances and
    /// paths read them). false frees the windows of an edge as soon as the wave has passed it
    /// (distances only, a fraction of the memory); the solver then recomputes once, keeping the
    /// windows, on its first face-location or path query. exact_mmp_distances and
    /// exact_mmp_distance_matrix never keep them.
    bool keep_windows = true;
    /// Guard against a runaway propagation: at most this many windows are propagated; 0 picks
    /// 4096 * halfedges (far above anything measured: ~30 per halfedge on a 41k-vertex sphere).
    /// Exceeding it throws SolverFailure instead of hanging.
    std::size_t max_propagated_windows = 0;
};

/// DistanceReport plus what the window propagation did.
struct ExactMmpReport : DistanceReport {
    std::size_t windows_created = 0;     ///< windows that survived trimming when inserted
    std::size_t windows_propagated = 0;  ///< windows taken from the queue and propagated
    std::size_t windows_pruned = 0;      ///< windows dropped by the vertex-distance test
    std::size_t windows_kept = 0;        ///< windows alive at the end (kept for queries)
    std::size_t windows_peak = 0;        ///< largest number of windows alive at once
    std::size_t pseudo_sources = 0;      ///< vertex emissions (sources, saddle/boundary vertices)
    std::size_t saddle_or_boundary_vertices = 0;  ///< vertices allowed to become pseudo-sources
    std::size_t peak_bytes = 0;  ///< peak of window pool + queue + per-mesh arrays (estimate)
    /// Distance at which the propagation stopped (max_distance or the farthest target);
    /// +infinity when it ran to the end.
    double stopped_at = std::numeric_limits<double>::infinity();
};

}  // namespace tapeline::geodesic
