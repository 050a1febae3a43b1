// JSON writers (nlohmann to_json) of DistanceReport and the options of the baseline methods
// (geodesic_types.h).
//
// Light header (the types and nlohmann/json, no CGAL): loggers and benchmark drivers write the
// options a run used and what it reported, every field under its C++ name, enums by name.
#pragma once

#include <tapeline/geodesic/geodesic_types.h>

#include <nlohmann/json.hpp>

namespace tapeline::geodesic {

inline void to_json(nlohmann::json& j, const DistanceReport& r) {
    j = nlohmann::json::object();
    j["method"] = r.method;
    j["vertices"] = r.vertices;
    j["faces"] = r.faces;
    j["sources"] = r.sources;
    j["unreachable"] = r.unreachable;
    j["components"] = r.components;
    j["prepare_seconds"] = r.prepare_seconds;
    j["query_seconds"] = r.query_seconds;
    j["seconds"] = r.seconds;
    j["status"] = r.status;
    j["message"] = r.message;
}

inline void to_json(nlohmann::json& j, HeatMultiSource v) {
    j = to_string(v);
}

inline void to_json(nlohmann::json& j, const HeatOptions& o) {
    j = nlohmann::json::object();
    j["intrinsic_delaunay"] = o.intrinsic_delaunay;
    j["multi_source"] = o.multi_source;
    j["degenerate_face_tolerance"] = o.degenerate_face_tolerance;
    j["reject_degenerate_faces"] = o.reject_degenerate_faces;
}

inline void to_json(nlohmann::json& j, const ExactCgalOptions&) {
    j = nlohmann::json::object();
}

inline void to_json(nlohmann::json& j, const DijkstraOptions&) {
    j = nlohmann::json::object();
}

inline void to_json(nlohmann::json& j, const FastMarchingOptions& o) {
    j = nlohmann::json::object();
    j["unfold_obtuse"] = o.unfold_obtuse;
    j["max_unfold_faces"] = o.max_unfold_faces;
}

inline void to_json(nlohmann::json& j, const FastMarchingReport& r) {
    to_json(j, static_cast<const DistanceReport&>(r));
    j["obtuse_corners"] = r.obtuse_corners;
    j["virtual_edges"] = r.virtual_edges;
    j["unsplit_obtuse"] = r.unsplit_obtuse;
    j["face_updates"] = r.face_updates;
    j["edge_updates"] = r.edge_updates;
}

}  // namespace tapeline::geodesic
