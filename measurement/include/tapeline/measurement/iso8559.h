// ISO 8559-1:2017 clause numbers and titles of our measurements: the one table (DESIGN.md §3: a
// light header without CGAL). measure_body and the skin lengths apply it to what they create.
//
// Source of every number: Bodygram's public measurement definitions, which give the ISO 8559-1
// name and clause number of each item they return
// (https://developers.bodygram.com/measurements/definitions). ISO 8559-1 itself was not available
// to check; items it surely has but whose number no source we could read states (stature, inside
// leg length, crotch length, ...) carry their title only, and an empty number. Do not add a
// number without a source.
#pragma once

#include <tapeline/measurement/measurement_types.h>

#include <map>
#include <string>

namespace tapeline::measurement {

/// An ISO 8559-1 item: clause number ("5.3.10"; empty when no source states it) and title.
struct Iso8559Item {
    std::string number;
    std::string title;
};

/// Our measurement name → its ISO 8559-1 item; nullptr when the table has none.
inline const Iso8559Item* iso8559_item(const std::string& name) {
    static const std::map<std::string, Iso8559Item> items = {
        // Numbered (Bodygram's table).
        {"neck_girth", {"5.3.2", "neck girth"}},
        {"neck_base_girth", {"5.3.3", "neck base girth"}},
        {"bust_girth", {"5.3.4", "bust girth"}},
        {"underbust_girth", {"5.3.8", "under-bust girth"}},
        {"waist_girth", {"5.3.10", "waist girth"}},
        {"high_hip_girth", {"5.3.12", "top hip girth"}},
        {"hip_girth", {"5.3.13", "hip girth"}},
        {"upper_arm_girth", {"5.3.16", "upper-arm girth"}},
        {"wrist_girth", {"5.3.19", "wrist girth"}},
        {"thigh_girth", {"5.3.20", "thigh girth"}},
        {"mid_thigh_girth", {"5.3.21", "mid-thigh girth"}},
        {"across_back_shoulder_width",
         {"5.4.3", "across back shoulder width (through the back neck point)"}},
        {"back_neck_to_waist", {"5.4.5", "back neck point to waist"}},
        {"back_neck_to_wrist", {"5.4.17", "back neck point to wrist length"}},
        {"shoulder_to_wrist", {"5.7.8", "outer arm length"}},
        // Titles only: ISO 8559-1 items whose clause number no source we read states.
        {"stature", {"", "stature"}},
        {"head_girth", {"", "head girth"}},
        {"knee_girth", {"", "knee girth"}},
        {"calf_girth", {"", "calf girth"}},
        {"ankle_girth", {"", "ankle girth"}},
        {"elbow_girth", {"", "elbow girth"}},
        {"inseam", {"", "inside leg length"}},
        {"outseam", {"", "outside leg length"}},
        {"shoulder_to_elbow", {"", "upper arm length"}},
        {"cross_seam", {"", "crotch length"}},
    };
    const auto it = items.find(name);
    return it == items.end() ? nullptr : &it->second;
}

/// Sets iso_number and iso_clause of a measurement from the table (left as they are when the
/// table has no entry for its name). The _left/_right variants of a limb girth are the same ISO
/// item, taken on that side.
inline void apply_iso8559(Measurement& m) {
    const Iso8559Item* item = iso8559_item(m.name);
    for (const char* suffix : {"_left", "_right"}) {
        const std::string s = suffix;
        if (!item && m.name.size() > s.size() &&
            m.name.compare(m.name.size() - s.size(), s.size(), s) == 0) {
            item = iso8559_item(m.name.substr(0, m.name.size() - s.size()));
        }
    }
    if (item) {
        m.iso_number = item->number;
        m.iso_clause = item->title;
    }
}

inline void apply_iso8559(MeasurementSet& set) {
    for (Measurement& m : set.measurements) {
        apply_iso8559(m);
    }
}

}  // namespace tapeline::measurement
