// Grading as `tapeline grade` grades: a FreeSewing draft gets the FreeSewing bindings and seam
// table, the graded pattern keeps the seams it was graded with. Compiled once in the harness for
// the command-line tool and the Python module.
#pragma once

#ifdef TAPELINE_HAVE_GRADING
#include <tapeline/grading/grading_types.h>
#include <tapeline/pattern/pattern.h>
#include <tapeline/sizes/measurement_set.h>

namespace tapeline::bench {

/// grade_pattern(base, from, to, options) with, when `base` is a FreeSewing draft and
/// `freesewing_bindings` is set, its FreeSewing seam rules and (unless `freesewing_table` is
/// unset) the bindings of FreeSewing's point names for the measurements not bound yet. The
/// graded pattern keeps
/// the seams it was graded with; seam rules that could not be applied, and a FreeSewing design
/// without a seam table, are notes of the report. Throws as grade_pattern.
grading::GradeResult grade_as_tool(pattern::Pattern base, const sizes::MeasurementSet& from,
                                   const sizes::MeasurementSet& to,
                                   const grading::GradingOptions& options,
                                   bool freesewing_bindings = true, bool freesewing_table = true);

}  // namespace tapeline::bench
#endif
