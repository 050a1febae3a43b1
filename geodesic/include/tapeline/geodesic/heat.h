// Approximate geodesic distances by the heat method through CGAL's `Heat_method_3`:
// K. Crane, C. Weischedel, M. Wardetzky, "Geodesics in heat: a new approach to computing distance
// based on heat flow", ACM TOG 32(5), 2013; optional intrinsic Delaunay Laplacian after
// M. Fisher, B. Springborn, P. Schroeder, A. Bobenko, "An algorithm for the construction of
// intrinsic Delaunay triangulations with applications to digital geometry processing", 2006.
//
// The solver copies every connected component that has faces into its own CGAL::Surface_mesh and
// factorises one CGAL solver per component. Why:
//  - CGAL 5.5 builds one Laplacian for the whole mesh; on a component without a source the heat is
//    0, the normalised gradient 0/0, and CGAL hands out DBL_MAX there (measured), so other
//    components are kept out of the solve (they get +infinity);
//  - isolated vertices have no Laplacian row worth the name; they are left out the same way;
//  - the CGAL templates are instantiated for one mesh type, whatever the input type.
// Guards (see geodesic/README.md): degenerate faces are rejected before the intrinsic Delaunay
// flips can loop (CGAL#5010); several sources are solved one by one by default (CGAL PR #9565:
// the joint normalisation is biased); face-location sources are rejected (CGAL 5.5 takes vertex
// sources only); a NaN result is a SolverFailure; CGAL's own failures become SolverFailure.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/geodesic_types.h>
#include <tapeline/geodesic/internal/mesh_checks.h>
#include <tapeline/geodesic/internal/named_parameters.h>
#include <tapeline/geodesic/sources.h>

#include <CGAL/Heat_method_3/Surface_mesh_geodesic_distances_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/exceptions.h>

#include <boost/property_map/property_map.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <memory>
#include <sstream>
#include <vector>

namespace tapeline::geodesic {

namespace internal {

/// One connected component copied into a Surface_mesh, with its prefactored heat solver.
template <class Kernel>
class HeatComponent {
public:
    using Mesh = CGAL::Surface_mesh<typename Kernel::Point_3>;
    using DirectSolver = CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<
        Mesh, CGAL::Heat_method_3::Direct, CGAL::Default, CGAL::Default, Kernel>;
    using IdtSolver = CGAL::Heat_method_3::Surface_mesh_geodesic_distances_3<
        Mesh, CGAL::Heat_method_3::Intrinsic_Delaunay, CGAL::Default, CGAL::Default, Kernel>;

    Mesh mesh;
    std::vector<std::size_t> global;  ///< local vertex index -> input vertex index

    HeatComponent() = default;
    HeatComponent(const HeatComponent&) = delete;
    HeatComponent& operator=(const HeatComponent&) = delete;
    ~HeatComponent();

    /// Builds and factorises CGAL's solver on `mesh` (which must not change afterwards).
    void factorise(bool intrinsic_delaunay);

    /// Heat distances from local source vertices; `out` is indexed by local vertex.
    void solve(const std::vector<std::size_t>& local_sources, std::vector<double>& out);

private:
    std::unique_ptr<DirectSolver> direct_;
    std::unique_ptr<IdtSolver> idt_;
};

// Out of class and not inline, so that `extern template class HeatComponent<K>;` keeps the
// Heat_method_3 instantiations in one translation unit (DESIGN.md §5).
template <class Kernel>
HeatComponent<Kernel>::~HeatComponent() = default;

template <class Kernel>
void HeatComponent<Kernel>::factorise(bool intrinsic_delaunay) {
    if (intrinsic_delaunay)
        idt_ = std::make_unique<IdtSolver>(mesh);
    else
        direct_ = std::make_unique<DirectSolver>(mesh);
}

template <class Kernel>
void HeatComponent<Kernel>::solve(const std::vector<std::size_t>& local_sources,
                                  std::vector<double>& out) {
    out.assign(num_vertices(mesh), 0.0);
    auto map = boost::make_iterator_property_map(out.begin(), get(boost::vertex_index, mesh));
    auto run = [&](auto& solver) {
        solver.clear_sources();
        for (std::size_t s : local_sources)
            solver.add_source(typename Mesh::Vertex_index(static_cast<std::uint32_t>(s)));
        solver.estimate_geodesic_distances(map);
    };
    if (idt_)
        run(*idt_);
    else
        run(*direct_);
    // CGAL 5.5 turns an internal NaN into DBL_MAX (value_at_source_set keeps its initial max()
    // when every comparison with NaN fails): make it a NaN again so that the caller's NaN check
    // reports a SolverFailure instead of a silent absurd distance.
    for (double& x : out)
        if (!(x < std::numeric_limits<double>::max()))
            x = std::numeric_limits<double>::quiet_NaN();
}

}  // namespace internal

/// Prefactored heat method: the constructor does the source-independent work (copy and Cholesky
/// factorisations, report().prepare_seconds); each distances() call does the solves.
/// Each connected component gets its own factorisation.
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
///         (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map` and `face_index_map` (`ReadablePropertyMap`s onto [0, n)),
///         `geom_traits` (a CGAL kernel).
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
class HeatDistanceSolver {
    using P = internal::MeshParameters<TriangleMesh, NamedParameters>;
    using GT = boost::graph_traits<TriangleMesh>;
    using Kernel = typename P::GeomTraits;
    using Index =
        internal::MeshIndex<TriangleMesh, typename P::VertexIndexMap, typename P::FaceIndexMap>;
    using Component = internal::HeatComponent<Kernel>;
    static constexpr std::size_t npos = std::numeric_limits<std::size_t>::max();

public:
    using vertex_descriptor = typename GT::vertex_descriptor;  ///< a vertex of the mesh

    /// Checks the mesh, copies each component and factorises its operators.
    ///
    /// \param tm the mesh; it must outlive the solver and stay unchanged.
    /// \param options intrinsic Delaunay, time step, multi-source mode, degenerate-face check.
    /// \param np the named parameters listed with the class.
    /// \throws TopologyError when a face is not a triangle.
    /// \throws InvalidInput on a non-finite coordinate or an index map that is not a bijection
    ///         onto [0, n) (a Surface_mesh with removed elements needs collect_garbage()).
    /// \throws InvalidInput also on a degenerate face when `options.intrinsic_delaunay` or
    ///         `options.reject_degenerate_faces` is set.
    /// \throws TopologyError also when a face cannot be copied into its component's mesh
    ///         (non-manifold input).
    /// \throws SolverFailure when CGAL's Heat_method_3 fails to factorise.
    explicit HeatDistanceSolver(const TriangleMesh& tm, const HeatOptions& options = {},
                                const NamedParameters& np = CGAL::parameters::default_values())
        : tm_(tm),
          index_(tm, P::vertex_index_map(tm, np), P::face_index_map(tm, np), where(options)),
          options_(options) {
        const auto vpm = P::vertex_point_map(tm, np);
        internal::check_triangle_mesh(tm, vpm, index_.vertex_index_map(), index_.face_index_map(),
                                      where(options));
        if (options.intrinsic_delaunay || options.reject_degenerate_faces)
            reject_degenerate_faces(vpm);
        components_ = internal::connected_components(tm, index_);
        report_.method = where(options);
        report_.vertices = index_.vertex_count();
        report_.faces = index_.face_count();
        report_.components = components_.count;

        const auto t0 = internal::Clock::now();
        // Split the faces by component and copy each component into its own Surface_mesh.
        const std::size_t n = index_.vertex_count();
        solver_of_component_.assign(components_.count, npos);
        component_of_.assign(n, npos);
        local_of_.assign(n, npos);
        for (auto f : faces(tm)) {
            const auto fv = internal::face_vertices(f, tm);
            const std::size_t label = components_.label[index_.index(fv[0])];
            if (solver_of_component_[label] == npos) {
                solver_of_component_[label] = parts_.size();
                parts_.push_back(std::make_unique<Component>());
            }
            const std::size_t c = solver_of_component_[label];
            Component& part = *parts_[c];
            typename Component::Mesh::Vertex_index lv[3];
            for (int k = 0; k < 3; ++k) {
                const std::size_t g = index_.index(fv[k]);
                if (local_of_[g] == npos) {
                    const auto& p = get(vpm, fv[k]);
                    local_of_[g] = part.global.size();
                    component_of_[g] = c;
                    part.global.push_back(g);
                    part.mesh.add_vertex(typename Kernel::Point_3(p.x(), p.y(), p.z()));
                }
                lv[k] = typename Component::Mesh::Vertex_index(
                    static_cast<std::uint32_t>(local_of_[g]));
            }
            if (part.mesh.add_face(lv[0], lv[1], lv[2]) == Component::Mesh::null_face()) {
                std::ostringstream s;
                s << where(options) << ": face #" << index_.index(f)
                  << " could not be copied into the per-component mesh (non-manifold input?)";
                throw TopologyError(s.str());
            }
        }
        try {
            for (auto& part : parts_)
                part->factorise(options.intrinsic_delaunay);
        } catch (const CGAL::Failure_exception& e) {
            throw SolverFailure(std::string(where(options)) +
                                ": CGAL Heat_method_3 failed during factorisation: " + e.what());
        }
        report_.prepare_seconds = internal::seconds_since(t0);
    }

    /// Heat distances from vertex sources into `distances` (+infinity on components without a
    /// source). A face-location source is rejected with InvalidInput.
    ///
    /// \tparam VertexDistanceMap a model of `WritablePropertyMap` with key vertex_descriptor and
    ///         value double.
    /// \throws InvalidInput when `sources` is empty, holds a face location, or a vertex that is
    ///         not on the mesh.
    /// \throws SolverFailure when a solve fails or yields NaN (a vanishing heat gradient on a
    ///         coarse or symmetric mesh); `distances` is left untouched then.
    template <class VertexDistanceMap>
    DistanceReport distances(const SourceSet<TriangleMesh>& sources, VertexDistanceMap distances) {
        const char* w = where(options_);
        if (sources.empty())
            throw InvalidInput(std::string(w) + ": the source set is empty");
        if (!sources.locations.empty())
            throw InvalidInput(std::string(w) +
                               ": a face-location source is not supported by the heat method "
                               "(CGAL 5.5 Heat_method_3 takes vertex sources only); use a vertex "
                               "source, or exact_cgal / dijkstra for surface points");
        std::vector<std::size_t> src;
        for (auto v : sources.vertices)
            src.push_back(index_.checked(v, "source vertex"));
        std::sort(src.begin(), src.end());
        src.erase(std::unique(src.begin(), src.end()), src.end());

        const auto t0 = internal::Clock::now();
        const std::size_t n = index_.vertex_count();
        std::vector<double> d(n, internal::kInfinity);
        std::vector<std::vector<std::size_t>> local_sources(parts_.size());
        for (std::size_t g : src) {
            if (component_of_[g] == npos)
                d[g] = 0.0;  // isolated vertex (or on a face-less component): its own distance
            else
                local_sources[component_of_[g]].push_back(local_of_[g]);
        }
        std::vector<double> local;
        try {
            for (std::size_t c = 0; c < parts_.size(); ++c) {
                const auto& ls = local_sources[c];
                if (ls.empty())
                    continue;
                Component& part = *parts_[c];
                if (options_.multi_source == HeatMultiSource::cgal_joint || ls.size() == 1) {
                    part.solve(ls, local);
                    for (std::size_t i = 0; i < local.size(); ++i)
                        d[part.global[i]] = local[i];
                } else {
                    for (std::size_t s : ls) {
                        part.solve({s}, local);
                        for (std::size_t i = 0; i < local.size(); ++i) {
                            double& di = d[part.global[i]];
                            // keep NaN visible to the check in write_distances
                            di = (std::isnan(local[i]) || std::isnan(di)) ? local[i]
                                                                          : std::min(di, local[i]);
                        }
                    }
                }
            }
        } catch (const CGAL::Failure_exception& e) {
            throw SolverFailure(std::string(w) +
                                ": CGAL Heat_method_3 failed in a solve: " + e.what());
        }
        for (std::size_t i = 0; i < d.size(); ++i)
            if (std::isnan(d[i]))
                // CGAL normalises the heat gradient per face; where the heat is equal at a
                // face's three corners (a coarse, symmetric mesh) that is 0 / 0.
                throw SolverFailure(std::string(w) +
                                    ": CGAL Heat_method_3 returned NaN at vertex #" +
                                    std::to_string(i) +
                                    ": the heat gradient vanishes on a face (a mesh too coarse "
                                    "or too symmetric for the heat method); refine the mesh or "
                                    "use exact-mmp");
        DistanceReport report = report_;
        report.sources = sources.size();
        report.unreachable = internal::write_distances(d, index_, distances, w);
        report.query_seconds = internal::seconds_since(t0);
        report.seconds = report.prepare_seconds + report.query_seconds;
        return report;
    }

    /// Heat distances from one vertex; as the source-set overload.
    template <class VertexDistanceMap>
    DistanceReport distances(vertex_descriptor source, VertexDistanceMap distances) {
        return this->distances(SourceSet<TriangleMesh>(source), distances);
    }

    /// Sizes and pre-computation time of the factorisation.
    const DistanceReport& report() const { return report_; }
    /// The options the solver runs with.
    const HeatOptions& options() const { return options_; }

private:
    static const char* where(const HeatOptions& o) {
        return o.intrinsic_delaunay ? "heat_idt" : "heat";
    }

    template <class VertexPointMap>
    void reject_degenerate_faces(VertexPointMap vpm) const {
        for (auto f : faces(tm_)) {
            const double slack = internal::relative_slack(f, tm_, vpm);
            if (!(slack > options_.degenerate_face_tolerance)) {
                std::ostringstream s;
                s << where(options_) << ": face #" << index_.index(f)
                  << " is degenerate (relative triangle-inequality slack " << slack
                  << " <= degenerate_face_tolerance " << options_.degenerate_face_tolerance
                  << "); zero-area faces make the heat method's cotan weights NaN and its "
                     "intrinsic Delaunay flips loop forever (CGAL#5010): remove them first "
                     "(e.g. Polygon_mesh_processing::remove_degenerate_faces)";
                throw InvalidInput(s.str());
            }
        }
    }

    const TriangleMesh& tm_;
    Index index_;
    HeatOptions options_;
    internal::Components components_;
    std::vector<std::unique_ptr<Component>> parts_;
    std::vector<std::size_t> solver_of_component_;  ///< component label -> parts_ index
    std::vector<std::size_t> component_of_;         ///< input vertex -> parts_ index or npos
    std::vector<std::size_t> local_of_;             ///< input vertex -> local vertex index
    DistanceReport report_;
};

/// One-shot heat distances (factorise + one query).
///
/// \tparam TriangleMesh a model of `FaceListGraph`, `VertexListGraph` and `EdgeListGraph`
///         (CGAL::Surface_mesh, CGAL::Polyhedron_3, ...), every face a triangle.
/// \tparam VertexDistanceMap a model of `WritablePropertyMap` with key vertex_descriptor and
///         value double.
/// \tparam NamedParameters a sequence of CGAL named parameters; accepted: `vertex_point_map`
///         (a `ReadablePropertyMap` vertex_descriptor -> `geom_traits::Point_3`),
///         `vertex_index_map` and `face_index_map` (`ReadablePropertyMap`s onto [0, n)),
///         `geom_traits` (a CGAL kernel).
/// \throws TopologyError when a face is not a triangle.
/// \throws InvalidInput on a non-finite coordinate or an index map that is not a bijection
///         onto [0, n) (a Surface_mesh with removed elements needs collect_garbage()).
/// \throws InvalidInput also on a degenerate face when `options.intrinsic_delaunay` or
///         `options.reject_degenerate_faces` is set.
/// \throws TopologyError also when a face cannot be copied into its component's mesh
///         (non-manifold input).
/// \throws SolverFailure when CGAL's Heat_method_3 fails to factorise.
/// \throws InvalidInput when `sources` is empty, holds a face location, or a vertex that is
///         not on the mesh.
/// \throws SolverFailure when a solve fails or yields NaN (a vanishing heat gradient on a
///         coarse or symmetric mesh); `distances` is left untouched then.
template <class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
DistanceReport heat_distances(const TriangleMesh& tm, const SourceSet<TriangleMesh>& sources,
                              VertexDistanceMap distances, const HeatOptions& options = {},
                              const NamedParameters& np = CGAL::parameters::default_values()) {
    HeatDistanceSolver<TriangleMesh, NamedParameters> solver(tm, options, np);
    return solver.distances(sources, distances);
}

/// One-shot heat distances from one vertex; as the source-set overload.
template <class TriangleMesh, class VertexDistanceMap,
          class NamedParameters = CGAL::parameters::Default_named_parameters>
DistanceReport heat_distances(const TriangleMesh& tm,
                              typename boost::graph_traits<TriangleMesh>::vertex_descriptor source,
                              VertexDistanceMap distances, const HeatOptions& options = {},
                              const NamedParameters& np = CGAL::parameters::default_values()) {
    return heat_distances(tm, SourceSet<TriangleMesh>(source), distances, options, np);
}

}  // namespace tapeline::geodesic
