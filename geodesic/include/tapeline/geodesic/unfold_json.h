// JSON writer (nlohmann to_json) of the unfolding options (unfold_types.h).
//
// Light header (the types and nlohmann/json, no CGAL): loggers and benchmark drivers write the
// options a run used and what it reported, every field under its C++ name, enums by name.
#pragma once

#include <tapeline/geodesic/unfold_types.h>

#include <nlohmann/json.hpp>

namespace tapeline::geodesic {

inline void to_json(nlohmann::json& j, const UnfoldOptions& o) {
    j = nlohmann::json::object();
    j["tolerance"] = o.tolerance;
}

}  // namespace tapeline::geodesic
