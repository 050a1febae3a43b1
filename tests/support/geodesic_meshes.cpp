// Test meshes, smooth truth and the soup -> CGAL mesh conversions of the geodesic tests.
#define TAPELINE_TEST_GEODESIC_WITH_CGAL
#include <tapeline_test/fast_marching.h>
#include <tapeline_test/geodesic.h>

#include <tapeline/surfaces/analytic_geodesics.h>
#include <tapeline/surfaces/analytic_surface_types.h>

#include <CGAL/IO/OBJ.h>
#include <CGAL/IO/OFF.h>
#include <CGAL/boost/graph/copy_face_graph.h>
#include <CGAL/boost/graph/helpers.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iterator>
#include <limits>
#include <stdexcept>

namespace tapeline_test::geodesic {

const char* name(Method m) {
    switch (m) {
        case Method::exact:
            return "exact_cgal";
        case Method::heat:
            return "heat";
        case Method::heat_idt:
            return "heat_idt";
        case Method::dijkstra:
            return "dijkstra";
        case Method::fast_marching:
            return "fast_marching";
    }
    return "?";
}

Field distances(const Soup& soup, Method method, const Sources& sources, MeshKind kind,
                HeatOptions heat) {
    switch (method) {
        case Method::exact:
            return cgal::exact_field(soup, sources, kind);
        case Method::heat:
            return cgal::heat_field(soup, sources, kind, heat);
        case Method::heat_idt:
            heat.intrinsic_delaunay = true;
            return cgal::heat_field(soup, sources, kind, heat);
        case Method::dijkstra:
            return cgal::dijkstra_field(soup, sources, kind);
        case Method::fast_marching: {
            FastMarchingField f = fast_marching(soup, sources, {}, kind);
            return Field{std::move(f.d), f.report};
        }
    }
    throw std::logic_error("unknown method");
}

Soup surface(const std::string& spec) {
    const tapeline::SurfaceSoup s = tapeline::generate_surface(tapeline::SurfaceSpec::parse(spec));
    Soup out;
    out.points = s.points;
    for (const auto& t : s.triangles)
        out.faces.push_back({t[0], t[1], t[2]});
    return out;
}

Soup spot() {
    std::vector<cgal::Kernel::Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    const std::string path = std::string(TAPELINE_DATA_DIR) + "/spot.obj";
    if (!CGAL::IO::read_OBJ(path, points, polygons))
        throw std::runtime_error("cannot read " + path);
    Soup out;
    for (const auto& p : points)
        out.points.push_back(cgal::to_vec3(p));
    out.faces = std::move(polygons);
    return out;
}

bool shared_mesh(const std::string& relative_path, Soup& out) {
    const std::string path = std::string(TAPELINE_SHARED_DATA_DIR) + "/" + relative_path;
    if (!std::ifstream(path))
        return false;
    std::vector<cgal::Kernel::Point_3> points;
    std::vector<std::vector<std::size_t>> polygons;
    const bool off = path.size() > 4 && path.compare(path.size() - 4, 4, ".off") == 0;
    if (!(off ? CGAL::IO::read_OFF(path, points, polygons)
              : CGAL::IO::read_OBJ(path, points, polygons)))
        throw std::runtime_error("cannot read " + path);
    out = Soup{};
    for (const auto& p : points)
        out.points.push_back(cgal::to_vec3(p));
    out.faces = std::move(polygons);
    return true;
}

Soup flat_grid(std::size_t n, double size, bool alternate_diagonals) {
    Soup out;
    for (std::size_t j = 0; j <= n; ++j)
        for (std::size_t i = 0; i <= n; ++i)
            out.points.push_back({size * double(i) / double(n), size * double(j) / double(n), 0});
    auto id = [n](std::size_t i, std::size_t j) { return j * (n + 1) + i; };
    for (std::size_t j = 0; j < n; ++j)
        for (std::size_t i = 0; i < n; ++i) {
            const std::size_t a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1),
                              d = id(i, j + 1);
            if (!alternate_diagonals || (i + j) % 2 == 0) {
                out.faces.push_back({a, b, c});
                out.faces.push_back({a, c, d});
            } else {
                out.faces.push_back({a, b, d});
                out.faces.push_back({b, c, d});
            }
        }
    return out;
}

Soup sheared_grid(std::size_t n) {
    Soup out = flat_grid(n, 1.0, /*alternate_diagonals=*/false);
    for (auto& p : out.points)
        p[0] += 2.0 * p[1];
    return out;
}

std::vector<double> analytic_distances(const std::string& spec, const Soup& soup,
                                       std::size_t source) {
    return tapeline::analytic_distances(tapeline::SurfaceSpec::parse(spec), soup.points, source);
}

double mean_edge_length(const Soup& soup) {
    double sum = 0;
    std::size_t count = 0;
    for (const auto& f : soup.faces)
        for (std::size_t k = 0; k < f.size(); ++k) {
            const Vec3& p = soup.points[f[k]];
            const Vec3& q = soup.points[f[(k + 1) % f.size()]];
            sum += std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
            ++count;
        }
    return count ? sum / double(count) : 0.0;
}

double distance_to_surface(const Soup& soup, const Vec3& p) {
    using K = cgal::Kernel;
    const K::Point_3 q(p[0], p[1], p[2]);
    double best = std::numeric_limits<double>::infinity();
    for (const auto& f : soup.faces) {
        const auto& a = soup.points[f[0]];
        const auto& b = soup.points[f[1]];
        const auto& c = soup.points[f[2]];
        const K::Triangle_3 t(K::Point_3(a[0], a[1], a[2]), K::Point_3(b[0], b[1], b[2]),
                              K::Point_3(c[0], c[1], c[2]));
        best = std::min(best, CGAL::squared_distance(q, t));
    }
    return std::sqrt(best);
}

Vec3 position(const Soup& soup, const SurfacePoint& p) {
    if (!p.on_face)
        return soup.points.at(p.index);
    const auto& f = soup.faces.at(p.index);
    Vec3 out{0, 0, 0};
    for (int k = 0; k < 3; ++k)
        for (int c = 0; c < 3; ++c)
            out[c] += p.bary[k] * soup.points[f[k]][c];
    return out;
}

double euclidean(const Vec3& p, const Vec3& q) {
    return std::hypot(p[0] - q[0], p[1] - q[1], p[2] - q[2]);
}

std::size_t vertex_at_angle(const Soup& soup, std::size_t a, double degrees) {
    const auto& p = soup.points[a];
    std::size_t best = a;
    double best_err = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < soup.points.size(); ++i) {
        const auto& q = soup.points[i];
        const double c = (p[0] * q[0] + p[1] * q[1] + p[2] * q[2]) /
                         (euclidean(p, {0, 0, 0}) * euclidean(q, {0, 0, 0}));
        const double ang = std::acos(std::max(-1.0, std::min(1.0, c))) * 180.0 / M_PI;
        if (std::abs(ang - degrees) < best_err) {
            best_err = std::abs(ang - degrees);
            best = i;
        }
    }
    return best;
}

ErrorStats compare(const std::vector<double>& d, const std::vector<double>& truth) {
    ErrorStats s;
    double tmax = 0;
    for (double t : truth)
        if (std::isfinite(t))
            tmax = std::max(tmax, t);
    for (std::size_t i = 0; i < d.size() && i < truth.size(); ++i) {
        const double t = truth[i];
        if (!(t > 0) || !std::isfinite(t))
            continue;
        const double rel = std::abs(d[i] - t) / t;
        s.mean_rel += rel;
        s.max_rel = std::max(s.max_rel, rel);
        if (t > 0.1 * tmax)
            s.max_rel_far = std::max(s.max_rel_far, rel);
        s.max_abs = std::max(s.max_abs, std::abs(d[i] - t));
        s.max_signed = std::max(s.max_signed, d[i] - t);
        s.min_signed = std::min(s.min_signed, d[i] - t);
        ++s.count;
    }
    if (s.count)
        s.mean_rel /= double(s.count);
    return s;
}

Soup disjoint_union(const Soup& a, const Soup& b, const Vec3& offset) {
    Soup out = a;
    const std::size_t base = a.points.size();
    for (const auto& p : b.points)
        out.points.push_back({p[0] + offset[0], p[1] + offset[1], p[2] + offset[2]});
    for (auto f : b.faces) {
        for (auto& v : f)
            v += base;
        out.faces.push_back(f);
    }
    return out;
}

namespace cgal {

void build(const Soup& soup, SurfaceMesh& tm, bool leave_garbage) {
    tm.clear();
    for (const auto& p : soup.points)
        tm.add_vertex(Kernel::Point_3(p[0], p[1], p[2]));
    for (const auto& f : soup.faces) {
        std::vector<SurfaceMesh::Vertex_index> vs;
        for (auto i : f)
            vs.push_back(SurfaceMesh::Vertex_index(static_cast<SurfaceMesh::size_type>(i)));
        if (tm.add_face(vs) == SurfaceMesh::null_face())
            throw std::runtime_error("test soup: Surface_mesh refused a face");
    }
    if (leave_garbage && tm.number_of_faces() > 0)
        tm.remove_face(*tm.faces().begin());  // face indices become 1..n-1
}

void build(const Soup& soup, Polyhedron& tm) {
    SurfaceMesh sm;
    build(soup, sm);
    tm.clear();
    using SmV = boost::graph_traits<SurfaceMesh>::vertex_descriptor;
    using SmF = boost::graph_traits<SurfaceMesh>::face_descriptor;
    using PV = boost::graph_traits<Polyhedron>::vertex_descriptor;
    using PF = boost::graph_traits<Polyhedron>::face_descriptor;
    std::vector<std::pair<SmV, PV>> v2v;
    std::vector<std::pair<SmF, PF>> f2f;
    CGAL::copy_face_graph(
        sm, tm,
        CGAL::parameters::vertex_to_vertex_output_iterator(std::back_inserter(v2v))
            .face_to_face_output_iterator(std::back_inserter(f2f)));
    // copy_face_graph does not keep the order of the elements; the ids carry the soup numbering
    // (vertex id i = soup point i, face id j = soup polygon j), halfedges are numbered in order.
    CGAL::set_halfedgeds_items_id(tm);
    for (const auto& [s, p] : v2v)
        p->id() = s.idx();
    for (const auto& [s, p] : f2f)
        p->id() = s.idx();
    if (v2v.size() != soup.points.size() || f2f.size() != soup.faces.size())
        throw std::runtime_error("test soup: Polyhedron copy lost elements");
    for (auto v : vertices(tm))
        if (to_vec3(v->point()) != soup.points[v->id()])
            throw std::runtime_error("test soup: Polyhedron vertex ids differ from the soup");
}

boost::graph_traits<SurfaceMesh>::vertex_descriptor vertex_at(SurfaceMesh&, std::size_t i) {
    return SurfaceMesh::Vertex_index(static_cast<SurfaceMesh::size_type>(i));
}
boost::graph_traits<Polyhedron>::vertex_descriptor vertex_at(Polyhedron& tm, std::size_t i) {
    for (auto v : vertices(tm))
        if (v->id() == i)
            return v;
    return boost::graph_traits<Polyhedron>::null_vertex();
}
boost::graph_traits<SurfaceMesh>::face_descriptor face_at(SurfaceMesh&, std::size_t j) {
    return SurfaceMesh::Face_index(static_cast<SurfaceMesh::size_type>(j));
}
boost::graph_traits<Polyhedron>::face_descriptor face_at(Polyhedron& tm, std::size_t j) {
    for (auto f : faces(tm))
        if (f->id() == j)
            return f;
    return boost::graph_traits<Polyhedron>::null_face();
}

namespace {
template <class Mesh>
tapeline::geodesic::SurfacePoint<Mesh> to_surface_point(Mesh& tm, const Soup& soup,
                                                        const SurfacePoint& p) {
    if (!p.on_face)
        return vertex_at(tm, p.index);
    const auto f = face_at(tm, p.index);
    tapeline::geodesic::FaceLocation<Mesh> loc{f, {p.bary[0], p.bary[1], p.bary[2]}};
    // Reorder the soup-corner coordinates into the PMP order when the face is a real triangle;
    // invalid faces are passed through for the library to reject.
    if (p.index < soup.faces.size() && p.index < num_faces(tm) && soup.faces[p.index].size() == 3) {
        const auto vim = get(boost::vertex_index, tm);
        const auto h = halfedge(f, tm);
        const std::size_t ids[3] = {get(vim, source(h, tm)), get(vim, target(h, tm)),
                                    get(vim, target(next(h, tm), tm))};
        for (int k = 0; k < 3; ++k) {
            loc.second[k] = 0;
            for (int s = 0; s < 3; ++s)
                if (soup.faces[p.index][s] == ids[k])
                    loc.second[k] = p.bary[s];
        }
    }
    return loc;
}
}  // namespace

tapeline::geodesic::SurfacePoint<SurfaceMesh> surface_point(SurfaceMesh& tm, const Soup& soup,
                                                            const SurfacePoint& p) {
    return to_surface_point(tm, soup, p);
}
tapeline::geodesic::SurfacePoint<Polyhedron> surface_point(Polyhedron& tm, const Soup& soup,
                                                           const SurfacePoint& p) {
    return to_surface_point(tm, soup, p);
}

}  // namespace cgal
}  // namespace tapeline_test::geodesic
