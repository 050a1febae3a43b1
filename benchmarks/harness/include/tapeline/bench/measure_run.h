// A body measured as `tapeline measure` measures it: make_body, measure_body and the skin lengths
// on the tool's mesh type, compiled once in the harness for the command-line tool and the Python
// module.
#pragma once

#include <tapeline/bench/methods.h>
#include <tapeline/measurement/body.h>
#include <tapeline/measurement/landmarks.h>
#include <tapeline/measurement/measure.h>

namespace tapeline::bench {

/// The prepared body and what was measured on it.
struct MeasureRun {
    measurement::Body body;
    /// Landmarks, girths and, when asked, the lengths along the skin.
    measurement::BodyMeasurements result;
    double frame_seconds = 0;   ///< make_body
    double length_seconds = 0;  ///< measure_skin_lengths (0 without them)
};

/// make_body(mesh, options), measure_body with `overrides`, and measure_skin_lengths when
/// `skin_lengths`; throws as those do.
MeasureRun measure_mesh(const Mesh& mesh, const measurement::BodyOptions& options,
                        const measurement::LandmarkOverrides& overrides = {},
                        bool skin_lengths = true);

}  // namespace tapeline::bench
