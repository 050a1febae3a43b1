// Measurement bindings found by laying a pattern on a body: the girths a pattern realises, for
// patterns that carry no bindings (GarmentCode, DXF, Seamly2D, FreeSewing designs without a
// table), so that any of them can be graded.
//
// The pieces are laid out as dressing lays them (placement.h): every piece gets its body region
// and, per point of its plane, the height on the body it is placed at (an affine function of the
// pattern coordinates for every kind of piece). A girth of the body taken in a horizontal plane
// (bust, underbust, waist, high hip, hip) at height y cuts every torso or skirt piece whose
// height range holds y along a straight line of the piece; the line's ends on the outline (the
// first and last crossings across the piece) become two named points of the piece, and the
// girth's binding is the sum of those spans, each counted as often as the piece goes round the
// body (2 for a half piece cut on the fold, cut_count for pieces cut several times). Its ease is
// the garment's girth there minus the body's: grading keeps it. The body is the one the pattern
// was made for (its measurements are the grading's base set).
//
// Arm girths (upper arm, elbow, wrist) cut the sleeves of one arm the same way, at the distance
// down the sleeve from the top of its cap at which the body's girth plane lies from the shoulder
// point (acromion) along the arm: the cap's top is sewn to the end of the shoulder seam, which
// sits on the shoulder point. A sleeve goes round one arm: a piece counts once (twice when cut on
// the fold), whatever its cut count (its copies dress the other arm).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/garment/placement.h>
#include <tapeline/measurement/measure.h>
#include <tapeline/pattern/pattern.h>
#include <tapeline/sizes/catalogue.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace tapeline::garment {

/// The girths bindings are looked for, in this order: horizontal torso girths, then arm girths
/// (on the sleeves).
inline const std::vector<std::string>& inferred_girths() {
    static const std::vector<std::string> names = {
        "bust_girth", "underbust_girth", "waist_girth", "high_hip_girth",
        "hip_girth",  "upper_arm_girth", "elbow_girth", "wrist_girth"};
    return names;
}

/// What binding inference found.
struct BindingInference {
    /// The pattern with the new named points (`girth:<measurement>:<a|b>`) on its pieces and the
    /// inferred bindings (replacing any it had).
    pattern::Pattern pattern;
    /// One line per girth: bound (pieces, garment girth, ease, height) or why not.
    std::vector<std::string> notes;
};

namespace internal {

/// Where the height of a piece's layout equals `y` along its outline: the crossing points (mm,
/// pattern coordinates) with their arc position `s` across the piece.
struct Crossing {
    pattern::Point2 p;
    double s = 0;
    std::size_t edge = 0;  ///< the outline edge crossed
};

inline std::vector<Crossing> outline_crossings(const pattern::Piece& piece, Region region,
                                               const LayoutHeights& heights, double y) {
    pattern::PieceMesh samples;
    const pattern::OutlinePolyline line = pattern::sample(piece.outline, 0.25);
    samples.uv = line.points;
    const PieceLayout l =
        piece_layout(piece, samples, region, heights.top_y, heights.waist_y, heights.gc_shift);
    std::vector<Crossing> out;
    const std::size_t n = samples.uv.size();
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const double a = l.h[i] - y, b = l.h[i + 1] - y;
        if ((a < 0) == (b < 0) || a == b) {
            continue;
        }
        const double t = a / (a - b);
        const pattern::Point2 p{samples.uv[i].x + t * (samples.uv[i + 1].x - samples.uv[i].x),
                                samples.uv[i].y + t * (samples.uv[i + 1].y - samples.uv[i].y)};
        out.push_back({p, l.s[i] + t * (l.s[i + 1] - l.s[i]), line.edge_of_point[i + 1]});
    }
    return out;
}

/// How often a piece goes round the body (a trunk piece) or the arm (a sleeve).
inline double girth_count(const pattern::Piece& piece, bool sleeve) {
    return (sleeve ? 1.0 : double(std::max(piece.cut_count, 1))) * (piece.fold ? 2.0 : 1.0);
}

inline bool trunk_region(Region r) {
    return r == Region::torso_front || r == Region::torso_back || r == Region::skirt_front ||
           r == Region::skirt_back;
}
inline bool sleeve_region(Region r) {
    return r == Region::sleeve_left || r == Region::sleeve_right;
}

}  // namespace internal

/// Infers the girth bindings of `base` laid out on `body` (canonical frame; its landmarks and
/// measurements from measure_body), `gap_mm` from the skin as dressing places it. A binding is
/// named as the pattern's own measurements name it (FreeSewing's "chest" when the pattern uses
/// FreeSewing names), else by our name. Girths the body lacks, or that cut no piece, and pieces
/// without a body region (bindings, collars, ...) are left out with a note. Throws InvalidInput
/// when no girth cuts the pattern.
inline BindingInference infer_girth_bindings(const measurement::Body& body,
                                             const measurement::LandmarkSet& landmarks,
                                             const measurement::MeasurementSet& measurements,
                                             pattern::Pattern base,
                                             double gap_mm = PlacementOptions{}.gap_mm) {
    BindingInference out;
    std::vector<std::optional<Region>> placed;
    std::vector<Region> regions;  // of the placed pieces; unplaced ones: torso_front, unused
    std::vector<std::vector<pattern::Point2>> outline_points;
    for (const pattern::Piece& p : base.pieces) {
        std::string why;
        placed.push_back(piece_region(p, why));
        if (!placed.back()) {
            out.notes.push_back("piece " + p.name + ": in no girth (no body region: " + why + ")");
        }
        regions.push_back(placed.back().value_or(Region::torso_front));
        outline_points.push_back(placed.back() ? pattern::sample(p.outline, 0.25).points
                                               : std::vector<pattern::Point2>{});
    }
    // The edges a girth may cross: sewn to a piece of the same kind (trunk to trunk, sleeve to
    // sleeve), or a fold. Crossing any other edge (an armhole, a hem) means the garment is open
    // at that level.
    using internal::sleeve_region;
    using internal::trunk_region;
    std::set<std::pair<std::string, std::size_t>> closed_edges;
    for (std::size_t i = 0; i < base.pieces.size(); ++i) {
        const pattern::Piece& p = base.pieces[i];
        if (placed[i] && p.fold && p.fold->edge) {
            closed_edges.insert({p.name, *p.fold->edge});
        }
    }
    const auto region_of = [&](const std::string& name) -> std::optional<Region> {
        for (std::size_t i = 0; i < base.pieces.size(); ++i) {
            if (base.pieces[i].name == name) {
                return placed[i];
            }
        }
        return std::nullopt;
    };
    for (const pattern::Seam& seam : base.seams) {
        const auto ra = region_of(seam.a.piece), rb = region_of(seam.b.piece);
        if (!ra || !rb ||
            !((trunk_region(*ra) && trunk_region(*rb)) ||
              (sleeve_region(*ra) && sleeve_region(*rb)))) {
            continue;
        }
        for (const pattern::EdgeRange* r : {&seam.a, &seam.b}) {
            const pattern::Piece* p = pattern::find_piece(base, r->piece);
            const std::size_t n = p->outline.edges.size();
            for (std::size_t k = 0; k < r->count && n > 0; ++k) {
                closed_edges.insert({r->piece, (r->first_edge + k) % n});
            }
        }
    }
    const BodyShape shape = body_shape(body.points(), body.triangles(), body.height(), landmarks);
    const LayoutHeights heights = layout_heights(base, regions, outline_points, shape, gap_mm);
    // The sleeves of each arm: their layout's distance down the arm at the top of the cap.
    std::optional<Region> sleeve_side;  // the arm whose sleeves are cut (the body's left first)
    double cap_top[2] = {1e300, 1e300};
    for (std::size_t i = 0; i < base.pieces.size(); ++i) {
        if (!placed[i] || !sleeve_region(*placed[i])) {
            continue;
        }
        pattern::PieceMesh samples;
        samples.uv = outline_points[i];
        const PieceLayout l = piece_layout(base.pieces[i], samples, *placed[i], heights.top_y,
                                           heights.waist_y, heights.gc_shift);
        const int k = *placed[i] == Region::sleeve_left ? 0 : 1;
        for (const double h : l.h) {
            cap_top[k] = std::min(cap_top[k], h);
        }
        if (!sleeve_side || (*sleeve_side == Region::sleeve_right && k == 0)) {
            sleeve_side = *placed[i];
        }
    }
    std::vector<pattern::MeasurementBinding> bindings;
    for (const std::string& name : inferred_girths()) {
        const bool arm =
            name == "upper_arm_girth" || name == "elbow_girth" || name == "wrist_girth";
        if (arm && !sleeve_side) {
            out.notes.push_back(name + ": not bound (no sleeve)");
            continue;
        }
        // An arm girth without a side is the right arm's, else the left's (the base set's value);
        // its shoulder point is on the same side (+x: the body's left).
        const measurement::Measurement* g = measurements.find(name);
        const std::string side = g && g->plane_point[0] > 0 ? "_left" : "_right";
        const std::optional<Vec3> acromion = landmarks.point("acromion" + side);
        if (!g || !g->closed || (!arm && std::abs(g->plane_normal[1]) < 0.9) ||
            (arm && !acromion)) {
            out.notes.push_back(name + ": not bound (the body has no " +
                                (arm ? name + " or acromion" + side : "horizontal " + name) + ")");
            continue;
        }
        // The level in the layout's terms: a height for the trunk, a distance down the arm from
        // the cap's top for a sleeve.
        const double top = arm ? cap_top[*sleeve_side == Region::sleeve_left ? 0 : 1] : 0;
        const double y =
            arm ? top + std::abs(vec3::dot(vec3::sub(g->plane_point, *acromion), g->plane_normal))
                : g->plane_point[1];
        const std::string at =
            std::to_string(int(std::lround(y - top))) + (arm ? " mm below the cap's top" : " mm");
        const std::string fs = sizes::freesewing_name(name);
        const bool fs_named = !fs.empty() && base.measurements_used.count(fs) > 0;
        pattern::MeasurementBinding b;
        b.measurement = fs_named ? fs : name;
        double garment = 0;
        std::string pieces, open;
        for (std::size_t i = 0; i < base.pieces.size(); ++i) {
            if (!placed[i] || (arm ? *placed[i] != *sleeve_side : !trunk_region(*placed[i]))) {
                continue;
            }
            pattern::Piece& piece = base.pieces[i];
            const auto c = internal::outline_crossings(piece, regions[i], heights, y);
            if (c.size() < 2) {
                continue;
            }
            const auto [lo, hi] = std::minmax_element(
                c.begin(), c.end(), [](const auto& a, const auto& b) { return a.s < b.s; });
            for (const internal::Crossing* x : {&*lo, &*hi}) {
                if (!closed_edges.count({piece.name, x->edge}) && open.empty()) {
                    open = "piece " + piece.name + " edge " + std::to_string(x->edge);
                }
            }
            const std::string pa = "girth:" + name + ":a", pb = "girth:" + name + ":b";
            piece.points[pa] = lo->p;
            piece.points[pb] = hi->p;
            pattern::BoundFeature f;
            f.piece = piece.name;
            f.from_point = pa;
            f.to_point = pb;
            f.count = internal::girth_count(piece, arm);
            garment += f.count * std::hypot(hi->p.x - lo->p.x, hi->p.y - lo->p.y);
            pieces += (pieces.empty() ? "" : ", ") + piece.name +
                      (f.count != 1 ? " ×" + std::to_string(int(f.count)) : "");
            b.features.push_back(std::move(f));
        }
        if (b.features.empty()) {
            out.notes.push_back(name + ": not bound (no " +
                                (arm ? "sleeve reaches " : "torso or skirt piece reaches ") + at +
                                ")");
            continue;
        }
        if (!open.empty()) {
            // The level cuts an opening (an armhole, a hem, a neckline): the garment does not go
            // round the body there, and a span to that edge is no part of a girth.
            out.notes.push_back(name + ": not bound (at " + at + " it crosses " + open +
                                ", which is sewn to no " + (arm ? "sleeve" : "torso") +
                                " piece: the garment is open there)");
            for (pattern::BoundFeature& f : b.features) {
                pattern::Piece* piece = pattern::find_piece(base, f.piece);
                piece->points.erase(f.from_point);
                piece->points.erase(f.to_point);
            }
            continue;
        }
        b.ease_mm = garment - g->value;
        out.notes.push_back(b.measurement + ": " + pieces + "; garment " +
                            std::to_string(int(std::lround(garment))) + " mm, body " +
                            std::to_string(int(std::lround(g->value))) + " mm, ease " +
                            std::to_string(int(std::lround(b.ease_mm))) + " mm, at " + at);
        bindings.push_back(std::move(b));
    }
    if (bindings.empty()) {
        throw InvalidInput("pattern '" + base.name +
                           "': no girth of the body goes round its torso, skirt or sleeve "
                           "pieces, so no binding was found: give the bindings (--bindings)");
    }
    base.bindings = std::move(bindings);
    out.pattern = std::move(base);
    return out;
}

}  // namespace tapeline::garment
