// Reading a base or target measurement set for grading, whatever file it comes in, and refusing
// absurd sets before any work is done.
//
// Accepted: a Seamly2D individual file (.vit); a `tapeline measure` JSON — an object with a
// "measurements" array of {"name" or "freesewing_name", "value_mm"} (both names are kept); a
// FreeSewing measurement_sets.json (an object of sets: pick one by name, or the only one); a flat
// JSON object {"chest": 979, ...} in millimetres, or in the unit of its "units" member.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/pattern/internal/json_read.h>
#include <tapeline/pattern/measurement_set.h>

#include <cmath>
#include <string>

namespace tapeline::grading {

namespace tp = tapeline::pattern;

/// Refuses non-finite or non-positive lengths and a waist above the height (when both are given),
/// naming the set.
inline void check_measurement_set(const tp::MeasurementSet& m) {
    const std::string where = m.source.empty() ? "set '" + m.name + "'" : m.source;
    for (const auto& [k, v] : m.values) {
        if (!std::isfinite(v)) {
            throw InvalidInput(where + ": measurement '" + k + "' is not a finite number");
        }
        if (!tp::is_angle_measurement(k) && v <= 0) {
            throw InvalidInput(where + ": measurement '" + k + "' is " + std::to_string(v) +
                               " mm; lengths must be positive");
        }
    }
    for (const char* h : {"height", "body_height", "heightTotal"}) {
        const auto height = m.get(h);
        const auto waist = m.get("waist");
        if (height && waist && *waist > *height) {
            throw InvalidInput(where + ": waist " + std::to_string(*waist) +
                               " mm is bigger than the height " + std::to_string(*height) + " mm");
        }
    }
}

/// Reads `path` (see the file comment); `set_name` picks a set of a FreeSewing sets file.
inline tp::MeasurementSet read_measurement_input(const std::string& path,
                                                 const std::string& set_name = "") {
    using namespace tp::internal;
    tp::MeasurementSet m;
    const std::string ext = path.size() > 4 ? path.substr(path.size() - 4) : "";
    if (ext == ".vit") {
        m = tp::read_seamly_individual(path);
    } else {
        const Json doc = parse_json_file(path);
        const Where top{path, ""};
        require_object(doc, top);
        if (const Json* arr = optional_field(doc, "measurements"); arr && arr->is_array()) {
            m.name = file_stem(path);
            for (std::size_t i = 0; i < arr->size(); ++i) {
                const Where w = top.key("measurements").index(i);
                const Json& e = (*arr)[i];
                require_object(e, w);
                if (!e.contains("value_mm")) {
                    throw InvalidInput(w.str() + ": no value_mm");
                }
                if (e["value_mm"].is_null()) {
                    continue;  // a measurement `tapeline measure` could not take
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
        } else {
            bool all_objects = !doc.empty();
            for (const auto& [k, v] : doc.items()) {
                all_objects = all_objects && v.is_object();
            }
            if (all_objects) {
                std::vector<tp::MeasurementSet> sets = tp::read_freesewing_measurement_sets(path);
                std::string names;
                for (tp::MeasurementSet& s : sets) {
                    names += (names.empty() ? "" : ", ") + s.name;
                    if (s.name == set_name || (set_name.empty() && sets.size() == 1)) {
                        m = std::move(s);
                    }
                }
                if (m.name.empty()) {
                    throw InvalidInput(path + ": " +
                                       (set_name.empty() ? std::string("holds several sets")
                                                         : "has no set '" + set_name + "'") +
                                       " (" + names + "); pick one with --from-set/--to-set");
                }
            } else {
                std::string unit = "mm";
                Json values = doc;
                if (const Json* u = optional_field(doc, "units")) {
                    unit = string(*u, top.key("units"));
                    values.erase("units");
                }
                const double s = tp::millimetres_per_unit(unit, path + ": units");
                m.name = file_stem(path);
                for (const auto& [k, v] : values.items()) {
                    const double x = number(v, top.key(k));
                    m.values[k] = tp::is_angle_measurement(k) ? x : s * x;
                }
            }
        }
    }
    m.source = path;
    check_measurement_set(m);
    return m;
}

}  // namespace tapeline::grading
