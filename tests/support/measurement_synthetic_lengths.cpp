// Lengths along the skin of the synthetic body and exact-MMP distances on it (the curvature flow
// and MMP are heavy templates, compiled once here: DESIGN.md §5).
#include <tapeline/geodesic/exact_mmp.h>
#include <tapeline/measurement/lengths.h>
#include <tapeline/measurement/measure.h>
#include <tapeline/measurement/synthetic_body.h>
#include <tapeline_test/measurement_synthetic.h>

#include "measurement_synthetic_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_processing/connected_components.h>
#include <CGAL/Polygon_mesh_processing/corefinement.h>
#include <CGAL/Polygon_mesh_processing/polygon_soup_to_polygon_mesh.h>
#include <CGAL/Polygon_mesh_processing/repair_degeneracies.h>
#include <CGAL/Surface_mesh.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace tapeline_test::measurement {

namespace {
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Epick::Point_3>;
namespace meas = tapeline::measurement;
namespace geo = tapeline::geodesic;
using NP = CGAL::parameters::Default_named_parameters;

double dist(const Vec3& a, const Vec3& b) {
    return std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
}
}  // namespace

SyntheticSurfaceMesh synthetic_surface_mesh(const SyntheticBodyOptions& synthetic, bool connected) {
    const meas::SyntheticBody body(synthetic);
    std::vector<Epick::Point_3> pts;
    for (const auto& p : body.points()) {
        pts.emplace_back(p[0], p[1], p[2]);
    }
    std::vector<std::vector<std::size_t>> polys;
    for (const auto& t : body.triangles()) {
        polys.push_back({t[0], t[1], t[2]});
    }
    SurfaceMesh tm;
    CGAL::Polygon_mesh_processing::polygon_soup_to_polygon_mesh(pts, polys, tm);
    if (!connected) {
        return tm;
    }
    // One skin: the closed parts merged by corefinement (their boolean union).
    std::vector<SurfaceMesh> parts;
    CGAL::Polygon_mesh_processing::split_connected_components(tm, parts);
    std::sort(parts.begin(), parts.end(), [](const SurfaceMesh& a, const SurfaceMesh& b) {
        return a.number_of_faces() > b.number_of_faces();
    });
    SurfaceMesh skin = parts.front();
    for (std::size_t i = 1; i < parts.size(); ++i) {
        SurfaceMesh out;
        if (!CGAL::Polygon_mesh_processing::corefine_and_compute_union(skin, parts[i], out)) {
            throw std::runtime_error("synthetic body: union of its parts failed");
        }
        skin = std::move(out);
    }
    // Corefinement leaves zero-area and sliver triangles where cut lines meet (e.g. where the arm
    // touches the torso at the armpit level), on which a surface point has no finite barycentric
    // coordinates: collapse them (edges up to 0.05 mm; the surface moves by less than that).
    CGAL::Polygon_mesh_processing::remove_degenerate_faces(skin);
    CGAL::Polygon_mesh_processing::experimental::remove_almost_degenerate_faces(
        skin, std::cos(179.0 * M_PI / 180), 1e3, 0.05);
    skin.collect_garbage();
    return skin;
}

SyntheticLengths measure_synthetic_lengths(const SyntheticBodyOptions& synthetic, bool connected,
                                           bool exact, const std::vector<std::string>& exact_only) {
    const SurfaceMesh tm = synthetic_surface_mesh(synthetic, connected);
    BodyOptions o;
    o.unit = meas::LengthUnit::mm;
    const auto t0 = std::chrono::steady_clock::now();
    auto m = meas::measure_body(tm, o);
    const meas::SkinLocator<SurfaceMesh, NP> at(tm, m.frame);
    const geo::GeodesicPathSolver<SurfaceMesh, NP> solver(tm);
    const auto plan = meas::plan_skin_lengths(at, m.landmarks);
    meas::take_skin_lengths(solver, at, m.frame, plan, m.measurements);
    meas::measure_cross_seam(tm, m.frame, m.landmarks, m.measurements);
    meas::measure_shoulder_slope(m.landmarks, m.measurements);
    SyntheticLengths out;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    for (const auto& s : plan.lengths) {
        for (std::size_t i = 0; i + 1 < s.waypoints.size(); ++i) {
            SyntheticSegment c;
            c.measurement = s.name;
            c.from = at.canonical(s.waypoints[i]);
            c.to = at.canonical(s.waypoints[i + 1]);
            c.euclidean = dist(c.from, c.to);
            if (c.euclidean < 1e-9) {
                c.exact = 0;
                out.segments.push_back(c);
                continue;
            }
            const auto r = solver.path(s.waypoints[i], s.waypoints[i + 1]);
            c.gcf = r.on_mesh.found() ? r.on_mesh.length * m.frame.scale : NAN;
            if (exact && (exact_only.empty() || std::find(exact_only.begin(), exact_only.end(),
                                                          s.name) != exact_only.end())) {
                c.exact = geo::exact_mmp_path(tm, geo::SurfacePoint<SurfaceMesh>(s.waypoints[i]),
                                              geo::SurfacePoint<SurfaceMesh>(s.waypoints[i + 1]))
                              .length *
                          m.frame.scale;
            }
            out.segments.push_back(c);
        }
    }
    out.result = to_result(std::move(m), seconds);
    return out;
}

}  // namespace tapeline_test::measurement
