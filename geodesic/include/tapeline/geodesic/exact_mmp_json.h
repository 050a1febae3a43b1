// JSON writers (nlohmann to_json) of the exact MMP options and report (exact_mmp_types.h).
//
// Light header (the types and nlohmann/json, no CGAL): loggers and benchmark drivers write the
// options a run used and what it reported, every field under its C++ name, enums by name.
#pragma once

#include <tapeline/geodesic/exact_mmp_types.h>
#include <tapeline/geodesic/geodesic_json.h>

#include <nlohmann/json.hpp>

namespace tapeline::geodesic {

inline void to_json(nlohmann::json& j, const ExactMmpOptions& o) {
    j = nlohmann::json::object();
    j["max_distance"] = o.max_distance;
    j["target_vertices"] = o.target_vertices;
    j["prune_with_vertex_distances"] = o.prune_with_vertex_distances;
    j["keep_windows"] = o.keep_windows;
    j["max_propagated_windows"] = o.max_propagated_windows;
}

inline void to_json(nlohmann::json& j, const ExactMmpReport& r) {
    to_json(j, static_cast<const DistanceReport&>(r));
    j["windows_created"] = r.windows_created;
    j["windows_propagated"] = r.windows_propagated;
    j["windows_pruned"] = r.windows_pruned;
    j["windows_kept"] = r.windows_kept;
    j["windows_peak"] = r.windows_peak;
    j["pseudo_sources"] = r.pseudo_sources;
    j["saddle_or_boundary_vertices"] = r.saddle_or_boundary_vertices;
    j["peak_bytes"] = r.peak_bytes;
    j["stopped_at"] = r.stopped_at;
}

}  // namespace tapeline::geodesic
