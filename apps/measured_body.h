// A body file prepared and its landmarks found, as `tapeline measure` does it (defined in
// measure_commands.cpp, so that the measurement pipeline is compiled in one translation unit of
// the tool; `tapeline dress` uses it).
#pragma once

#include <tapeline/measurement/body.h>
#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/measurement_types.h>
#include <tapeline/sizes/measurement_set.h>

#include <optional>
#include <string>

namespace tapeline::app {

struct MeasuredBody {
    measurement::Body body;
    measurement::LandmarkSet landmarks;
    double seconds = 0;  ///< make_body + measure_body, wall clock (the load excluded)
    /// Every measurement, skin lengths included, as `tapeline measure` writes them (when asked).
    std::optional<sizes::MeasurementSet> measurements;
};

/// read_triangle_mesh, make_body with `options`, measure_body (and the skin lengths when
/// `with_measurements`); its warnings go to stderr.
MeasuredBody measured_body(const std::string& path, const measurement::BodyOptions& options,
                           bool with_measurements = false);

}  // namespace tapeline::app
