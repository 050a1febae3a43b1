// The measurement catalogue: every body measurement the toolkit names, with its ISO 8559-1:2017
// item, its FreeSewing and Seamly2D/Valentina names, its kind and its unit. It is the one place a
// measurement name is declared; measurement, the formats of this module and grading read it.
//
// Source of every ISO number: Bodygram's public measurement definitions, which give the ISO
// 8559-1 name and clause number of each item they return
// (https://developers.bodygram.com/measurements/definitions). ISO 8559-1 itself was not available
// to check; items it surely has but whose number no source we could read states (stature, inside
// leg length, crotch length, ...) carry their title only, and an empty number. Do not add a
// number without a source.
//
// FreeSewing names are its measurement identifiers (chest, hpsToWaistBack, ...); a measurement
// FreeSewing does not define has none (we do not invent one). Seamly2D names are the known names
// of its measurement database (bust_circ, arm_shoulder_tip_to_wrist, ...); a measurement without
// one is written as a custom measurement, "@" + our name. Limb girths and the shoulder slope are
// also taken per side, "<name>_left" and "<name>_right": the same ISO item taken on that side,
// without FreeSewing or Seamly2D name.
#pragma once

#include <cstddef>
#include <string>
#include <vector>

namespace tapeline::sizes {

/// What a measurement measures: a closed tape (girth), a tape along the skin (length, width:
/// a length across the body), a vertical distance (height), an angle.
enum class MeasurementKind { girth, length, width, height, angle };

inline const char* to_string(MeasurementKind k) {
    switch (k) {
        case MeasurementKind::girth:
            return "girth";
        case MeasurementKind::length:
            return "length";
        case MeasurementKind::width:
            return "width";
        case MeasurementKind::height:
            return "height";
        case MeasurementKind::angle:
            break;
    }
    return "angle";
}

/// One row of the catalogue. Empty strings mean "none".
struct CatalogueEntry {
    const char* name;        ///< ours, snake_case: "waist_girth"
    const char* iso_number;  ///< ISO 8559-1:2017 clause number ("5.3.10"); empty: no source
    const char* iso_title;   ///< ISO 8559-1:2017 item title ("waist girth"); empty: no such item
    const char* freesewing;  ///< FreeSewing name ("waist")
    const char* seamly;      ///< Seamly2D known name ("waist_circ")
    MeasurementKind kind;    ///< length, girth or angle
    bool sided;              ///< also taken per side as name_left, name_right

    /// "mm" for lengths, "degree" for angles (which are never unit-scaled).
    const char* unit() const { return kind == MeasurementKind::angle ? "degree" : "mm"; }
};

/// Every measurement, in the order `tapeline measure` takes them.
inline const std::vector<CatalogueEntry>& catalogue() {
    using K = MeasurementKind;
    static const std::vector<CatalogueEntry> c = {
        // name, ISO number, ISO title, FreeSewing, Seamly2D, kind, sided
        {"stature", "", "stature", "", "height", K::height, false},
        {"head_girth", "", "head girth", "head", "head_circ", K::girth, false},
        {"neck_girth", "5.3.2", "neck girth", "neck", "neck_mid_circ", K::girth, false},
        {"neck_base_girth", "5.3.3", "neck base girth", "", "neck_circ", K::girth, false},
        {"bust_girth", "5.3.4", "bust girth", "chest", "bust_circ", K::girth, false},
        {"high_bust_girth", "", "", "highBust", "highbust_circ", K::girth, false},
        {"underbust_girth", "5.3.8", "under-bust girth", "underbust", "lowbust_circ", K::girth,
         false},
        {"waist_girth", "5.3.10", "waist girth", "waist", "waist_circ", K::girth, false},
        {"high_hip_girth", "5.3.12", "top hip girth", "hips", "highhip_circ", K::girth, false},
        {"hip_girth", "5.3.13", "hip girth", "seat", "hip_circ", K::girth, false},
        {"thigh_girth", "5.3.20", "thigh girth", "upperLeg", "leg_thigh_upper_circ", K::girth,
         true},
        {"mid_thigh_girth", "5.3.21", "mid-thigh girth", "", "leg_thigh_mid_circ", K::girth, true},
        {"knee_girth", "", "knee girth", "knee", "leg_knee_circ", K::girth, true},
        {"calf_girth", "", "calf girth", "", "leg_calf_circ", K::girth, true},
        {"ankle_girth", "", "ankle girth", "ankle", "leg_ankle_circ", K::girth, true},
        {"upper_arm_girth", "5.3.16", "upper-arm girth", "biceps", "arm_upper_circ", K::girth,
         true},
        {"elbow_girth", "", "elbow girth", "", "arm_elbow_circ", K::girth, true},
        {"wrist_girth", "5.3.19", "wrist girth", "wrist", "arm_wrist_circ", K::girth, true},
        {"shoulder_width_back", "", "back shoulder width", "shoulderToShoulder",
         "shoulder_tip_to_shoulder_tip_b", K::width, false},
        {"hps_to_waist_back", "", "", "hpsToWaistBack", "neck_side_to_waist_b", K::length, false},
        {"hps_to_waist_front", "", "", "hpsToWaistFront", "neck_side_to_waist_f", K::length, false},
        {"shoulder_to_elbow", "", "upper arm length", "shoulderToElbow",
         "arm_shoulder_tip_to_elbow", K::length, false},
        {"shoulder_to_wrist", "5.7.8", "outer arm length", "shoulderToWrist",
         "arm_shoulder_tip_to_wrist", K::length, false},
        {"inseam", "", "inside leg length", "inseam", "leg_crotch_to_floor", K::length, false},
        {"outseam", "", "outside leg length", "waistToFloor", "leg_waist_side_to_floor", K::length,
         false},
        {"waist_to_knee", "", "", "waistToKnee", "leg_waist_side_to_knee", K::length, false},
        // FreeSewing's `hips` line (its waistToHips) is the top hip, its `seat` line (waistToSeat)
        // the hip girth's level.
        {"waist_to_high_hip", "", "", "waistToHips", "waist_to_highhip_side", K::length, false},
        {"waist_to_hips", "", "", "waistToSeat", "waist_to_hip_side", K::length, false},
        {"waist_to_armpit", "", "", "waistToArmpit", "armpit_to_waist_side", K::length, false},
        {"back_neck_to_waist", "5.4.5", "back neck point to waist", "", "neck_back_to_waist_b",
         K::length, false},
        {"front_neck_to_waist", "", "", "", "neck_front_to_waist_flat_f", K::length, false},
        {"hps_to_bust", "", "", "hpsToBust", "bustpoint_to_neck_side", K::length, false},
        {"across_back_shoulder_width", "5.4.3",
         "across back shoulder width (through the back neck point)", "", "", K::width, false},
        {"back_neck_to_wrist", "5.4.17", "back neck point to wrist length", "", "", K::length,
         false},
        {"cross_seam", "", "crotch length", "crossSeam", "crotch_length", K::length, false},
        {"cross_seam_front", "", "", "crossSeamFront", "crotch_length_f", K::length, false},
        {"cross_seam_back", "", "", "", "crotch_length_b", K::length, false},
        {"shoulder_slope", "", "", "shoulderSlope", "shoulder_slope_neck_side_angle", K::angle,
         true},
    };
    return c;
}

/// A name resolved against the catalogue: its row, and the side ("left", "right") when the name
/// is the per-side variant of a sided row.
struct CatalogueMatch {
    const CatalogueEntry* entry = nullptr;  ///< the row, null when the name is unknown
    std::string side;                       ///< "left", "right", or empty

    /// True when the name was found.
    explicit operator bool() const { return entry != nullptr; }
    /// The name itself is the row's (not a side of it).
    bool whole() const { return entry && side.empty(); }
};

/// The row named exactly `name`; nullptr when none.
inline const CatalogueEntry* catalogue_entry(const std::string& name) {
    for (const CatalogueEntry& e : catalogue()) {
        if (name == e.name) {
            return &e;
        }
    }
    return nullptr;
}

/// `name` itself, or `base_left` / `base_right` of a sided row.
inline CatalogueMatch find_measurement(const std::string& name) {
    if (const CatalogueEntry* e = catalogue_entry(name)) {
        return {e, ""};
    }
    for (const char* side : {"left", "right"}) {
        const std::string suffix = std::string("_") + side;
        if (name.size() > suffix.size() &&
            name.compare(name.size() - suffix.size(), suffix.size(), suffix) == 0) {
            const CatalogueEntry* e = catalogue_entry(name.substr(0, name.size() - suffix.size()));
            if (e && e->sided) {
                return {e, side};
            }
        }
    }
    return {};
}

/// The ISO 8559-1 title of a measurement (sides share their row's); empty when none.
inline std::string iso_title(const std::string& name) {
    const CatalogueMatch m = find_measurement(name);
    return m ? m.entry->iso_title : "";
}

/// The ISO 8559-1 clause number of a measurement (sides share their row's); empty when none.
inline std::string iso_number(const std::string& name) {
    const CatalogueMatch m = find_measurement(name);
    return m ? m.entry->iso_number : "";
}

/// The FreeSewing name of a measurement; empty when none (and for the per-side variants).
inline std::string freesewing_name(const std::string& name) {
    const CatalogueMatch m = find_measurement(name);
    return m.whole() ? m.entry->freesewing : "";
}

/// The Seamly2D known name of a measurement; empty when none (and for the per-side variants).
inline std::string seamly_name(const std::string& name) {
    const CatalogueMatch m = find_measurement(name);
    return m.whole() ? m.entry->seamly : "";
}

/// The row whose Seamly2D known name is `seamly`; nullptr when none.
inline const CatalogueEntry* from_seamly_name(const std::string& seamly) {
    for (const CatalogueEntry& e : catalogue()) {
        if (*e.seamly && seamly == e.seamly) {
            return &e;
        }
    }
    return nullptr;
}

/// The row whose FreeSewing name is `freesewing`; nullptr when none.
inline const CatalogueEntry* from_freesewing_name(const std::string& freesewing) {
    for (const CatalogueEntry& e : catalogue()) {
        if (*e.freesewing && freesewing == e.freesewing) {
            return &e;
        }
    }
    return nullptr;
}

/// Whether a measurement name denotes an angle (kept in degrees, never unit-scaled): an angle
/// of the catalogue, or any name (FreeSewing's, Seamly2D's, a user's) containing "slope",
/// "angle" or "incl".
inline bool is_angle_measurement(const std::string& name) {
    const CatalogueMatch m = find_measurement(name);
    if (m && m.entry->kind == MeasurementKind::angle) {
        return true;
    }
    std::string n;
    for (char c : name) {
        n += (c >= 'A' && c <= 'Z') ? static_cast<char>(c - 'A' + 'a') : c;
    }
    return n.find("slope") != std::string::npos || n.find("angle") != std::string::npos ||
           n.find("incl") != std::string::npos;
}

/// The values a measurement of a human body can take, newborn to the largest adults recorded,
/// with margin: every length, girth, width and height within [10, 4000] mm (the tallest stature
/// recorded is 2,720 mm; a newborn's shortest catalogue length, shoulder to elbow, is about
/// 70 mm), every angle within [-90, 90] degrees. A value outside is a unit mistake or garbage,
/// not a body.
struct PlausibleRange {
    double low = 0, high = 0;  ///< inclusive bounds, in the row's unit()
};

/// The plausible range of a catalogue row (see PlausibleRange).
inline PlausibleRange plausible_range(const CatalogueEntry& e) {
    return e.kind == MeasurementKind::angle ? PlausibleRange{-90, 90} : PlausibleRange{10, 4000};
}

/// The catalogue row a measurement set key stands for, whatever naming it uses: ours (with
/// the per-side variants), Seamly2D's known names, FreeSewing's; "@" stripped. nullptr when
/// none.
inline const CatalogueEntry* catalogue_row_of_key(const std::string& key) {
    const std::string k = !key.empty() && key[0] == '@' ? key.substr(1) : key;
    if (const CatalogueMatch m = find_measurement(k)) {
        return m.entry;
    }
    if (const CatalogueEntry* e = from_seamly_name(k)) {
        return e;
    }
    return from_freesewing_name(k);
}

}  // namespace tapeline::sizes
