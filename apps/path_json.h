// A geodesic path as the JSON `tapeline geodesic path` writes: points and length.
#pragma once

#include <nlohmann/json.hpp>

namespace tapeline::app {

template <class Path>
nlohmann::json path_json(const Path& path) {
    nlohmann::json j;
    j["length"] = path.found() ? nlohmann::json(path.length) : nlohmann::json(nullptr);
    j["reachable"] = path.found();
    nlohmann::json points = nlohmann::json::array();
    for (const auto& p : path.points) {
        points.push_back({p.x(), p.y(), p.z()});
    }
    j["points"] = points;
    return j;
}

}  // namespace tapeline::app
