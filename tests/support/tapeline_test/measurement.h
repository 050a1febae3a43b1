// Test facade for the measurement module (DESIGN.md §5): plain functions compiled once in
// tapeline_test_support_measurement (support/measurement_*.cpp); test files include gtest, this
// header and, for analytic truth, <tapeline/measurement/synthetic_body.h> (no CGAL).
#pragma once

#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/measurement_types.h>
#include <tapeline/measurement/synthetic_body.h>

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace tapeline_test::measurement {

using namespace tapeline::measurement;
using Triangles = std::vector<std::array<std::uint32_t, 3>>;

/// How to read a body: `name` (for messages), its unit, up +Y, front +Z, `pose`.
inline BodyOptions body_options(const std::string& name, LengthUnit unit,
                                Pose pose = Pose::a_pose) {
    BodyOptions o;
    o.name = name;
    o.unit = unit;
    o.pose = pose;
    return o;
}

/// A body as plain points and triangles (the body-check and hole tests rotate, combine and cut
/// it); the coordinates are those of whatever made it (see the function that returns it).
struct Soup {
    std::vector<Vec3> points;
    Triangles triangles;
};

/// What measure_body returned, in plain types.
struct Result {
    BodyFrame frame;
    LandmarkSet landmarks;
    MeasurementSet measurements;
    MeasureReport report;
    std::vector<CheckWarning> warnings;  ///< self-checks
    double seconds = 0;                  ///< wall clock of the whole call (load excluded)
};

/// Moves a measure_body result (measurement::BodyMeasurements, or anything with the same members)
/// into a Result; a template so that this header stays free of CGAL.
template <class BodyMeasurements>
Result to_result(BodyMeasurements&& m, double seconds) {
    Result r;
    r.frame = m.frame;
    r.landmarks = std::move(m.landmarks);
    r.measurements = std::move(m.measurements);
    r.report = std::move(m.report);
    r.warnings = std::move(m.warnings);
    r.seconds = seconds;
    return r;
}

/// ISO 20685-1's tolerance for a measurement taken twice on the same body: 9 mm for the large
/// torso girths and the thigh, 4 mm for the other girths and for heights, 5 mm for lengths along
/// the skin.
inline double iso20685_tolerance(const Measurement& m) {
    if (m.kind == MeasurementKind::length) {
        return 5;
    }
    if (m.kind != MeasurementKind::girth) {
        return 4;
    }
    for (const char* large : {"bust_girth", "underbust_girth", "high_bust_girth", "waist_girth",
                              "high_hip_girth", "hip_girth", "thigh_girth", "mid_thigh_girth"}) {
        if (m.name.rfind(large, 0) == 0) {
            return 9;
        }
    }
    return 4;
}

enum class MeshKind { surface_mesh, polyhedron };

/// read_triangle_mesh<Surface_mesh<Epick>> then measure_body; `overrides` is a landmark file
/// path or empty.
Result measure_file(const std::string& path, const BodyOptions& options,
                    const std::string& overrides = "", const MeasureOptions& measure = {});

/// A CGAL mesh built directly from points and triangles (no validation or repair, so bad
/// coordinates reach the measurement module), then measure_body on it.
Result measure_mesh(const std::vector<Vec3>& points, const Triangles& triangles,
                    const BodyOptions& options, MeshKind kind = MeshKind::surface_mesh,
                    const std::string& overrides = "");

/// The synthetic body measured through the plain make_body overload.
Result measure_synthetic(const SyntheticBodyOptions& synthetic, const BodyOptions& options = {},
                         const std::string& overrides = "", const MeasureOptions& measure = {});

/// One plane section of the synthetic body by our cut and by CGAL::Polygon_mesh_slicer.
struct SliceComparison {
    std::size_t loops = 0, cgal_polylines = 0;
    double length = 0, cgal_length = 0;  ///< total polyline lengths
    bool cgal_all_closed = true;
};
SliceComparison compare_with_cgal_slicer(const SyntheticBodyOptions& synthetic, const Vec3& point,
                                         const Vec3& normal);

/// The landmark finder's two-segment breakpoint (internal::hinge_breakpoint; the elbow's level
/// along the arm) of samples (t, y), t ascending.
std::optional<double> hinge_breakpoint(const std::vector<std::pair<double, double>>& samples);

/// parse_landmark_overrides on a string (throws as the library does).
std::size_t parse_overrides(const std::string& json);

/// One geodesic segment of a length along the skin, measured twice: by the curvature flow (the
/// on-mesh path the measurement uses) and by exact MMP between the same surface points; with the
/// straight distance between them. Millimetres.
struct SegmentCheck {
    std::string measurement;
    double gcf = 0, exact = 0, euclidean = 0;
};

/// measure_file, then the lengths along the skin (lengths.h) added to result.measurements, and
/// every segment of every length checked against exact MMP.
struct LengthsResult {
    Result result;
    std::vector<SegmentCheck> segments;
    double length_seconds = 0;  ///< measure_skin_lengths alone
};
LengthsResult measure_file_with_lengths(const std::string& path, const BodyOptions& options);

/// The synthetic body as a Surface_mesh<Epick>, measure_body on it, then measure_cross_seam
/// (lengths.h) only: a plane section, which the synthetic body's overlapping parts allow as they
/// are (the geodesic lengths need one skin: measurement_synthetic.h merges the parts first).
/// `overrides` is a landmark file path or empty.
Result measure_synthetic_cross_seam(const SyntheticBodyOptions& synthetic,
                                    const std::string& overrides = "");

/// SkinLocator::nearest on a closed mesh whose two faces have zero area (three collinear
/// corners (0,0,0), (1,0,0), (3,0,0)), queried at `query`: the located point and its barycentric
/// coordinates.
struct LocatedPoint {
    Vec3 point{0, 0, 0};
    std::array<double, 3> barycentric{0, 0, 0};
};
LocatedPoint locate_on_zero_area_faces(const Vec3& query);

}  // namespace tapeline_test::measurement
