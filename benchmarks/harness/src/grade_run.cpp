// The grading of `tapeline grade` (grade_run.h).
#include <tapeline/bench/grade_run.h>

#ifdef TAPELINE_HAVE_GRADING
#include <tapeline/grading/freesewing_bindings.h>
#include <tapeline/grading/grade.h>
#include <tapeline/pattern/freesewing_designs.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::bench {

grading::GradeResult grade_as_tool(pattern::Pattern base, const sizes::MeasurementSet& from,
                                   const sizes::MeasurementSet& to,
                                   const grading::GradingOptions& options, bool freesewing_bindings,
                                   bool freesewing_table) {
    namespace tp = tapeline::pattern;
    const bool freesewing = freesewing_bindings && base.designer == "FreeSewing";
    std::vector<tp::SeamSpec> seams;
    std::vector<std::string> skipped;
    if (freesewing) {
        if (freesewing_table) {
            grading::add_freesewing_bindings(base);
        }
        // The importer stored the derived seams a pattern can hold; the rest join here.
        for (tp::SeamSpec& s : tp::freesewing_seams(base, &skipped)) {
            const bool held = std::any_of(base.seams.begin(), base.seams.end(),
                                          [&](const tp::Seam& q) { return q.name == s.name; });
            if (!held) {
                seams.push_back(std::move(s));
            }
        }
    }
    grading::GradeResult g = grading::grade_pattern(base, from, to, options, seams);
    if (freesewing && seams.empty() && base.seams.empty() && skipped.empty()) {
        g.report.notes.push_back("no seam table for FreeSewing design '" + base.name +
                                 "': graded without seams");
    }
    for (const tp::Seam& s : tp::pattern_seams(seams)) {
        g.pattern.seams.push_back(s);  // the graded pattern keeps the seams it was graded with
    }
    for (const std::string& s : skipped) {
        g.report.notes.push_back("seam rule '" + s + "' not applied: a chain end is not an " +
                                 "outline vertex of this draft");
    }
    return g;
}

}  // namespace tapeline::bench
#endif
