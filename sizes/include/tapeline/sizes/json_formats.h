// Measurement sets in JSON:
// - FreeSewing's measurement_sets.json: {"set name": {"measurement": mm, ...}, ...};
// - a flat object {"measurement": value, ...} whose unit the caller declares (the file does not
//   say; DESIGN.md §8);
// - the measurement JSON `tapeline measure` writes ("format": "tapeline-measurements"): a
//   "measurements" array whose entries carry the catalogue's columns (name, kind, value_mm or
//   value_degrees, iso_clause, iso_number, freesewing_name, seamly2d_name). The measurement
//   module adds where each was taken (landmarks, tape loops) and the body's frame; reading
//   keeps value_mm under both names and skips entries without one (angles, measurements that
//   could not be taken).
// Angles (is_angle_measurement) stay in degrees and are never unit-scaled.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/json_read.h>
#include <tapeline/core/units.h>
#include <tapeline/sizes/catalogue.h>
#include <tapeline/sizes/measurement_set.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::sizes {

namespace internal {

inline MeasurementSet measurement_object(const json::Json& obj, const json::Where& w,
                                         double scale) {
    json::require_object(obj, w);
    MeasurementSet m;
    for (const auto& [k, v] : obj.items()) {
        const double x = json::number(v, w.key(k));
        m.values[k] = is_angle_measurement(k) ? x : scale * x;
    }
    return m;
}

}  // namespace internal

/// FreeSewing's measurement_sets.json: {"set name": {"measurement": mm, ...}, ...}.
///
/// \throws InvalidInput naming the file and the JSON path when the file cannot be read or
///         parsed, or a member has the wrong type.
inline std::vector<MeasurementSet> read_freesewing_measurement_sets(const std::string& path) {
    const json::Json doc = json::parse_json_file(path);
    const json::Where top{path, ""};
    json::require_object(doc, top);
    std::vector<MeasurementSet> out;
    for (const auto& [name, obj] : doc.items()) {
        MeasurementSet m = internal::measurement_object(obj, top.key(name), 1.0);
        m.name = name;
        m.source = path;
        out.push_back(std::move(m));
    }
    return out;
}

/// A flat JSON object {"measurement": value, ...} whose values are in `unit` (declared by the
/// caller: the file does not say).
///
/// \throws InvalidInput naming the file and the JSON path when the file cannot be read or
///         parsed, or a member has the wrong type.
/// \throws InvalidInput when `unit` is not mm, cm, dm, m, inch or in.
inline MeasurementSet read_measurement_json(const std::string& path, const std::string& unit) {
    const double scale = millimetres_per_unit(unit, path);
    MeasurementSet m =
        internal::measurement_object(json::parse_json_file(path), json::Where{path, ""}, scale);
    m.name = internal::file_stem(path);
    m.source = path;
    return m;
}

/// One entry of the measurement JSON: the catalogue's columns for `name` and its value (mm, or
/// degrees when `kind` is "angle"), rounded to 0.01. A name the catalogue lacks has no ISO or
/// FreeSewing name and the Seamly2D custom name "@" + name.
inline nlohmann::ordered_json measurement_json_entry(const std::string& name,
                                                     const std::string& kind, double value) {
    using Json = nlohmann::ordered_json;
    Json j;
    j["name"] = name;
    j["kind"] = kind;
    // `tapeline grade` reads value_mm and both names; an angle has no millimetre value.
    const bool angle = kind == to_string(MeasurementKind::angle);
    j["value_mm"] = angle ? Json(nullptr) : Json(std::round(value * 100.0) / 100.0);
    if (angle) {
        j["value_degrees"] = std::round(value * 100.0) / 100.0;
    }
    const std::string title = iso_title(name), number = iso_number(name);
    const std::string freesewing = freesewing_name(name), seamly = seamly_name(name);
    j["iso_clause"] = title.empty() ? Json(nullptr) : Json(title);
    j["iso_number"] = number.empty() ? Json(nullptr) : Json(number);
    j["freesewing_name"] = freesewing.empty() ? Json(nullptr) : Json(freesewing);
    j["seamly2d_name"] = seamly.empty() ? "@" + name : seamly;
    return j;
}

/// The kind the measurement JSON gives `name`: the catalogue's, "angle" for any other angle
/// name, else "length".
inline std::string measurement_json_kind(const std::string& name) {
    const CatalogueMatch m = find_measurement(name);
    if (m) {
        return to_string(m.entry->kind);
    }
    return is_angle_measurement(name) ? "angle" : "length";
}

/// A set as a measurement JSON document (no frame or tape geometry: a set has none).
inline nlohmann::ordered_json measurement_json(const NamedValues& values,
                                               const std::string& body = "") {
    using Json = nlohmann::ordered_json;
    Json j;
    j["format"] = "tapeline-measurements";
    j["version"] = 1;
    j["body"] = body;
    Json ms = Json::array();
    for (const auto& [name, value] : values) {
        ms.push_back(measurement_json_entry(name, measurement_json_kind(name), value));
    }
    j["measurements"] = ms;
    return j;
}

/// Whether a parsed JSON document is a measurement JSON (an object with a "measurements" array).
inline bool is_measurement_json(const json::Json& doc) {
    const json::Json* arr = json::optional_field(doc, "measurements");
    return arr && arr->is_array();
}

/// The measurement JSON `doc` read from `path`: each entry's value_mm under its "name" and its
/// "freesewing_name" (at least one is required); entries whose value_mm is null are skipped.
///
/// \throws InvalidInput naming `path` and the entry when `doc` has no "measurements" array, an
///         entry lacks value_mm or both names, or a member has the wrong type.
inline MeasurementSet parse_measurement_json(const json::Json& doc, const std::string& path) {
    using namespace json;
    const Where top{path, ""};
    require_object(doc, top);
    const Json& arr = field(doc, "measurements", top);
    require_array(arr, top.key("measurements"));
    MeasurementSet m;
    m.name = internal::file_stem(path);
    m.source = path;
    for (std::size_t i = 0; i < arr.size(); ++i) {
        const Where w = top.key("measurements").index(i);
        const Json& e = arr[i];
        require_object(e, w);
        if (!e.contains("value_mm")) {
            throw InvalidInput(w.str() + ": no value_mm");
        }
        if (e["value_mm"].is_null()) {
            continue;  // a measurement `tapeline measure` could not take, or an angle
        }
        const double x = number(e["value_mm"], w.key("value_mm"));
        bool named = false;
        for (const char* key : {"name", "freesewing_name"}) {
            if (const Json* n = optional_field(e, key); n && n->is_string()) {
                m.values[n->get<std::string>()] = x;
                named = true;
            }
        }
        if (!named) {
            throw InvalidInput(w.str() + ": no name or freesewing_name");
        }
    }
    return m;
}

/// Reads a measurement JSON file (see parse_measurement_json).
///
/// \throws InvalidInput naming the file and the JSON path when the file cannot be read or
///         parsed, or a member has the wrong type.
/// \throws InvalidInput also as parse_measurement_json.
inline MeasurementSet read_tapeline_measurements(const std::string& path) {
    return parse_measurement_json(json::parse_json_file(path), path);
}

}  // namespace tapeline::sizes
