// Bodies with holes cut in, as scans have them (soles, crown, armpits): the body as a triangle
// soup in canonical millimetres, faces removed around chosen points, and the soup measured with
// its lengths along the skin. Plain types only, no CGAL (the heavy calls are compiled once in
// support/measurement_holes.cpp, DESIGN.md §5).
#pragma once

#include <tapeline/measurement/body_types.h>
#include <tapeline/measurement/measurement_types.h>
#include <tapeline_test/measurement.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

namespace tapeline_test::measurement {

/// A body file brought into the canonical frame by make_body (closed, so nothing is filled).
Soup canonical_soup(const std::string& path, const BodyOptions& options);

/// A ball whose faces are cut out: every triangle with a corner inside it.
struct HoleCut {
    Vec3 centre{0, 0, 0};
    double radius = 0;
};

/// The soup without the triangles that have a corner inside one of the balls, and without the
/// vertices no triangle uses any more (a scan has no points where it has no surface).
inline Soup cut_holes(const Soup& in, const std::vector<HoleCut>& cuts) {
    std::vector<char> inside(in.points.size(), 0);
    for (std::size_t v = 0; v < in.points.size(); ++v) {
        for (const auto& c : cuts) {
            const Vec3& p = in.points[v];
            const double dx = p[0] - c.centre[0], dy = p[1] - c.centre[1], dz = p[2] - c.centre[2];
            if (dx * dx + dy * dy + dz * dz < c.radius * c.radius) {
                inside[v] = 1;
            }
        }
    }
    Soup out;
    std::vector<std::int64_t> index(in.points.size(), -1);
    for (const auto& t : in.triangles) {
        if (inside[t[0]] || inside[t[1]] || inside[t[2]]) {
            continue;
        }
        std::array<std::uint32_t, 3> n{};
        for (int k = 0; k < 3; ++k) {
            if (index[t[k]] < 0) {
                index[t[k]] = static_cast<std::int64_t>(out.points.size());
                out.points.push_back(in.points[t[k]]);
            }
            n[k] = static_cast<std::uint32_t>(index[t[k]]);
        }
        out.triangles.push_back(n);
    }
    return out;
}

/// The soup measured as a body in millimetres (+Y up, +Z front; `pose`), holes filled by
/// make_body, with the lengths along the skin taken on the filled mesh. Throws what make_body
/// throws (a hole too big to fill, ...).
Result measure_soup_with_skin_lengths(const Soup& soup, const std::string& name,
                                      Pose pose = Pose::a_pose);

/// The filled faces' share of the soup's faces after make_body, and the body's filled holes.
struct FilledSoup {
    std::size_t faces = 0, filled_faces = 0;
    std::vector<BodyHole> holes;
};
FilledSoup fill_soup(const Soup& soup, const std::string& name);

}  // namespace tapeline_test::measurement
