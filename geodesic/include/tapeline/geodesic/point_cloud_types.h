// Options and reports of geodesics on point sets by geodesic curvature flow (point_cloud.h).
//
// Light header without CGAL (DESIGN.md §3): loggers, benchmark drivers and test facades include it
// to read and print what the propagation did without paying for the CGAL templates.
#pragma once

#include <tapeline/geodesic/curvature_flow_types.h>

#include <cstddef>
#include <string>
#include <vector>

namespace tapeline::geodesic {

/// How a sample of a path is put back onto the surface the points sample.
enum class PointCloudProjection {
    /// Onto the least-squares plane of the d nearest points (PCA); tangent space = that plane.
    plane,
    /// Onto the moving-least-squares quadric of the d nearest points: the normal coordinates as a
    /// weighted quadratic polynomial of the tangent coordinates over the PCA plane (one MLS step,
    /// Levin's projection without its iteration); tangent space = that of the quadric at the
    /// projected point. Needs d >= 1 + k + k (k + 1) / 2 + 2 neighbours (8 for surfaces).
    mls,
};

inline const char* to_string(PointCloudProjection p) {
    return p == PointCloudProjection::plane ? "plane" : "mls";
}

/// k-nearest-neighbour search used to build the neighbourhoods.
enum class PointCloudKnn {
    /// nanoflann when the header <nanoflann.hpp> (Debian libnanoflann-dev) is available, else
    /// CGAL: nanoflann measured faster (see the README, "Point clouds").
    automatic,
    /// CGAL Spatial_searching: Orthogonal_k_neighbor_search on a Kd_tree with D-dimensional
    /// search traits over the point array.
    cgal,
    /// nanoflann::KDTreeSingleIndexAdaptor (InvalidInput when the header was not available).
    nanoflann,
};

inline const char* to_string(PointCloudKnn k) {
    switch (k) {
        case PointCloudKnn::cgal:
            return "cgal";
        case PointCloudKnn::nanoflann:
            return "nanoflann";
        default:
            return "automatic";
    }
}

/// Behaviour of the point-cloud propagation (the thesis' Algorithm 3). Lengths are in the
/// points' unit. The knobs shared with meshes (sample_spacing, 0 = the cell size;
/// cut_locus_guard; near_source_samples; anchor_slides) are in FlowPropagationOptions.
struct PointCloudDistanceOptions : FlowPropagationOptions {
    /// Edge length of the regular grid's cubic cells; each non-empty cell is one destination node
    /// (the mean of its points, projected onto the local surface). 0 picks the median distance
    /// of a point to its d-th nearest neighbour (a few points per cell).
    double cell_size = 0;
    /// d: the neighbours of a point that define its tangent space (PCA) and local surface.
    std::size_t neighbours = 16;
    /// Samples flowed per node (Algorithm 2's window, field-anchored as on meshes); 0 flows the
    /// whole path of every node (Algorithm 1; cost grows with the distance).
    std::size_t window = 8;
    /// Dimension k of the manifold the points sample; 0 estimates it from the PCA spectra of
    /// sampled neighbourhoods (largest eigenvalue gap, median over the samples).
    std::size_t manifold_dimension = 0;
    PointCloudProjection projection = PointCloudProjection::mls;  ///< local surface of a sample
    PointCloudKnn knn = PointCloudKnn::automatic;  ///< nearest-neighbour search library
    /// The flow of each node (sample_spacing and sample_count ignored; the ceres solver is for
    /// meshes only and is rejected). Tolerance 1e-4 and at most 30 steps, not the 1e-7 of mesh
    /// distances: a sample's surface is the chart of its nearest input point, which changes
    /// from step to step by the fitting error of the charts, so the flow stops improving at
    /// that level (measured on 10k points of the unit sphere: the same mean and max error at
    /// tolerance 1e-7, 1e-5 and 1e-4 and at 200 or 30 steps, 2.2x faster clean and 3-5x
    /// faster under 0.1-0.5 % noise, where flows otherwise spend 200 steps oscillating).
    CurvatureFlowOptions flow = [] {
        CurvatureFlowOptions o;
        o.tolerance = 1e-4;
        o.max_iterations = 30;
        return o;
    }();
    /// The flow of two-point paths (flowed whole: long polylines need more steps).
    CurvatureFlowOptions path_flow = [] {
        CurvatureFlowOptions o;
        o.tolerance = 1e-4;
        o.max_iterations = 300;
        return o;
    }();
};

/// What the preparation and a query did, beyond DistanceReport (vertices and points: the input
/// points; prepare_seconds: checks, kNN, grid, dimension estimate, all of set-up; query_seconds:
/// one query; seconds: the whole call, set-up included for one-shot calls; unreachable: input
/// points left at +infinity (other components); status: "ok" when every flow converged or
/// stalled, "max_iterations", "solver_failure"). Times are wall-clock seconds.
struct PointCloudDistanceReport : DistanceReport {
    std::size_t points = 0;                     ///< number of input points
    std::size_t dimension = 0;                  ///< D, of the ambient space
    std::size_t manifold_dimension = 0;         ///< k used (given or estimated)
    bool manifold_dimension_estimated = false;  ///< k came from the PCA spectra
    std::size_t neighbours = 0;                 ///< neighbours per point used
    double cell_size = 0;                       ///< the cell size used
    double sample_spacing = 0;                  ///< sample spacing used
    std::size_t nodes = 0;                      ///< non-empty cells
    std::size_t node_edges = 0;                 ///< pairs of neighbouring non-empty cells
    /// Grid components joined through their closest k-nearest-neighbour pair (sampling sparser
    /// than the cell somewhere); 0 when the grid of non-empty cells was connected.
    std::size_t bridged_components = 0;
    std::size_t window = 0;           ///< window used (samples flowed per vertex)
    std::string projection;           ///< local surface used
    std::string knn;                  ///< the backend used: "cgal" or "nanoflann"
    std::size_t reached_nodes = 0;    ///< nodes with a finite distance
    std::size_t reached = 0;          ///< input points with a finite distance (source included)
    std::size_t flows = 0;            ///< flows run (several per node with the cut-locus guard)
    std::size_t iterations = 0;       ///< flow steps, all flows together
    std::size_t converged = 0;        ///< flows ending "converged"
    std::size_t stalled = 0;          ///< flows ending "stalled"
    std::size_t max_iterations = 0;   ///< flows stopped by the iteration limit
    std::size_t solver_failures = 0;  ///< flows whose linear solve failed
    std::size_t charts = 0;           ///< local surfaces fitted (lazily, per input point)
    double knn_seconds = 0;           ///< k-nearest-neighbour graph (index build and queries)
    double grid_seconds = 0;          ///< grid, nodes and their adjacency
    double propagate_seconds = 0;     ///< the propagation over the nodes
    double interpolate_seconds = 0;   ///< node distances to every input point
};

/// A geodesic path between two input points: the flowed samples (endpoints are the two points as
/// given), D coordinates per sample.
struct PointCloudPath {
    std::size_t dimension = 0;        ///< D, coordinates per sample
    std::vector<double> coordinates;  ///< sample i is [D i, D i + D)
    double length = 0;                ///< polyline length; +infinity if unreachable
    /// number of samples
    std::size_t samples() const { return dimension ? coordinates.size() / dimension : 0; }
    PointCloudDistanceReport report;  ///< sizes and timings; flows/iterations of this path
    std::string status = "ok";        ///< flow outcome, or "unreachable" (empty path)
};

}  // namespace tapeline::geodesic
