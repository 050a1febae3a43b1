// Compiles grading (Ceres, pagmo, TBB) once for the grading tests.
#include <tapeline/grading/compare.h>
#include <tapeline/grading/freesewing_bindings.h>
#include <tapeline/grading/grade.h>
#include <tapeline/grading/output.h>
#include <tapeline/pattern/freesewing_designs.h>
#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/sizes/read_input.h>
#include <tapeline_test/grading.h>

namespace tapeline_test {

namespace tg = tapeline::grading;
namespace tp = tapeline::pattern;
namespace ts = tapeline::sizes;

tg::GradeResult grade(const tp::Pattern& base, const ts::MeasurementSet& from,
                      const ts::MeasurementSet& to, const tg::GradingOptions& options,
                      const std::vector<tg::SeamSpec>& seams) {
    return tg::grade_pattern(base, from, to, options, seams);
}

std::vector<tg::SeamSpec> freesewing_seams(const tp::Pattern& p,
                                           std::vector<std::string>* skipped) {
    return tp::freesewing_seams(p, skipped);
}

tp::Pattern freesewing_draft(const std::string& design, const std::string& size) {
    tp::Pattern p = tp::read_freesewing(std::string(TAPELINE_SHARED_DATA_DIR) +
                                        "/patterns/freesewing/" + design + "_" + size + ".json");
    tg::add_freesewing_bindings(p);
    return p;
}

ts::MeasurementSet freesewing_set(const std::string& name) {
    return ts::read_measurement_input(
        std::string(TAPELINE_SHARED_DATA_DIR) + "/patterns/freesewing/measurement_sets.json", name);
}

Deviation deviation(const tp::Pattern& reference, const tp::Pattern& graded) {
    Deviation d;
    const auto rows = tg::pattern_deviation(reference, graded);
    for (const auto& r : rows) {
        d.mean_mm += r.mean_mm / rows.size();
        d.max_mm = std::max(d.max_mm, r.max_mm);
    }
    return d;
}

std::size_t add_freesewing_bindings(tp::Pattern& p) {
    return tg::add_freesewing_bindings(p);
}

std::vector<std::uint8_t> pareto_png(const tg::GradingReport& r) {
    return tg::pareto_png(r);
}

}  // namespace tapeline_test
