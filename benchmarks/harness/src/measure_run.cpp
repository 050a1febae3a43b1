// The measurement pipeline on bench::Mesh (measure_run.h).
#include <tapeline/bench/measure_run.h>

#include <tapeline/measurement/lengths.h>

#include <chrono>

namespace tapeline::bench {

MeasureRun measure_mesh(const Mesh& mesh, const measurement::BodyOptions& options,
                        const measurement::LandmarkOverrides& overrides, bool skin_lengths) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    MeasureRun run{measurement::make_body(mesh, options), {}, 0, 0};
    run.frame_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    run.result = measurement::measure_body(run.body, {}, overrides);
    run.result.report.frame_seconds = run.frame_seconds;
    if (skin_lengths) {
        run.length_seconds = measurement::measure_skin_lengths(run.body, mesh, run.result.landmarks,
                                                               run.result.measurements);
    }
    return run;
}

}  // namespace tapeline::bench
