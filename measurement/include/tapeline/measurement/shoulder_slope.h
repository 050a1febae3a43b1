// Shoulder slope from the landmarks (no CGAL): the angle below the horizontal of the line from
// the side neck point (HPS) to the shoulder point (acromion), the angle Seamly2D calls "shoulder
// slope angle from neck side" and FreeSewing `shoulderSlope`. ASTM D6240 takes it with a
// goniometer; here it is the angle between that 3D line and the horizontal plane.
#pragma once

#include <tapeline/measurement/measurement_types.h>

#include <cmath>
#include <string>
#include <vector>

namespace tapeline::measurement {

/// Adds shoulder_slope_left and shoulder_slope_right (degrees; positive when the shoulder point
/// is below the side neck point) and shoulder_slope, their mean (the one side's value when the
/// other cannot be taken). Points: side neck point, then shoulder point (the mean: left shoulder
/// point, left and right side neck points, right shoulder point).
inline void measure_shoulder_slope(const LandmarkSet& lm, MeasurementSet& set) {
    std::vector<double> taken;
    std::vector<Vec3> points;
    std::vector<std::string> used;
    std::string reason;
    for (const std::string side : {"left", "right"}) {
        const std::string name = "shoulder_slope_" + side;
        const std::string hps = "side_neck_" + side, acromion = "acromion_" + side;
        std::string why;
        for (const auto& n : {hps, acromion}) {
            const Landmark* l = lm.find(n);
            if (why.empty() && (!l || !l->available())) {
                why = l ? l->reason : n + ": unknown landmark";
            }
        }
        if (!why.empty()) {
            set.add_missing(name, name + ": " + why);
            reason = reason.empty() ? why : reason;
            continue;
        }
        const Vec3 h = *lm.point(hps), a = *lm.point(acromion);
        Measurement m;
        m.name = name;
        m.kind = MeasurementKind::angle;
        m.value = std::atan2(h[1] - a[1], std::hypot(a[0] - h[0], a[2] - h[2])) * 180 / M_PI;
        m.points = {h, a};
        m.landmarks = {hps, acromion};
        apply_catalogue(m);
        taken.push_back(m.value);
        if (side == "left") {
            points = {a, h};
        } else {
            points.insert(points.end(), {h, a});
        }
        used.insert(used.end(), {hps, acromion});
        set.add(std::move(m));
    }
    if (taken.empty()) {
        set.add_missing("shoulder_slope", "shoulder_slope: " + reason);
        return;
    }
    Measurement m;
    m.name = "shoulder_slope";
    m.kind = MeasurementKind::angle;
    m.value = taken.size() == 2 ? 0.5 * (taken[0] + taken[1]) : taken[0];
    m.points = std::move(points);
    m.landmarks = std::move(used);
    apply_catalogue(m);
    set.add(std::move(m));
}

}  // namespace tapeline::measurement
