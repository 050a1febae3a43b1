// A body dressed as `tapeline dress` dresses it: measured (and, given the measurement set the
// pattern was drafted for, the pattern graded to the body first), the pieces placed, sewn and
// draped. Compiled once in the harness for the command-line tool and the Python module; this header
// includes types only.
#pragma once

#include <tapeline/bench/measure_run.h>
#include <tapeline/bench/methods.h>
#include <tapeline/garment/garment_types.h>
#include <tapeline/measurement/body_types.h>
#include <tapeline/pattern/pattern.h>
#include <tapeline/sizes/measurement_set.h>

#include <nlohmann/json.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace tapeline::bench {

/// The dressed body.
struct DressRun {
    measurement::Body body;        ///< the prepared body (canonical frame, mm)
    garment::GarmentMesh garment;  ///< welded, canonical mm of the body
    std::vector<double> stretch;   ///< per garment triangle: largest principal stretch
    /// Per seam of the report, the welded positions of its stitch pairs in order (canonical mm).
    std::vector<std::vector<garment::Vec3>> seam_lines;
    garment::DressReport report;        ///< quality gates, seams, pieces, timings
    std::vector<std::string> warnings;  ///< the measurement's warnings
    /// When graded to the body: the grading's notes, and "graded P from A to B".
    std::vector<std::string> grading_notes;
};

/// make_body(mesh, body_options) and measure_body (every measurement when `base` is given, and
/// the pattern graded from `base` to them with bench::grade_as_tool and `seed`), then
/// garment::dress. The report's measure time (body and measurements) and total time (the whole
/// call) are filled in. Throws as those do;
/// InvalidInput when `base` is given and this build has no grading.
DressRun dress_mesh(const Mesh& mesh, const measurement::BodyOptions& body_options,
                    pattern::Pattern pattern, const garment::DressOptions& options,
                    const sizes::MeasurementSet* base = nullptr, std::uint32_t seed = 1);

/// dress_mesh on a body measured already (`measured`, from measure_mesh; its landmarks place the
/// pieces). `measure_seconds` is reported as the measure time and counted in the total time.
DressRun dress_measured(MeasureRun measured, const std::string& body_name, pattern::Pattern pattern,
                        const garment::DressOptions& options, double measure_seconds,
                        const sizes::MeasurementSet* base = nullptr, std::uint32_t seed = 1);

/// Sets the settling time after the seams close; 0 also turns off the extra settling while the
/// cloth still moves (`max_extra_seconds`): what `tapeline dress --settle-seconds` and the batch's
/// `settle_seconds` mean.
void set_settle_seconds(garment::SewingOptions& sewing, double seconds);

/// A pattern's base taken from the body it was made for: the body measured (its measurements are
/// the grading's base set) and the pattern laid on it to find its girth bindings
/// (garment::infer_girth_bindings).
struct BodyBase {
    pattern::Pattern pattern;            ///< with the bindings found on the body
    sizes::MeasurementSet measurements;  ///< the body's, named `body_options.name`
    std::vector<std::string> notes;      ///< per girth: bound (where, ease) or why not
};

/// Reads the body at `path` (any mesh format the tool reads), measures it and finds the girth
/// bindings of `pattern` on it. Throws as reading, measuring and garment::infer_girth_bindings.
BodyBase base_from_body(pattern::Pattern pattern, const std::string& path,
                        const measurement::BodyOptions& body_options);

/// base_from_body on a mesh already read.
BodyBase base_from_mesh(pattern::Pattern pattern, const Mesh& mesh,
                        const measurement::BodyOptions& body_options);

/// The report `tapeline dress --report` writes: body and pattern names, the body's unit, then
/// garment::dress_report_json.
nlohmann::ordered_json dress_report_json(const DressRun& run, const std::string& body,
                                         const std::string& pattern,
                                         const garment::DressOptions& options);

/// The failed gates as "name value (limit L), ..." (empty when every gate passed).
std::string failed_gates(const garment::DressReport& report);

}  // namespace tapeline::bench
