// The JSON writers of the grading options and report: every field of a default-constructed struct
// appears with the struct's value and nothing else does; the hand-written field lists are checked
// against the struct's member count, so a field added without a writer line fails here.
#include <tapeline/grading/grading_json.h>

#include <tapeline_test/json_fields.h>

#include <gtest/gtest.h>

#include <string>

namespace {

using namespace tapeline::grading;
using nlohmann::json;
using Fields = tapeline::test::JsonFields;
using tapeline::test::expect_fields;

#define FIELD TAPELINE_JSON_FIELD

TEST(GradingJson, Options) {
    const GradingOptions o;
    const Fields f = {FIELD(o, seed),
                      FIELD(o, population),
                      FIELD(o, generations),
                      FIELD(o, ease),
                      FIELD(o, weights),
                      FIELD(o, tolerances),
                      FIELD(o, threads),
                      FIELD(o, ceres_polish),
                      FIELD(o, ceres_iterations),
                      FIELD(o, reference_length_mm),
                      FIELD(o, neighbours),
                      FIELD(o, min_fit_factor),
                      FIELD(o, max_fit_factor),
                      FIELD(o, split_girths),
                      FIELD(o, trim_aspect),
                      FIELD(o, max_target_ratio)};
    EXPECT_EQ(tapeline::test::field_count<GradingOptions>(), f.size());
    const json j = o;
    expect_fields(j, f, "GradingOptions");
    EXPECT_EQ(j["ease"], "proportional");

    const GradingWeights& w = o.weights;
    const Fields fw = {FIELD(w, fit),         FIELD(w, seam),       FIELD(w, angle),
                       FIELD(w, curve),       FIELD(w, proportion), FIELD(w, grain),
                       FIELD(w, consistency), FIELD(w, bending),    FIELD(w, global),
                       FIELD(w, trim)};
    EXPECT_EQ(tapeline::test::field_count<GradingWeights>(), fw.size());
    expect_fields(j["weights"], fw, "GradingWeights");
    EXPECT_EQ(j["weights"]["fit"], 100.0);

    const GradingTolerances& t = o.tolerances;
    const Fields ft = {FIELD(t, fit_mm), FIELD(t, seam_mm)};
    EXPECT_EQ(tapeline::test::field_count<GradingTolerances>(), ft.size());
    expect_fields(j["tolerances"], ft, "GradingTolerances");
}

// The report keeps the keys of the `--report` file (some differ from the C++ names).
TEST(GradingJson, Report) {
    GradingReport r;
    r.fit.push_back({"waist", "front, back", 700, 20, 701, 1});
    r.seams.push_back({"side", 400, 399, 1, 1});
    r.front.push_back({});
    r.ceres_status = "CONVERGENCE";
    r.evaluations = 640;
    const Fields f = {FIELD(r, pieces),
                      FIELD(r, nodes),
                      FIELD(r, variables),
                      FIELD(r, residuals),
                      FIELD(r, fit),
                      FIELD(r, seams),
                      FIELD(r, style),
                      FIELD(r, front),
                      FIELD(r, chosen),
                      FIELD(r, chosen_why),
                      FIELD(r, within_tolerance),
                      FIELD(r, max_fit_error_mm),
                      FIELD(r, max_seam_mismatch_mm),
                      {"ceres", {{"iterations", r.ceres_iterations}, {"status", r.ceres_status}}},
                      {"nsga2_evaluations", r.evaluations},
                      FIELD(r, notes),
                      {"timings_s", json(r.timings)}};
    // ceres_iterations and ceres_status share one key: one field fewer in the JSON.
    EXPECT_EQ(tapeline::test::field_count<GradingReport>(), f.size() + 1);
    const json j = r;
    expect_fields(j, f, "GradingReport");
    EXPECT_EQ(j["fit"][0]["pieces"], "front, back");
    EXPECT_EQ(j["nsga2_evaluations"], 640);

    const FitRow& fr = r.fit[0];
    const Fields ff = {FIELD(fr, measurement), {"pieces", fr.where},   FIELD(fr, target_mm),
                       FIELD(fr, ease_mm),     FIELD(fr, achieved_mm), FIELD(fr, error_mm)};
    EXPECT_EQ(tapeline::test::field_count<FitRow>(), ff.size());
    expect_fields(j["fit"][0], ff, "FitRow");

    const SeamRow& sr = r.seams[0];
    const Fields fs = {FIELD(sr, name), FIELD(sr, length_a_mm), FIELD(sr, length_b_mm),
                       FIELD(sr, ratio), FIELD(sr, mismatch_mm)};
    EXPECT_EQ(tapeline::test::field_count<SeamRow>(), fs.size());
    expect_fields(j["seams"][0], fs, "SeamRow");

    const StyleMetrics& st = r.style;
    const Fields fst = {FIELD(st, max_angle_change_deg), FIELD(st, mean_angle_change_deg),
                        FIELD(st, max_curve_change),     FIELD(st, proportion_spread),
                        FIELD(st, max_grain_change_deg), FIELD(st, cost)};
    EXPECT_EQ(tapeline::test::field_count<StyleMetrics>(), fst.size());
    expect_fields(j["style"], fst, "StyleMetrics");

    const ParetoPoint& p = r.front[0];
    const Fields fp = {FIELD(p, fit),
                       FIELD(p, style),
                       FIELD(p, max_fit_error_mm),
                       FIELD(p, max_seam_mismatch_mm),
                       FIELD(p, polished),
                       FIELD(p, within_tolerance),
                       FIELD(p, origin)};
    EXPECT_EQ(tapeline::test::field_count<ParetoPoint>(), fp.size());
    expect_fields(j["front"][0], fp, "ParetoPoint");

    const GradingTimings& tm = r.timings;
    const Fields ftm = {{"setup", tm.setup_s},
                        {"ceres_fast_path", tm.ceres_fast_path_s},
                        {"nsga2", tm.nsga2_s},
                        {"polish", tm.polish_s},
                        {"total", tm.total_s}};
    EXPECT_EQ(tapeline::test::field_count<GradingTimings>(), ftm.size());
    expect_fields(j["timings_s"], ftm, "GradingTimings");
}

}  // namespace
