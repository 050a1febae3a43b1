// Input checks and small shared machinery of the baseline geodesic methods.
//
// Every check runs in Release builds (DESIGN.md §4): CGAL_precondition vanishes under NDEBUG, and
// the CGAL packages wrapped here crash, hang or answer silently wrong on the inputs rejected below.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/geodesic/sources.h>

#include <CGAL/boost/graph/helpers.h>
#include <CGAL/boost/graph/iterator.h>
#include <CGAL/boost/graph/properties.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstddef>
#include <limits>
#include <numeric>
#include <sstream>
#include <string>
#include <vector>

namespace tapeline::geodesic::internal {

using Clock = std::chrono::steady_clock;

inline double seconds_since(Clock::time_point start) {
    return std::chrono::duration<double>(Clock::now() - start).count();
}

constexpr double kInfinity = std::numeric_limits<double>::infinity();

/// The three vertices of a triangle in the PMP Face_location order.
template <class TriangleMesh>
std::array<typename boost::graph_traits<TriangleMesh>::vertex_descriptor, 3> face_vertices(
    typename boost::graph_traits<TriangleMesh>::face_descriptor f, const TriangleMesh& tm) {
    const auto h = halfedge(f, tm);
    return {source(h, tm), target(h, tm), target(next(h, tm), tm)};
}

/// Throws TopologyError unless every face is a triangle, InvalidInput on a non-finite coordinate.
template <class TriangleMesh, class VertexPointMap, class FaceIndexMap, class VertexIndexMap>
void check_triangle_mesh(const TriangleMesh& tm, VertexPointMap vpm, VertexIndexMap vim,
                         FaceIndexMap fim, const char* where) {
    for (auto f : faces(tm)) {
        const auto h = halfedge(f, tm);
        std::size_t degree = 0;
        auto c = h;
        do {
            ++degree;
            c = next(c, tm);
        } while (c != h);
        if (degree != 3) {
            std::ostringstream s;
            s << where << ": face #" << get(fim, f) << " has " << degree
              << " sides; the input is not a triangle mesh (triangulate it first)";
            throw TopologyError(s.str());
        }
    }
    for (auto v : vertices(tm)) {
        const auto& p = get(vpm, v);
        const double x = CGAL::to_double(p.x()), y = CGAL::to_double(p.y()),
                     z = CGAL::to_double(p.z());
        if (!std::isfinite(x) || !std::isfinite(y) || !std::isfinite(z)) {
            std::ostringstream s;
            s << where << ": vertex #" << get(vim, v) << " has a non-finite coordinate (" << x
              << ", " << y << ", " << z << ")";
            throw InvalidInput(s.str());
        }
    }
}

/// Vertex and face numbering of the mesh, checked to be a bijection onto [0, n) (SMSP and our
/// vector-backed maps index arrays with it; a Surface_mesh with garbage breaks that silently).
template <class TriangleMesh, class VertexIndexMap, class FaceIndexMap>
class MeshIndex {
public:
    using GT = boost::graph_traits<TriangleMesh>;
    using vertex_descriptor = typename GT::vertex_descriptor;
    using face_descriptor = typename GT::face_descriptor;

    MeshIndex(const TriangleMesh& tm, VertexIndexMap vim, FaceIndexMap fim, const char* where)
        : tm_(&tm), vim_(vim), fim_(fim), where_(where) {
        vertex_of_.assign(num_vertices(tm), GT::null_vertex());
        for (auto v : vertices(tm)) {
            const std::size_t i = static_cast<std::size_t>(get(vim, v));
            if (i >= vertex_of_.size() || vertex_of_[i] != GT::null_vertex())
                throw InvalidInput(std::string(where) +
                                   ": the vertex index map is not a bijection onto [0, " +
                                   std::to_string(vertex_of_.size()) +
                                   ") (a Surface_mesh with removed elements needs "
                                   "collect_garbage())");
            vertex_of_[i] = v;
        }
        // num_vertices() of a Surface_mesh counts removed elements: an empty slot means garbage.
        for (const auto& v : vertex_of_)
            if (v == GT::null_vertex())
                throw InvalidInput(std::string(where) +
                                   ": the vertex index map is not a bijection onto [0, " +
                                   std::to_string(vertex_of_.size()) +
                                   ") (a Surface_mesh with removed elements needs "
                                   "collect_garbage())");
        face_of_.assign(num_faces(tm), GT::null_face());
        for (auto f : faces(tm)) {
            const std::size_t i = static_cast<std::size_t>(get(fim, f));
            if (i >= face_of_.size() || face_of_[i] != GT::null_face())
                throw InvalidInput(std::string(where) +
                                   ": the face index map is not a bijection onto [0, " +
                                   std::to_string(face_of_.size()) + ")");
            face_of_[i] = f;
        }
        for (const auto& f : face_of_)
            if (f == GT::null_face())
                throw InvalidInput(std::string(where) +
                                   ": the face index map is not a bijection onto [0, " +
                                   std::to_string(face_of_.size()) +
                                   ") (a Surface_mesh with removed elements needs "
                                   "collect_garbage())");
    }

    std::size_t vertex_count() const { return vertex_of_.size(); }
    std::size_t face_count() const { return face_of_.size(); }
    VertexIndexMap vertex_index_map() const { return vim_; }
    FaceIndexMap face_index_map() const { return fim_; }
    vertex_descriptor vertex(std::size_t i) const { return vertex_of_[i]; }
    face_descriptor face(std::size_t i) const { return face_of_[i]; }
    std::size_t index(vertex_descriptor v) const { return static_cast<std::size_t>(get(vim_, v)); }
    std::size_t index(face_descriptor f) const { return static_cast<std::size_t>(get(fim_, f)); }

    /// Index of a vertex given by the user; InvalidInput if it is not a vertex of this mesh.
    std::size_t checked(vertex_descriptor v, const char* what) const {
        if (v != GT::null_vertex()) {
            const std::size_t i = static_cast<std::size_t>(get(vim_, v));
            if (i < vertex_of_.size() && vertex_of_[i] == v)
                return i;
        }
        std::ostringstream s;
        s << where_ << ": " << what << " is not a vertex of the mesh";
        if (v == GT::null_vertex())
            s << " (null vertex)";
        else
            s << " (index " << get(vim_, v) << ", the mesh has " << vertex_of_.size()
              << " vertices)";
        throw InvalidInput(s.str());
    }

    std::size_t checked(face_descriptor f, const char* what) const {
        if (f != GT::null_face()) {
            const std::size_t i = static_cast<std::size_t>(get(fim_, f));
            if (i < face_of_.size() && face_of_[i] == f)
                return i;
        }
        std::ostringstream s;
        s << where_ << ": " << what << " is not a face of the mesh";
        if (f == GT::null_face())
            s << " (null face)";
        else
            s << " (index " << get(fim_, f) << ", the mesh has " << face_of_.size() << " faces)";
        throw InvalidInput(s.str());
    }

    /// Checks a face location and returns it cleaned: coordinates within 1e-9 of [0, 1] and of
    /// sum 1 are accepted, clamped to [0, 1], |b| < 1e-14 snapped to 0, renormalised. The exact
    /// zeros matter: SMSP classifies a location as vertex / edge / face by testing coordinates
    /// exactly, and a -5e-17 roots the wavefront at the wrong place (CGAL#9646).
    FaceLocation<TriangleMesh> checked(const FaceLocation<TriangleMesh>& loc,
                                       const char* what) const {
        checked(loc.first, what);
        const auto& b = loc.second;
        const double sum = b[0] + b[1] + b[2];
        bool ok = std::isfinite(sum) && std::abs(sum - 1.0) <= 1e-9;
        for (double c : b)
            ok = ok && c >= -1e-9 && c <= 1.0 + 1e-9;
        if (!ok) {
            std::ostringstream s;
            s.precision(17);
            s << where_ << ": " << what << " on face #" << get(fim_, loc.first)
              << " has barycentric coordinates (" << b[0] << ", " << b[1] << ", " << b[2]
              << "); they must be finite, in [0, 1] and sum to 1";
            throw InvalidInput(s.str());
        }
        FaceLocation<TriangleMesh> out = loc;
        double total = 0;
        for (double& c : out.second) {
            c = std::clamp(c, 0.0, 1.0);
            if (c < 1e-14)
                c = 0.0;
            total += c;
        }
        for (double& c : out.second)
            c /= total;
        // Renormalising can leave 1 - 1ulp on a vertex; make vertex locations exact.
        for (double& c : out.second)
            if (c > 1.0 - 1e-14)
                c = 1.0;
        return out;
    }

    /// The vertex a location sits on, or null_vertex() if it is not at a corner.
    vertex_descriptor corner_vertex(const FaceLocation<TriangleMesh>& clean) const {
        const auto fv = face_vertices(clean.first, *tm_);
        for (int k = 0; k < 3; ++k)
            if (clean.second[k] == 1.0)
                return fv[k];
        return GT::null_vertex();
    }

private:
    const TriangleMesh* tm_;
    VertexIndexMap vim_;
    FaceIndexMap fim_;
    const char* where_;
    std::vector<vertex_descriptor> vertex_of_;
    std::vector<face_descriptor> face_of_;
};

/// Connected components over edges; an isolated vertex (no incident halfedge) is its own one.
struct Components {
    std::vector<std::size_t> label;  ///< per vertex index
    std::vector<char> isolated;      ///< per vertex index
    std::size_t count = 0;
};

template <class TriangleMesh, class MeshIndexT>
Components connected_components(const TriangleMesh& tm, const MeshIndexT& index) {
    using GT = boost::graph_traits<TriangleMesh>;
    const std::size_t n = index.vertex_count();
    std::vector<std::size_t> parent(n);
    std::iota(parent.begin(), parent.end(), std::size_t(0));
    auto find = [&parent](std::size_t i) {
        while (parent[i] != i) {
            parent[i] = parent[parent[i]];
            i = parent[i];
        }
        return i;
    };
    for (auto e : edges(tm)) {
        const auto h = halfedge(e, tm);
        const std::size_t a = find(index.index(source(h, tm)));
        const std::size_t b = find(index.index(target(h, tm)));
        if (a != b)
            parent[std::max(a, b)] = std::min(a, b);
    }
    Components c;
    c.label.assign(n, 0);
    c.isolated.assign(n, 0);
    std::vector<std::size_t> root_label(n, std::numeric_limits<std::size_t>::max());
    for (std::size_t i = 0; i < n; ++i) {
        const std::size_t r = find(i);
        if (root_label[r] == std::numeric_limits<std::size_t>::max())
            root_label[r] = c.count++;
        c.label[i] = root_label[r];
        c.isolated[i] = halfedge(index.vertex(i), tm) == GT::null_halfedge() ? 1 : 0;
    }
    return c;
}

/// Relative triangle-inequality slack of a face: 0 for a zero-area (collinear or coincident)
/// triangle, 1/3 for an equilateral one.
template <class TriangleMesh, class VertexPointMap>
double relative_slack(typename boost::graph_traits<TriangleMesh>::face_descriptor f,
                      const TriangleMesh& tm, VertexPointMap vpm) {
    const auto fv = face_vertices(f, tm);
    double len[3];
    for (int k = 0; k < 3; ++k) {
        const auto& p = get(vpm, fv[k]);
        const auto& q = get(vpm, fv[(k + 1) % 3]);
        const double dx = CGAL::to_double(p.x()) - CGAL::to_double(q.x());
        const double dy = CGAL::to_double(p.y()) - CGAL::to_double(q.y());
        const double dz = CGAL::to_double(p.z()) - CGAL::to_double(q.z());
        len[k] = std::sqrt(dx * dx + dy * dy + dz * dz);
    }
    const double perimeter = len[0] + len[1] + len[2];
    if (!(perimeter > 0))
        return 0.0;
    double slack = perimeter;
    for (int k = 0; k < 3; ++k)
        slack = std::min(slack, perimeter - 2 * len[k]);
    return slack / perimeter;
}

/// Seeds the distances `d` (per vertex index, +infinity elsewhere) of the methods that start from
/// vertex values (Dijkstra, fast marching): 0 at a vertex source; a face location gives the
/// corners of its face their straight-line distance from it (exact within the face; exactly 0 at
/// a location on a corner). Checks every source (InvalidInput naming it).
template <class TriangleMesh, class VertexPointMap, class MeshIndexT>
void seed_corners(const TriangleMesh& tm, VertexPointMap vpm, const MeshIndexT& index,
                  const SourceSet<TriangleMesh>& sources, std::vector<double>& d) {
    auto coordinates = [&](typename boost::graph_traits<TriangleMesh>::vertex_descriptor v) {
        const auto& p = get(vpm, v);
        return std::array<double, 3>{CGAL::to_double(p.x()), CGAL::to_double(p.y()),
                                     CGAL::to_double(p.z())};
    };
    for (auto v : sources.vertices)
        d[index.checked(v, "source vertex")] = 0.0;
    for (const auto& l : sources.locations) {
        const auto clean = index.checked(l, "source face location");
        const auto fv = face_vertices(clean.first, tm);
        std::array<double, 3> at{0, 0, 0};
        for (int k = 0; k < 3; ++k) {
            const auto p = coordinates(fv[k]);
            for (int c = 0; c < 3; ++c)
                at[c] += clean.second[k] * p[c];
        }
        for (int k = 0; k < 3; ++k) {
            const auto p = coordinates(fv[k]);
            const double dx = at[0] - p[0], dy = at[1] - p[1], dz = at[2] - p[2];
            double& dk = d[index.index(fv[k])];
            dk =
                std::min(dk, clean.second[k] == 1.0 ? 0.0 : std::sqrt(dx * dx + dy * dy + dz * dz));
        }
    }
}

/// Writes the distances and checks them: NaN is a SolverFailure, +inf is counted as unreachable.
template <class MeshIndexT, class VertexDistanceMap>
std::size_t write_distances(const std::vector<double>& d, const MeshIndexT& index,
                            VertexDistanceMap distances, const char* where) {
    // Check everything before writing anything: a failure leaves the caller's map untouched.
    std::size_t unreachable = 0;
    for (std::size_t i = 0; i < d.size(); ++i) {
        if (std::isnan(d[i])) {
            std::ostringstream s;
            s << where << ": the solver returned NaN at vertex #" << i
              << " (degenerate geometry or numerical breakdown)";
            throw SolverFailure(s.str());
        }
        if (std::isinf(d[i]))
            ++unreachable;
    }
    for (std::size_t i = 0; i < d.size(); ++i)
        put(distances, index.vertex(i), d[i]);
    return unreachable;
}

}  // namespace tapeline::geodesic::internal
