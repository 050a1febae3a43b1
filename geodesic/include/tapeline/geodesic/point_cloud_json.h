// JSON writers (nlohmann to_json) of the point-cloud options and report (point_cloud_types.h).
//
// Light header (the types and nlohmann/json, no CGAL): loggers and benchmark drivers write the
// options a run used and what it reported, every field under its C++ name, enums by name.
#pragma once

#include <tapeline/geodesic/curvature_flow_json.h>
#include <tapeline/geodesic/point_cloud_types.h>

#include <nlohmann/json.hpp>

namespace tapeline::geodesic {

inline void to_json(nlohmann::json& j, PointCloudProjection v) {
    j = to_string(v);
}

inline void to_json(nlohmann::json& j, PointCloudKnn v) {
    j = to_string(v);
}

inline void to_json(nlohmann::json& j, const PointCloudDistanceOptions& o) {
    to_json(j, static_cast<const FlowPropagationOptions&>(o));
    j["cell_size"] = o.cell_size;
    j["neighbours"] = o.neighbours;
    j["window"] = o.window;
    j["manifold_dimension"] = o.manifold_dimension;
    j["projection"] = o.projection;
    j["knn"] = o.knn;
    j["flow"] = o.flow;
    j["path_flow"] = o.path_flow;
}

inline void to_json(nlohmann::json& j, const PointCloudDistanceReport& r) {
    to_json(j, static_cast<const DistanceReport&>(r));
    j["points"] = r.points;
    j["dimension"] = r.dimension;
    j["manifold_dimension"] = r.manifold_dimension;
    j["manifold_dimension_estimated"] = r.manifold_dimension_estimated;
    j["neighbours"] = r.neighbours;
    j["cell_size"] = r.cell_size;
    j["sample_spacing"] = r.sample_spacing;
    j["nodes"] = r.nodes;
    j["node_edges"] = r.node_edges;
    j["bridged_components"] = r.bridged_components;
    j["window"] = r.window;
    j["projection"] = r.projection;
    j["knn"] = r.knn;
    j["reached_nodes"] = r.reached_nodes;
    j["reached"] = r.reached;
    j["flows"] = r.flows;
    j["iterations"] = r.iterations;
    j["converged"] = r.converged;
    j["stalled"] = r.stalled;
    j["max_iterations"] = r.max_iterations;
    j["solver_failures"] = r.solver_failures;
    j["charts"] = r.charts;
    j["knn_seconds"] = r.knn_seconds;
    j["grid_seconds"] = r.grid_seconds;
    j["propagate_seconds"] = r.propagate_seconds;
    j["interpolate_seconds"] = r.interpolate_seconds;
}

}  // namespace tapeline::geodesic
