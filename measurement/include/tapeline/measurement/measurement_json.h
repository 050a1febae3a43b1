// JSON writers (nlohmann to_json) of the measurement options and report (body_types.h,
// measurement_types.h).
//
// Light header (the types and nlohmann/json, no CGAL): loggers and benchmark drivers write the
// options a run used and what it reported, every field under its C++ name, enums by name, an
// axis as "+Y", an inferred unit as null.
#pragma once

#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/measurement_types.h>

#include <nlohmann/json.hpp>

namespace tapeline::measurement {

inline void to_json(nlohmann::json& j, LengthUnit v) {
    j = to_string(v);
}

inline void to_json(nlohmann::json& j, Pose v) {
    j = to_string(v);
}

inline void to_json(nlohmann::json& j, const Axis& a) {
    j = a.to_string();
}

inline void to_json(nlohmann::json& j, const BodyOptions& o) {
    j = nlohmann::json::object();
    j["unit"] = o.unit ? nlohmann::json(*o.unit) : nlohmann::json(nullptr);
    j["up"] = o.up;
    j["front"] = o.front;
    j["pose"] = o.pose;
    j["name"] = o.name;
}

inline void to_json(nlohmann::json& j, const MeasureOptions& o) {
    j = nlohmann::json::object();
    j["scan_step"] = o.scan_step;
    j["level_tolerance"] = o.level_tolerance;
    j["max_neck_tilt_degrees"] = o.max_neck_tilt_degrees;
}

inline void to_json(nlohmann::json& j, const MeasureReport& r) {
    j = nlohmann::json::object();
    j["vertices"] = r.vertices;
    j["faces"] = r.faces;
    j["components"] = r.components;
    j["sections"] = r.sections;
    j["frame_seconds"] = r.frame_seconds;
    j["landmark_seconds"] = r.landmark_seconds;
    j["girth_seconds"] = r.girth_seconds;
    j["landmarks_found"] = r.landmarks_found;
    j["landmarks_missing"] = r.landmarks_missing;
    j["warnings"] = r.warnings;
}

}  // namespace tapeline::measurement
