// The measurement pipeline on bench::Mesh (measure_run.h).
#include <tapeline/bench/measure_run.h>
#include <tapeline/sizes/json_formats.h>

#include <tapeline/measurement/lengths.h>
#include <tapeline/measurement/measure.h>
#include <tapeline/measurement/measurement_json.h>

#include <chrono>

namespace tapeline::bench {

MeasureRun measure_mesh(const Mesh& mesh, const measurement::BodyOptions& options,
                        const measurement::LandmarkOverrides& overrides, bool skin_lengths,
                        const measurement::MeasureOptions& measure) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    MeasureRun run{measurement::make_body(mesh, options), {}, 0, 0};
    run.frame_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    run.result = measurement::measure_body(run.body, measure, overrides);
    run.result.report.frame_seconds = run.frame_seconds;
    if (skin_lengths) {
        run.length_seconds = measurement::measure_skin_lengths(run.body, mesh, run.result.landmarks,
                                                               run.result.measurements);
    }
    return run;
}

nlohmann::ordered_json measure_json(const MeasureRun& run, const std::string& body,
                                    double load_seconds, double total_seconds) {
    const measurement::BodyMeasurements& r = run.result;
    nlohmann::ordered_json j = measurement::body_measurements_json(
        body, r.frame, r.measurements, r.landmarks, r.report, r.warnings);
    j["timings_seconds"] = {{"load", load_seconds},
                            {"frame", r.report.frame_seconds},
                            {"landmarks", r.report.landmark_seconds},
                            {"girths", r.report.girth_seconds},
                            {"lengths", run.length_seconds},
                            {"total", total_seconds}};
    return j;
}

sizes::MeasurementSet measured_set(const MeasureRun& run, const std::string& name) {
    const measurement::BodyMeasurements& r = run.result;
    return sizes::parse_measurement_json(
        nlohmann::json::parse(measurement::body_measurements_json(name, r.frame, r.measurements,
                                                                  r.landmarks, r.report, r.warnings)
                                  .dump()),
        name);
}

}  // namespace tapeline::bench
