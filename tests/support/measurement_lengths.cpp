// Lengths along the skin on a Surface_mesh<Epick>, and the exact-MMP check of their segments
// (compiled once here: the curvature flow and MMP are heavy templates, DESIGN.md §5).
#include <tapeline/core/mesh_io.h>
#include <tapeline/geodesic/exact_mmp.h>
#include <tapeline/measurement/lengths.h>
#include <tapeline/measurement/measure.h>
#include <tapeline/measurement/synthetic_body.h>
#include <tapeline_test/measurement.h>

#include "measurement_synthetic_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>
#include <cmath>

namespace tapeline_test::measurement {

namespace {
using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Epick::Point_3>;
namespace meas = tapeline::measurement;
namespace geo = tapeline::geodesic;
using NP = CGAL::parameters::Default_named_parameters;
}  // namespace

LengthsResult measure_file_with_lengths(const std::string& path, const BodyOptions& options) {
    const auto loaded = tapeline::read_triangle_mesh<SurfaceMesh>(path);
    const SurfaceMesh& tm = loaded.mesh;
    auto m = meas::measure_body(tm, options);
    LengthsResult out;
    const auto t0 = std::chrono::steady_clock::now();
    const meas::SkinLocator<SurfaceMesh, NP> at(tm, m.frame);
    const geo::GeodesicPathSolver<SurfaceMesh, NP> solver(tm);
    const auto plan = meas::plan_skin_lengths(at, m.landmarks);
    meas::take_skin_lengths(solver, at, m.frame, plan, m.measurements);
    meas::measure_cross_seam(tm, m.frame, m.landmarks, m.measurements);
    meas::measure_shoulder_slope(m.landmarks, m.measurements);
    out.length_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    for (const auto& s : plan.lengths) {
        for (std::size_t i = 0; i + 1 < s.waypoints.size(); ++i) {
            const Vec3 a = at.canonical(s.waypoints[i]), b = at.canonical(s.waypoints[i + 1]);
            SegmentCheck c;
            c.measurement = s.name;
            c.euclidean = std::hypot(a[0] - b[0], a[1] - b[1], a[2] - b[2]);
            c.gcf = solver.path(s.waypoints[i], s.waypoints[i + 1]).on_mesh.length * m.frame.scale;
            c.exact = geo::exact_mmp_path(tm, geo::SurfacePoint<SurfaceMesh>(s.waypoints[i]),
                                          geo::SurfacePoint<SurfaceMesh>(s.waypoints[i + 1]))
                          .length *
                      m.frame.scale;
            out.segments.push_back(c);
        }
    }
    out.result = to_result(std::move(m), 0);
    return out;
}

Result measure_synthetic_cross_seam(const SyntheticBodyOptions& synthetic,
                                    const std::string& overrides) {
    const SyntheticSurfaceMesh tm = synthetic_surface_mesh(synthetic, false);
    BodyOptions o;
    o.unit = meas::LengthUnit::mm;
    const auto t0 = std::chrono::steady_clock::now();
    auto m = meas::measure_body(
        tm, o, {},
        overrides.empty() ? meas::LandmarkOverrides{} : meas::read_landmark_overrides(overrides));
    meas::measure_cross_seam(tm, m.frame, m.landmarks, m.measurements);
    return to_result(std::move(m),
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

LocatedPoint locate_on_zero_area_faces(const Vec3& query) {
    SurfaceMesh tm;
    const auto a = tm.add_vertex({0, 0, 0}), b = tm.add_vertex({1, 0, 0}),
               c = tm.add_vertex({3, 0, 0});
    tm.add_face(a, b, c);
    tm.add_face(a, c, b);
    meas::BodyFrame frame;
    frame.rows = {Vec3{1, 0, 0}, Vec3{0, 1, 0}, Vec3{0, 0, 1}};
    const meas::SkinLocator<SurfaceMesh, NP> at(tm, frame);
    const auto l = at.nearest(query);
    LocatedPoint out;
    out.point = at.canonical(l);
    for (int k = 0; k < 3; ++k) {
        out.barycentric[static_cast<std::size_t>(k)] = l.second[k];
    }
    return out;
}

}  // namespace tapeline_test::measurement
