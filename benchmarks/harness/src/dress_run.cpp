// The dressing pipeline on bench::Mesh (dress_run.h).
#include <tapeline/bench/dress_run.h>
#include <tapeline/core/mesh_io.h>
#include <tapeline/garment/bindings.h>

#include <tapeline/bench/measure_run.h>
#include <tapeline/core/errors.h>
#include <tapeline/garment/dress.h>
#include <tapeline/garment/garment_io.h>
#include <tapeline/measurement/measurement_json.h>
#include <tapeline/sizes/json_formats.h>
#ifdef TAPELINE_HAVE_GRADING
#include <tapeline/bench/grade_run.h>
#endif

#include <algorithm>
#include <chrono>
#include <utility>

namespace tapeline::bench {

DressRun dress_mesh(const Mesh& mesh, const measurement::BodyOptions& body_options,
                    pattern::Pattern pattern, const garment::DressOptions& options,
                    const sizes::MeasurementSet* base, std::uint32_t seed) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
    MeasureRun m = measure_mesh(mesh, body_options, {}, base != nullptr);
    const double measure_seconds = std::chrono::duration<double>(Clock::now() - t0).count();
    return dress_measured(std::move(m), body_options.name, std::move(pattern), options,
                          measure_seconds, base, seed);
}

DressRun dress_measured(MeasureRun m, const std::string& body_name, pattern::Pattern pattern,
                        const garment::DressOptions& options, double measure_seconds,
                        const sizes::MeasurementSet* base, std::uint32_t seed) {
    using Clock = std::chrono::steady_clock;
    const auto t0 = Clock::now();
#ifndef TAPELINE_HAVE_GRADING
    if (base) {
        throw InvalidInput(
            "grading to the body: this tapeline was built without Ceres or pagmo, so it cannot "
            "grade (install libceres-dev and libpagmo-dev)");
    }
#endif
    DressRun run;
    run.body = std::move(m.body);
    for (const auto& w : m.result.report.warnings) {
        run.warnings.push_back(w);
    }
#ifdef TAPELINE_HAVE_GRADING
    if (base) {
        const sizes::MeasurementSet to = measured_set(m, body_name);
        grading::GradingOptions go;
        go.seed = seed;
        go.threads = std::size_t(std::max(0, options.drape.threads));
        grading::GradeResult g = grade_as_tool(std::move(pattern), *base, to, go, true);
        run.grading_notes = g.report.notes;
        run.grading_notes.push_back("graded " + g.pattern.name + " from " + base->name + " to " +
                                    to.name);
        pattern = std::move(g.pattern);
    }
#else
    (void)seed;
#endif

    garment::DressResult d =
        garment::dress(run.body, m.result.landmarks, std::move(pattern), options);
    run.seam_lines.resize(d.report.seams.size());
    for (std::size_t k = 0; k < d.sewing.pairs.size(); ++k) {
        run.seam_lines[d.sewing.seam_of_pair[k]].push_back(d.draped[d.sewing.pairs[k].a]);
    }
    run.garment = std::move(d.garment);
    run.stretch = std::move(d.stretch);
    run.report = std::move(d.report);
    run.report.measure_seconds = measure_seconds;
    run.report.total_seconds =
        measure_seconds + std::chrono::duration<double>(Clock::now() - t0).count();
    return run;
}

BodyBase base_from_body(pattern::Pattern pattern, const std::string& path,
                        const measurement::BodyOptions& body_options) {
    return base_from_mesh(std::move(pattern), read_triangle_mesh<Mesh>(path).mesh, body_options);
}

BodyBase base_from_mesh(pattern::Pattern pattern, const Mesh& mesh,
                        const measurement::BodyOptions& body_options) {
    const MeasureRun m = measure_mesh(mesh, body_options);
    BodyBase b;
    b.measurements = measured_set(m, body_options.name);
    garment::BindingInference inf = garment::infer_girth_bindings(
        m.body, m.result.landmarks, m.result.measurements, std::move(pattern));
    b.pattern = std::move(inf.pattern);
    b.notes = std::move(inf.notes);
    // The measurements the pattern declares it was drafted for are its base values (the found
    // bindings' ease was taken against them; FreeSewing's table bindings take theirs so too);
    // the body gives the rest. The largest difference says how far the body is from the draft's.
    std::string widest;
    double widest_rel = -1;
    for (const auto& [name, value] : b.pattern.measurements_used) {
        const std::optional<double> body = b.measurements.get(name);
        if (body && value > 0 && !sizes::is_angle_measurement(name) &&
            std::abs(*body - value) / value > widest_rel) {
            widest_rel = std::abs(*body - value) / value;
            widest = name + " drafted for " + std::to_string(int(std::lround(value))) +
                     " mm, the body's " + std::to_string(int(std::lround(*body))) + " mm";
        }
        b.measurements.values[name] = value;
    }
    if (!b.pattern.measurements_used.empty()) {
        b.notes.push_back(
            "base measurements: the " + std::to_string(b.pattern.measurements_used.size()) +
            " the pattern declares, the body's for the rest" +
            (widest.empty() ? std::string()
                            : "; largest difference " + widest + " (" +
                                  std::to_string(int(std::lround(100 * widest_rel))) + " %)"));
    }
    return b;
}

void set_settle_seconds(garment::SewingOptions& sewing, double seconds) {
    sewing.settle_seconds = seconds;
    if (seconds == 0) {
        sewing.max_extra_seconds = 0;
    }
}

nlohmann::ordered_json dress_report_json(const DressRun& run, const std::string& body,
                                         const std::string& pattern,
                                         const garment::DressOptions& options) {
    nlohmann::ordered_json j;
    j["body"] = body;
    j["pattern"] = pattern;
    j["units"] = measurement::to_string(run.body.frame.unit);
    const nlohmann::ordered_json rep =
        garment::dress_report_json(run.report, options.fabric, options);
    for (auto it = rep.begin(); it != rep.end(); ++it) {
        j[it.key()] = it.value();
    }
    return j;
}

std::string failed_gates(const garment::DressReport& report) {
    std::string failed;
    for (const garment::Gate& g : report.gates) {
        if (!g.passed) {
            failed += (failed.empty() ? "" : ", ") + g.name + " " + std::to_string(g.value) +
                      " (limit " + std::to_string(g.limit) + ")";
        }
    }
    return failed;
}

}  // namespace tapeline::bench
