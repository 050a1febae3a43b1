// JSON writers (nlohmann to_json) of the grading options and report (grading_types.h). The
// report's JSON is the `--report` file of `tapeline grade` (grading/README.md names its keys).
//
// Light header (the types and nlohmann/json; no Ceres, no pagmo): loggers and the command-line
// tool write the options a run used and what it reported.
#pragma once

#include <tapeline/grading/grading_types.h>

#include <nlohmann/json.hpp>

namespace tapeline::grading {

inline void to_json(nlohmann::json& j, EaseMode v) {
    j = to_string(v);
}

inline void to_json(nlohmann::json& j, const GradingWeights& w) {
    j = nlohmann::json::object();
    j["fit"] = w.fit;
    j["seam"] = w.seam;
    j["angle"] = w.angle;
    j["curve"] = w.curve;
    j["proportion"] = w.proportion;
    j["grain"] = w.grain;
    j["consistency"] = w.consistency;
    j["bending"] = w.bending;
    j["global"] = w.global;
    j["trim"] = w.trim;
}

inline void to_json(nlohmann::json& j, const GradingTolerances& t) {
    j = nlohmann::json::object();
    j["fit_mm"] = t.fit_mm;
    j["seam_mm"] = t.seam_mm;
}

inline void to_json(nlohmann::json& j, const GradingOptions& o) {
    j = nlohmann::json::object();
    j["seed"] = o.seed;
    j["population"] = o.population;
    j["generations"] = o.generations;
    j["ease"] = o.ease;
    j["weights"] = o.weights;
    j["tolerances"] = o.tolerances;
    j["threads"] = o.threads;
    j["ceres_polish"] = o.ceres_polish;
    j["ceres_iterations"] = o.ceres_iterations;
    j["reference_length_mm"] = o.reference_length_mm;
    j["neighbours"] = o.neighbours;
    j["min_fit_factor"] = o.min_fit_factor;
    j["max_fit_factor"] = o.max_fit_factor;
    j["split_girths"] = o.split_girths;
    j["trim_aspect"] = o.trim_aspect;
    j["max_target_ratio"] = o.max_target_ratio;
}

inline void to_json(nlohmann::json& j, const FitRow& f) {
    j = {{"measurement", f.measurement}, {"pieces", f.where},
         {"target_mm", f.target_mm},     {"ease_mm", f.ease_mm},
         {"achieved_mm", f.achieved_mm}, {"error_mm", f.error_mm}};
}

inline void to_json(nlohmann::json& j, const SeamRow& s) {
    j = {{"name", s.name},
         {"length_a_mm", s.length_a_mm},
         {"length_b_mm", s.length_b_mm},
         {"ratio", s.ratio},
         {"mismatch_mm", s.mismatch_mm}};
}

inline void to_json(nlohmann::json& j, const StyleMetrics& s) {
    j = {{"max_angle_change_deg", s.max_angle_change_deg},
         {"mean_angle_change_deg", s.mean_angle_change_deg},
         {"max_curve_change", s.max_curve_change},
         {"proportion_spread", s.proportion_spread},
         {"max_grain_change_deg", s.max_grain_change_deg},
         {"cost", s.cost}};
}

inline void to_json(nlohmann::json& j, const ParetoPoint& p) {
    j = {{"fit", p.fit},
         {"style", p.style},
         {"max_fit_error_mm", p.max_fit_error_mm},
         {"max_seam_mismatch_mm", p.max_seam_mismatch_mm},
         {"polished", p.polished},
         {"within_tolerance", p.within_tolerance},
         {"origin", p.origin}};
}

inline void to_json(nlohmann::json& j, const GradingTimings& t) {
    j = {{"setup", t.setup_s},
         {"ceres_fast_path", t.ceres_fast_path_s},
         {"nsga2", t.nsga2_s},
         {"polish", t.polish_s},
         {"total", t.total_s}};
}

inline void to_json(nlohmann::json& j, const GradingReport& r) {
    j = nlohmann::json::object();
    j["pieces"] = r.pieces;
    j["nodes"] = r.nodes;
    j["variables"] = r.variables;
    j["residuals"] = r.residuals;
    j["fit"] = r.fit;
    j["seams"] = r.seams;
    j["style"] = r.style;
    j["front"] = r.front;
    j["chosen"] = r.chosen;
    j["chosen_why"] = r.chosen_why;
    j["within_tolerance"] = r.within_tolerance;
    j["max_fit_error_mm"] = r.max_fit_error_mm;
    j["max_seam_mismatch_mm"] = r.max_seam_mismatch_mm;
    j["ceres"] = {{"iterations", r.ceres_iterations}, {"status", r.ceres_status}};
    j["nsga2_evaluations"] = r.evaluations;
    j["notes"] = r.notes;
    j["timings_s"] = r.timings;
}

}  // namespace tapeline::grading
