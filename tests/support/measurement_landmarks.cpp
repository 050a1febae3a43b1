// T-pose bodies and arm lengths along the skin for the landmark tests
// (tapeline_test/measurement_landmarks.h).
#include <tapeline/core/mesh_io.h>
#include <tapeline/measurement/lengths.h>
#include <tapeline/measurement/measure.h>
#include <tapeline_test/measurement_landmarks.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Surface_mesh.h>

#include <chrono>

namespace tapeline_test::measurement {
namespace {

using Epick = CGAL::Exact_predicates_inexact_constructions_kernel;
using SurfaceMesh = CGAL::Surface_mesh<Epick::Point_3>;
namespace meas = tapeline::measurement;

double since(std::chrono::steady_clock::time_point t0) {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

PosePair measure_file_a_and_t_pose(const std::string& path, const BodyOptions& options) {
    const auto loaded = tapeline::read_triangle_mesh<SurfaceMesh>(path);
    BodyOptions a = options;
    a.pose = meas::Pose::a_pose;
    const meas::Body body = meas::make_body(loaded.mesh, a);
    PosePair out;
    auto t0 = std::chrono::steady_clock::now();
    out.a_pose = to_result(meas::measure_body(body), since(t0));
    BodyOptions t = options;
    t.pose = meas::Pose::t_pose;
    t.unit = meas::LengthUnit::mm;
    t.up = meas::Axis{1, 1};
    t.front = meas::Axis{2, 1};
    t.name = options.name + " (arms raised)";
    const meas::Body posed = meas::make_body(
        raise_arms_to_t_pose(body.mesh.points, out.a_pose.landmarks, 0.02 * body.height()),
        body.mesh.triangles, t);
    t0 = std::chrono::steady_clock::now();
    out.t_pose = to_result(meas::measure_body(posed), since(t0));
    return out;
}

Result measure_file_with_skin_lengths(const std::string& path, const BodyOptions& options) {
    const auto loaded = tapeline::read_triangle_mesh<SurfaceMesh>(path);
    const auto t0 = std::chrono::steady_clock::now();
    auto m = meas::measure_body(loaded.mesh, options);
    meas::measure_skin_lengths(loaded.mesh, m.frame, m.landmarks, m.measurements);
    return to_result(std::move(m), since(t0));
}

}  // namespace tapeline_test::measurement
