// Options and reports of the baseline geodesic methods (exact CGAL, heat, Dijkstra, fast
// marching).
//
// Light header without CGAL (DESIGN.md §3): loggers, benchmark drivers and test facades include it
// to read and print what an algorithm did without paying for the CGAL templates.
#pragma once

#include <cstddef>
#include <limits>
#include <string>
#include <vector>

namespace tapeline::geodesic {

/// What one distance computation did: the part every distance method reports the same way (the
/// exact methods, heat, Dijkstra and the curvature flows on meshes and point sets derive their
/// reports from it), so that a caller can time, size and check any method generically. Times are
/// wall-clock seconds.
struct DistanceReport {
    std::string method;           ///< "exact_mmp", "exact_cgal", "heat", "gcf_window", ...
    std::size_t vertices = 0;     ///< vertices of the input mesh (points of a point set)
    std::size_t faces = 0;        ///< faces of the input mesh (0 for a point set)
    std::size_t sources = 0;      ///< source points (vertices + face locations) as given
    std::size_t unreachable = 0;  ///< vertices given +infinity (other component, isolated vertex)
    std::size_t components = 0;   ///< connected components of the mesh (isolated vertices count)
    /// Source-independent work: SMSP object construction, heat factorisation, MMP mesh arrays,
    /// curvature-flow set-up, point-set kNN and grid (0 for Dijkstra).
    double prepare_seconds = 0;
    /// Source-dependent work: SMSP sources + sequence tree + reading, heat solves, Dijkstra run,
    /// window propagation, curvature-flow propagation and repair.
    double query_seconds = 0;
    double seconds = 0;         ///< prepare_seconds + query_seconds: the whole call
    std::string status = "ok";  ///< "ok" or a short reason when a non-fatal guard fired
    std::string message;        ///< human-readable detail for status
};

/// Surface_mesh_shortest_path has no behavioural knob in CGAL 5.5; the struct exists so that the
/// call shape is the same for every method and options can be logged.
struct ExactCgalOptions {};

/// How several source vertices are handled by the heat method.
enum class HeatMultiSource {
    /// One heat solve per source vertex, then the minimum per vertex. Costs one back-substitution
    /// pair per source but is immune to the multi-source normalisation bug of CGAL 5.5
    /// `Heat_method_3` (CGAL PR #9565: distances ~0.5x the truth near the source set).
    min_of_single_sources,
    /// One solve with all sources, as CGAL 5.5 does it (fast, biased; kept to measure the bias).
    cgal_joint,
};

inline const char* to_string(HeatMultiSource m) {
    return m == HeatMultiSource::cgal_joint ? "cgal_joint" : "min_of_single_sources";
}

/// Heat method (Crane, Weischedel, Wardetzky 2013) as CGAL 5.5 `Heat_method_3` exposes it.
/// CGAL 5.5 fixes the time step to t = h^2 (h = mean edge length of the component) and the linear
/// solver to Eigen's SimplicialLDLT; neither is a knob here.
struct HeatOptions {
    /// Build the Laplacian on the intrinsic Delaunay triangulation (Fisher et al. 2006), CGAL's
    /// `Intrinsic_Delaunay` mode; otherwise the cotan Laplacian of the input (`Direct`).
    bool intrinsic_delaunay = false;
    /// how several sources combine
    HeatMultiSource multi_source = HeatMultiSource::min_of_single_sources;
    /// A face is degenerate when its relative triangle-inequality slack
    /// min(b + c - a) / (a + b + c) is <= this value. Degenerate faces make the iDT edge flips loop
    /// forever (CGAL#5010) and the cotan weights NaN; they are rejected with InvalidInput.
    double degenerate_face_tolerance = 1e-12;
    /// Only for the Direct mode: false skips the degenerate-face check and lets CGAL run (used to
    /// observe what plain heat does on zero-area faces; a NaN result is then a SolverFailure).
    /// The intrinsic-Delaunay mode always checks, since it would not terminate.
    bool reject_degenerate_faces = true;
};

/// Dijkstra on the edge graph has no behavioural knob; see ExactCgalOptions.
struct DijkstraOptions {};

/// Fast marching on triangle meshes (Kimmel and Sethian 1998; fast_marching.h).
struct FastMarchingOptions {
    /// Split every obtuse corner by a virtual edge to a vertex found by unfolding the faces
    /// beyond its opposite edge into the corner's plane, at an acute angle to both of the corner's
    /// edges (Kimmel and Sethian, section 4). Without it an obtuse corner is updated from its own
    /// face only, and the front can pass it before the values it needs are final (larger errors
    /// on meshes with obtuse faces; kept as a knob to measure that).
    bool unfold_obtuse = true;
    /// At most this many faces are unfolded for one obtuse corner; a corner whose section holds
    /// no vertex within them (or that meets the border first) keeps its own face's update.
    std::size_t max_unfold_faces = 32;
};

/// DistanceReport plus what the fast marching did.
struct FastMarchingReport : DistanceReport {
    std::size_t obtuse_corners = 0;  ///< corners with an angle above 90 degrees
    std::size_t virtual_edges = 0;   ///< obtuse corners split by a virtual edge
    std::size_t unsplit_obtuse = 0;  ///< obtuse corners left without one (border, cap)
    std::size_t face_updates = 0;    ///< two-vertex (plane-wave) updates that were accepted
    std::size_t edge_updates = 0;    ///< one-vertex updates (along an edge) that were accepted
};

/// A shortest path on the surface: polyline from the start point to the end point.
/// An unreachable end point is an empty polyline with length +infinity.
template <class Point>
struct GeodesicPath {
    std::vector<Point> points;  ///< polyline from the source to the target
    double length = std::numeric_limits<double>::infinity();  ///< polyline length
    bool found() const { return !points.empty(); }  ///< false when the target is unreachable
};

}  // namespace tapeline::geodesic
