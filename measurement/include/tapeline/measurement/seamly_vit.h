// Seamly2D / Valentina individual measurement file (.vit) export of a MeasurementSet. No CGAL.
//
// The file is XML, unit mm, one <m name=... value=.../> per measurement. Measurements that have a
// Seamly2D known name (its measurement database: bust_circ, arm_shoulder_tip_to_wrist, ...) are
// written under that name; the others as custom measurements, "@" + our name (Seamly2D's rule for
// user-defined names). tapeline::pattern::read_seamly_individual reads the file back.
#pragma once

#include <tapeline/core/xml_escape.h>
#include <tapeline/measurement/measurement_types.h>

#include <cmath>
#include <cstdio>
#include <map>
#include <ostream>
#include <string>

namespace tapeline::measurement {

/// Our measurement name → Seamly2D known measurement name; empty when Seamly2D has none.
inline std::string seamly_name(const std::string& name) {
    static const std::map<std::string, std::string> names = {
        {"stature", "height"},
        {"head_girth", "head_circ"},
        {"neck_girth", "neck_mid_circ"},
        {"neck_base_girth", "neck_circ"},
        {"high_bust_girth", "highbust_circ"},
        {"bust_girth", "bust_circ"},
        {"underbust_girth", "lowbust_circ"},
        {"waist_girth", "waist_circ"},
        {"high_hip_girth", "highhip_circ"},
        {"hip_girth", "hip_circ"},
        {"thigh_girth", "leg_thigh_upper_circ"},
        {"mid_thigh_girth", "leg_thigh_mid_circ"},
        {"knee_girth", "leg_knee_circ"},
        {"calf_girth", "leg_calf_circ"},
        {"ankle_girth", "leg_ankle_circ"},
        {"upper_arm_girth", "arm_upper_circ"},
        {"elbow_girth", "arm_elbow_circ"},
        {"wrist_girth", "arm_wrist_circ"},
        {"shoulder_width_back", "shoulder_tip_to_shoulder_tip_b"},
        {"hps_to_waist_back", "neck_side_to_waist_b"},
        {"hps_to_waist_front", "neck_side_to_waist_f"},
        {"shoulder_to_elbow", "arm_shoulder_tip_to_elbow"},
        {"shoulder_to_wrist", "arm_shoulder_tip_to_wrist"},
        {"inseam", "leg_crotch_to_floor"},
        {"outseam", "leg_waist_side_to_floor"},
        {"back_neck_to_waist", "neck_back_to_waist_b"},
        {"front_neck_to_waist", "neck_front_to_waist_flat_f"},
        {"hps_to_bust", "bustpoint_to_neck_side"},
        {"cross_seam", "crotch_length"},
        {"cross_seam_front", "crotch_length_f"},
        {"cross_seam_back", "crotch_length_b"},
        {"shoulder_slope", "shoulder_slope_neck_side_angle"},
        {"waist_to_hips", "waist_to_hip_side"},
        {"waist_to_armpit", "armpit_to_waist_side"},
    };
    const auto it = names.find(name);
    return it == names.end() ? std::string() : it->second;
}

/// Writes `set` as a Seamly2D individual measurement file (unit mm; angles in degrees, which
/// Seamly2D keeps unscaled). `notes` goes into <notes> (the body file, say).
inline void write_seamly_individual(std::ostream& out, const MeasurementSet& set,
                                    const std::string& notes = "") {
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<vit>\n"
        << "    <!--Measured by tapeline measure (tape girths and skin lengths).-->\n"
        << "    <version>0.3.3</version>\n"
        << "    <read-only>false</read-only>\n";
    if (notes.empty()) {
        out << "    <notes/>\n";
    } else {
        out << "    <notes>" << xml_escape(notes) << "</notes>\n";
    }
    out << "    <unit>mm</unit>\n"
        << "    <pm_system>998</pm_system>\n"
        << "    <personal>\n"
        << "        <family-name/>\n"
        << "        <given-name/>\n"
        << "        <gender>unknown</gender>\n"
        << "    </personal>\n"
        << "    <body-measurements>\n";
    for (const Measurement& m : set.measurements) {
        if (!std::isfinite(m.value)) {
            continue;
        }
        const std::string known = seamly_name(m.name);
        const std::string name = known.empty() ? "@" + m.name : known;
        char value[64];
        std::snprintf(value, sizeof value, "%.3f", m.value);
        const std::string full = m.iso_clause.empty() ? m.name : m.iso_clause;
        out << "        <m name=\"" << xml_escape(name) << "\" value=\"" << value
            << "\" full_name=\"" << xml_escape(full) << "\"";
        if (!m.iso_number.empty()) {
            out << " description=\"" << xml_escape("ISO 8559-1:2017 " + m.iso_number + " " + full)
                << "\"";
        }
        out << "/>\n";
    }
    out << "    </body-measurements>\n"
        << "</vit>\n";
}

}  // namespace tapeline::measurement
