// Landmark override files: points given by the user replace the landmarks found (landmarks.h).
//
// Override file (JSON):
//   { "frame": "input",                       // or "canonical" (mm, y up, z front, x left)
//     "landmarks": { "crotch": [x, y, z], "armpit_left": [x, y, z] } }
// "input" (the default) means the mesh's own coordinates and unit, as a viewer shows them.
// An overridden landmark replaces the found one and every later search uses it.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/json_read.h>
#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/measurement_types.h>

#include <nlohmann/json.hpp>

#include <fstream>
#include <map>
#include <sstream>
#include <string>

namespace tapeline::measurement {

/// Landmark points given by the user.
struct LandmarkOverrides {
    bool canonical = false;              ///< points are canonical mm, else input coordinates
    std::map<std::string, Vec3> points;  ///< by landmark name
    std::string source;                  ///< file name, for messages

    /// The points in the canonical frame of `frame`.
    std::map<std::string, Vec3> canonical_points(const BodyFrame& frame) const {
        std::map<std::string, Vec3> out;
        for (const auto& [name, p] : points) {
            out[name] = canonical ? p : frame.to_canonical(p);
        }
        return out;
    }
};

/// Parses an override document (see the top of this file); `where` names it in messages.
///
/// \throws InvalidInput naming `where`: invalid JSON, no "landmarks" object, a "frame" other
///         than "input" or "canonical", an unknown landmark name, or a point that is not three
///         finite numbers.
inline LandmarkOverrides parse_landmark_overrides(const std::string& text,
                                                  const std::string& where) {
    const nlohmann::json doc = tapeline::json::parse_json(text, where);
    if (!doc.is_object() || !doc.contains("landmarks") || !doc["landmarks"].is_object()) {
        throw InvalidInput(where + ": expected an object with a \"landmarks\" object");
    }
    LandmarkOverrides o;
    o.source = where;
    if (doc.contains("frame")) {
        const auto& f = doc["frame"];
        if (!f.is_string() || (f != "input" && f != "canonical")) {
            throw InvalidInput(where + ": \"frame\" must be \"input\" or \"canonical\", got " +
                               f.dump());
        }
        o.canonical = f == "canonical";
    }
    const auto& names = landmark_names();
    for (const auto& [name, value] : doc["landmarks"].items()) {
        if (std::find(names.begin(), names.end(), name) == names.end()) {
            std::string known;
            for (const auto& n : names) {
                known += (known.empty() ? "" : ", ") + n;
            }
            throw InvalidInput(where + ": unknown landmark '" + name + "' (known: " + known + ")");
        }
        bool ok = value.is_array() && value.size() == 3;
        Vec3 p{0, 0, 0};
        for (std::size_t k = 0; ok && k < 3; ++k) {
            ok = value[k].is_number() && std::isfinite(value[k].get<double>());
            p[k] = ok ? value[k].get<double>() : 0.0;
        }
        if (!ok) {
            throw InvalidInput(where + ": landmarks." + name +
                               " must be an array of 3 finite numbers, got " + value.dump());
        }
        o.points[name] = p;
    }
    return o;
}

/// Reads an override file; InvalidInput naming the file when it cannot be read or is invalid.
///
/// \throws InvalidInput when the file cannot be opened, or as parse_landmark_overrides.
inline LandmarkOverrides read_landmark_overrides(const std::string& path) {
    std::ifstream in(path, std::ios::binary);
    if (!in) {
        throw InvalidInput(path + ": cannot open landmark file");
    }
    std::ostringstream s;
    s << in.rdbuf();
    return parse_landmark_overrides(s.str(), path);
}

}  // namespace tapeline::measurement
