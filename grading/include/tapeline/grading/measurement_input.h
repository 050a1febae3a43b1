// Reading a base or target measurement set for grading, whatever file it comes in, and refusing
// absurd sets before any work is done.
//
// Accepted: a Seamly2D individual file (.vit); a `tapeline measure` JSON — an object with a
// "measurements" array of {"name" or "freesewing_name", "value_mm"} (both names are kept); a
// FreeSewing measurement_sets.json (an object of sets: pick one by name, or the only one); a flat
// JSON object {"chest": 979, ...} in millimetres, or in the unit of its "units" member.
//
// Patterns bind FreeSewing names (chest, hpsToWaistBack, ...). A .vit names its measurements the
// Seamly2D way (bust_circ, neck_side_to_waist_b, ...) or, for user-defined ones, "@" + a name
// (`tapeline measure --vit` writes "@" + its ISO-style name when Seamly2D has none): each known one
// also gets its FreeSewing name (seamly_to_freesewing_names below; a name the file already holds
// is never overwritten).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/pattern/internal/json_read.h>
#include <tapeline/pattern/measurement_set.h>

#include <cmath>
#include <map>
#include <string>

namespace tapeline::grading {

namespace tp = tapeline::pattern;

/// Seamly2D known measurement names, and the ISO-style names `tapeline measure` gives (they come
/// back from a .vit as "@" + name when Seamly2D has none), → FreeSewing names. Inverse of
/// measurement/seamly_vit.h's table composed with the measurement catalogue's FreeSewing names.
inline const std::map<std::string, std::string>& seamly_to_freesewing_names() {
    static const std::map<std::string, std::string> names = {
        // Seamly2D known names
        {"height", "height"},
        {"head_circ", "head"},
        {"neck_mid_circ", "neck"},
        {"highbust_circ", "highBust"},
        {"bust_circ", "chest"},
        {"lowbust_circ", "underbust"},
        {"waist_circ", "waist"},
        {"highhip_circ", "hips"},
        {"hip_circ", "seat"},
        {"leg_thigh_upper_circ", "upperLeg"},
        {"leg_knee_circ", "knee"},
        {"leg_ankle_circ", "ankle"},
        {"arm_upper_circ", "biceps"},
        {"arm_wrist_circ", "wrist"},
        {"shoulder_tip_to_shoulder_tip_b", "shoulderToShoulder"},
        {"neck_side_to_waist_b", "hpsToWaistBack"},
        {"neck_side_to_waist_f", "hpsToWaistFront"},
        {"arm_shoulder_tip_to_elbow", "shoulderToElbow"},
        {"arm_shoulder_tip_to_wrist", "shoulderToWrist"},
        {"leg_crotch_to_floor", "inseam"},
        {"leg_waist_side_to_floor", "waistToFloor"},
        {"bustpoint_to_neck_side", "hpsToBust"},
        {"crotch_length", "crossSeam"},
        {"crotch_length_f", "crossSeamFront"},
        {"shoulder_slope_neck_side_angle", "shoulderSlope"},
        {"waist_to_hip_side", "waistToHips"},
        {"armpit_to_waist_side", "waistToArmpit"},
        // tapeline measure's names (a .vit custom "@name", or a flat file using them)
        {"stature", "height"},
        {"head_girth", "head"},
        {"neck_girth", "neck"},
        {"high_bust_girth", "highBust"},
        {"bust_girth", "chest"},
        {"underbust_girth", "underbust"},
        {"waist_girth", "waist"},
        {"high_hip_girth", "hips"},
        {"hip_girth", "seat"},
        {"thigh_girth", "upperLeg"},
        {"knee_girth", "knee"},
        {"ankle_girth", "ankle"},
        {"upper_arm_girth", "biceps"},
        {"wrist_girth", "wrist"},
        {"shoulder_width_back", "shoulderToShoulder"},
        {"hps_to_waist_back", "hpsToWaistBack"},
        {"hps_to_waist_front", "hpsToWaistFront"},
        {"shoulder_to_elbow", "shoulderToElbow"},
        {"shoulder_to_wrist", "shoulderToWrist"},
        {"outseam", "waistToFloor"},
        {"hps_to_bust", "hpsToBust"},
        {"cross_seam", "crossSeam"},
        {"cross_seam_front", "crossSeamFront"},
        {"shoulder_slope", "shoulderSlope"},
        {"waist_to_hips", "waistToHips"},
        {"waist_to_armpit", "waistToArmpit"},
    };
    return names;
}

/// Adds the FreeSewing name of every Seamly2D or tapeline-measure name of `m` ("@" stripped) that
/// `m` does not hold yet.
inline void add_freesewing_aliases(tp::MeasurementSet& m) {
    std::map<std::string, double> add;
    for (const auto& [k, v] : m.values) {
        const std::string key = !k.empty() && k[0] == '@' ? k.substr(1) : k;
        const auto it = seamly_to_freesewing_names().find(key);
        const std::string fs = it != seamly_to_freesewing_names().end() ? it->second : key;
        if (!m.values.count(fs) && !add.count(fs)) {
            add[fs] = v;
        }
    }
    m.values.insert(add.begin(), add.end());
}

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
        add_freesewing_aliases(m);
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
