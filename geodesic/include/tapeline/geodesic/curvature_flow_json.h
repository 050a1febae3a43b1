// JSON writers (nlohmann to_json) of the curvature-flow options and reports
// (curvature_flow_types.h).
//
// Light header (the types and nlohmann/json, no CGAL): loggers and benchmark drivers write the
// options a run used and what it reported, every field under its C++ name, enums by name.
#pragma once

#include <tapeline/geodesic/curvature_flow_types.h>
#include <tapeline/geodesic/geodesic_json.h>

#include <nlohmann/json.hpp>

namespace tapeline::geodesic {

inline void to_json(nlohmann::json& j, CurvatureFlowSolver v) {
    j = to_string(v);
}

inline void to_json(nlohmann::json& j, CeresLinearSolver v) {
    j = to_string(v);
}

inline void to_json(nlohmann::json& j, WindowAnchor v) {
    j = to_string(v);
}

inline void to_json(nlohmann::json& j, const CurvatureFlowOptions& o) {
    j = nlohmann::json::object();
    j["sample_spacing"] = o.sample_spacing;
    j["sample_count"] = o.sample_count;
    j["step"] = o.step;
    j["tolerance"] = o.tolerance;
    j["update_tolerance"] = o.update_tolerance;
    j["max_iterations"] = o.max_iterations;
    j["endpoint_weight"] = o.endpoint_weight;
    j["solver"] = o.solver;
    j["ceres_linear_solver"] = o.ceres_linear_solver;
    j["straighten"] = o.straighten;
    j["interpolate_normals"] = o.interpolate_normals;
}

inline void to_json(nlohmann::json& j, const CurvatureFlowReport& r) {
    j = nlohmann::json::object();
    j["vertices"] = r.vertices;
    j["faces"] = r.faces;
    j["samples"] = r.samples;
    j["iterations"] = r.iterations;
    j["initial_length"] = r.initial_length;
    j["max_geodesic_curvature"] = r.max_geodesic_curvature;
    j["scaled_max_geodesic_curvature"] = r.scaled_max_geodesic_curvature;
    j["residual"] = r.residual;
    j["max_update"] = r.max_update;
    j["trace_fallbacks"] = r.trace_fallbacks;
    j["traced_length"] = r.traced_length;
    j["straightened"] = r.straightened;
    j["straighten_flips"] = r.straighten_flips;
    j["straighten_bends"] = r.straighten_bends;
    j["on_mesh_from_initial"] = r.on_mesh_from_initial;
    j["init_seconds"] = r.init_seconds;
    j["flow_seconds"] = r.flow_seconds;
    j["seconds"] = r.seconds;
    j["status"] = r.status;
    j["solver"] = r.solver;
}

/// The knobs meshes and point sets share (the base of both distance options).
inline void to_json(nlohmann::json& j, const FlowPropagationOptions& o) {
    j = nlohmann::json::object();
    j["sample_spacing"] = o.sample_spacing;
    j["cut_locus_guard"] = o.cut_locus_guard;
    j["near_source_samples"] = o.near_source_samples;
    j["anchor_slides"] = o.anchor_slides;
}

inline void to_json(nlohmann::json& j, const CurvatureFlowDistanceOptions& o) {
    to_json(j, static_cast<const FlowPropagationOptions&>(o));
    j["window"] = o.window;
    j["smooth_length"] = o.smooth_length;
    j["polyhedral_length"] = o.polyhedral_length;
    j["shortest_parent"] = o.shortest_parent;
    j["repair_tolerance"] = o.repair_tolerance;
    j["repair_rounds"] = o.repair_rounds;
    j["repair_flow_iterations"] = o.repair_flow_iterations;
    j["repair_steiner_points"] = o.repair_steiner_points;
    j["repair_graph_margin"] = o.repair_graph_margin;
    j["anchor"] = o.anchor;
    j["flow"] = o.flow;
    j["window_max_iterations"] = o.window_max_iterations;
}

inline void to_json(nlohmann::json& j, const CurvatureFlowDistanceReport& r) {
    to_json(j, static_cast<const DistanceReport&>(r));
    j["reached"] = r.reached;
    j["flows"] = r.flows;
    j["iterations"] = r.iterations;
    j["converged"] = r.converged;
    j["stalled"] = r.stalled;
    j["max_iterations"] = r.max_iterations;
    j["solver_failures"] = r.solver_failures;
    j["stored_samples"] = r.stored_samples;
    j["epsilon"] = r.epsilon;
    j["max_faces"] = r.max_faces;
    j["error_bound"] = r.error_bound;
    j["repair_checked"] = r.repair_checked;
    j["repair_improved"] = r.repair_improved;
    j["repair_graph_flagged"] = r.repair_graph_flagged;
    j["repair_graph_seconds"] = r.repair_graph_seconds;
    j["repair_seconds"] = r.repair_seconds;
    j["sample_spacing"] = r.sample_spacing;
}

}  // namespace tapeline::geodesic
