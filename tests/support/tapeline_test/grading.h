// Test facade for the grading module: the Ceres and pagmo instantiations are compiled once in
// support/grading_*.cpp; test files include this header and gtest only (DESIGN.md §5).
#pragma once

#include <tapeline/grading/grading_types.h>
#include <tapeline/pattern/pattern.h>
#include <tapeline/sizes/measurement_set.h>

#include <string>
#include <vector>

namespace tapeline_test {

tapeline::grading::GradeResult grade(const tapeline::pattern::Pattern& base,
                                     const tapeline::sizes::MeasurementSet& from,
                                     const tapeline::sizes::MeasurementSet& to,
                                     const tapeline::grading::GradingOptions& options,
                                     const std::vector<tapeline::grading::SeamSpec>& seams = {});

/// The seams of a FreeSewing draft's design (pattern/freesewing_designs.h); `skipped` gets the
/// rules that did not apply.
std::vector<tapeline::grading::SeamSpec> freesewing_seams(const tapeline::pattern::Pattern& p,
                                                          std::vector<std::string>* skipped);

/// FreeSewing draft `design` at `size` from ../shared/data (with the FreeSewing span bindings).
tapeline::pattern::Pattern freesewing_draft(const std::string& design, const std::string& size);

/// A FreeSewing set from ../shared/data/patterns/freesewing/measurement_sets.json.
tapeline::sizes::MeasurementSet freesewing_set(const std::string& name);

struct Deviation {
    double mean_mm = 0, max_mm = 0;
};
/// Mean over pieces of the aligned outline deviation (compare.h), and the max over pieces.
Deviation deviation(const tapeline::pattern::Pattern& reference,
                    const tapeline::pattern::Pattern& graded);

std::size_t add_freesewing_bindings(tapeline::pattern::Pattern& p);

std::vector<std::uint8_t> pareto_png(const tapeline::grading::GradingReport& r);

}  // namespace tapeline_test
