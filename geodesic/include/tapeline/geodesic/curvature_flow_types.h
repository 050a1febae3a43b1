// Options and report of two-point geodesic paths by geodesic curvature flow (curvature_flow.h).
//
// Light header without CGAL (DESIGN.md §3): loggers, benchmark drivers and test facades include it
// to read and print what the flow did without paying for the CGAL templates.
#pragma once

#include <tapeline/geodesic/geodesic_types.h>

#include <cstddef>
#include <string>

namespace tapeline::geodesic {

/// Linear least-squares solver of one flow step.
enum class CurvatureFlowSolver {
    /// Normal equations AᵀA x = Aᵀb, Eigen::SimplicialLDLT. The system is block banded (2x2 blocks,
    /// five block diagonals), so the factorisation is linear in the sample count. Default: measured
    /// 3.3x faster per iteration than SparseQR and 5.7x faster than LSCG (icosphere:5, 75
    /// samples), with the same path; the squared conditioning is harmless at these sizes.
    eigen_normal_ldlt,
    /// Eigen::SparseQR on the overdetermined system itself (better conditioned, slower).
    eigen_sparse_qr,
    /// Eigen::LeastSquaresConjugateGradient (iterative; no factorisation).
    eigen_lscg,
    /// Ceres (ceres::Problem, one Gauss-Newton step per flow step, samples as 3D parameter blocks
    /// on a tangent-plane ceres::Manifold). Needs <tapeline/geodesic/curvature_flow_ceres.h> in
    /// the program (CMake target tapeline::geodesic_ceres); InvalidInput otherwise. Same path
    /// as eigen_normal_ldlt (samples within 7e-11 mean edge lengths), measured 2.4-3.0x slower
    /// per iteration (40-300 samples, icospheres 5 and 6): problem set-up and preprocessing per
    /// step.
    ceres,
};

inline const char* to_string(CurvatureFlowSolver s) {
    switch (s) {
        case CurvatureFlowSolver::eigen_sparse_qr:
            return "eigen_sparse_qr";
        case CurvatureFlowSolver::eigen_lscg:
            return "eigen_lscg";
        case CurvatureFlowSolver::ceres:
            return "ceres";
        default:
            return "eigen_normal_ldlt";
    }
}

/// The linear solver Ceres uses inside CurvatureFlowSolver::ceres (ceres::LinearSolverType and
/// its sparse library).
enum class CeresLinearSolver {
    sparse_normal_cholesky,        ///< SPARSE_NORMAL_CHOLESKY with SuiteSparse (CHOLMOD)
    sparse_normal_cholesky_eigen,  ///< SPARSE_NORMAL_CHOLESKY with Eigen's sparse Cholesky
    dense_qr,                      ///< DENSE_QR
    cgnr,                          ///< CGNR (conjugate gradients on the normal equations)
};

inline const char* to_string(CeresLinearSolver s) {
    switch (s) {
        case CeresLinearSolver::sparse_normal_cholesky_eigen:
            return "sparse_normal_cholesky_eigen";
        case CeresLinearSolver::dense_qr:
            return "dense_qr";
        case CeresLinearSolver::cgnr:
            return "cgnr";
        default:
            return "sparse_normal_cholesky";
    }
}

/// Behaviour of the flow. Lengths are in the mesh's unit.
struct CurvatureFlowOptions {
    /// Target spacing of the samples; 0 picks the mean edge length of the mesh.
    double sample_spacing = 0;
    /// Number of samples including both endpoints (>= 3); 0 derives it from sample_spacing.
    std::size_t sample_count = 0;
    /// Step size mu (> 0, dimensionless). Each step minimises
    ///   sum_i |T_iᵀ (second difference of p + delta)_i|^2 + (1/mu) sum_i |a_i|^2
    /// over tangent moves delta_i = T_i a_i, i.e. an implicit (backward Euler) step of the flow
    /// damped by 1/mu; mu -> infinity is a Gauss-Newton step on "zero geodesic curvature".
    /// Large by default: the smallest eigenvalue of the second-difference system is ~(pi/m)^4 for
    /// m samples, and a damping 1/mu above it slows the long-wavelength modes to a crawl (mu = 10
    /// did not converge in 200 steps on icosphere:5; mu = 1e6 converges in 2-32 steps).
    double step = 1e6;
    /// Convergence: max |geodesic curvature| times the mean edge length (dimensionless) below this.
    double tolerance = 1e-4;
    /// Also stop (status "stalled") when no sample moved farther than this times the mean edge
    /// length in a step (displacement after re-projection).
    double update_tolerance = 1e-10;
    std::size_t max_iterations = 200;  ///< cap on flow steps (status "max_iterations")
    /// Weight of the rows that hold the two endpoints in place (> 0). The endpoints are
    /// additionally reset exactly after every step.
    double endpoint_weight = 1e4;
    /// linear solver of a step
    CurvatureFlowSolver solver = CurvatureFlowSolver::eigen_normal_ldlt;
    /// Only with solver == ceres.
    CeresLinearSolver ceres_linear_solver = CeresLinearSolver::sparse_normal_cholesky;
    /// The on-mesh output: false keeps the thesis' plane-cut trace through the samples (output
    /// (b)); true (default) replaces it by the shortest path through the faces that trace crosses
    /// (funnel in their unfolding), moved across vertices where it bends with less than pi on
    /// the other side until none is left: a polyhedral geodesic near the flow's path, the exact
    /// polyhedral distance when the flow found the right face sequence. The plane-cut length is
    /// kept in the report (traced_length).
    bool straighten = true;
    /// Tangent plane of a sample: false takes the one of its nearest vertex (the thesis' rule);
    /// true blends the vertex normals of the sample's face by its barycentric coordinates, a
    /// normal field that does not jump when the nearest vertex changes.
    bool interpolate_normals = false;
};

/// What one flow did. Times are wall-clock seconds.
struct CurvatureFlowReport {
    std::size_t vertices = 0;           ///< mesh vertices
    std::size_t faces = 0;              ///< mesh faces
    std::size_t samples = 0;            ///< samples of the path, endpoints included
    std::size_t iterations = 0;         ///< flow steps taken
    double initial_length = 0;          ///< length of the initial (edge or given) path
    double max_geodesic_curvature = 0;  ///< final max |kappa_g| over interior samples (1/length)
    double scaled_max_geodesic_curvature = 0;  ///< the same times the mean edge length
    double residual = 0;                       ///< final sqrt(sum_i |T_iᵀ second difference_i|^2)
    double max_update = 0;                     ///< largest sample displacement of the last step
    std::size_t trace_fallbacks = 0;   ///< on-mesh segments not plane-cut (joined by edge paths)
    double traced_length = 0;          ///< length of the plane-cut trace through the samples
    bool straightened = false;         ///< on_mesh is the straightened trace (options.straighten)
    std::size_t straighten_flips = 0;  ///< vertices the strip was moved across while straightening
    std::size_t straighten_bends = 0;  ///< vertices the straightened path still turns at (saddles)
    /// on_mesh is the initial path straightened, not the flowed one: the flow ended in a longer
    /// locally shortest path (another homotopy class) than the one the initial path leads to
    bool on_mesh_from_initial = false;
    double init_seconds = 0;  ///< mesh arrays, Dijkstra, resampling
    double flow_seconds = 0;  ///< the iterations
    double seconds = 0;       ///< total
    /// "converged" (curvature below tolerance), "stalled" (moves below update_tolerance first,
    /// e.g. at sharp features where the re-projection undoes the tangent move),
    /// "max_iterations", "unreachable" (endpoints in different components: empty paths)
    std::string status = "ok";
    std::string solver;  ///< name of the linear solver used
};

/// Algorithm 2: where the distance of the fixed sample before the flowed window comes from.
enum class WindowAnchor {
    /// The thesis' rule: the length of the parent's polyline up to that sample. Exact for the
    /// parent's path, but every generation leaves a kink at its anchor in the prefix its children
    /// inherit, and the excess of those kinks adds up along the path (~1-2 % at W = 8).
    prefix,
    /// The anchor's distance is interpolated from the distances and arrival directions of the
    /// visited corners of its face (d_i + g_i . (x - v_i) / 2, barycentric weights: exact for a
    /// quadratic field), and the anchor is slid sideways until the window leaves it in the
    /// direction the field arrives in. Errors then no longer add up per generation.
    field,
};

inline const char* to_string(WindowAnchor a) {
    return a == WindowAnchor::prefix ? "prefix" : "field";
}
/// Knobs of the single-source curvature-flow propagation that meshes (CurvatureFlowDistanceOptions)
/// and point sets (PointCloudDistanceOptions, point_cloud_types.h) share; each method's options
/// derive from it. The window (Algorithm 2's flowed samples) and the flow settings are the
/// methods' own: their defaults differ.
struct FlowPropagationOptions {
    /// Target spacing of the path samples; 0 picks the method's own length (the mean edge length
    /// of a mesh, as the two-point flow does; the cell size of a point set).
    double sample_spacing = 0;
    /// Besides the straightest parent, also continue (and keep the shortest of) the visited
    /// neighbour that gives the smallest tentative distance and those whose geodesics arrive from
    /// a direction over 60 degrees away: where two wavefronts meet (a cut locus, the far side of
    /// a handle) the straightest continuation can come from the longer side. Not in the thesis;
    /// measured on the torus (80 x 32, W = 8): max error 16.6 % without, 0.26 % with it.
    bool cut_locus_guard = true;
    /// Algorithm 2 with the field anchor: paths of at most this many samples are flowed whole
    /// (Algorithm 1 near the source, where the distance field is too curved to interpolate);
    /// 0 picks 2 * window + 1.
    std::size_t near_source_samples = 0;
    /// Algorithm 2 with the field anchor: times the anchor is slid sideways to straighten the
    /// kink between the incoming distance gradient and the flowed window (each slide re-flows).
    std::size_t anchor_slides = 3;
};

/// Single-source distances by curvature flow (gcf_distances, curvature_flow.h): ring-by-ring
/// propagation from a source vertex, each new vertex started from the straightest continuation of
/// a visited neighbour's geodesic and flowed (the thesis' Algorithms 1 and 2). The shared knobs
/// (sample_spacing, cut_locus_guard, near_source_samples, anchor_slides) are in
/// FlowPropagationOptions.
struct CurvatureFlowDistanceOptions : FlowPropagationOptions {
    /// 0: Algorithm 1, the whole polyline of every vertex is flowed (cost and memory grow with the
    /// distance). w > 0: Algorithm 2, only the last w samples are flowed, the sample before them
    /// is held fixed and only w + 1 samples and the fixed prefix length are kept per vertex.
    std::size_t window = 0;
    /// true: d(v) = length of the sample polyline lifted by Phong tessellation (approaches the
    /// smooth surface); false: a length on the faces, like the exact polyhedral distance's (see
    /// polyhedral_length).
    bool smooth_length = true;
    /// With smooth_length = false: true (default) reads d(v) from the polyhedral length of the
    /// flowed samples: each segment traced on the faces (plane cut through both samples, split at
    /// its projected midpoint where no cut reaches the next sample), then the shortest path
    /// through the faces crossed, straightened across vertices (as the two-point flow's on-mesh
    /// output); a flowed path that cannot be traced is replaced by its unflowed start. false:
    /// the chords between the samples, which cut through creases and folds (measured W = 8, mean /
    /// max relative error against exact polyhedral on spot 1.5e-3 / 6.9e-2 with chords, 2.2e-4 /
    /// 1.4e-2 with this; see geodesic/README.md, "shared meshes").
    bool polyhedral_length = true;
    /// false (the thesis' rule): a new vertex w continues the geodesic of the one visited
    /// neighbour u whose edge (u, w) continues it most straightly. true: every visited neighbour's
    /// geodesic is continued and flowed and the shortest result is kept (degree times the cost;
    /// the fixed prefix of Algorithm 2 then accumulates less error).
    bool shortest_parent = false;
    /// With the on-face length (smooth_length = false): after the propagation, every vertex outside
    /// the source's 1-ring whose distance differs from the planar triangle update of its
    /// neighbours' distances by more than this (relative) is re-solved as a two-point path from the
    /// source (GeodesicPathSolver, straightened on-mesh path), started from a fresh search, from
    /// the path of the neighbour u with the smallest d(u) + |uv| with v appended, from the field's
    /// steepest-descent edge path and from a Steiner-graph path (repair_steiner_points, whose graph
    /// distance also flags vertices above it or far below it, repair_graph_margin). Too long: it
    /// keeps the shortest length. Too short (no path on the faces is that short; an anchor
    /// interpolated low): it takes the path's length where that is not above the update or is
    /// closer to it. Then the check runs again with the updated distances (a repaired vertex can
    /// expose its neighbours: a region whose distances are all too long by the same amount passes
    /// the check until its border is mended; a vertex solved before is judged again with its path
    /// length kept), until nothing changes or after `repair_rounds` rounds. Where the geodesic
    /// arrives between the directions of the visited neighbours' paths, no continuation of them is
    /// shortest, and the window cannot turn far enough. Not in the thesis. Negative: off. Measured
    /// (W = 8, fandisk from vertex 0, max error): 2 rounds 1.01 %, 8 rounds 0.84 %, with the
    /// neighbour's path and the re-check 0.51 %; decimated-knight (502 vertices) from vertex 186:
    /// 3.75 % -> 1.25 % (0.81 % with the Steiner-graph start).
    double repair_tolerance = 2e-3;
    std::size_t repair_rounds = 8;  ///< repair passes at most; 0 disables the repair
    /// Flow steps of each re-solved path (its max_iterations). The straightened on-mesh length
    /// decides, and it is the same after 5 steps as after 200 on every shared mesh and the torus
    /// (measured; fandisk's repair took 4.8 s with 200 steps, 0.8 s with 5).
    std::size_t repair_flow_iterations = 10;
    /// Points inside every edge of the Steiner graph (gcf_steiner.h: vertices and these points,
    /// joined across each face) whose single-source shortest paths the repair uses three times: a
    /// vertex whose distance is above its graph distance by more than repair_tolerance is flagged
    /// too (a path on the faces that much shorter exists), each re-solved vertex is also started
    /// from its graph path, and its graph distance is one more path length it may take. Graph
    /// paths cross the faces near the geodesic and so start the flow in its homotopy class where
    /// the other starts end on the wrong side of a saddle vertex (W = 8, decimated-knight from
    /// vertices 0 / 186: max error 1.39 % / 1.25 % without, 0.69 % / 0.81 % with 3 points; with 1
    /// or 2 points one vertex stays 1.01 % long; from vertex 293 one stays 2.47 % long with 3
    /// points, 0.41 % with 8, whose graph path is in the geodesic's class). Edges within 12 mean
    /// edge lengths of the source get 32 points: there a graph path is only a few edges long and
    /// its relative error largest (8 points: up to 4 % on bunny_decimated and blub, 0.8 % with 32).
    /// -1 (default): 8 on meshes under 50,000 vertices, 3 on larger ones (the graph's Dijkstra
    /// costs ~35 us per vertex with 8 points, ~7 with 3). 0: no graph.
    int repair_steiner_points = -1;
    /// With the Steiner graph: a distance below the graph distance by more than this (relative)
    /// is re-solved and replaced by the shortest path found (at most the graph distance) whatever
    /// its neighbours say: no path on the faces is that short. A run of anchors interpolated low
    /// agrees with itself, so the neighbour check misses it (W = 4: blub 29 %, decimated-knight
    /// 32 % short; W = 8: bunny_decimated from vertex 1090 2.0 %, decimated-knight from 420 1.1 %).
    /// The margin must exceed the graph's own error, or exact distances are flagged: with 8 points
    /// (32 near the source) that error is at most 0.78 % on the 12 shared meshes from 5 sources
    /// each (typically 0.2-0.5 %), with 3 points at most 2.2 %.
    /// -1 (default): 0.01 with 8 or more points per edge, 0.03 with fewer. 1: never.
    double repair_graph_margin = -1;
    /// Algorithm 2 only: what the distance at the first flowed sample (the anchor) is.
    WindowAnchor anchor = WindowAnchor::field;
    /// The flow of each vertex (sample_spacing and sample_count are ignored here). Tolerance
    /// 1e-7 instead of the two-point default 1e-4: a kink below 1e-4 would otherwise not be
    /// flowed at all, and on a flat grid the distances are then Euclidean to ~1e-13 instead of
    /// ~3e-8 (measured; the Gauss-Newton steps converge fast, so the cost is small).
    CurvatureFlowOptions flow = [] {
        CurvatureFlowOptions o;
        o.tolerance = 1e-7;
        return o;
    }();
    /// Algorithm 2 (window > 0): flow steps of one window whose path does not reach back to the
    /// source at most (the smaller of this and flow.max_iterations; 0: flow.max_iterations);
    /// paths flowed whole near the source keep flow.max_iterations, so that there Algorithm 2
    /// is Algorithm 1 to the last digit. A window that has not converged within 20
    /// steps creeps while its length hardly changes (measured on the scans at W = 8 with 200
    /// steps: 9 % of the flows ran to the limit and took three quarters of all flow steps); the
    /// repair re-solves whatever is left too long. Algorithm 1 flows whole paths, which need
    /// their steps: the cap does not apply. Against 200 steps (docs/bench_front/table.md,
    /// gcf-window:8/faces/steps:200 beside gcf-window:8/faces): armadillo 24.6 -> 13.3 s, bunny
    /// 3.61 -> 2.16 s, fertility 3.80 -> 2.24 s, errors equal to three digits; icospheres and the
    /// jittered ellipsoid unchanged (their windows converge).
    /// A window stopped by it counts in the report's max_iterations, whose status is then
    /// "max_iterations": some windows were left unconverged, no distance is missing.
    std::size_t window_max_iterations = 20;
};

/// What gcf_distances did, beyond DistanceReport (prepare_seconds: mesh arrays and checks;
/// query_seconds: propagation and repair; unreachable: vertices outside the source's component;
/// status: "ok" when every flow converged or stalled, "max_iterations" when some flow hit the
/// limit, "solver_failure" when some linear solve failed). Times are wall-clock seconds.
struct CurvatureFlowDistanceReport : DistanceReport {
    std::size_t reached = 0;  ///< vertices with a finite distance (source included)
    /// flows run past the 1-ring: a vertex's window is flowed once per candidate parent and again
    /// after each anchor slide (measured 2.5-4.5 per vertex on the shared meshes)
    std::size_t flows = 0;
    std::size_t iterations = 0;       ///< flow steps, all vertices together
    std::size_t converged = 0;        ///< flows ending "converged"
    std::size_t stalled = 0;          ///< flows ending "stalled"
    std::size_t max_iterations = 0;   ///< flows stopped by the iteration limit
    std::size_t solver_failures = 0;  ///< flows whose linear solve failed (path kept as it was)
    std::size_t stored_samples = 0;   ///< samples kept over all vertices (memory, O(n w))
    /// The thesis bounds the error of the window by O(epsilon m). Here epsilon is the largest
    /// length excess, in mean edge lengths, that the fixed anchor of one windowed flow leaves:
    /// |PA| + |AB| - |PB| for the anchor A, the sample B after it and the sample P before it
    /// (WindowAnchor::prefix) or one spacing back along the arrival direction of the distance
    /// field (WindowAnchor::field); 0 for Algorithm 1. m (max_faces) is the largest number of
    /// faces holding samples of one vertex's path (runs on one face counted once).
    double epsilon = 0;
    std::size_t max_faces = 0;  ///< most faces one vertex's path crosses
    /// epsilon * max_faces * mean edge length: the bound, in the mesh's unit, on how far the
    /// windowed distances may lie from the whole-path flow (Algorithm 1), with constant 1.
    double error_bound = 0;
    std::size_t repair_checked = 0;   ///< vertices re-solved as two-point paths (repair_tolerance)
    std::size_t repair_improved = 0;  ///< of them, those whose distance the two-point path replaced
    /// re-solved because the Steiner graph's distance says so (above it by more than
    /// repair_tolerance, or below it by more than repair_graph_margin) and the neighbours do not
    std::size_t repair_graph_flagged = 0;
    double repair_graph_seconds = 0;  ///< the Steiner graph's share of repair_seconds
    double repair_seconds = 0;        ///< the repair's share of `seconds`
    double sample_spacing = 0;        ///< the spacing used
};

}  // namespace tapeline::geodesic
