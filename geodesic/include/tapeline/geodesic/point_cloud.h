// Geodesic distances and paths on point sets in R^D sampling a k-dimensional manifold, by geodesic
// curvature flow: the point-cloud section of the project's virtual-clothing thesis draft (shared
// seed 000_cb1f07c4c9923062, "Geodesic on Point Cloud", Algorithm 3), written from its
// description: the d nearest points of a sample define its neighbourhood, a regular grid covers
// the points and the mean of each non-empty cell is a destination, the propagation runs over the
// grid's cells as Algorithm 2 does over a mesh's vertices. The flow is the one of
// curvature_flow.h (gcf_engine.h) with D-dimensional samples and k-dimensional tangent spaces.
// Local surfaces: the PCA plane of the neighbours, or a moving-least-squares quadric over it
// (D. Levin, "Mesh-independent surface interpolation", 2003; one projection step). Neighbours:
// CGAL Spatial_searching or nanoflann (gcf_knn.h).
//
// Input: a PointRange and a point_map (CGAL named parameter; default: the range's values are the
// points) whose points are CGAL points of any dimension (Point_2, Point_3, Point_d: anything with
// cartesian_begin()/cartesian_end()) or ranges of coordinates (std::array, std::vector, Eigen
// vectors); optionally a normal_map (hypersurfaces only: the tangent space is then orthogonal to
// the given normal). Distances are written into a property map keyed by the point's index in the
// range (0 .. size - 1).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/internal/gcf_points.h>
#include <tapeline/geodesic/point_cloud_types.h>

#include <CGAL/Named_function_parameters.h>
#include <CGAL/number_utils.h>
#include <CGAL/property_map.h>
#include <boost/property_map/property_map.hpp>

#include <iterator>
#include <memory>
#include <string>
#include <type_traits>
#include <utility>
#include <vector>

namespace tapeline::geodesic {

namespace internal::point_cloud {

template <class P, class = void>
struct HasCartesian : std::false_type {};
template <class P>
struct HasCartesian<P, std::void_t<decltype(std::declval<const P&>().cartesian_begin()),
                                   decltype(std::declval<const P&>().cartesian_end())>>
    : std::true_type {};

/// Appends the coordinates of p to out; returns how many.
template <class P>
std::size_t append_coordinates(const P& p, std::vector<double>& out) {
    std::size_t n = 0;
    if constexpr (HasCartesian<P>::value) {
        for (auto it = p.cartesian_begin(); it != p.cartesian_end(); ++it, ++n)
            out.push_back(CGAL::to_double(*it));
    } else {
        using std::begin;
        using std::end;
        for (auto it = begin(p); it != end(p); ++it, ++n)
            out.push_back(static_cast<double>(*it));
    }
    return n;
}

template <class PointRange, class NamedParameters>
struct Maps {
    using Value = typename std::iterator_traits<typename PointRange::const_iterator>::value_type;
    using PointMap = typename CGAL::internal_np::Lookup_named_param_def<
        CGAL::internal_np::point_t, NamedParameters, CGAL::Identity_property_map<Value>>::type;
    using NormalParam = typename CGAL::internal_np::Get_param<typename NamedParameters::base,
                                                              CGAL::internal_np::normal_t>::type;
    static constexpr bool has_normals =
        !std::is_same<NormalParam, CGAL::internal_np::Param_not_found>::value;
};

/// Reads the points (and normals) into pr.xyz (pr.normals), checking that every point has the
/// same number of coordinates.
template <class PointRange, class NamedParameters>
void read_points(const PointRange& points, const NamedParameters& np, gcf::points::Prepared& pr,
                 const char* where) {
    using CGAL::parameters::choose_parameter;
    using CGAL::parameters::get_parameter;
    using M = Maps<PointRange, NamedParameters>;
    const typename M::PointMap pmap =
        choose_parameter<typename M::PointMap>(get_parameter(np, CGAL::internal_np::point_map));
    std::size_t i = 0;
    for (const auto& item : points) {
        const std::size_t got = append_coordinates(get(pmap, item), pr.xyz);
        if (i == 0)
            pr.dim = got;
        else if (got != pr.dim)
            throw InvalidInput(std::string(where) + ": point #" + std::to_string(i) + " has " +
                               std::to_string(got) + " coordinates, point #0 has " +
                               std::to_string(pr.dim));
        if constexpr (M::has_normals) {
            const auto nmap = get_parameter(np, CGAL::internal_np::normal_map);
            const std::size_t gn = append_coordinates(get(nmap, item), pr.normals);
            if (gn != pr.dim)
                throw InvalidInput(std::string(where) + ": normal #" + std::to_string(i) + " has " +
                                   std::to_string(gn) + " coordinates, its point " +
                                   std::to_string(pr.dim));
        }
        ++i;
    }
    pr.n = i;
    if (i == 0)
        throw InvalidInput(std::string(where) + ": no points");
}

}  // namespace internal::point_cloud

/// Reusable set-up on one point set: the checks, the kNN graph, the manifold dimension, the grid
/// and its nodes (projected onto the local surfaces), the local charts (fitted on first use and
/// kept). Build once, query many sources or pairs; queries may run concurrently.
///
/// \tparam PointRange a model of `ConstRange` (std::vector, ...) whose values the `point_map`
///         maps to points: CGAL points of any dimension (anything with cartesian_begin() and
///         cartesian_end()) or ranges of coordinates (std::array, std::vector, Eigen).
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `point_map` (a
///         `ReadablePropertyMap` from the range's value type to a point; default: identity)
///         and `normal_map` (a `ReadablePropertyMap` to a normal of the same dimension;
///         hypersurfaces only).
template <class PointRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
class PointCloudGeodesicSolver {
public:
    /// Prefix of every error message of the point-cloud method.
    static constexpr const char* kWhere = "gcf_point_cloud";

    /// InvalidInput (one line naming the point or option): no points, fewer points than
    /// options.neighbours + 1, points with different numbers of coordinates, a non-finite
    /// coordinate, two points at the same position, bad options.
    ///
    /// \param points the samples; read once, not kept.
    /// \param options neighbours, grid, projection, window and the flow's options.
    /// \param np the named parameters listed with the class.
    /// \throws InvalidInput (one line naming the point or option) on no points, fewer points than
    ///         options.neighbours + 1, points or normals with different numbers of coordinates,
    ///         a non-finite coordinate, two points at the same position, or bad options.
    explicit PointCloudGeodesicSolver(
        const PointRange& points, const PointCloudDistanceOptions& options = {},
        const NamedParameters& np = CGAL::parameters::default_values())
        : options_(options), pr_(std::make_unique<internal::gcf::points::Prepared>()) {
        const auto t0 = internal::gcf::points::Clock::now();
        internal::point_cloud::read_points(points, np, *pr_, kWhere);
        internal::gcf::points::prepare(*pr_, options_, kWhere);
        engine_ = internal::gcf::points::make_engine(*pr_, options_);
        pr_->report.sample_spacing =
            options_.sample_spacing > 0 ? options_.sample_spacing : pr_->cell;
        pr_->report.prepare_seconds = internal::gcf::points::since(t0);
    }

    /// Distances from point `source` (index in the range) to every point, written as
    /// put(distances, i, d) for i in 0 .. size - 1; +infinity for points the propagation does not
    /// reach (another component of the cell graph). InvalidInput for a source out of range.
    ///
    /// \tparam PointDistanceMap a model of `WritablePropertyMap` with key std::size_t (the point's
    ///         index in the range) and value double.
    /// \throws InvalidInput when `source` is not an index of the range.
    template <class PointDistanceMap>
    PointCloudDistanceReport distances(std::size_t source, PointDistanceMap distances) const {
        const auto t0 = internal::gcf::points::Clock::now();
        check_index(source, "source");
        auto q = engine_->distances(static_cast<std::uint32_t>(source));
        PointCloudDistanceReport r = pr_->report;
        fill(r, q);
        for (std::size_t i = 0; i < pr_->n; ++i) {
            put(distances, i, q.d[i]);
            if (std::isfinite(q.d[i]))
                ++r.reached;
        }
        r.unreachable = pr_->n - r.reached;
        r.method = "gcf_points";
        r.vertices = pr_->n;
        r.sources = 1;
        r.query_seconds = internal::gcf::points::since(t0);
        r.seconds = r.prepare_seconds + r.query_seconds;
        return r;
    }

    /// Geodesic path between points `from` and `to` (indices in the range): the node path of
    /// Dijkstra over the cells, resampled and flowed whole (Algorithm 1 between two points).
    /// Endpoints are the two points projected onto their local surfaces (the points themselves on
    /// clean samples). Different components: empty path, length +infinity, status "unreachable".
    ///
    /// \throws InvalidInput when `from` or `to` is not an index of the range, or from == to.
    PointCloudPath path(std::size_t from, std::size_t to) const {
        const auto t0 = internal::gcf::points::Clock::now();
        check_index(from, "from");
        check_index(to, "to");
        if (from == to)
            throw InvalidInput(std::string(kWhere) + ": path from a point to itself (from = to = " +
                               std::to_string(from) + ")");
        auto q = engine_->path(static_cast<std::uint32_t>(from), static_cast<std::uint32_t>(to));
        PointCloudPath out;
        out.dimension = pr_->dim;
        out.coordinates = std::move(q.path);
        out.length = q.length;
        out.status = q.status;
        out.report = pr_->report;
        fill(out.report, q);
        out.report.seconds = internal::gcf::points::since(t0);
        return out;
    }

    /// Sizes and set-up timings.
    const PointCloudDistanceReport& report() const { return pr_->report; }
    /// Number of points.
    std::size_t size() const { return pr_->n; }
    /// Dimension D of the ambient space (coordinates per point).
    std::size_t dimension() const { return pr_->dim; }
    /// The node (grid cell) of each point, and the nodes' count: for tests and drawings.
    const std::vector<std::uint32_t>& point_nodes() const { return pr_->point_node; }

private:
    void check_index(std::size_t i, const char* what) const {
        if (i >= pr_->n)
            throw InvalidInput(std::string(kWhere) + ": " + what + " point #" + std::to_string(i) +
                               " out of range (" + std::to_string(pr_->n) + " points)");
    }
    static void fill(PointCloudDistanceReport& r, const internal::gcf::points::QueryResult& q) {
        r.reached_nodes = q.reached_nodes;
        q.counts.write(r);
        r.charts = q.charts;
        r.propagate_seconds = q.propagate_seconds;
        r.interpolate_seconds = q.interpolate_seconds;
        r.status = q.counts.failed           ? "solver_failure"
                   : q.counts.max_iterations ? "max_iterations"
                                             : "ok";
    }

    PointCloudDistanceOptions options_;
    // Behind a pointer: the engine refers to it, and the solver may be moved.
    std::unique_ptr<internal::gcf::points::Prepared> pr_;
    std::unique_ptr<internal::gcf::points::EngineBase> engine_;
};

/// One-shot: geodesic distances from points[source_index] to every point (the thesis' Algorithm
/// 3; see PointCloudGeodesicSolver). The report's seconds include the set-up.
///
/// \tparam PointRange a model of `ConstRange` (std::vector, ...) whose values the `point_map`
///         maps to points: CGAL points of any dimension (anything with cartesian_begin() and
///         cartesian_end()) or ranges of coordinates (std::array, std::vector, Eigen).
/// \tparam PointDistanceMap a model of `WritablePropertyMap` with key std::size_t (the point's
///         index in the range) and value double.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `point_map` (a
///         `ReadablePropertyMap` from the range's value type to a point; default: identity)
///         and `normal_map` (a `ReadablePropertyMap` to a normal of the same dimension;
///         hypersurfaces only).
/// \throws InvalidInput (one line naming the point or option) on no points, fewer points than
///         options.neighbours + 1, points or normals with different numbers of coordinates,
///         a non-finite coordinate, two points at the same position, or bad options.
/// \throws InvalidInput when `source_index` is not an index of the range.
template <class PointRange, class PointDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
PointCloudDistanceReport gcf_point_cloud_distances(
    const PointRange& points, std::size_t source_index, PointDistanceMap distance_out,
    const PointCloudDistanceOptions& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
    const auto t0 = internal::gcf::points::Clock::now();
    const PointCloudGeodesicSolver<PointRange, NamedParameters> solver(points, options, np);
    PointCloudDistanceReport r = solver.distances(source_index, distance_out);
    r.seconds = internal::gcf::points::since(t0);
    return r;
}

/// One-shot: geodesic path between points[from] and points[to] (see
/// PointCloudGeodesicSolver::path).
///
/// \tparam PointRange a model of `ConstRange` (std::vector, ...) whose values the `point_map`
///         maps to points: CGAL points of any dimension (anything with cartesian_begin() and
///         cartesian_end()) or ranges of coordinates (std::array, std::vector, Eigen).
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `point_map` (a
///         `ReadablePropertyMap` from the range's value type to a point; default: identity)
///         and `normal_map` (a `ReadablePropertyMap` to a normal of the same dimension;
///         hypersurfaces only).
/// \throws InvalidInput (one line naming the point or option) on no points, fewer points than
///         options.neighbours + 1, points or normals with different numbers of coordinates,
///         a non-finite coordinate, two points at the same position, or bad options.
/// \throws InvalidInput when `from` or `to` is not an index of the range, or from == to.
template <class PointRange, class NamedParameters = CGAL::parameters::Default_named_parameters>
PointCloudPath gcf_point_cloud_path(
    const PointRange& points, std::size_t from, std::size_t to,
    const PointCloudDistanceOptions& options = {},
    const NamedParameters& np = CGAL::parameters::default_values()) {
    const auto t0 = internal::gcf::points::Clock::now();
    const PointCloudGeodesicSolver<PointRange, NamedParameters> solver(points, options, np);
    PointCloudPath p = solver.path(from, to);
    p.report.seconds = internal::gcf::points::since(t0);
    return p;
}

}  // namespace tapeline::geodesic
