// One call from a body mesh to its landmarks and measurements (DESIGN.md §3: the one-shot free
// function). Later stages (lengths along the skin, pictures, exports) take a BodyMeasurements
// and the Body and add to `measurements`.
#pragma once

#include <tapeline/measurement/body.h>
#include <tapeline/measurement/body_checks.h>
#include <tapeline/measurement/girths.h>
#include <tapeline/measurement/holes.h>
#include <tapeline/measurement/landmarks.h>
#include <tapeline/measurement/measurement_types.h>
#include <tapeline/measurement/self_checks.h>

#include <chrono>
#include <cstdio>

namespace tapeline::measurement {

/// Refuses (InvalidInput) a mesh on which five or more of the landmarks found lie outside their
/// height bands (self_checks.h, landmark_height_bands): a creature or an object with limbs,
/// whose girths would be garbage. A human body, even an unusual one, breaks at most a pair.
inline void refuse_unlike_human_heights(const Body& body, const LandmarkSet& landmarks) {
    const double h = body.frame.height;
    std::size_t off = 0;
    std::string which;
    for (const auto& b : landmark_height_bands()) {
        const Landmark* l = landmarks.find(b.landmark);
        if (l == nullptr || l->status != LandmarkStatus::found) {
            continue;
        }
        const double f = l->point[1] / h;
        if (f < b.lo || f > b.hi) {
            char buf[160];
            std::snprintf(buf, sizeof buf, "%s%s at %.3f (%.2f-%.2f)", off++ == 0 ? "" : ", ",
                          b.landmark, f, b.lo, b.hi);
            which += buf;
        }
    }
    if (off >= 5) {
        throw InvalidInput(body.mesh.name + ": does not look like a body: " + std::to_string(off) +
                           " landmarks lie outside the heights of a human body, as fractions of "
                           "the stature: " +
                           which + "; check --up, --front and --units, or the mesh");
    }
}

/// Landmarks (with overrides), girths and self-checks of a prepared body; the filled holes of
/// its input are in the report, and the measurements resting on them are marked
/// (Measurement::crosses_filled_hole). A mesh that is not one upright human body is refused
/// (InvalidInput, body_checks.h; refuse_unlike_human_heights) before any girth is measured.
inline BodyMeasurements measure_body(const Body& body, const MeasureOptions& options = {},
                                     const LandmarkOverrides& overrides = {}) {
    using Clock = std::chrono::steady_clock;
    BodyMeasurements out;
    out.frame = body.frame;
    out.report.vertices = body.mesh.points.size();
    out.report.faces = body.mesh.triangles.size();
    out.report.components = body.mesh.components;
    out.report.holes = body.holes;
    const auto t0 = Clock::now();
    check_body_shape(body);
    LandmarkReport lr;
    out.landmarks = find_landmarks(body, options, overrides, &lr);
    check_body_proportions(body, out.landmarks);
    refuse_unlike_human_heights(body, out.landmarks);
    const auto t1 = Clock::now();
    std::size_t cuts = 0;
    out.measurements = measure_girths(body, out.landmarks, options, &cuts);
    mark_filled_crossings(body.mesh, out.measurements);
    apply_catalogue(out.measurements);
    out.warnings = self_check(body, out.landmarks, out.measurements, lr.chin_underside);
    const auto t2 = Clock::now();
    out.report.landmark_seconds = std::chrono::duration<double>(t1 - t0).count();
    out.report.girth_seconds = std::chrono::duration<double>(t2 - t1).count();
    out.report.sections = lr.sections + cuts;
    out.report.smooth_surface = options.smooth_surface;
    out.report.warnings = lr.warnings;
    out.report.landmarks_found = out.landmarks.available_count();
    out.report.landmarks_missing = out.landmarks.landmarks.size() - out.report.landmarks_found;
    return out;
}

/// Same from a CGAL triangle mesh (named parameter: vertex_point_map); the frame step's time is
/// report.frame_seconds.
template <class TriangleMesh, class NamedParameters = CGAL::parameters::Default_named_parameters>
BodyMeasurements measure_body(const TriangleMesh& tm, const BodyOptions& body_options,
                              const MeasureOptions& options = {},
                              const LandmarkOverrides& overrides = {},
                              const NamedParameters& np = CGAL::parameters::default_values()) {
    const auto t0 = std::chrono::steady_clock::now();
    const Body body = make_body(tm, body_options, np);
    const double frame_seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    BodyMeasurements out = measure_body(body, options, overrides);
    out.report.frame_seconds = frame_seconds;
    return out;
}

}  // namespace tapeline::measurement
