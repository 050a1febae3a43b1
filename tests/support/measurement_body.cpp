// Instantiates the measurement module for Surface_mesh<Epick> and Polyhedron_3<Epick> and
// flattens results into the plain types of tapeline_test/measurement.h.
#include <tapeline/core/mesh_io.h>
#include <tapeline/measurement/measure.h>
#include <tapeline/measurement/synthetic_body.h>
#include <tapeline_test/measured_body.h>
#include <tapeline_test/measurement.h>

#include "measurement_soup_mesh.h"

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Polygon_mesh_slicer.h>
#include <CGAL/Polyhedron_3.h>
#include <CGAL/Surface_mesh.h>
#include <CGAL/boost/graph/properties_Polyhedron_3.h>

#include <chrono>

namespace tapeline_test::measurement {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Epick::Point_3>;
using Polyhedron = CGAL::Polyhedron_3<Epick>;
namespace meas = tapeline::measurement;

meas::LandmarkOverrides overrides_from(const std::string& path) {
    return path.empty() ? meas::LandmarkOverrides{} : meas::read_landmark_overrides(path);
}

template <class Mesh>
Result measure_built(const std::vector<Vec3>& points, const Triangles& triangles,
                     const BodyOptions& options, const std::string& overrides) {
    Mesh mesh;
    mesh_from_soup(points, triangles, mesh);
    const auto o = overrides_from(overrides);
    const auto t0 = std::chrono::steady_clock::now();
    auto m = meas::measure_body(mesh, options, {}, o);
    return to_result(std::move(m),
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

}  // namespace

MeasuredBody load_measured_body(const std::string& path, const BodyOptions& options) {
    const auto loaded = tapeline::read_triangle_mesh<SurfaceMesh>(path);
    MeasuredBody b{meas::make_body(loaded.mesh, options), {}, {}};
    meas::BodyMeasurements m = meas::measure_body(b.body);
    b.landmarks = std::move(m.landmarks);
    b.measurements = std::move(m.measurements);
    return b;
}

Result measure_file(const std::string& path, const BodyOptions& options,
                    const std::string& overrides, const MeasureOptions& measure) {
    const auto loaded = tapeline::read_triangle_mesh<SurfaceMesh>(path);
    const auto o = overrides_from(overrides);
    const auto t0 = std::chrono::steady_clock::now();
    auto m = meas::measure_body(loaded.mesh, options, measure, o);
    return to_result(std::move(m),
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

Result measure_mesh(const std::vector<Vec3>& points, const Triangles& triangles,
                    const BodyOptions& options, MeshKind kind, const std::string& overrides) {
    if (kind == MeshKind::polyhedron) {
        return measure_built<Polyhedron>(points, triangles, options, overrides);
    }
    return measure_built<SurfaceMesh>(points, triangles, options, overrides);
}

Result measure_synthetic(const SyntheticBodyOptions& synthetic, const BodyOptions& options,
                         const std::string& overrides, const MeasureOptions& measure) {
    const meas::SyntheticBody body(synthetic);
    BodyOptions o = options;
    if (!o.unit) {
        o.unit = meas::LengthUnit::mm;
    }
    const auto t0 = std::chrono::steady_clock::now();
    const meas::Body b = meas::make_body(body.points(), body.triangles(), o);
    auto m = meas::measure_body(b, measure, overrides_from(overrides));
    return to_result(std::move(m),
                     std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count());
}

std::optional<double> hinge_breakpoint(const std::vector<std::pair<double, double>>& samples) {
    return meas::internal::hinge_breakpoint(samples);
}

SliceComparison compare_with_cgal_slicer(const SyntheticBodyOptions& synthetic, const Vec3& point,
                                         const Vec3& normal) {
    const meas::SyntheticBody body(synthetic);
    meas::BodyOptions o;
    o.unit = meas::LengthUnit::mm;
    const meas::Body b = meas::make_body(body.points(), body.triangles(), o);
    SliceComparison c;
    meas::internal::CutWorkspace ws;
    const auto plane = meas::internal::Plane::make(point, normal, {1, 0, 0});
    for (const auto& loop : meas::internal::cut(b.mesh, plane, ws)) {
        ++c.loops;
        for (std::size_t i = 0; i < loop.points.size(); ++i) {
            c.length +=
                meas::internal::dist(loop.points[i], loop.points[(i + 1) % loop.points.size()]);
        }
    }
    // The slicer on the same canonical points.
    SurfaceMesh mesh;
    mesh_from_soup(b.mesh.points, b.mesh.triangles, mesh);
    CGAL::Polygon_mesh_slicer<SurfaceMesh, Epick> slicer(mesh);
    std::vector<std::vector<Epick::Point_3>> polylines;
    slicer(Epick::Plane_3(Epick::Point_3(point[0], point[1], point[2]),
                          Epick::Vector_3(normal[0], normal[1], normal[2])),
           std::back_inserter(polylines));
    for (const auto& pl : polylines) {
        ++c.cgal_polylines;
        c.cgal_all_closed = c.cgal_all_closed && pl.size() > 2 && pl.front() == pl.back();
        for (std::size_t i = 0; i + 1 < pl.size(); ++i) {
            c.cgal_length += std::sqrt(CGAL::to_double(CGAL::squared_distance(pl[i], pl[i + 1])));
        }
    }
    return c;
}

std::size_t parse_overrides(const std::string& json) {
    return meas::parse_landmark_overrides(json, "L.json").points.size();
}

}  // namespace tapeline_test::measurement
