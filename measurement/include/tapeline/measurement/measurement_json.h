// The measurement JSON of a measured body ("format": "tapeline-measurements", what `tapeline
// measure --out` writes): the frame, each measurement — the catalogue's columns
// (tapeline/sizes/json_formats.h) plus where it was taken (landmarks, tape loop or path, girth
// plane, whether it crosses a filled hole) —, the measurements that could not be taken, the
// landmarks and the report (with the input's filled holes). Points are canonical millimetres
// rounded to 0.001 mm, far below any mesh's resolution. No CGAL.
// tapeline::sizes::read_measurement_input reads it back as a measurement set.
//
// Also the nlohmann to_json writers of the options and the report (body_types.h,
// measurement_types.h): loggers and benchmark drivers write the options a run used and what it
// reported, every field under its C++ name, enums by name, an axis as "+Y", an inferred unit as
// null.
#pragma once

#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/measurement_types.h>
#include <tapeline/sizes/json_formats.h>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>
#include <vector>

namespace tapeline::measurement {

namespace internal {

inline nlohmann::ordered_json rounded_point(const Vec3& p) {
    nlohmann::ordered_json a = nlohmann::ordered_json::array();
    for (double x : p) {
        a.push_back(std::round(x * 1000.0) / 1000.0);
    }
    return a;
}

}  // namespace internal

inline nlohmann::ordered_json frame_json(const BodyFrame& f) {
    using internal::rounded_point;
    nlohmann::ordered_json j;
    j["unit"] = to_string(f.unit);
    j["unit_inferred"] = f.unit_inferred;
    j["up"] = f.up.to_string();
    j["front"] = f.front.to_string();
    j["pose"] = to_string(f.pose);
    j["millimetres_per_unit"] = f.scale;
    j["height_mm"] = f.height;
    j["floor_mm"] = f.floor;
    j["points"] =
        "canonical frame: millimetres, x to the body's left, y up, z to the front, floor at y = 0";
    nlohmann::ordered_json rows = nlohmann::ordered_json::array();
    for (const auto& r : f.rows) {
        rows.push_back(rounded_point(r));
    }
    j["canonical_axes_in_input"] = rows;
    return j;
}

inline nlohmann::ordered_json landmark_json(const Landmark& l, const BodyFrame& f) {
    using internal::rounded_point;
    nlohmann::ordered_json j;
    j["name"] = l.name;
    j["status"] = to_string(l.status);
    if (l.available()) {
        j["point"] = rounded_point(l.point);
        j["point_input"] = rounded_point(f.to_input(l.point));
    } else {
        j["point"] = nullptr;
        j["reason"] = l.reason;
    }
    return j;
}

inline nlohmann::ordered_json measurement_json(const Measurement& m) {
    using internal::rounded_point;
    nlohmann::ordered_json j = sizes::measurement_json_entry(m.name, to_string(m.kind), m.value);
    j["landmarks"] = m.landmarks;
    j["closed"] = m.closed;
    j["crosses_filled_hole"] = m.crosses_filled_hole;
    if (m.kind == MeasurementKind::girth) {
        j["plane"] = {{"point", rounded_point(m.plane_point)},
                      {"normal", rounded_point(m.plane_normal)}};
    }
    nlohmann::ordered_json pts = nlohmann::ordered_json::array();
    for (const auto& p : m.points) {
        pts.push_back(rounded_point(p));
    }
    j["points"] = pts;
    return j;
}

/// The whole document for `body` (the file name, say); the caller adds timings.
inline nlohmann::ordered_json body_measurements_json(
    const std::string& body, const BodyFrame& frame, const MeasurementSet& set,
    const LandmarkSet& landmarks, const MeasureReport& report,
    const std::vector<CheckWarning>& warnings = {}) {
    using Json = nlohmann::ordered_json;
    Json j;
    j["format"] = "tapeline-measurements";
    j["version"] = 1;
    j["body"] = body;
    j["frame"] = frame_json(frame);
    Json ms = Json::array();
    for (const auto& m : set.measurements) {
        ms.push_back(measurement_json(m));
    }
    j["measurements"] = ms;
    Json missing = Json::array();
    for (const auto& m : set.missing) {
        missing.push_back({{"name", m.name}, {"reason", m.reason}});
    }
    j["missing"] = missing;
    Json ls = Json::array();
    for (const auto& l : landmarks.landmarks) {
        ls.push_back(landmark_json(l, frame));
    }
    j["landmarks"] = ls;
    Json checks = Json::array();  // broken self-check rules (self_checks.h)
    for (const auto& w : warnings) {
        checks.push_back(
            {{"measurement", w.measurement}, {"rule", w.rule}, {"message", w.message}});
    }
    j["warnings"] = checks;
    Json holes = Json::array();  // the input's holes, filled before measuring (holes.h)
    for (const auto& h : report.holes) {
        holes.push_back({{"size_mm", std::round(h.size * 10) / 10},
                         {"height_mm", std::round(h.height * 10) / 10},
                         {"centre", internal::rounded_point(h.centre)},
                         {"region", h.region},
                         {"filling", h.filling},
                         {"boundary_edges", h.boundary_edges},
                         {"faces_added", h.faces_added},
                         {"vertices_added", h.vertices_added}});
    }
    j["report"] = {{"vertices", report.vertices},
                   {"faces", report.faces},
                   {"components", report.components},
                   {"sections", report.sections},
                   {"smooth_surface", report.smooth_surface},
                   {"landmarks_found", report.landmarks_found},
                   {"landmarks_missing", report.landmarks_missing},
                   {"warnings", report.warnings},
                   {"holes", holes}};
    return j;
}

// nlohmann to_json of the options and the report.

inline void to_json(nlohmann::json& j, Pose v) {
    j = to_string(v);
}

inline void to_json(nlohmann::json& j, const Axis& a) {
    j = a.to_string();
}

inline void to_json(nlohmann::json& j, const BodyOptions& o) {
    j = nlohmann::json::object();
    // LengthUnit lives in tapeline (core/units.h): written by name here, not by a to_json.
    j["unit"] = o.unit ? nlohmann::json(to_string(*o.unit)) : nlohmann::json(nullptr);
    j["up"] = o.up;
    j["front"] = o.front;
    j["pose"] = o.pose;
    j["name"] = o.name;
}

inline void to_json(nlohmann::json& j, const MeasureOptions& o) {
    j = nlohmann::json::object();
    j["scan_step"] = o.scan_step;
    j["level_tolerance"] = o.level_tolerance;
    j["max_neck_tilt_degrees"] = o.max_neck_tilt_degrees;
    j["smooth_surface"] = o.smooth_surface;
}

inline void to_json(nlohmann::json& j, const BodyHole& h) {
    j = nlohmann::json::object();
    j["size"] = h.size;
    j["centre"] = h.centre;
    j["height"] = h.height;
    j["region"] = h.region;
    j["filling"] = h.filling;
    j["boundary_edges"] = h.boundary_edges;
    j["faces_added"] = h.faces_added;
    j["vertices_added"] = h.vertices_added;
}

inline void to_json(nlohmann::json& j, const MeasureReport& r) {
    j = nlohmann::json::object();
    j["vertices"] = r.vertices;
    j["faces"] = r.faces;
    j["components"] = r.components;
    j["sections"] = r.sections;
    j["smooth_surface"] = r.smooth_surface;
    j["frame_seconds"] = r.frame_seconds;
    j["landmark_seconds"] = r.landmark_seconds;
    j["girth_seconds"] = r.girth_seconds;
    j["landmarks_found"] = r.landmarks_found;
    j["landmarks_missing"] = r.landmarks_missing;
    j["warnings"] = r.warnings;
    j["holes"] = r.holes;
}

}  // namespace tapeline::measurement
