// Landmark checks beyond measurement.h: a T-pose body made from an A-pose one (no T-pose body is
// in the shared data), and the arm lengths along the skin. Plain types only, no CGAL (the heavy
// calls are compiled once in support/measurement_landmarks.cpp, DESIGN.md §5).
//
// The arms are raised to horizontal like a one-joint skeleton would do it (linear blend
// skinning): every vertex turns in the frontal plane about the shoulder joint (the midpoint of
// the A-pose acromion and armpit) by the arm's angle below the horizontal (shoulder joint to
// wrist) times a weight. The weight is 0 on the torso side and 1 on the arm side of the plane
// through the armpit that bisects the angle between the torso's side (vertical) and the arm,
// blended over `band` on either side of it, and fades to 0 above the acromion (neck and head
// stay). Vertices never change their triangles, so the mesh stays closed; nothing below the
// armpit on the torso side moves, so every measurement that does not involve the arms must stay
// the same.
#pragma once

#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/measurement_types.h>
#include <tapeline_test/measurement.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace tapeline_test::measurement {

/// Raises the arms of `points` (canonical mm, as the landmarks) to horizontal; needs the
/// landmarks armpit_*, acromion_* and wrist_* of the A-pose measurement. Returns the posed
/// points (same order and count).
inline std::vector<tapeline::measurement::Vec3> raise_arms_to_t_pose(
    std::vector<tapeline::measurement::Vec3> points,
    const tapeline::measurement::LandmarkSet& a_pose, double band) {
    for (int s = 0; s < 2; ++s) {
        const std::string side = s == 0 ? "_left" : "_right";
        const double sg = s == 0 ? 1 : -1;  // x is the body's left
        for (const char* n : {"armpit", "acromion", "wrist"}) {
            if (!a_pose.point(n + side)) {
                throw std::runtime_error("raise_arms_to_t_pose: the A-pose has no " + (n + side));
            }
        }
        const auto ap = *a_pose.point("armpit" + side), ac = *a_pose.point("acromion" + side);
        const auto wr = *a_pose.point("wrist" + side);
        // Mirrored frontal coordinates (X outwards, y up).
        const double px = 0.5 * sg * (ap[0] + ac[0]), py = 0.5 * (ap[1] + ac[1]);
        const double dx = sg * wr[0] - px, dy = wr[1] - py, dl = std::hypot(dx, dy);
        const double raise = -std::atan2(dy, dx);  // angle of the arm below the horizontal
        // Bisector of "straight down" and the arm's direction; the normal points to the arm.
        double bx = dx / dl, by = dy / dl - 1;
        const double bl = std::hypot(bx, by);
        bx /= bl;
        by /= bl;
        const double nx = -by, ny = bx;
        for (auto& p : points) {
            const double X = sg * p[0], y = p[1];
            const double d = (X - sg * ap[0]) * nx + (y - ap[1]) * ny;
            double w = std::clamp((d + band) / (2 * band), 0.0, 1.0);
            w = w * w * (3 - 2 * w);
            const double above = std::clamp((y - ac[1]) / band, 0.0, 1.0);
            w *= 1 - above * above * (3 - 2 * above);
            if (w <= 0) {
                continue;
            }
            const double a = raise * w, c = std::cos(a), sn = std::sin(a);
            const double rx = X - px, ry = y - py;
            p[0] = sg * (px + c * rx - sn * ry);
            p[1] = py + sn * rx + c * ry;
        }
    }
    return points;
}

/// A body file measured as it is (A-pose) and again with its arms raised by
/// raise_arms_to_t_pose (band: 2% of the height) and BodyOptions::pose = T. The posed body is in
/// canonical millimetres, so both results share one frame.
struct PosePair {
    Result a_pose, t_pose;
};
PosePair measure_file_a_and_t_pose(const std::string& path, const BodyOptions& options);

/// measure_file, then the lengths along the skin (lengths.h) added to the measurements.
Result measure_file_with_skin_lengths(const std::string& path, const BodyOptions& options);

}  // namespace tapeline_test::measurement
