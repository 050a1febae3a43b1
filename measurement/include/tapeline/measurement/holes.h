// Holes of a body mesh (loops of boundary edges, as scans have at the soles, the crown and the
// armpits): a hole at most 5 % of the stature across is filled with CGAL's hole filling —
// triangulation, refinement and fairing, after P. Liepa, "Filling holes in meshes", SGP 2003
// (CGAL::Polygon_mesh_processing::triangulate_refine_and_fair_hole) — and named by where it is;
// a bigger one is refused with one line naming its size, height and place. The filled faces are
// flagged (BodyMesh::filled) so that measurements whose tape crosses them can say so.
//
// Where a hole is: its centre (the mean of its boundary vertices) as fractions of the stature H,
// from the floor and from the body's midline (the centre of its bounding box across), with the
// bands of Drillis & Contini's segment proportions (body_checks.h): below 0.04 H the soles, above
// 0.95 H the crown, 0.87-0.95 H the head, 0.83-0.87 H the neck or shoulders, more than 0.13 H out
// from the midline between 0.40 and 0.87 H an arm, 0.06-0.13 H out at 0.70-0.79 H an armpit,
// the rest of 0.46-0.83 H the torso (its front, back or a side, by the centre's offset from the
// mean of the torso's vertices at that height; "around the torso" when that offset is small),
// below that the crotch or a leg. measurement/README.md lists the names.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/internal/sections.h>
#include <tapeline/measurement/measurement_types.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/border.h>
#include <CGAL/Polygon_mesh_processing/triangulate_hole.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::measurement {

/// Holes up to this fraction of the stature across are filled; bigger ones are refused.
constexpr double kFillableHoleFraction = 0.05;

/// CGAL's `density_control_factor` for the patches: the refinement's target density relative to
/// the rim's (CGAL's default is sqrt(2); larger is denser).
constexpr double kHoleDensityFactor = 4.0;

namespace internal {

/// Whole millimetres with thousands separators: 1120.4 -> "1,120".
inline std::string grouped_mm(double mm) {
    const long long v = std::llround(mm);
    std::string digits = std::to_string(v < 0 ? -v : v), out;
    for (std::size_t i = 0; i < digits.size(); ++i) {
        if (i > 0 && (digits.size() - i) % 3 == 0) {
            out += ',';
        }
        out += digits[i];
    }
    return (v < 0 ? "-" : "") + out;
}

/// Where a hole centred at `c` is on a body of height `height` whose midline is x = `mid_x`
/// and whose vertices at the centre's height have their mean at depth `mean_z` (see the top of
/// this file).
inline std::string hole_region(const Vec3& c, double height, double mid_x, double mean_z) {
    const double h = c[1] / height, dx = (c[0] - mid_x) / height, dz = (c[2] - mean_z) / height;
    const std::string side = dx >= 0 ? "left" : "right";  // x is the body's left
    const double out = std::abs(dx);
    if (h < 0.04) {
        return out < 0.02 ? "between the feet" : "the " + side + " sole";
    }
    if (h >= 0.95) {
        return "the crown";
    }
    if (h >= 0.87) {
        return "the head";
    }
    if (h >= 0.40 && out > 0.13) {
        return "the " + side + " arm";
    }
    if (h >= 0.83) {
        return out < 0.06 ? "the neck" : "the " + side + " shoulder";
    }
    if (h >= 0.70 && h < 0.79 && out >= 0.06) {
        return "the " + side + " armpit";
    }
    if (h >= 0.46) {
        if (std::hypot(dx, dz) < 0.03) {
            return "around the torso";
        }
        if (out >= std::abs(dz)) {
            return "the " + side + " side of the torso";
        }
        return dz > 0 ? "the front of the torso" : "the back of the torso";
    }
    if (out < 0.03 && h >= 0.40) {
        return "the crotch";
    }
    return h < 0.07 ? "the " + side + " foot" : "the " + side + " leg";
}

/// One loop of boundary vertices of a triangle soup.
struct BoundaryLoop {
    std::vector<std::uint32_t> vertices;
    double size = 0;
    Vec3 centre{0, 0, 0};
};

/// The largest distance between two of the points (the loop's extent across).
inline double largest_extent(const std::vector<Vec3>& points,
                             const std::vector<std::uint32_t>& loop) {
    double d2 = 0;
    for (std::size_t i = 0; i < loop.size(); ++i) {
        for (std::size_t j = i + 1; j < loop.size(); ++j) {
            const Vec3 d = sub(points[loop[i]], points[loop[j]]);
            d2 = std::max(d2, dot(d, d));
        }
    }
    return std::sqrt(d2);
}

/// Mean depth (z) of the points within 2 % of `height` of the level y and 13 % of it of the
/// midline x = mid_x (the torso's, without the arms, which hang forward in an A-pose).
inline double mean_depth_at(const std::vector<Vec3>& points, double y, double mid_x,
                            double height) {
    double sum = 0;
    std::size_t n = 0;
    for (const auto& p : points) {
        if (std::abs(p[1] - y) <= 0.02 * height && std::abs(p[0] - mid_x) <= 0.13 * height) {
            sum += p[2];
            ++n;
        }
    }
    return n > 0 ? sum / static_cast<double>(n) : 0;
}

/// How many edges of the soup have one triangle (boundary) and more than two (non-manifold).
inline std::pair<std::size_t, std::size_t> edge_counts(
    const std::vector<std::array<std::uint32_t, 3>>& tris) {
    std::vector<std::uint64_t> keys;
    keys.reserve(3 * tris.size());
    for (const auto& t : tris) {
        for (int k = 0; k < 3; ++k) {
            std::uint64_t a = t[k], b = t[(k + 1) % 3];
            keys.push_back(a < b ? (a << 32) | b : (b << 32) | a);
        }
    }
    std::sort(keys.begin(), keys.end());
    std::size_t boundary = 0, non_manifold = 0;
    for (std::size_t i = 0; i < keys.size();) {
        std::size_t j = i;
        while (j < keys.size() && keys[j] == keys[i]) {
            ++j;
        }
        boundary += j - i == 1 ? 1 : 0;
        non_manifold += j - i > 2 ? 1 : 0;
        i = j;
    }
    return {boundary, non_manifold};
}

}  // namespace internal

/// Fills the holes of a body's triangle soup (canonical mm, `height` its stature) in place:
/// new vertices and triangles are appended (the input's keep their indices), `filled` flags the
/// new triangles (left empty when nothing was filled), and each hole is returned with its size,
/// place and how it was filled. A hole bigger than kFillableHoleFraction of the height is refused
/// (TopologyError naming the biggest: its size, the height of its centre and where it is); so is a
/// soup that is not an oriented 2-manifold with boundary (edges with more than two triangles,
/// vertices where two surface sheets meet, neighbours with opposite orientations). A closed soup is
/// left as it is.
inline std::vector<BodyHole> fill_body_holes(std::vector<Vec3>& points,
                                             std::vector<std::array<std::uint32_t, 3>>& tris,
                                             std::vector<bool>& filled, double height,
                                             const std::string& name) {
    filled.clear();
    const auto [boundary, non_manifold] = internal::edge_counts(tris);
    if (boundary == 0 || non_manifold > 0) {
        return {};  // closed, or refused by build_adjacency naming a non-manifold edge
    }
    using Point = CGAL::Exact_predicates_inexact_constructions_kernel::Point_3;
    using Mesh = CGAL::Surface_mesh<Point>;
    using halfedge_descriptor = Mesh::Halfedge_index;
    Mesh sm;
    sm.reserve(static_cast<Mesh::size_type>(points.size()),
               static_cast<Mesh::size_type>(3 * tris.size() / 2),
               static_cast<Mesh::size_type>(tris.size()));
    for (const auto& p : points) {
        sm.add_vertex(Point(p[0], p[1], p[2]));
    }
    for (std::size_t f = 0; f < tris.size(); ++f) {
        const auto& t = tris[f];
        if (sm.add_face(Mesh::Vertex_index(t[0]), Mesh::Vertex_index(t[1]),
                        Mesh::Vertex_index(t[2])) == Mesh::null_face()) {
            throw TopologyError(name + ": face " + std::to_string(f) + " (vertices " +
                                std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " +
                                std::to_string(t[2]) +
                                ") makes the open mesh non-manifold or flips its orientation; "
                                "its holes cannot be filled");
        }
    }
    std::vector<halfedge_descriptor> borders;
    CGAL::Polygon_mesh_processing::extract_boundary_cycles(sm, std::back_inserter(borders));

    double lo_x = std::numeric_limits<double>::infinity(), hi_x = -lo_x;
    for (const auto& p : points) {
        lo_x = std::min(lo_x, p[0]);
        hi_x = std::max(hi_x, p[0]);
    }
    const double mid_x = 0.5 * (lo_x + hi_x), limit = kFillableHoleFraction * height;
    std::vector<BodyHole> holes;
    std::size_t worst = 0;
    for (const halfedge_descriptor h0 : borders) {
        std::vector<std::uint32_t> loop;
        for (halfedge_descriptor h = h0;;) {
            loop.push_back(static_cast<std::uint32_t>(sm.target(h)));
            h = sm.next(h);
            if (h == h0 || loop.size() > sm.number_of_halfedges()) {
                break;
            }
        }
        BodyHole hole;
        hole.boundary_edges = loop.size();
        hole.size = internal::largest_extent(points, loop);
        for (std::uint32_t v : loop) {
            hole.centre = internal::add(hole.centre, points[v]);
        }
        hole.centre = internal::mul(hole.centre, 1.0 / static_cast<double>(loop.size()));
        hole.height = hole.centre[1];
        hole.region =
            internal::hole_region(hole.centre, height, mid_x,
                                  internal::mean_depth_at(points, hole.centre[1], mid_x, height));
        if (holes.empty() || hole.size > holes[worst].size) {
            worst = holes.size();
        }
        holes.push_back(std::move(hole));
    }
    if (!holes.empty() && holes[worst].size > limit) {
        const BodyHole& w = holes[worst];
        std::size_t big = 0;
        for (const auto& h : holes) {
            big += h.size > limit ? 1 : 0;
        }
        throw TopologyError(name + ": a hole " + internal::grouped_mm(w.size) + " mm across at " +
                            internal::grouped_mm(w.height) + " mm height, " + w.region +
                            " (holes up to " + internal::grouped_mm(limit) +
                            " mm, 5 % of the stature, are filled" +
                            (big > 1 ? "; " + std::to_string(big - 1) + " more too big" : "") +
                            "); the mesh needs repair before measuring");
    }
    namespace PMP = CGAL::Polygon_mesh_processing;
    for (std::size_t i = 0; i < borders.size(); ++i) {
        std::vector<Mesh::Face_index> faces;
        std::vector<Mesh::Vertex_index> vertices;
        // Refined to twice the rim's density (CGAL's default sqrt(2) made 6-11 faces for a
        // 60 mm hole at the crown or an armpit, where a body's triangles are large: the faired
        // patch came out nearly flat, moved the top of the head and the armpit a few mm and the
        // landmarks hung on them up to 16 mm; with 4, 40-75 faces, all measurements stay within
        // ISO 20685-1 of the closed body's).
        const auto result = PMP::triangulate_refine_and_fair_hole(
            sm, borders[i], std::back_inserter(faces), std::back_inserter(vertices),
            CGAL::parameters::density_control_factor(kHoleDensityFactor));
        BodyHole& hole = holes[i];
        if (std::get<0>(result)) {
            hole.filling = "faired";
        } else if (!faces.empty()) {
            // Fairing failed: the patch keeps its refined, unfaired triangles (what
            // triangulate_and_refine_hole makes).
            hole.filling = "refined";
        } else {
            PMP::triangulate_hole(sm, borders[i], std::back_inserter(faces));
            hole.filling = "triangulated";
        }
        if (faces.empty()) {
            throw TopologyError(name + ": a hole " + internal::grouped_mm(hole.size) +
                                " mm across at " + internal::grouped_mm(hole.height) +
                                " mm height, " + hole.region + " could not be filled");
        }
        hole.faces_added = faces.size();
        hole.vertices_added = vertices.size();
    }
    // The input's vertices and faces keep their indices (nothing was removed from them); the
    // patches' are appended in the mesh's order.
    const std::size_t nv = points.size(), nf = tris.size();
    filled.assign(nf, false);
    std::vector<std::uint32_t> index(sm.num_vertices(), 0);
    for (const auto v : sm.vertices()) {
        const std::size_t i = static_cast<std::size_t>(v);
        if (i < nv) {
            index[i] = static_cast<std::uint32_t>(i);
            continue;
        }
        index[i] = static_cast<std::uint32_t>(points.size());
        const Point& p = sm.point(v);
        points.push_back({p.x(), p.y(), p.z()});
    }
    for (const auto f : sm.faces()) {
        if (static_cast<std::size_t>(f) < nf) {
            continue;
        }
        std::array<std::uint32_t, 3> t{};
        int k = 0;
        for (const auto v : CGAL::vertices_around_face(sm.halfedge(f), sm)) {
            t[static_cast<std::size_t>(k++)] = index[static_cast<std::size_t>(v)];
        }
        tris.push_back(t);
        filled.push_back(true);
    }
    return holes;
}

/// Marks (Measurement::crosses_filled_hole) the lengths, heights and angles of `set` one of
/// whose points or piece midpoints lies on a filled face of `mesh` and not on an input face
/// around the hole (a path along a hole's rim does not cross it). Girths are marked by
/// measure_girths from their sections. Distances within 1e-6 of the body's height count as on.
inline void mark_filled_crossings(const internal::BodyMesh& mesh, MeasurementSet& set) {
    if (mesh.filled.empty()) {
        return;
    }
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    struct Face {
        K::Triangle_3 triangle;
        Vec3 lo, hi;
    };
    const double eps = 1e-6 * std::max(1.0, mesh.max_y - mesh.min_y);
    auto make = [&](std::size_t f) {
        const auto& t = mesh.triangles[f];
        Face face;
        auto P = [&](std::uint32_t v) {
            return K::Point_3(mesh.points[v][0], mesh.points[v][1], mesh.points[v][2]);
        };
        face.triangle = K::Triangle_3(P(t[0]), P(t[1]), P(t[2]));
        for (int k = 0; k < 3; ++k) {
            face.lo[k] =
                std::min({mesh.points[t[0]][k], mesh.points[t[1]][k], mesh.points[t[2]][k]}) - eps;
            face.hi[k] =
                std::max({mesh.points[t[0]][k], mesh.points[t[1]][k], mesh.points[t[2]][k]}) + eps;
        }
        return face;
    };
    // The filled faces, and the input's faces that share a vertex with one (the rim).
    std::vector<Face> filled, rim;
    std::vector<char> patch_vertex(mesh.points.size(), 0);
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        if (mesh.is_filled(f)) {
            filled.push_back(make(f));
            for (std::uint32_t v : mesh.triangles[f]) {
                patch_vertex[v] = 1;
            }
        }
    }
    for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
        const auto& t = mesh.triangles[f];
        if (!mesh.is_filled(f) &&
            (patch_vertex[t[0]] || patch_vertex[t[1]] || patch_vertex[t[2]])) {
            rim.push_back(make(f));
        }
    }
    auto near = [&](const std::vector<Face>& faces, const Vec3& p) {
        const K::Point_3 q(p[0], p[1], p[2]);
        for (const Face& f : faces) {
            if (p[0] < f.lo[0] || p[0] > f.hi[0] || p[1] < f.lo[1] || p[1] > f.hi[1] ||
                p[2] < f.lo[2] || p[2] > f.hi[2]) {
                continue;
            }
            if (CGAL::squared_distance(q, f.triangle) <= eps * eps) {
                return true;
            }
        }
        return false;
    };
    auto on_patch = [&](const Vec3& p) { return near(filled, p) && !near(rim, p); };
    for (Measurement& m : set.measurements) {
        if (m.kind == MeasurementKind::girth) {
            continue;
        }
        for (std::size_t i = 0; i < m.points.size() && !m.crosses_filled_hole; ++i) {
            m.crosses_filled_hole =
                on_patch(m.points[i]) ||
                (i + 1 < m.points.size() &&
                 on_patch(internal::mul(internal::add(m.points[i], m.points[i + 1]), 0.5)));
        }
    }
}

}  // namespace tapeline::measurement
