// Placement of pattern pieces around a body before sewing (the first step of dressing).
//
// Each piece gets a body region (torso front/back, left/right sleeve, skirt front/back, left/right
// trouser leg front/back) from the pattern: GarmentCode panels by their names and by where their
// own placement puts them (front or back, left or right: the absolute coordinates, meant for
// GarmentCode's own body, are not trusted); FreeSewing pieces by the design's piece names (a
// trouser leg by its fork point). The piece is then wrapped, as a tailor holds a piece against a
// dress form and as CLO's arrangement points do:
//  - torso and skirt pieces around a prism whose cross-section is the convex hull of the body's
//    trunk over their heights (arms removed), offset outwards by a gap, with the piece's centre
//    line on the body's centre front (back) line and its width laid out in arc length along the
//    section;
//  - trouser legs around a prism per leg, the hull of the body's half on that side, each piece
//    from its fork at the centre line outwards round the hip (see wrap_pieces);
//  - sleeves around a circular cylinder along the arm's axis (fitted to the arm's cross-sections
//    where the sleeve goes), the sleeve cap as near the shoulder as it keeps clear of the body
//    pieces.
// Heights come from the body's landmarks: the top of the upper-body pieces at the side-neck
// height, skirts hang from the waist. Where front and back would overlap, the section is offset
// further so that its perimeter holds both. The result is checked by the caller (dress.h): no
// cloth vertex inside the body, no two pieces crossing.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/vec3.h>
#include <tapeline/garment/garment_types.h>
#include <tapeline/measurement/measurement_types.h>
#include <tapeline/pattern/io_garmentcode.h>
#include <tapeline/pattern/meshing_types.h>
#include <tapeline/pattern/pattern.h>

#include <Eigen/Eigenvalues>

#include <algorithm>
#include <array>
#include <cmath>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::garment {

/// The landmarks and trunk of a body that placement needs (canonical mm).
struct BodyShape {
    std::vector<Vec3> points;  ///< body vertices, canonical mm
    double height = 0;         ///< stature, mm
    double neck_y = 0;         ///< side-neck height
    double waist_y = 0;        ///< waist height
    double armpit_y = 0;       ///< armpit height
    double crotch_y = 0;       ///< crotch height
    /// Per side (0: left, +x; 1: right, −x): arm axis from the shoulder to the wrist centre.
    ///@{
    std::array<Vec3, 2> shoulder{}, wrist{};
    ///@}
    std::array<double, 2> armpit_x{};  ///< |x| of the armpits
    std::vector<std::uint8_t> is_arm;  ///< per body vertex: on an arm (or hand)
};

namespace internal {

using vec3::add;
using vec3::cross;
using vec3::dot;
using vec3::norm;
using vec3::normalized;
using vec3::scale;
using vec3::sub;

inline Vec3 landmark_point(const measurement::LandmarkSet& lm, const std::string& name,
                           bool axis = false) {
    const measurement::Landmark* l = lm.find(name);
    if (!l || !l->available()) {
        throw InvalidInput("dress: the body's landmark '" + name +
                           "' was not found, so the garment cannot be placed (" +
                           (l ? l->reason : std::string("unknown landmark")) + ")");
    }
    return axis ? l->axis_point : l->point;
}

/// Convex hull (Andrew's monotone chain) of 2D points, counter-clockwise.
inline std::vector<std::array<double, 2>> convex_hull(std::vector<std::array<double, 2>> p) {
    std::sort(p.begin(), p.end());
    p.erase(std::unique(p.begin(), p.end()), p.end());
    if (p.size() < 3) {
        return p;
    }
    const auto turn = [](const auto& o, const auto& a, const auto& b) {
        return (a[0] - o[0]) * (b[1] - o[1]) - (a[1] - o[1]) * (b[0] - o[0]);
    };
    std::vector<std::array<double, 2>> h(2 * p.size());
    std::size_t k = 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
        while (k >= 2 && turn(h[k - 2], h[k - 1], p[i]) <= 0) {
            --k;
        }
        h[k++] = p[i];
    }
    for (std::size_t i = p.size() - 1, t = k + 1; i > 0; --i) {
        while (k >= t && turn(h[k - 2], h[k - 1], p[i - 1]) <= 0) {
            --k;
        }
        h[k++] = p[i - 1];
    }
    h.resize(k - 1);
    return h;
}

/// A closed convex curve in the (x, z) plane sampled densely, with arc lengths, and the arc
/// positions of its centre-front and centre-back points.
struct Section {
    std::vector<std::array<double, 2>> pts;  ///< counter-clockwise seen from above? see make
    std::vector<double> arc;                 ///< arc length at each point; arc.back() = perimeter
    double front_arc = 0, back_arc = 0;
    /// +1 when increasing arc at the centre front goes towards +x.
    double dir_front = 1;
};

/// The hull of `xz` offset by `offset` (Minkowski sum with a disc, sampled), with arc lengths.
inline Section make_section(const std::vector<std::array<double, 2>>& xz, double offset) {
    std::vector<std::array<double, 2>> cloud;
    cloud.reserve(xz.size() * 24);
    for (const auto& p : xz) {
        for (int k = 0; k < 24; ++k) {
            const double a = 2 * M_PI * k / 24;
            cloud.push_back({p[0] + offset * std::cos(a), p[1] + offset * std::sin(a)});
        }
    }
    Section s;
    s.pts = convex_hull(std::move(cloud));
    s.pts.push_back(s.pts.front());
    s.arc.assign(s.pts.size(), 0.0);
    for (std::size_t i = 1; i < s.pts.size(); ++i) {
        s.arc[i] =
            s.arc[i - 1] + std::hypot(s.pts[i][0] - s.pts[i - 1][0], s.pts[i][1] - s.pts[i - 1][1]);
    }
    // Centre front/back: where the curve crosses x = centre of its x range, at max/min z.
    double xmin = 1e300, xmax = -1e300;
    for (const auto& p : s.pts) {
        xmin = std::min(xmin, p[0]);
        xmax = std::max(xmax, p[0]);
    }
    const double xc = 0.0 * (xmin + xmax);  // the body's mid-sagittal plane is x = 0
    double best_front = -1e300, best_back = 1e300;
    for (std::size_t i = 0; i + 1 < s.pts.size(); ++i) {
        const auto& a = s.pts[i];
        const auto& b = s.pts[i + 1];
        if ((a[0] - xc) * (b[0] - xc) > 0 || a[0] == b[0]) {
            if (!(a[0] == xc)) {
                continue;
            }
        }
        const double t = a[0] == b[0] ? 0.0 : (xc - a[0]) / (b[0] - a[0]);
        const double z = a[1] + t * (b[1] - a[1]);
        const double arc = s.arc[i] + t * (s.arc[i + 1] - s.arc[i]);
        if (z > best_front) {
            best_front = z;
            s.front_arc = arc;
            s.dir_front = b[0] > a[0] ? 1 : -1;
        }
        if (z < best_back) {
            best_back = z;
            s.back_arc = arc;
        }
    }
    return s;
}

/// The point at arc position `a` (wrapped onto [0, perimeter)).
inline std::array<double, 2> section_point(const Section& s, double a) {
    const double per = s.arc.back();
    a = std::fmod(a, per);
    if (a < 0) {
        a += per;
    }
    const auto it = std::upper_bound(s.arc.begin(), s.arc.end(), a);
    const std::size_t i = std::min<std::size_t>(std::max<std::ptrdiff_t>(it - s.arc.begin(), 1) - 1,
                                                s.arc.size() - 2);
    const double len = s.arc[i + 1] - s.arc[i];
    const double t = len > 0 ? (a - s.arc[i]) / len : 0.0;
    return {s.pts[i][0] + t * (s.pts[i + 1][0] - s.pts[i][0]),
            s.pts[i][1] + t * (s.pts[i + 1][1] - s.pts[i][1])};
}

inline bool contains(const std::string& s, const char* sub) {
    return s.find(sub) != std::string::npos;
}

}  // namespace internal

/// The body's trunk, arms and the heights placement needs, from its landmarks (canonical mm).
/// An arm is the part of the surface joined to its wrist through vertices lying beyond the armpit
/// sideways (|x| above the armpit's by 0.5 % of the stature) and below the acromion: the mesh's
/// connectivity, not a distance to an axis, so a hand held away from the hip or a bent elbow
/// stays an arm and a wide hip stays trunk. InvalidInput naming the landmark when one that
/// placement needs was not found.
inline BodyShape body_shape(const std::vector<Vec3>& points, const std::vector<Tri>& triangles,
                            double height, const measurement::LandmarkSet& lm) {
    using namespace internal;
    BodyShape b;
    b.points = points;
    b.height = height;
    b.neck_y =
        0.5 * (landmark_point(lm, "side_neck_left")[1] + landmark_point(lm, "side_neck_right")[1]);
    b.waist_y = landmark_point(lm, "waist_front")[1];
    b.crotch_y = landmark_point(lm, "crotch")[1];
    const char* side[2] = {"left", "right"};
    std::array<double, 2> acromion_y{};
    for (int s = 0; s < 2; ++s) {
        const Vec3 acromion = landmark_point(lm, std::string("acromion_") + side[s]);
        const Vec3 armpit = landmark_point(lm, std::string("armpit_") + side[s]);
        b.wrist[s] = landmark_point(lm, std::string("wrist_") + side[s], true);
        // The shoulder joint sits about halfway between the acromion and the armpit.
        b.shoulder[s] = {acromion[0], 0.5 * (acromion[1] + armpit[1]), acromion[2]};
        b.armpit_x[s] = std::abs(armpit[0]);
        b.armpit_y += 0.5 * armpit[1];
        acromion_y[std::size_t(s)] = acromion[1];
    }
    const auto side_of = [](const Vec3& p) { return p[0] >= 0 ? 0 : 1; };
    const auto candidate = [&](const Vec3& p) {
        const int s = side_of(p);
        return std::abs(p[0]) > b.armpit_x[std::size_t(s)] + 0.005 * height &&
               p[1] < acromion_y[std::size_t(s)];
    };
    std::vector<std::vector<std::uint32_t>> adj(points.size());
    for (const Tri& t : triangles) {
        for (int k = 0; k < 3; ++k) {
            adj[t[k]].push_back(t[(k + 1) % 3]);
            adj[t[(k + 1) % 3]].push_back(t[k]);
        }
    }
    b.is_arm.assign(points.size(), 0);
    for (int s = 0; s < 2; ++s) {
        // Seed: the candidate vertex nearest to the wrist's axis point.
        std::uint32_t seed = std::uint32_t(-1);
        double best = 1e300;
        for (std::size_t v = 0; v < points.size(); ++v) {
            if (candidate(points[v]) && side_of(points[v]) == s && !adj[v].empty()) {
                const double d = norm(sub(points[v], b.wrist[std::size_t(s)]));
                if (d < best) {
                    best = d;
                    seed = std::uint32_t(v);
                }
            }
        }
        if (seed == std::uint32_t(-1)) {
            continue;
        }
        std::vector<std::uint32_t> stack{seed};
        b.is_arm[seed] = 1;
        while (!stack.empty()) {
            const std::uint32_t v = stack.back();
            stack.pop_back();
            for (std::uint32_t w : adj[v]) {
                if (!b.is_arm[w] && candidate(points[w])) {
                    b.is_arm[w] = 1;
                    stack.push_back(w);
                }
            }
        }
    }
    return b;
}

/// A piece's region and its layout coordinates: per vertex `s` (arc position, mm) and `h`
/// (height for torso and skirt pieces; distance down the arm from the shoulder for sleeves).
struct PieceLayout {
    /// The body region the piece is wrapped around.
    Region region = Region::torso_front;
    /// Per vertex of the piece mesh: arc position `s` and `h` (height, or distance down the
    /// arm), mm.
    ///@{
    std::vector<double> s, h;
    ///@}
    /// A whole sleeve (FreeSewing): s = 0 goes on top of the arm, s > 0 towards the front, and
    /// its two side edges meet under the arm.
    bool whole_sleeve = false;
};

/// For a FreeSewing sleeve (no 3D placement) of `p` at `index`: +1 when the edges sewn to the
/// front torso pieces lie at larger x than the piece's centre, −1 when at smaller x; 1 for other
/// pieces or when no seam tells.
inline double sleeve_front_sign(const pattern::Pattern& p, std::size_t index,
                                const std::vector<Region>& regions) {
    const pattern::Piece& piece = p.pieces[index];
    if (piece.placement || !is_sleeve(regions[index])) {
        return 1;
    }
    double xmin = 1e300, xmax = -1e300;
    for (const pattern::Edge& e : piece.outline.edges) {
        xmin = std::min(xmin, pattern::start_point(e).x);
        xmax = std::max(xmax, pattern::start_point(e).x);
    }
    const double xc = 0.5 * (xmin + xmax);
    double lean = 0;
    for (const pattern::Seam& seam : p.seams) {
        for (int side = 0; side < 2; ++side) {
            const pattern::EdgeRange& mine = side == 0 ? seam.a : seam.b;
            const pattern::EdgeRange& other = side == 0 ? seam.b : seam.a;
            if (mine.piece != piece.name) {
                continue;
            }
            Region r = Region::torso_front;
            for (std::size_t j = 0; j < p.pieces.size(); ++j) {
                if (p.pieces[j].name == other.piece) {
                    r = regions[j];
                }
            }
            const double w = r == Region::torso_front ? 1 : r == Region::torso_back ? -1 : 0;
            const std::size_t n = piece.outline.edges.size();
            for (std::size_t k = 0; k < mine.count; ++k) {
                const auto& e = piece.outline.edges[(mine.first_edge + k) % n];
                lean += w * (pattern::start_point(e).x + pattern::end_point(e).x - 2 * xc);
            }
        }
    }
    return lean < 0 ? -1 : 1;
}

/// The region of a piece, or nullopt with `why` set. GarmentCode panels: "sleeve" → sleeve (side
/// by the panel's placement x), "skirt" → skirt, "torso" → torso (front or back by placement z).
/// FreeSewing pieces: "front*" → torso front, "back" and "yoke" → torso back, "sleeve" → the
/// left sleeve, its mirrored copy (unfold.h) → the right one: the copy is sewn to the mirror
/// halves of the front and back, which lie on the body's right (piece_layout).
inline std::optional<Region> piece_region(const pattern::Piece& piece, std::string& why) {
    using internal::contains;
    const std::string& n = piece.name;
    if (piece.placement) {
        const auto& t = piece.placement->translation;
        const bool front = t[2] >= 0;
        if (contains(n, "sleeve")) {
            return t[0] >= 0 ? Region::sleeve_left : Region::sleeve_right;
        }
        if (contains(n, "skirt")) {
            return front ? Region::skirt_front : Region::skirt_back;
        }
        if (contains(n, "torso")) {
            return front ? Region::torso_front : Region::torso_back;
        }
        if (contains(n, "pant")) {
            const bool left = t[0] >= 0;
            return front ? (left ? Region::leg_left_front : Region::leg_right_front)
                         : (left ? Region::leg_left_back : Region::leg_right_back);
        }
        why = contains(n, "hood") ? "hoods are not placed yet"
                                  : "its name says neither torso, skirt, sleeve nor pant";
        return std::nullopt;
    }
    // FreeSewing names pieces "design.piece" ("aaron.front"); a trouser leg's front and back
    // (titan's) carry the fork, where the inseam meets the crotch seam. The piece as drafted goes
    // on the right leg, its mirrored copy (unfold.h) on the left.
    const std::string base = n.substr(n.rfind('.') == std::string::npos ? 0 : n.rfind('.') + 1);
    if (piece.points.count("fork")) {
        const bool mirror = contains(base, "(mirror)");
        if (base.rfind("front", 0) == 0) {
            return mirror ? Region::leg_left_front : Region::leg_right_front;
        }
        if (base.rfind("back", 0) == 0) {
            return mirror ? Region::leg_left_back : Region::leg_right_back;
        }
        why = "a trouser leg (it has a fork point) named neither front nor back";
        return std::nullopt;
    }
    if (base.rfind("front", 0) == 0 && base.find("Binding") == std::string::npos) {
        return Region::torso_front;
    }
    if (base == "back" || base == "yoke") {
        return Region::torso_back;
    }
    if (base == "sleeve") {
        return Region::sleeve_left;
    }
    if (base == "sleeve (mirror)") {
        return Region::sleeve_right;
    }
    why =
        "the design table gives no region for it (bindings, cuffs and collars are not placed yet)";
    return std::nullopt;
}

/// Layout coordinates of every vertex of a meshed piece (see PieceLayout). `top_y` is the body
/// height the top of the garment goes to; `gc_shift` the vertical offset from GarmentCode's
/// placement to the body (GarmentCode pieces keep their relative heights).
inline PieceLayout piece_layout(const pattern::Piece& piece, const pattern::PieceMesh& mesh,
                                Region region, double top_y, double waist_y, double gc_shift,
                                double sleeve_front = 1) {
    PieceLayout out;
    out.region = region;
    const std::size_t n = mesh.uv.size();
    out.s.resize(n);
    out.h.resize(n);
    const bool sleeve = is_sleeve(region);
    // Skirts and trouser legs hang from the waist.
    const bool skirt =
        region == Region::skirt_front || region == Region::skirt_back || is_leg(region);
    const bool front = is_front(region);
    if (piece.placement && !sleeve) {
        // GarmentCode torso/skirt panels lie in planes z = const: x is the offset from the centre
        // line (the body's left for x > 0), y the height on GarmentCode's body.
        for (std::size_t v = 0; v < n; ++v) {
            const auto p = pattern::placed_point(*piece.placement, mesh.uv[v]);
            out.s[v] = front ? p[0] : -p[0];
            out.h[v] = p[1] + gc_shift;
        }
        return out;
    }
    if (piece.placement && sleeve) {
        // Along the panel's own x axis (rotated down the arm), across its y axis (top edge up).
        const auto o = pattern::placed_point(*piece.placement, {0, 0});
        auto ex = vec3::sub(pattern::placed_point(*piece.placement, {1, 0}), o);
        auto ey = vec3::sub(pattern::placed_point(*piece.placement, {0, 1}), o);
        if (ex[1] > 0) {
            ex = vec3::scale(ex, -1);
        }
        if (ey[1] < 0) {
            ey = vec3::scale(ey, -1);
        }
        for (std::size_t v = 0; v < n; ++v) {
            const auto p = pattern::placed_point(*piece.placement, mesh.uv[v]);
            out.h[v] = vec3::dot(p, ex);
            out.s[v] = vec3::dot(p, ey);
        }
        return out;
    }
    // FreeSewing torso pieces: centre line at the middle of the piece's x range, top at top_y.
    double xmin = 1e300, xmax = -1e300, ymax = -1e300;
    for (const auto& q : mesh.uv) {
        xmin = std::min(xmin, q.x);
        xmax = std::max(xmax, q.x);
        ymax = std::max(ymax, q.y);
    }
    if (sleeve) {
        // A whole FreeSewing sleeve, cap up: across its x axis around the arm (centre on top, the
        // front edges towards the front), down its y axis along the arm from the top of the cap.
        out.whole_sleeve = true;
        for (std::size_t v = 0; v < n; ++v) {
            out.s[v] = sleeve_front * (mesh.uv[v].x - 0.5 * (xmin + xmax));
            out.h[v] = ymax - mesh.uv[v].y;
        }
        return out;
    }
    // A trouser leg's s starts at its fork, which goes to the body's centre line (wrap_pieces
    // turns it outwards, towards its leg).
    const auto fork = piece.points.find("fork");
    const double xc = is_leg(region) && fork != piece.points.end() ? fork->second.x
                      : piece.fold ? 0.5 * (piece.fold->line.a.x + piece.fold->line.b.x)
                                   : 0.5 * (xmin + xmax);
    for (std::size_t v = 0; v < n; ++v) {
        // FreeSewing draws front and back halves alike, the fold on the same side, so that a side
        // seam joins edges on the same side of both drawings: seen from behind, the back is
        // mirrored.
        out.s[v] = front ? mesh.uv[v].x - xc : xc - mesh.uv[v].x;
        out.h[v] = (skirt ? waist_y : top_y) + (mesh.uv[v].y - ymax);
    }
    return out;
}

/// The heights pieces are laid out from (canonical mm): the top of the upper-body pieces, the
/// waist skirts hang from (both a gap above the body's), and the vertical shift from GarmentCode's
/// placement to the body, which keeps GarmentCode pieces at their relative heights (their
/// highest torso point goes to the top; without torso pieces, the highest point of the skirt and
/// trouser pieces goes to the waist). `uv[i]` holds points of
/// piece i (its mesh vertices or its outline): their highest placed point is the piece's.
struct LayoutHeights {
    double top_y = 0, waist_y = 0, gc_shift = 0;
};

inline LayoutHeights layout_heights(const pattern::Pattern& pattern,
                                    const std::vector<Region>& regions,
                                    const std::vector<std::vector<pattern::Point2>>& uv,
                                    const BodyShape& body, double gap_mm) {
    double gc_top = -1e300, gc_skirt_top = -1e300;
    for (std::size_t i = 0; i < pattern.pieces.size(); ++i) {
        const auto& p = pattern.pieces[i];
        if (!p.placement) {
            continue;
        }
        for (const auto& q : uv[i]) {
            const double y = pattern::placed_point(*p.placement, q)[1];
            if (regions[i] == Region::torso_front || regions[i] == Region::torso_back) {
                gc_top = std::max(gc_top, y);
            } else if (!is_sleeve(regions[i])) {
                gc_skirt_top = std::max(gc_skirt_top, y);  // skirts and trouser legs
            }
        }
    }
    LayoutHeights h;
    h.top_y = body.neck_y + gap_mm;
    h.waist_y = body.waist_y + gap_mm;
    h.gc_shift = gc_top > -1e300         ? h.top_y - gc_top
                 : gc_skirt_top > -1e300 ? h.waist_y - gc_skirt_top
                                         : 0.0;
    return h;
}

/// The axis a sleeve is wrapped round: a line fitted to the arm where the sleeve goes, and the
/// arm's radius about it.
struct ArmAxis {
    Vec3 start{0, 0, 0};      ///< on the line, level with the shoulder joint
    Vec3 direction{0, 0, 0};  ///< unit, from the shoulder towards the wrist
    double length = 0;        ///< from `start` to the wrist along the line, mm
    double radius = 0;        ///< 90th percentile of the arm's distance from the line, mm
};

/// Fits the axis of arm `side` (0 left, 1 right) over the first `sleeve_length` mm (at least a
/// third of the arm) below the shoulder joint. The straight line from the shoulder joint to the
/// wrist misses a bent elbow by several centimetres; here the line goes through the centroids of
/// the arm's cross-sections (arm vertices binned by their position along the shoulder–wrist
/// line; principal direction of the centroids). The radius is taken below the shoulder's junction
/// with the trunk (the first tenth of the arm), where the arm is round.
inline ArmAxis fit_arm_axis(const BodyShape& body, int side, double sleeve_length) {
    using namespace internal;
    const std::size_t s = std::size_t(side);
    const Vec3 a = body.shoulder[s];
    const double full = norm(sub(body.wrist[s], a));
    ArmAxis out;
    out.start = a;
    out.direction = full > 0 ? scale(sub(body.wrist[s], a), 1.0 / full) : Vec3{0, -1, 0};
    out.length = full;
    if (!(full > 0)) {
        return out;
    }
    const double reach = std::min(1.0, std::max(1.0 / 3, 1.15 * sleeve_length / full));
    // The arm's vertices on this side.
    std::vector<Vec3> pts;
    for (std::size_t v = 0; v < body.points.size(); ++v) {
        if (body.is_arm[v] && (body.points[v][0] >= 0) == (side == 0)) {
            pts.push_back(body.points[v]);
        }
    }
    constexpr int bins = 20;
    std::array<Vec3, bins> sum{};
    std::array<int, bins> count{};
    for (const Vec3& p : pts) {
        const double t = dot(sub(p, a), out.direction) / full;
        if (t < 0.1 || t > reach) {
            continue;
        }
        const int b = std::min(bins - 1, int(t * bins));
        sum[std::size_t(b)] = add(sum[std::size_t(b)], p);
        ++count[std::size_t(b)];
    }
    std::vector<Vec3> centroids;
    for (int b = 0; b < bins; ++b) {
        if (count[std::size_t(b)] > 0) {
            centroids.push_back(scale(sum[std::size_t(b)], 1.0 / count[std::size_t(b)]));
        }
    }
    if (centroids.size() >= 2) {
        Vec3 c{0, 0, 0};
        for (const Vec3& p : centroids) {
            c = add(c, scale(p, 1.0 / double(centroids.size())));
        }
        // Principal direction of the centroids: the eigenvector of their scatter matrix with the
        // largest eigenvalue (Eigen sorts them ascending).
        Eigen::Matrix3d m = Eigen::Matrix3d::Zero();
        for (const Vec3& p : centroids) {
            const Eigen::Vector3d q(p[0] - c[0], p[1] - c[1], p[2] - c[2]);
            m += q * q.transpose();
        }
        const Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(m);
        const Eigen::Vector3d e = eig.eigenvectors().col(2);
        Vec3 dir = normalized(Vec3{e[0], e[1], e[2]});
        if (dot(dir, out.direction) < 0) {
            dir = scale(dir, -1);
        }
        out.direction = dir;
        // The line's point level with the shoulder joint (its projection on the line).
        out.start = add(c, scale(dir, dot(sub(a, c), dir)));
        out.length = std::max(0.0, dot(sub(body.wrist[s], out.start), dir));
    }
    std::vector<double> dist;
    for (const Vec3& p : pts) {
        const Vec3 q = sub(p, out.start);
        const double t = dot(q, out.direction);
        if (t >= 0.1 * full && t <= reach * full) {
            dist.push_back(norm(sub(q, scale(out.direction, t))));
        }
    }
    if (!dist.empty()) {
        std::sort(dist.begin(), dist.end());
        out.radius = dist[std::size_t(0.9 * double(dist.size() - 1))];
    }
    return out;
}

/// Wraps every piece around its region (see the file comment). `layouts[i]` belongs to
/// `mesh.pieces[i]`; writes the 3D positions (canonical mm) of every piece vertex to `xyz`.
inline void wrap_pieces(const BodyShape& body, const std::vector<PieceLayout>& layouts,
                        const pattern::PatternMesh& mesh, const PlacementOptions& o,
                        std::vector<std::vector<Vec3>>& xyz) {
    using namespace internal;
    xyz.assign(mesh.pieces.size(), {});
    // --- torso and skirt: one prism around the trunk. Its section is the convex hull of the
    // trunk's points (the arms below the armpits removed) over the pieces' heights, seen from
    // above, offset by the gap (and further when the front and back pieces together are wider than
    // its perimeter). A prism is developable: the pieces are wrapped onto it without stretch,
    // straight up and round; the sewing and the drape then bring the cloth in to the body.
    double hmin = 1e300, hmax = -1e300, need = 0;
    Section prism;
    bool have_prism = false;
    {
        std::vector<double> fmin, fmax, bmin, bmax;
        for (const PieceLayout& l : layouts) {
            if (is_sleeve(l.region) || is_leg(l.region)) {
                continue;
            }
            for (double h : l.h) {
                hmin = std::min(hmin, h);
                hmax = std::max(hmax, h);
            }
        }
        // The widths the perimeter must hold, per 10 mm of height: front extent + back extent.
        const double step = o.slice_mm;
        const std::size_t ns = hmin <= hmax ? std::size_t((hmax - hmin) / step) + 1 : 0;
        fmin.assign(ns, 1e300);
        fmax.assign(ns, -1e300);
        bmin.assign(ns, 1e300);
        bmax.assign(ns, -1e300);
        for (const PieceLayout& l : layouts) {
            if (is_sleeve(l.region) || is_leg(l.region)) {
                continue;
            }
            const bool front = is_front(l.region);
            for (std::size_t v = 0; v < l.s.size(); ++v) {
                const std::size_t k = std::min(ns - 1, std::size_t((l.h[v] - hmin) / step));
                (front ? fmin : bmin)[k] = std::min((front ? fmin : bmin)[k], l.s[v]);
                (front ? fmax : bmax)[k] = std::max((front ? fmax : bmax)[k], l.s[v]);
            }
        }
        for (std::size_t k = 0; k < ns; ++k) {
            const double wf = fmax[k] > fmin[k] ? fmax[k] - fmin[k] : 0;
            const double wb = bmax[k] > bmin[k] ? bmax[k] - bmin[k] : 0;
            need = std::max(need, 1.04 * (wf + wb) + 2 * o.layer_gap_mm);
        }
    }
    if (hmin <= hmax) {
        std::vector<std::array<double, 2>> trunk;
        for (std::size_t v = 0; v < body.points.size(); ++v) {
            const Vec3& p = body.points[v];
            // The arms are left out below the armpits, where they hang free; the top of the
            // upper arm (the deltoid) is kept, so that the body pieces pass outside it.
            const bool free_arm = body.is_arm[v] && p[1] < body.armpit_y - 0.03 * body.height;
            if (!free_arm && p[1] >= hmin - o.gap_mm && p[1] <= hmax + o.gap_mm) {
                trunk.push_back({p[0], p[2]});
            }
        }
        if (trunk.size() < 3) {
            throw InvalidInput("dress: the body has no trunk between " + std::to_string(int(hmin)) +
                               " and " + std::to_string(int(hmax)) +
                               " mm height, where the pieces go");
        }
        Section sec = make_section(trunk, o.gap_mm);
        if (sec.arc.back() < need) {
            sec = make_section(trunk, o.gap_mm + (need - sec.arc.back()) / (2 * M_PI));
        }
        prism = sec;
        have_prism = true;
        for (std::size_t i = 0; i < layouts.size(); ++i) {
            const PieceLayout& l = layouts[i];
            if (is_sleeve(l.region) || is_leg(l.region)) {
                continue;
            }
            const bool front = is_front(l.region);
            xyz[i].resize(l.s.size());
            // Pieces on one side of the centre line (GarmentCode's left and right halves) keep
            // a layer gap from it, so that halves meeting there do not touch before sewing.
            const auto [smin_it, smax_it] = std::minmax_element(l.s.begin(), l.s.end());
            const double shift = *smin_it > -1.0  ? 0.5 * o.layer_gap_mm
                                 : *smax_it < 1.0 ? -0.5 * o.layer_gap_mm
                                                  : 0.0;
            for (std::size_t v = 0; v < l.s.size(); ++v) {
                // Front: positive s towards +x (the body's left, the viewer's right). Back seen
                // from behind: positive s towards -x.
                const double a =
                    (front ? sec.front_arc : sec.back_arc) + sec.dir_front * (l.s[v] + shift);
                const auto q = section_point(sec, a);
                xyz[i][v] = {q[0], l.h[v], q[1]};
            }
        }
    }
    // --- trouser legs: a prism per leg, as the trunk's, its section the convex hull of the body's
    // half on that side (x >= 0 for the left leg; arms and hands left out) over the legs' heights,
    // offset by the gap. Each piece's fork (FreeSewing; GarmentCode: its edge nearest the centre
    // line) goes to the centre line, half a layer gap off it, as GarmentCode arranges its own
    // trousers, and the piece wraps outwards from there, the front from the centre front and the
    // back from the centre back, round the hip to the side seam. The crotch extension thus starts
    // in front of (behind) the crotch, and the sewing pulls it in between the legs along its
    // strings. The offset grows until the section's arc from the centre front round the outside to
    // the centre back holds the front and the back piece side by side.
    for (int side = 0; side < 2; ++side) {
        const double sigma = side == 0 ? 1 : -1;  // the leg's side: +x is the body's left
        std::vector<std::size_t> legs;
        for (std::size_t i = 0; i < layouts.size(); ++i) {
            const Region r = layouts[i].region;
            if (is_leg(r) &&
                (r == Region::leg_left_front || r == Region::leg_left_back) == (side == 0)) {
                legs.push_back(i);
            }
        }
        if (legs.empty()) {
            continue;
        }
        // Per piece: s turned towards this leg (the front's positive s goes to +x, the back's to
        // −x) and shifted so that its innermost vertex is half a layer gap off the centre line.
        std::vector<std::vector<double>> sl(legs.size());
        double lo = 1e300, hi = -1e300;
        for (std::size_t k = 0; k < legs.size(); ++k) {
            const PieceLayout& l = layouts[legs[k]];
            const double out = sigma * (is_front(l.region) ? 1 : -1);
            double sum = 0;
            for (double v : l.s) {
                sum += v;
            }
            const double turn = out * sum >= 0 ? 1 : -1;
            double inner = 1e300;
            for (double v : l.s) {
                inner = std::min(inner, out * turn * v);
            }
            sl[k].resize(l.s.size());
            for (std::size_t v = 0; v < l.s.size(); ++v) {
                sl[k][v] = turn * l.s[v] + out * (0.5 * o.layer_gap_mm - inner);
            }
            for (double h : l.h) {
                lo = std::min(lo, h);
                hi = std::max(hi, h);
            }
        }
        // The widths the outer arc must hold, per slice: front and back extents from the centre.
        const double step = o.slice_mm;
        const std::size_t ns = std::size_t((hi - lo) / step) + 1;
        std::vector<double> wf(ns, 0.0), wb(ns, 0.0);
        for (std::size_t k = 0; k < legs.size(); ++k) {
            const PieceLayout& l = layouts[legs[k]];
            const bool front = is_front(l.region);
            for (std::size_t v = 0; v < l.s.size(); ++v) {
                const std::size_t b = std::min(ns - 1, std::size_t((l.h[v] - lo) / step));
                (front ? wf : wb)[b] = std::max((front ? wf : wb)[b], std::abs(sl[k][v]));
            }
        }
        double need = 0;
        for (std::size_t b = 0; b < ns; ++b) {
            need = std::max(need, 1.04 * (wf[b] + wb[b]) + o.layer_gap_mm);
        }
        std::vector<std::array<double, 2>> half;
        for (std::size_t v = 0; v < body.points.size(); ++v) {
            const Vec3& p = body.points[v];
            if (!body.is_arm[v] && sigma * p[0] >= 0 && p[1] >= lo - o.gap_mm &&
                p[1] <= hi + o.gap_mm) {
                half.push_back({p[0], p[2]});
            }
        }
        if (half.size() < 3) {
            throw InvalidInput("dress: the body has no " +
                               std::string(side == 0 ? "left" : "right") + " leg between " +
                               std::to_string(int(lo)) + " and " + std::to_string(int(hi)) +
                               " mm height, where the trouser legs go");
        }
        // The arc from the centre front outwards (towards this leg's side) to the centre back.
        const auto outer_arc = [&](const Section& sec) {
            const double per = sec.arc.back();
            const double d = std::fmod(sigma * sec.dir_front * (sec.back_arc - sec.front_arc), per);
            return d < 0 ? d + per : d;
        };
        double offset = o.gap_mm;
        Section sec = make_section(half, offset);
        for (int round = 0; round < 8 && outer_arc(sec) < need; ++round) {
            offset += (need - outer_arc(sec)) / M_PI;  // the outer arc turns through half a turn
            sec = make_section(half, offset);
        }
        for (std::size_t k = 0; k < legs.size(); ++k) {
            const PieceLayout& l = layouts[legs[k]];
            const bool front = is_front(l.region);
            xyz[legs[k]].resize(l.s.size());
            for (std::size_t v = 0; v < l.s.size(); ++v) {
                const double a = (front ? sec.front_arc : sec.back_arc) + sec.dir_front * sl[k][v];
                const auto q = section_point(sec, a);
                xyz[legs[k]][v] = {q[0], l.h[v], q[1]};
            }
        }
    }
    // --- sleeves: a cylinder per arm. The body pieces' vertices in a hash grid, for the
    // clearance of the sleeves from them.
    const double clear_mm = 2 * o.layer_gap_mm;
    std::map<std::array<long, 3>, std::vector<Vec3>> torso_grid;
    const auto cell_of = [&](const Vec3& p) {
        return std::array<long, 3>{long(std::floor(p[0] / clear_mm)),
                                   long(std::floor(p[1] / clear_mm)),
                                   long(std::floor(p[2] / clear_mm))};
    };
    for (std::size_t i = 0; i < layouts.size(); ++i) {
        if (!is_sleeve(layouts[i].region)) {
            for (const Vec3& p : xyz[i]) {
                torso_grid[cell_of(p)].push_back(p);
            }
        }
    }
    const auto near_torso = [&](const Vec3& p) {
        const auto c = cell_of(p);
        for (long dx = -1; dx <= 1; ++dx) {
            for (long dy = -1; dy <= 1; ++dy) {
                for (long dz = -1; dz <= 1; ++dz) {
                    const auto it = torso_grid.find({c[0] + dx, c[1] + dy, c[2] + dz});
                    if (it == torso_grid.end()) {
                        continue;
                    }
                    for (const Vec3& q : it->second) {
                        if (norm(sub(p, q)) < clear_mm) {
                            return true;
                        }
                    }
                }
            }
        }
        return false;
    };
    for (int side = 0; side < 2; ++side) {
        const Region reg = side == 0 ? Region::sleeve_left : Region::sleeve_right;
        // The sleeve's length down the arm (its pieces' height range).
        double sleeve_length = 0;
        for (const PieceLayout& l : layouts) {
            if (l.region == reg && !l.h.empty()) {
                const auto [lo, hi] = std::minmax_element(l.h.begin(), l.h.end());
                sleeve_length = std::max(sleeve_length, *hi - *lo);
            }
        }
        const ArmAxis arm = fit_arm_axis(body, side, sleeve_length);
        const Vec3 a0 = arm.start;
        const Vec3 d = arm.direction;
        const double r_arm = arm.radius;
        double smin = 1e300, smax = -1e300, hmin_s = 1e300;
        std::size_t count = 0;
        for (const PieceLayout& l : layouts) {
            if (l.region != reg) {
                continue;
            }
            ++count;
            for (std::size_t v = 0; v < l.s.size(); ++v) {
                smin = std::min(smin, l.s[v]);
                smax = std::max(smax, l.s[v]);
                hmin_s = std::min(hmin_s, l.h[v]);
            }
        }
        if (count == 0) {
            continue;
        }
        // Front and back halves each span half the circumference (one whole sleeve: all of it).
        double span = 0;
        for (const PieceLayout& l : layouts) {
            if (l.region != reg) {
                continue;
            }
            const auto [lo, hi] = std::minmax_element(l.s.begin(), l.s.end());
            span += *hi - *lo;
        }
        // The tube is at least as wide as the sleeve (3 % of ease, and the layer gap between two
        // halves) and clears the arm by the gap.
        const double radius_min =
            std::max(r_arm + o.gap_mm, (1.03 * span + o.layer_gap_mm) / (2 * M_PI));
        double radius = radius_min;
        // Frame: n_up ⟂ d pointing up, n_front ⟂ both pointing to the front (+z).
        Vec3 n_up = sub(Vec3{0, 1, 0}, scale(d, d[1]));
        n_up = normalized(n_up);
        Vec3 n_front = cross(d, n_up);
        if (n_front[2] < 0) {
            n_front = scale(n_front, -1);
        }
        // Where a sleeve vertex goes when the top of the sleeve is `start` down the arm. Two
        // halves meet along the top of the arm, a layer gap apart (as the torso's halves at the
        // centre line), so that they do not touch before they are sewn.
        const auto sleeve_point = [&](const PieceLayout& l, bool front_half, std::size_t v,
                                      double start) {
            const double theta =
                l.whole_sleeve
                    ? l.s[v] / radius
                    : (front_half ? 1 : -1) * (smax - l.s[v] + 0.5 * o.layer_gap_mm) / radius;
            const Vec3 c = add(a0, scale(d, start + l.h[v] - hmin_s));
            return add(c, add(scale(n_up, radius * std::cos(theta)),
                              scale(n_front, radius * std::sin(theta))));
        };
        std::vector<std::size_t> sleeves;
        std::vector<bool> front_halves;
        for (std::size_t i = 0; i < layouts.size(); ++i) {
            if (layouts[i].region != reg) {
                continue;
            }
            sleeves.push_back(i);
            // GarmentCode halves: the one placed in front goes over the front of the arm.
            front_halves.push_back(mesh.pieces[i].xyz.empty() ? true : [&] {
                double z = 0;
                for (const auto& p : mesh.pieces[i].xyz) {
                    z += p[2];
                }
                return z >= 0;
            }());
        }
        // The sleeve starts as near the shoulder as it keeps clear of the body pieces already
        // placed (twice the layer gap from every vertex of theirs: the armhole leaves room for the
        // cap), so that sleeves and body pieces do not cross before they are sewn. A wide sleeve
        // on an arm near the trunk may only clear them far down the arm, and the sewing would
        // then drag it up the whole way and crumple it: when the sleeve's own tube starts below
        // the first third of the arm, tubes up to 1.75 times wider are tried too, and the
        // narrowest that starts within a tenth of the arm's length of the nearest start is kept
        // (a wider tube leaves the underarm edges further apart).
        // Failing all, the sleeve starts where its cylinder has left the trunk's prism.
        const double arm_length = arm.length;
        const auto first_clear_start = [&]() {
            for (double start = 0; start < arm_length; start += 5) {
                bool clear = true;
                for (std::size_t k = 0; k < sleeves.size() && clear; ++k) {
                    const PieceLayout& l = layouts[sleeves[k]];
                    for (std::size_t v = 0; v < l.s.size() && clear; ++v) {
                        clear = !near_torso(sleeve_point(l, front_halves[k], v, start));
                    }
                }
                if (clear) {
                    return start;
                }
            }
            return -1.0;
        };
        double start = 0;
        bool placed = !have_prism || torso_grid.empty();
        if (!placed) {
            const std::array<double, 4> widen{1.0, 1.25, 1.5, 1.75};
            std::array<double, 4> starts{-1, -1, -1, -1};
            double best = -1;
            for (std::size_t k = 0; k < widen.size(); ++k) {
                radius = widen[k] * radius_min;
                starts[k] = first_clear_start();
                if (starts[k] >= 0 && (best < 0 || starts[k] < best)) {
                    best = starts[k];
                }
                if (k == 0 && best >= 0 && best <= arm_length / 3) {
                    break;  // the sleeve's own tube starts high enough on the arm
                }
            }
            radius = radius_min;
            for (std::size_t k = 0; best >= 0 && k < widen.size(); ++k) {
                if (starts[k] >= 0 && starts[k] <= best + 0.1 * arm_length) {
                    radius = widen[k] * radius_min;
                    start = starts[k];
                    placed = true;
                    break;
                }
            }
        }
        if (!placed) {
            start = 0;
            const auto inside_prism = [&](const Vec3& p) {
                if (p[1] > hmax + o.layer_gap_mm || p[1] < hmin - o.layer_gap_mm) {
                    return false;
                }
                for (std::size_t k = 0; k + 1 < prism.pts.size(); ++k) {
                    const auto& a = prism.pts[k];
                    const auto& b = prism.pts[k + 1];
                    const double cr = (b[0] - a[0]) * (p[2] - a[1]) - (b[1] - a[1]) * (p[0] - a[0]);
                    if (cr < -o.layer_gap_mm * std::hypot(b[0] - a[0], b[1] - a[1])) {
                        return false;  // outside this edge of the counter-clockwise hull
                    }
                }
                return true;
            };
            for (; start < arm_length; start += 5) {
                bool clear = true;
                for (int k = 0; k < 24 && clear; ++k) {
                    const double th = 2 * M_PI * k / 24;
                    const Vec3 q =
                        add(add(a0, scale(d, start)), add(scale(n_up, radius * std::cos(th)),
                                                          scale(n_front, radius * std::sin(th))));
                    clear = !inside_prism(q);
                }
                if (clear) {
                    break;
                }
            }
        }
        for (std::size_t k = 0; k < sleeves.size(); ++k) {
            const PieceLayout& l = layouts[sleeves[k]];
            xyz[sleeves[k]].resize(l.s.size());
            for (std::size_t v = 0; v < l.s.size(); ++v) {
                xyz[sleeves[k]][v] = sleeve_point(l, front_halves[k], v, start);
            }
        }
    }
}

}  // namespace tapeline::garment
