// Landmarks, measurements, options and reports of the measurement module (DESIGN.md §3: a light
// header without CGAL, so loggers, exporters and test facades can include it cheaply).
//
// Every point is in the canonical frame of body_types.h (mm, y up, z front, x to the body's left,
// floor at y = 0); BodyFrame::to_input maps it back to the mesh's own coordinates.
#pragma once

#include <tapeline/measurement/body_types.h>
#include <tapeline/sizes/catalogue.h>
#include <tapeline/sizes/measurement_set.h>

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::measurement {

/// found: from the geometry; overridden: from a landmark file; not_found: `reason` says why.
enum class LandmarkStatus { found, overridden, not_found };

inline const char* to_string(LandmarkStatus s) {
    switch (s) {
        case LandmarkStatus::found:
            return "found";
        case LandmarkStatus::overridden:
            return "overridden";
        case LandmarkStatus::not_found:
            break;
    }
    return "not_found";
}

/// A named point of the body, how it was obtained, or why it was not found.
struct Landmark {
    /// One of landmark_names() ("waist_front", "wrist_left", ...).
    std::string name;
    /// Found on the mesh, set by an override, or not found.
    LandmarkStatus status = LandmarkStatus::not_found;
    Vec3 point{0, 0, 0};  ///< canonical mm; meaningless when not_found
    std::string reason;   ///< not_found: one line naming the landmark and why; else empty
    /// Limb landmarks (elbows, wrists, knees, ankles): the centre of the limb's cross-section at
    /// the landmark, which limb girths use as their axis point. Others: equal to `point`.
    Vec3 axis_point{0, 0, 0};

    /// Whether `point` holds a position: found or overridden.
    bool available() const { return status != LandmarkStatus::not_found; }
};

/// Every landmark the module knows, in a fixed order (definitions in measurement/README.md).
/// "left"/"right" are the body's own sides (left = +x in the canonical frame).
inline const std::vector<std::string>& landmark_names() {
    static const std::vector<std::string> names = {
        "top_of_head",    "crotch",          "armpit_left", "armpit_right",  "cervicale",
        "side_neck_left", "side_neck_right", "front_neck",  "acromion_left", "acromion_right",
        "bust_left",      "bust_right",      "waist_front", "waist_back",    "hip_back",
        "elbow_left",     "elbow_right",     "wrist_left",  "wrist_right",   "knee_left",
        "knee_right",     "ankle_left",      "ankle_right"};
    return names;
}

/// One Landmark per landmark_names() entry, in that order.
struct LandmarkSet {
    /// One per landmark_names() entry, in that order; a new set has them all not_found.
    std::vector<Landmark> landmarks;

    LandmarkSet() {
        for (const auto& n : landmark_names()) {
            landmarks.push_back(
                Landmark{n, LandmarkStatus::not_found, {0, 0, 0}, n + ": not set", {0, 0, 0}});
        }
    }
    /// The landmark called `name`; null for an unknown name.
    const Landmark* find(const std::string& name) const {
        for (const auto& l : landmarks) {
            if (l.name == name) {
                return &l;
            }
        }
        return nullptr;
    }
    /// The landmark called `name`, to modify; null for an unknown name.
    Landmark* find(const std::string& name) {
        for (auto& l : landmarks) {
            if (l.name == name) {
                return &l;
            }
        }
        return nullptr;
    }
    /// The point of an available landmark, nullopt otherwise (also for unknown names).
    std::optional<Vec3> point(const std::string& name) const {
        const Landmark* l = find(name);
        return l && l->available() ? std::optional<Vec3>(l->point) : std::nullopt;
    }
    /// Number of landmarks found or overridden.
    std::size_t available_count() const {
        std::size_t n = 0;
        for (const auto& l : landmarks) {
            n += l.available() ? 1 : 0;
        }
        return n;
    }
};

/// The catalogue's kinds; a measurement is taken as a girth, a length (also for the catalogue's
/// widths), a height or an angle.
using sizes::MeasurementKind;
using sizes::to_string;

/// One measurement with where it was taken.
struct Measurement {
    std::string name;  ///< our identifier, snake_case: "waist_girth", "hip_girth", ...
    /// How it is taken: girth, length (also for widths), height or angle.
    MeasurementKind kind = MeasurementKind::girth;
    double value = 0;  ///< mm (angle: degrees)
    /// The ISO 8559-1:2017 clause, named by its title ("waist girth"); empty when ISO 8559-1 has
    /// no such item.
    std::string iso_clause;
    /// Its ISO 8559-1:2017 clause number ("5.3.10"); empty where no source states one
    /// (the catalogue, tapeline/sizes/catalogue.h, holds the numbers and their source).
    std::string iso_number;
    std::string freesewing;  ///< FreeSewing measurement name ("waist"); empty when none
    /// Canonical mm. Girths: the tape loop (the convex hull of the section, in order, closed
    /// implicitly). Lengths: the path from start to end. Heights: floor point, then top point.
    std::vector<Vec3> points;
    bool closed = false;                 ///< points form a loop
    Vec3 plane_point{0, 0, 0};           ///< girths: a point of the tape's plane
    Vec3 plane_normal{0, 1, 0};          ///< girths: the plane's unit normal
    std::vector<std::string> landmarks;  ///< the landmarks it depends on
    /// The tape crosses a face that fills a hole of the input mesh (BodyMesh::filled): girths,
    /// a loop of their section passes through one; lengths and heights, a piece of their path
    /// or one of their points lies on one. Its value then rests on the filled surface.
    bool crosses_filled_hole = false;
};

/// A measurement that could not be taken, with a one-line reason naming it and its cause.
struct MissingMeasurement {
    /// The measurement's identifier, as Measurement::name.
    std::string name;
    /// One line naming the measurement and why it could not be taken.
    std::string reason;
};

/// Named measurements of one body, in the order they were taken.
struct MeasurementSet {
    /// The measurements taken, in the order they were taken.
    std::vector<Measurement> measurements;
    /// The measurements that could not be taken, with their reasons.
    std::vector<MissingMeasurement> missing;

    /// The measurement called `name`; null when it was not taken.
    const Measurement* find(const std::string& name) const {
        for (const auto& m : measurements) {
            if (m.name == name) {
                return &m;
            }
        }
        return nullptr;
    }
    /// The value of the measurement called `name` (mm; angles in degrees); nullopt when it was
    /// not taken.
    std::optional<double> value(const std::string& name) const {
        const Measurement* m = find(name);
        return m ? std::optional<double>(m->value) : std::nullopt;
    }
    /// Adds or replaces (by name); a measurement replaces a missing entry of the same name.
    void add(Measurement m) {
        remove(m.name);
        measurements.push_back(std::move(m));
    }
    /// Records `name` as missing with `reason`; replaces a measurement or missing entry of the
    /// same name.
    void add_missing(const std::string& name, const std::string& reason) {
        remove(name);
        missing.push_back({name, reason});
    }

private:
    void remove(const std::string& name) {
        for (auto it = measurements.begin(); it != measurements.end(); ++it) {
            if (it->name == name) {
                measurements.erase(it);
                break;
            }
        }
        for (auto it = missing.begin(); it != missing.end(); ++it) {
            if (it->name == name) {
                missing.erase(it);
                break;
            }
        }
    }
};

/// One broken self-check rule (self_checks.h).
struct CheckWarning {
    std::string measurement;  ///< the measurement or landmark it concerns
    /// left_right, bust_underbust, bust_high_bust, bust_armpit, wrist_elbow, landmark_height,
    /// segment_length, shoulder_breadth, loop_around_part, neck_base_wide, neck_base_narrow,
    /// neck_below_chin
    std::string rule;
    std::string message;  ///< one line naming both
};
/// Sets iso_clause, iso_number and freesewing of a measurement from the catalogue (left as they
/// are when the catalogue does not know its name). The _left/_right variants of a sided
/// measurement are its ISO item taken on that side, without FreeSewing name.
inline void apply_catalogue(Measurement& m) {
    const sizes::CatalogueMatch c = sizes::find_measurement(m.name);
    if (c) {
        m.iso_clause = c.entry->iso_title;
        m.iso_number = c.entry->iso_number;
        m.freesewing = c.whole() ? c.entry->freesewing : "";
    }
}

inline void apply_catalogue(MeasurementSet& set) {
    for (Measurement& m : set.measurements) {
        apply_catalogue(m);
    }
}

/// The taken measurements' values in the order they were taken (what the writers of
/// tapeline/sizes take).
inline sizes::NamedValues named_values(const MeasurementSet& set) {
    sizes::NamedValues out;
    for (const Measurement& m : set.measurements) {
        out.emplace_back(m.name, m.value);
    }
    return out;
}

/// The flat set of a measuring: each value under our name and, where the catalogue has one, its
/// FreeSewing name. Reading the measurement JSON back gives the same set without the angles
/// (its reader takes value_mm only).
inline sizes::MeasurementSet flat_set(const MeasurementSet& set, const std::string& name = "") {
    sizes::MeasurementSet out;
    out.name = name;
    for (const Measurement& m : set.measurements) {
        out.values[m.name] = m.value;
        if (!m.freesewing.empty()) {
            out.values[m.freesewing] = m.value;
        }
    }
    return out;
}

/// How landmarks are searched and girth levels optimised.
struct MeasureOptions {
    /// Distance between the horizontal sections of the landmark scan, mm; 0: height / 400.
    double scan_step = 0;
    /// Levels found by bisection or golden-section search are located to within this, mm.
    double level_tolerance = 0.1;
    /// The neck girth plane may tilt forward or backward by up to this (the neck leans forward;
    /// ISO takes the girth perpendicular to the neck's axis).
    double max_neck_tilt_degrees = 30;
    /// Girths go round the smooth surface the mesh's vertices and normals stand for (Phong
    /// tessellation, tapeline/core/phong.h), so that a coarse mesh of a body measures as a fine
    /// one does; false: round its flat facets, whose chords cut inside a convex part by their
    /// sagitta (a wrist meshed with 20 mm edges measures about 4 mm short).
    bool smooth_surface = true;
};

/// What one measuring run did. Times are wall-clock seconds.
struct MeasureReport {
    /// Vertices, faces and connected components of the measured mesh (holes filled).
    ///@{
    std::size_t vertices = 0, faces = 0, components = 0;
    ///@}
    std::size_t sections = 0;     ///< plane sections cut (scan, refinements, girths)
    bool smooth_surface = true;   ///< MeasureOptions::smooth_surface the girths were taken with
    double frame_seconds = 0;     ///< mesh to canonical frame and adjacency
    double landmark_seconds = 0;  ///< scan and landmark search
    double girth_seconds = 0;     ///< girth levels, sections and hulls
    /// Landmarks found or overridden, and landmarks not found.
    ///@{
    std::size_t landmarks_found = 0, landmarks_missing = 0;
    ///@}
    std::vector<std::string> warnings;  ///< one line each (landmarks not found, ...)
    std::vector<BodyHole> holes;        ///< the input's holes, filled before measuring
};

/// Everything measured on one body; points are canonical mm (frame.to_input maps them back).
struct BodyMeasurements {
    /// The body's frame (Body::frame).
    BodyFrame frame;
    /// Every landmark: found, overridden, or not found with the reason.
    LandmarkSet landmarks;
    /// The measurements taken, and those that could not be.
    MeasurementSet measurements;
    /// Mesh size, filled holes, timings and landmark counts.
    MeasureReport report;
    /// Broken self-check rules (self_checks.h); empty on a plausible result.
    std::vector<CheckWarning> warnings;
};

}  // namespace tapeline::measurement
