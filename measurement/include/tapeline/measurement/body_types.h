// How a body mesh is to be read: length unit, up and front axes, pose (DESIGN.md §3: a plain
// Options struct, no CGAL), and the BodyFrame that records what was used.
//
// Canonical frame used by every measurement: millimetres, y up, z to the body's front and
// x = y × z, which points to the body's LEFT (a right-handed frame looking at the body from the
// front has its x axis towards the body's left hand). The floor is y = 0: the lowest vertex of
// the mesh. x and z keep the input's origin.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/units.h>

#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::measurement {

using Vec3 = std::array<double, 3>;

/// The units a body mesh may be in: the metric ones of core's table (infer_length_unit tells
/// them apart by the body's height).
using tapeline::LengthUnit;
using tapeline::millimetres_per;
using tapeline::to_string;

enum class Pose { a_pose, t_pose };

/// How much larger than the leg's smallest girth above the foot the ankle level's girth may be,
/// mm (the ankle rule of the landmark finder, and SyntheticBody::ankle_level): ISO 20685-1's
/// tolerance for small girths (4 mm), below which two tapes are one measurement.
inline constexpr double kAnkleGirthTolerance = 4.0;

/// "m", "dm", "cm" or "mm"; anything else is InvalidInput naming `where` (e.g. "--units").
inline LengthUnit parse_length_unit(const std::string& text, const std::string& where) {
    for (LengthUnit u : {LengthUnit::m, LengthUnit::dm, LengthUnit::cm, LengthUnit::mm}) {
        if (text == to_string(u)) {
            return u;
        }
    }
    throw InvalidInput(where + ": unknown length unit '" + text + "' (expected m, dm, cm or mm)");
}

inline const char* to_string(Pose p) {
    return p == Pose::t_pose ? "T" : "A";
}

/// "A" or "T" (any case); anything else is InvalidInput naming `where`.
inline Pose parse_pose(const std::string& text, const std::string& where) {
    if (text == "A" || text == "a") {
        return Pose::a_pose;
    }
    if (text == "T" || text == "t") {
        return Pose::t_pose;
    }
    throw InvalidInput(where + ": unknown pose '" + text + "' (expected A or T)");
}

/// A signed coordinate axis of the input mesh: +X, -X, +Y, -Y, +Z or -Z.
struct Axis {
    int index = 1;  ///< 0 = x, 1 = y, 2 = z
    int sign = 1;   ///< +1 or -1

    /// "+Y", "-z", "Y" (sign +), any case; anything else is InvalidInput naming `where`.
    ///
    /// \throws InvalidInput for any other text.
    static Axis parse(const std::string& text, const std::string& where) {
        std::string t = text;
        int sign = 1;
        if (!t.empty() && (t[0] == '+' || t[0] == '-')) {
            sign = t[0] == '-' ? -1 : 1;
            t = t.substr(1);
        }
        if (t.size() == 1) {
            const char c = t[0];
            if (c == 'x' || c == 'X' || c == 'y' || c == 'Y' || c == 'z' || c == 'Z') {
                const int index = (c == 'x' || c == 'X') ? 0 : (c == 'y' || c == 'Y') ? 1 : 2;
                return Axis{index, sign};
            }
        }
        throw InvalidInput(where + ": unknown axis '" + text +
                           "' (expected +X, -X, +Y, -Y, +Z or -Z)");
    }
    /// "+X" ... "-Z".
    std::string to_string() const {
        return std::string(sign < 0 ? "-" : "+") + static_cast<char>('X' + index);
    }
    /// The unit vector of the axis.
    Vec3 vector() const {
        Vec3 v{0, 0, 0};
        v[static_cast<std::size_t>(index)] = sign;
        return v;
    }
};

/// How to read a body mesh. The unit is required unless the height makes it unambiguous (see
/// infer_length_unit).
struct BodyOptions {
    std::optional<LengthUnit> unit;  ///< empty: inferred from the height
    Axis up{1, 1};                   ///< +Y
    Axis front{2, 1};                ///< +Z
    Pose pose = Pose::a_pose;        ///< arms down (A) or out (T)
    std::string name = "body";       ///< used in messages (the file name, usually)
};

/// BodyOptions from its settings as a user types them: `unit` "m", "dm", "cm" or "mm" (empty:
/// inferred from the height), `up` and `front` axes ("+Y", "-z", ...), `pose` "A" or "T".
/// InvalidInput naming `prefix` + the setting ("--units" for the tool, "units" for a keyword
/// argument) on anything else, an empty axis or pose included.
inline BodyOptions parse_body_options(const std::string& name, const std::string& unit,
                                      const std::string& up, const std::string& front,
                                      const std::string& pose, const std::string& prefix = "") {
    BodyOptions o;
    o.name = name;
    if (!unit.empty()) {
        o.unit = parse_length_unit(unit, prefix + "units");
    }
    o.up = Axis::parse(up, prefix + "up");
    o.front = Axis::parse(front, prefix + "front");
    o.pose = parse_pose(pose, prefix + "pose");
    return o;
}

/// A hole of the input mesh (a loop of boundary edges) that make_body filled (holes.h).
struct BodyHole {
    double size = 0;       ///< largest distance between two of its boundary vertices, mm
    Vec3 centre{0, 0, 0};  ///< mean of its boundary vertices, canonical mm
    double height = 0;     ///< of the centre above the floor, mm
    std::string region;    ///< where it is: "the left sole", "the crown", ... (holes.h)
    /// How it was filled: "faired" (triangulated, refined and faired), "refined" (fairing
    /// failed: triangulated and refined) or "triangulated" (no refinement).
    std::string filling;
    /// Edges of its boundary loop, and the faces and vertices added to fill it.
    ///@{
    std::size_t boundary_edges = 0, faces_added = 0, vertices_added = 0;
    ///@}
};

/// What was used to map the input into the canonical frame (see the top of this file):
/// canonical = scale * R * input - (0, floor, 0), R's rows being left, up and front.
struct BodyFrame {
    LengthUnit unit = LengthUnit::mm;  ///< unit of the input coordinates
    bool unit_inferred = false;        ///< the unit came from the height
    /// Input axes pointing up and to the front of the body.
    ///@{
    Axis up, front;
    ///@}
    Pose pose = Pose::a_pose;    ///< the body's pose
    double scale = 1;            ///< millimetres per input unit
    std::array<Vec3, 3> rows{};  ///< R: canonical x (left), y (up), z (front) in input coordinates
    double floor = 0;            ///< input height of the lowest vertex, in mm
    double height = 0;           ///< body height (floor to the highest vertex), mm

    /// Canonical (mm) point to the input's coordinates and unit.
    Vec3 to_input(const Vec3& c) const {
        const Vec3 q{c[0], c[1] + floor, c[2]};
        Vec3 p{0, 0, 0};
        for (int r = 0; r < 3; ++r) {
            for (int k = 0; k < 3; ++k) {
                p[k] += rows[r][k] * q[r] / scale;
            }
        }
        return p;
    }
    /// Input point to canonical millimetres.
    Vec3 to_canonical(const Vec3& p) const {
        Vec3 c{0, 0, 0};
        for (int r = 0; r < 3; ++r) {
            c[r] = scale * (rows[r][0] * p[0] + rows[r][1] * p[1] + rows[r][2] * p[2]);
        }
        c[1] -= floor;
        return c;
    }
};

/// The unit whose reading of `height` (in input units) gives a human height between 0.5 m and
/// 2.5 m. These bands are a decade apart and do not overlap, so at most one unit fits; a height
/// in none of them (3.7, 40, 900, ...) is InvalidInput asking for --units.
inline LengthUnit infer_length_unit(double height, const std::string& where) {
    for (LengthUnit u : {LengthUnit::m, LengthUnit::dm, LengthUnit::cm, LengthUnit::mm}) {
        const double mm = height * millimetres_per(u);
        if (mm >= 500 && mm <= 2500) {
            return u;
        }
    }
    char h[32];
    std::snprintf(h, sizeof h, "%.6g", height);
    throw InvalidInput(where + ": units cannot be inferred from height " + h +
                       " (a body 0.5-2.5 m tall reads 0.5-2.5 m, 5-25 dm, 50-250 cm or "
                       "500-2500 mm); pass --units");
}

namespace internal {

/// Closed triangle mesh in canonical millimetres with edge/face adjacency.
struct BodyMesh {
    std::string name;
    std::vector<Vec3> points;
    std::vector<std::array<std::uint32_t, 3>> triangles;
    /// Per triangle: added by filling a hole of the input (holes.h); empty when none was.
    std::vector<bool> filled;
    std::vector<std::array<std::uint32_t, 2>> edges;       // end vertices
    std::vector<std::array<std::uint32_t, 2>> edge_faces;  // the two faces of each edge
    std::vector<std::array<std::uint32_t, 3>> face_edges;  // edge k joins corners k and k+1
    std::size_t components = 0;
    double min_y = 0, max_y = 0;
    // Edges in chunks of kChunk, spatially sorted (Morton order of their midpoints), each with
    // its bounding box: a cut skips the chunks the plane misses (see cut()).
    static constexpr std::size_t kChunk = 64;
    std::vector<std::uint32_t> chunk_edges;
    std::vector<std::array<Vec3, 2>> chunk_ends;  // end points of chunk_edges[i], contiguous
    std::vector<std::array<Vec3, 2>> chunk_box;   // min, max corner

    bool is_filled(std::size_t f) const { return !filled.empty() && filled[f]; }
};

}  // namespace internal

/// The body in the canonical frame, with the frame that maps it back.
struct Body {
    /// How the input was mapped into the canonical frame; BodyFrame::to_input maps back.
    BodyFrame frame;
    internal::BodyMesh mesh;  ///< canonical mm, with edge/face adjacency
    /// The input's holes, filled (holes.h): their faces and vertices follow the input's.
    std::vector<BodyHole> holes;

    /// Vertices, canonical mm: the input's in its order, then those added to fill holes.
    const std::vector<Vec3>& points() const { return mesh.points; }
    /// Triangles (indices into points()): the input's in its order, then those filling holes.
    const std::vector<std::array<std::uint32_t, 3>>& triangles() const { return mesh.triangles; }
    /// Stature: the floor to the highest vertex, mm.
    double height() const { return frame.height; }
};

}  // namespace tapeline::measurement
