// A body measured as `tapeline measure` measures it: make_body, measure_body and the skin lengths
// on the tool's mesh type, compiled once in the harness for the command-line tool and the Python
// module. This header includes types only: a file that includes it does not compile the
// measurement pipeline again.
#pragma once

#include <tapeline/bench/methods.h>
#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/landmark_overrides.h>
#include <tapeline/measurement/measurement_types.h>

#include <tapeline/sizes/measurement_set.h>

#include <nlohmann/json.hpp>

#include <string>

namespace tapeline::bench {

/// The prepared body and what was measured on it.
struct MeasureRun {
    measurement::Body body;
    /// Landmarks, girths and, when asked, the lengths along the skin.
    measurement::BodyMeasurements result;
    double frame_seconds = 0;   ///< make_body
    double length_seconds = 0;  ///< measure_skin_lengths (0 without them)
};

/// make_body(mesh, options), measure_body with `measure` and `overrides`, and
/// measure_skin_lengths when `skin_lengths`; throws as those do.
MeasureRun measure_mesh(const Mesh& mesh, const measurement::BodyOptions& options,
                        const measurement::LandmarkOverrides& overrides = {},
                        bool skin_lengths = true, const measurement::MeasureOptions& measure = {});

/// The measurement JSON `tapeline measure --out` writes: measurement::body_measurements_json of
/// `run` for `body`, with the stage times under "timings_seconds" (`load_seconds`: reading the
/// file; `total_seconds`: the whole measurement, the load included).
nlohmann::ordered_json measure_json(const MeasureRun& run, const std::string& body,
                                    double load_seconds, double total_seconds);

/// The measurements of `run` as a measurement set named `name` (each under our name and its
/// FreeSewing name, as sizes::parse_measurement_json reads `tapeline measure`'s JSON).
sizes::MeasurementSet measured_set(const MeasureRun& run, const std::string& name);

}  // namespace tapeline::bench
