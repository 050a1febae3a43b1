// Turns a prepared soup into a CGAL triangle mesh (any MutableFaceGraph), triangulating polygons
// with CGAL::Polygon_mesh_processing::triangulate_faces, and measures what downstream methods care
// about: degenerate and needle faces, boundary loops, connected components.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/internal/soup_repair.h>
#include <tapeline/core/mesh_io_types.h>

#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/shape_predicates.h>
#include <CGAL/Polygon_mesh_processing/triangulate_faces.h>
#include <CGAL/Surface_mesh/Surface_mesh_fwd.h>
#include <CGAL/boost/graph/Euler_operations.h>
#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

namespace tapeline::internal {

inline constexpr double kPi = 3.14159265358979323846;

/// Only Surface_mesh gets a capacity hint: for a vector-based Polyhedron_3 a wrong reserve would
/// invalidate handles, and list-based meshes do not need one.
template <class Mesh>
struct IsSurfaceMesh : std::false_type {};
template <class Point>
struct IsSurfaceMesh<CGAL::Surface_mesh<Point>> : std::true_type {};

/// Carries the input face index from a polygon to the triangles it is cut into.
template <class TriangleMesh, class FaceOriginMap>
struct FaceOriginVisitor {
    using face_descriptor = typename boost::graph_traits<TriangleMesh>::face_descriptor;
    FaceOriginMap* map = nullptr;
    std::size_t current = 0;
    void before_subface_creations(face_descriptor f) { current = get(*map, f); }
    void after_subface_created(face_descriptor f) { put(*map, f, current); }
    void after_subface_creations() {}
};

/// Smallest interior angle of a triangle, in radians (0 for a degenerate one).
template <class Point>
double smallest_angle(const Point& p, const Point& q, const Point& r) {
    const double a[3] = {CGAL::to_double(p.x()), CGAL::to_double(p.y()), CGAL::to_double(p.z())};
    const double b[3] = {CGAL::to_double(q.x()), CGAL::to_double(q.y()), CGAL::to_double(q.z())};
    const double c[3] = {CGAL::to_double(r.x()), CGAL::to_double(r.y()), CGAL::to_double(r.z())};
    const double* corners[3] = {a, b, c};
    double smallest = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 3; ++k) {
        const double* o = corners[k];
        const double* u = corners[(k + 1) % 3];
        const double* w = corners[(k + 2) % 3];
        const double e1[3] = {u[0] - o[0], u[1] - o[1], u[2] - o[2]};
        const double e2[3] = {w[0] - o[0], w[1] - o[1], w[2] - o[2]};
        const double cx = e1[1] * e2[2] - e1[2] * e2[1];
        const double cy = e1[2] * e2[0] - e1[0] * e2[2];
        const double cz = e1[0] * e2[1] - e1[1] * e2[0];
        const double dot = e1[0] * e2[0] + e1[1] * e2[1] + e1[2] * e2[2];
        // atan2 of |cross| and dot stays accurate for tiny angles, unlike acos.
        smallest = std::min(smallest, std::atan2(std::sqrt(cx * cx + cy * cy + cz * cz), dot));
    }
    return smallest;
}

/// Builds `loaded.mesh` (empty on entry) and fills every field of `loaded` (a LoadedMesh).
template <class Loaded>
void build_loaded_mesh(PreparedSoup&& soup, const PolygonSoup& input,
                       const MeshLoadOptions& options, Loaded& loaded) {
    using TriangleMesh = std::remove_reference_t<decltype(loaded.mesh)>;
    using GT = boost::graph_traits<TriangleMesh>;
    using vertex_descriptor = typename GT::vertex_descriptor;
    using halfedge_descriptor = typename GT::halfedge_descriptor;
    using face_descriptor = typename GT::face_descriptor;
    namespace PMP = CGAL::Polygon_mesh_processing;

    TriangleMesh& tm = loaded.mesh;
    MeshReport& report = loaded.report;
    const SoupNames name(input);
    auto warn = [&](const std::string& text) { report.warnings.push_back(name.file() + text); };

    if constexpr (IsSurfaceMesh<TriangleMesh>::value) {
        using size_type = typename TriangleMesh::size_type;
        std::size_t corners = 0;
        for (const auto& f : soup.faces) {
            corners += f.size();
        }
        // Triangulating polygons adds corners - 3 * faces edges and faces at most.
        tm.reserve(static_cast<size_type>(soup.points.size()), static_cast<size_type>(corners),
                   static_cast<size_type>(corners));
    }
    auto vpm = get(CGAL::vertex_point, tm);
    using Point = typename boost::property_traits<decltype(vpm)>::value_type;
    auto vertex_origin = get(CGAL::dynamic_vertex_property_t<std::size_t>(), tm);
    auto face_origin = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);

    std::vector<vertex_descriptor> created;
    created.reserve(soup.points.size());
    for (std::size_t k = 0; k < soup.points.size(); ++k) {
        const auto& p = soup.points[k];
        const vertex_descriptor v = add_vertex(tm);
        put(vpm, v, Point(p[0], p[1], p[2]));
        put(vertex_origin, v, soup.point_origin[k]);
        created.push_back(v);
    }
    std::vector<vertex_descriptor> corners;
    bool has_polygons = false;
    for (std::size_t j = 0; j < soup.faces.size(); ++j) {
        corners.clear();
        for (std::size_t v : soup.faces[j]) {
            corners.push_back(created[v]);
        }
        const face_descriptor f = CGAL::Euler::add_face(corners, tm);
        if (f == GT::null_face()) {
            // prepare_soup guarantees a manifold, oriented soup; reaching this is a bug.
            throw TopologyError(name.file() + name.face(soup.face_origin[j]) +
                                " cannot be added to the mesh (internal error: the repaired soup "
                                "is not a polygon mesh)");
        }
        put(face_origin, f, soup.face_origin[j]);
        has_polygons = has_polygons || soup.faces[j].size() > 3;
    }
    soup.points.clear();
    soup.faces.clear();

    if (has_polygons) {
        FaceOriginVisitor<TriangleMesh, decltype(face_origin)> visitor;
        visitor.map = &face_origin;
        PMP::triangulate_faces(tm, CGAL::parameters::visitor(visitor));
        // Polygons CGAL could not triangulate (zero normal, i.e. collinear corners) are cut
        // into fans; the triangles are then reported as degenerate.
        std::vector<face_descriptor> left;
        for (face_descriptor f : faces(tm)) {
            if (degree(f, tm) > 3) {
                left.push_back(f);
            }
        }
        for (face_descriptor f : left) {
            const std::size_t origin = get(face_origin, f);
            halfedge_descriptor h = halfedge(f, tm);
            while (degree(face(h, tm), tm) > 3) {
                const halfedge_descriptor cut =
                    CGAL::Euler::split_face(h, next(next(h, tm), tm), tm);
                put(face_origin, face(cut, tm), origin);
                put(face_origin, face(opposite(cut, tm), tm), origin);
                h = degree(face(cut, tm), tm) > 3 ? cut : opposite(cut, tm);
            }
        }
    }

    // Per-vertex and per-face bookkeeping, in mesh order.
    for (vertex_descriptor v : vertices(tm)) {
        loaded.vertices.push_back(v);
        loaded.input_index.push_back(get(vertex_origin, v));
    }
    for (face_descriptor f : faces(tm)) {
        loaded.faces.push_back(f);
        loaded.face_input_index.push_back(get(face_origin, f));
    }
    loaded.input_vertex_count = soup.input_vertex_count;
    // Copies per input vertex; a merged duplicate shares the copies of its representative.
    {
        const std::size_t n = soup.input_vertex_count;
        std::vector<std::size_t> own(n + 1, 0);
        for (std::size_t i : loaded.input_index) {
            ++own[i + 1];
        }
        for (std::size_t i = 0; i < n; ++i) {
            own[i + 1] += own[i];
        }
        std::vector<std::size_t> own_list(loaded.input_index.size());
        std::vector<std::size_t> fill(own.begin(), own.end() - 1);
        for (std::size_t k = 0; k < loaded.input_index.size(); ++k) {
            own_list[fill[loaded.input_index[k]]++] = k;
        }
        loaded.copies_begin.assign(n + 1, 0);
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t r = soup.representative[i];
            loaded.copies_begin[i + 1] = loaded.copies_begin[i] + own[r + 1] - own[r];
        }
        loaded.copies.resize(loaded.copies_begin[n]);
        for (std::size_t i = 0, out = 0; i < n; ++i) {
            const std::size_t r = soup.representative[i];
            for (std::size_t k = own[r]; k < own[r + 1]; ++k) {
                loaded.copies[out++] = own_list[k];
            }
        }
    }
    report.vertices = loaded.vertices.size();
    report.faces = loaded.faces.size();

    // Degenerate and needle faces.
    const double needle = options.needle_angle_degrees * kPi / 180.0;
    const std::size_t none = std::numeric_limits<std::size_t>::max();
    std::size_t first_degenerate = none, first_needle = none;
    double first_needle_angle = 0;
    for (std::size_t j = 0; j < loaded.faces.size(); ++j) {
        const face_descriptor f = loaded.faces[j];
        const std::size_t origin = loaded.face_input_index[j];
        if (PMP::is_degenerate_triangle_face(f, tm)) {
            ++report.degenerate_faces;
            first_degenerate = std::min(first_degenerate, origin);
            continue;
        }
        const halfedge_descriptor h = halfedge(f, tm);
        const double angle = smallest_angle(get(vpm, source(h, tm)), get(vpm, target(h, tm)),
                                            get(vpm, target(next(h, tm), tm)));
        if (angle < needle) {
            ++report.needle_faces;
            if (origin < first_needle) {
                first_needle = origin;
                first_needle_angle = angle * 180.0 / kPi;
            }
        }
    }
    if (report.degenerate_faces > 0) {
        warn(plural(report.degenerate_faces, "degenerate (zero-area) triangle",
                    "degenerate (zero-area) triangles") +
             " (first: in input " + name.face(first_degenerate) + ")");
    }
    if (report.needle_faces > 0) {
        std::ostringstream angle;
        angle.precision(3);
        angle << first_needle_angle;
        std::ostringstream limit;
        limit << options.needle_angle_degrees;
        warn(plural(report.needle_faces, "needle triangle", "needle triangles") +
             " with an angle below " + limit.str() + " degrees (first: in input " +
             name.face(first_needle) + ", smallest angle " + angle.str() + " degrees)");
    }

    // Boundary loops; name the loop through the lowest input vertex.
    std::vector<halfedge_descriptor> cycles;
    PMP::extract_boundary_cycles(tm, std::back_inserter(cycles));
    report.boundary_loops = cycles.size();
    if (!cycles.empty()) {
        std::size_t best_vertex = none, best_edges = 0;
        for (halfedge_descriptor c : cycles) {
            std::size_t lowest = none, edges = 0;
            for (halfedge_descriptor h : CGAL::halfedges_around_face(c, tm)) {
                lowest = std::min(lowest, get(vertex_origin, target(h, tm)));
                ++edges;
            }
            if (lowest < best_vertex) {
                best_vertex = lowest;
                best_edges = edges;
            }
        }
        warn(plural(report.boundary_loops, "boundary loop", "boundary loops") +
             " (first: the loop through " + name.vertex(best_vertex) + ", " +
             plural(best_edges, "edge", "edges") + ")");
    }

    // Connected components, ordered by their lowest input face.
    auto component = get(CGAL::dynamic_face_property_t<std::size_t>(), tm);
    report.components = PMP::connected_components(tm, component);
    if (report.components > 1) {
        std::vector<std::size_t> size(report.components, 0), lowest(report.components, none);
        for (std::size_t j = 0; j < loaded.faces.size(); ++j) {
            const std::size_t c = get(component, loaded.faces[j]);
            ++size[c];
            lowest[c] = std::min(lowest[c], loaded.face_input_index[j]);
        }
        std::vector<std::size_t> order(report.components);
        std::iota(order.begin(), order.end(), std::size_t{0});
        std::sort(order.begin(), order.end(),
                  [&](std::size_t a, std::size_t b) { return lowest[a] < lowest[b]; });
        std::string sizes;
        for (std::size_t k = 0; k < order.size() && k < 5; ++k) {
            sizes += (k ? ", " : "") + std::to_string(size[order[k]]);
        }
        sizes += order.size() > 5 ? ", ..." : "";
        warn(std::to_string(report.components) + " connected components of " + sizes +
             " triangles (first: the second component contains input " +
             name.face(lowest[order[1]]) + ")");
    }
}

}  // namespace tapeline::internal
