// Test facade for the baseline geodesic methods (DESIGN.md §5): plain functions compiled once in
// tapeline_test_support_geodesic (support/geodesic_*.cpp); test files include gtest and this.
//
// Meshes are polygon soups; vertex i and face j of the CGAL mesh built from a soup are point i
// and polygon j of the soup, on CGAL::Surface_mesh<Epick::Point_3> and on
// CGAL::Polyhedron_3<Epick, Polyhedron_items_with_id_3> alike. Barycentric coordinates in this
// facade refer to the corners of the soup polygon in soup order.
#pragma once

#include <tapeline/geodesic/geodesic_types.h>

#include <array>
#include <cstddef>
#include <string>
#include <vector>

namespace tapeline_test::geodesic {

using tapeline::geodesic::DistanceReport;
using tapeline::geodesic::HeatMultiSource;
using tapeline::geodesic::HeatOptions;
using Vec3 = std::array<double, 3>;

struct Soup {
    std::vector<Vec3> points;
    std::vector<std::vector<std::size_t>> faces;
};

enum class Method { exact, heat, heat_idt, dijkstra, fast_marching };
const char* name(Method m);

enum class MeshKind {
    surface_mesh,
    polyhedron,
    /// Surface_mesh whose last face was removed without collect_garbage() (bad index maps).
    surface_mesh_with_garbage,
};

/// A vertex (index) or a point in a face (index + barycentric coordinates over the soup corners).
struct SurfacePoint {
    bool on_face = false;
    std::size_t index = 0;
    Vec3 bary{0, 0, 0};
    static SurfacePoint vertex(std::size_t v) { return {false, v, {0, 0, 0}}; }
    static SurfacePoint face(std::size_t f, Vec3 b) { return {true, f, b}; }
};

struct Sources {
    std::vector<SurfacePoint> points;
    static Sources vertex(std::size_t v) { return {{SurfacePoint::vertex(v)}}; }
};

struct Field {
    std::vector<double> d;  ///< per soup vertex
    DistanceReport report;
};

/// Runs one method through its one-shot free function. Options only matter for heat / heat_idt
/// (heat_idt forces intrinsic_delaunay = true); fast_marching runs with its default options
/// (tapeline_test/fast_marching.h takes others and returns the whole report).
Field distances(const Soup& soup, Method method, const Sources& sources,
                MeshKind kind = MeshKind::surface_mesh, HeatOptions heat = {});

/// One HeatDistanceSolver, several queries (its report carries the factorisation time).
std::vector<Field> heat_queries(const Soup& soup, const std::vector<Sources>& queries,
                                HeatOptions heat = {}, MeshKind kind = MeshKind::surface_mesh);

/// ExactCgalSolver built once from `sources`, queried at several targets.
struct PathResult {
    std::vector<Vec3> points;  ///< from the source to the target
    double length = 0;         ///< polyline length
    double distance = 0;       ///< solver.distance_to(target)
};
std::vector<PathResult> exact_paths(const Soup& soup, const Sources& sources,
                                    const std::vector<SurfacePoint>& targets,
                                    MeshKind kind = MeshKind::surface_mesh);
/// The free function exact_cgal_path.
PathResult exact_path(const Soup& soup, const SurfacePoint& from, const SurfacePoint& to,
                      MeshKind kind = MeshKind::surface_mesh);

// --- meshes and truth (support/geodesic_meshes.cpp) -------------------------------------------

/// A surface of tapeline::SurfaceSpec::parse(spec) as a soup.
Soup surface(const std::string& spec);
/// data/spot.obj (closed, genus 0, 2930 vertices).
Soup spot();
/// An .obj or .off mesh of TAPELINE_SHARED_DATA_DIR (e.g. "bodies/mh_male_average.obj");
/// false if absent.
bool shared_mesh(const std::string& relative_path, Soup& out);
/// Flat square [0, size]^2 in the z = 0 plane, (n+1)^2 vertices; vertex (i, j) is j*(n+1)+i.
/// Diagonals alternate, or all go from (i, j) to (i+1, j+1).
Soup flat_grid(std::size_t n, double size, bool alternate_diagonals = true);
/// flat_grid(n, 1) with every cell cut along the same diagonal, then sheared by x += 2y: convex
/// (a parallelogram, so distances are Euclidean) with every face's corners at 8, 18 and 153
/// degrees.
Soup sheared_grid(std::size_t n);
/// Smooth truth from tapeline::analytic_distances; empty when the surface has none.
std::vector<double> analytic_distances(const std::string& spec, const Soup& soup,
                                       std::size_t source);
double mean_edge_length(const Soup& soup);
/// Euclidean distance from p to the closest triangle of the soup (brute force).
double distance_to_surface(const Soup& soup, const Vec3& p);
Vec3 position(const Soup& soup, const SurfacePoint& p);
double euclidean(const Vec3& p, const Vec3& q);
/// The vertex of a sphere-like soup (centred at the origin) whose angle from vertex `a`, seen
/// from the origin, is closest to `degrees`.
std::size_t vertex_at_angle(const Soup& soup, std::size_t a, double degrees);

/// Errors of `d` against `truth` over the vertices with truth > 0 (finite).
struct ErrorStats {
    double mean_rel = 0;     ///< mean |d - t| / t
    double max_rel = 0;      ///< max |d - t| / t
    double max_rel_far = 0;  ///< max |d - t| / t over t > 0.1 max(t) (near-source ratios are noisy)
    double max_abs = 0;      ///< max |d - t|
    double max_signed = -1e300;  ///< max (d - t)
    double min_signed = 1e300;   ///< min (d - t)
    std::size_t count = 0;
};
ErrorStats compare(const std::vector<double>& d, const std::vector<double>& truth);

/// Appends a copy of `b` with its points moved by `offset` (a second connected component).
Soup disjoint_union(const Soup& a, const Soup& b, const Vec3& offset);

}  // namespace tapeline_test::geodesic

#ifdef TAPELINE_TEST_GEODESIC_WITH_CGAL
// Internals shared by the support translation units only (never by test files): the CGAL mesh
// types of the tests and the conversions from the plain facade types.
#include <tapeline/geodesic/sources.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Polyhedron_items_with_id_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/graph_traits_Polyhedron_3.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

namespace tapeline_test::geodesic::cgal {

using Kernel = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Kernel::Point_3>;
using Polyhedron = CGAL::Polyhedron_3<Kernel, CGAL::Polyhedron_items_with_id_3>;

void build(const Soup& soup, SurfaceMesh& tm, bool leave_garbage = false);
void build(const Soup& soup, Polyhedron& tm);

/// Vertex i / face j, unchecked for Surface_mesh (an out-of-range index gives a descriptor the
/// library must reject), null for Polyhedron.
boost::graph_traits<SurfaceMesh>::vertex_descriptor vertex_at(SurfaceMesh& tm, std::size_t i);
boost::graph_traits<Polyhedron>::vertex_descriptor vertex_at(Polyhedron& tm, std::size_t i);
boost::graph_traits<SurfaceMesh>::face_descriptor face_at(SurfaceMesh& tm, std::size_t j);
boost::graph_traits<Polyhedron>::face_descriptor face_at(Polyhedron& tm, std::size_t j);

/// Soup barycentric coordinates are reordered into the PMP Face_location order.
tapeline::geodesic::SurfacePoint<SurfaceMesh> surface_point(SurfaceMesh& tm, const Soup& soup,
                                                            const SurfacePoint& p);
tapeline::geodesic::SurfacePoint<Polyhedron> surface_point(Polyhedron& tm, const Soup& soup,
                                                           const SurfacePoint& p);

template <class Mesh>
tapeline::geodesic::SourceSet<Mesh> source_set(Mesh& tm, const Soup& soup, const Sources& s) {
    tapeline::geodesic::SourceSet<Mesh> out;
    for (const auto& p : s.points)
        out.add(surface_point(tm, soup, p));
    return out;
}

inline Vec3 to_vec3(const Kernel::Point_3& p) {
    return {p.x(), p.y(), p.z()};
}

/// Builds the mesh of the requested kind from `soup` and calls `run(mesh)`.
template <class Run>
auto with_mesh(const Soup& soup, MeshKind kind, Run&& run) {
    if (kind == MeshKind::polyhedron) {
        Polyhedron tm;
        build(soup, tm);
        return run(tm);
    }
    SurfaceMesh tm;
    build(soup, tm, kind == MeshKind::surface_mesh_with_garbage);
    return run(tm);
}

/// Per-method entry points, one translation unit each (geodesic_<method>.cpp).
Field exact_field(const Soup& soup, const Sources& sources, MeshKind kind);
Field heat_field(const Soup& soup, const Sources& sources, MeshKind kind, HeatOptions heat);
Field dijkstra_field(const Soup& soup, const Sources& sources, MeshKind kind);

}  // namespace tapeline_test::geodesic::cgal
#endif
