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
// was made for (its measurements are the grading's base set). A pattern that declares the
// measurements it was drafted for (FreeSewing's `measurements`, in `measurements_used`) binds
// only those, and its ease is taken against the declared value; its levels are where its
// declared lengths put them below the layout's top (the high point of the shoulder): the waist
// at the back length, the high hip and the hip the waist-to-hip lengths below it, other trunk
// levels scaled with the waist's depth, arm levels with the arm length. The body then only tells
// how the levels lie in between. A level within kHemReach below a sleeve's end or the trunk's
// hem (a sleeve drafted to the wrist, a block drafted to the hips) is taken just above it.
//
// Vertical lengths bind one per piece (each piece realises the length on its own): the back
// length from the top of a back piece at its centre line to the waist level, the waist to the
// high hip and to the hip levels at the centre line, the waist level up the side seam to its top
// (the bottom of the armhole), and down a sleeve that reaches the wrist from its cap's top to
// its end. Points `length:<measurement>:<a|b>` mark their ends.
//
// Arm girths (upper arm, elbow, wrist) cut the sleeves of one arm the same way, at the distance
// down the sleeve from the top of its cap at which the body's girth plane lies from the shoulder
// point (acromion) along the arm: the cap's top is sewn to the end of the shoulder seam, which
// sits on the shoulder point. A sleeve goes round one arm: a piece counts once (twice when cut on
// the fold), whatever its cut count (its copies dress the other arm).
//
// Trouser legs hang from the waist as dressing lays them (the top of the legs at the body's waist,
// a gap above it): the waist binds the edges the pattern labels as its waist (FreeSewing's
// trousers on import, GarmentCode's `lower_interface`); the high hip and the hip cut every leg
// piece above its crotch (its `fork` point, else the lowest point of its seams to the other leg,
// else the body's crotch), a piece sewn to its own mirror image (a one-leg draft) counting twice;
// the thigh and the knee cut the pieces of one leg below the crotch, once each; their levels are
// the declared waist-to-hip and waist-to-knee lengths below the top of the legs, else the body's.
// The waist to the knee (and, for a draft that declares it, the waist to the floor, to the hem)
// runs down each piece of that leg through the middle of its knee span, when the legs start at the
// waist (not sewn below a bodice that binds it); the cross seam follows the centre seams of that
// leg's front and back.
//
// Two girths are the garment's at the underarm, as garments are specified: the upper arm is the
// sleeve's width at its underarm points (the top of its underarm seam, where the cap begins), and
// a chest level above the bottom of the armhole (the top of the side seams), or less than
// kChestBelowArmhole below it, is taken kChestBelowArmhole below it. The neck binds the
// neckline's edges (from the upper end of each torso piece's shoulder seam to the centre line's
// fold or seam) when front and back hold one and it is at most kNecklineAtNeck times the neck;
// the back shoulder width binds, on each back piece, the span from the centre line to the
// shoulder point level with it, counted twice.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/garment/placement.h>
#include <tapeline/garment/waistband.h>
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

/// The smallest garment girth, as a fraction of the body's, that counts as going round the body.
inline constexpr double kLeastGirthRatio = 0.75;

/// How far (mm) below a sleeve's end (the trunk's hem) a level may lie and still be taken just
/// above it: a sleeve drafted to the wrist ends on the wrist's level, a block drafted to the hips
/// on the hip's.
inline constexpr double kHemReach = 10;

/// How far (mm) below the bottom of the armhole a garment's chest is taken when the body's chest
/// level lies higher: garment specifications measure the chest an inch below the armhole, where
/// the side seams run straight.
inline constexpr double kChestBelowArmhole = 25;

/// The largest neckline, as a multiple of the neck's girth, that is bound to the neck: a wider
/// one (a scoop, a boat neck) is a style line the neck does not set.
inline constexpr double kNecklineAtNeck = 1.25;

/// How far (mm) above the back neckline's end on the centre line the centre point level with
/// the shoulder point may lie, in the neck: grading holds a piece's named points up to this far
/// outside it (grading/internal/model.h, near_piece_mm).
inline constexpr double kNeckReach = 25;

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
    double h = 0;
    std::size_t edge = 0;  ///< the outline edge crossed
};

/// The crossings of the outline with the layout's level h = `y`, or (`vertical`) with its line
/// s = `y` across the piece.
inline std::vector<Crossing> outline_crossings(const pattern::Piece& piece, Region region,
                                               const LayoutHeights& heights, double y,
                                               bool vertical = false) {
    pattern::PieceMesh samples;
    const pattern::OutlinePolyline line = pattern::sample(piece.outline, 0.25);
    samples.uv = line.points;
    const PieceLayout l =
        piece_layout(piece, samples, region, heights.top_y, heights.waist_y, heights.gc_shift);
    std::vector<Crossing> out;
    const std::size_t n = samples.uv.size();
    const std::vector<double>& f = vertical ? l.s : l.h;
    for (std::size_t i = 0; i + 1 < n; ++i) {
        const double a = f[i] - y, b = f[i + 1] - y;
        if ((a < 0) == (b < 0) || a == b) {
            continue;
        }
        const double t = a / (a - b);
        const pattern::Point2 p{samples.uv[i].x + t * (samples.uv[i + 1].x - samples.uv[i].x),
                                samples.uv[i].y + t * (samples.uv[i + 1].y - samples.uv[i].y)};
        out.push_back({p, l.s[i] + t * (l.s[i + 1] - l.s[i]), l.h[i] + t * (l.h[i + 1] - l.h[i]),
                       line.edge_of_point[i + 1]});
    }
    return out;
}

/// The outermost crossings across the piece (least and greatest `s`) of the outline with the
/// layout's level h = `y`: the span a girth or a length takes at that level. nullopt when the
/// level crosses the outline fewer than twice.
inline std::optional<std::pair<Crossing, Crossing>> outermost_crossings(
    const pattern::Piece& piece, Region region, const LayoutHeights& heights, double y) {
    const auto c = outline_crossings(piece, region, heights, y);
    if (c.size() < 2) {
        return std::nullopt;
    }
    const auto [lo, hi] = std::minmax_element(
        c.begin(), c.end(), [](const Crossing& a, const Crossing& b) { return a.s < b.s; });
    return std::make_pair(*lo, *hi);
}

/// The layout height of point `p` of `piece` (a drafted piece's layout is relative to its
/// outline's extent: the point is laid out with the outline's samples, `outline` when given,
/// else sampled here every 0.25 mm).
inline double layout_height(const pattern::Piece& piece, Region region,
                            const LayoutHeights& heights, const pattern::Point2& p,
                            const std::vector<pattern::Point2>* outline = nullptr) {
    pattern::PieceMesh samples;
    samples.uv = outline ? *outline : pattern::sample(piece.outline, 0.25).points;
    samples.uv.push_back(p);
    return piece_layout(piece, samples, region, heights.top_y, heights.waist_y, heights.gc_shift)
        .h.back();
}

/// The upper end, in the layout, of the seam side among `ranges` of `piece` that holds outline
/// edge `edge` (the highest on a trunk piece, the nearest the shoulder on a sleeve, whose layout
/// height is the distance down the arm); nullopt when no range holds it.
inline std::optional<pattern::Point2> seam_top(const pattern::Piece& piece, Region region,
                                               const LayoutHeights& heights, std::size_t edge,
                                               const std::vector<pattern::EdgeRange>& ranges) {
    const std::size_t n = piece.outline.edges.size();
    for (const pattern::EdgeRange& r : ranges) {
        bool holds = false;
        for (std::size_t k = 0; k < r.count && n > 0; ++k) {
            holds = holds || (r.first_edge + k) % n == edge;
        }
        if (r.piece != piece.name || !holds) {
            continue;
        }
        pattern::PieceMesh ends;
        ends.uv = {pattern::start_point(piece.outline.edges[r.first_edge % n]),
                   pattern::end_point(piece.outline.edges[(r.first_edge + r.count - 1) % n])};
        const PieceLayout l =
            piece_layout(piece, ends, region, heights.top_y, heights.waist_y, heights.gc_shift);
        const bool down = is_sleeve(region);
        return ends.uv[(l.h[0] >= l.h[1]) != down ? 0 : 1];
    }
    return std::nullopt;
}

/// The layout height of the upper end nearest level `y` among the seams of `ranges` that the
/// level crosses on `piece`: above a trunk piece's waist, the top of its side seam (the bottom
/// of the armhole; a centre seam ends higher, at the neck); down a sleeve, the top of its
/// underarm seam (the underarm point, where the cap begins; a seam along the top of the arm ends
/// higher, at the cap's top). nullopt when the level crosses no such seam.
inline std::optional<double> nearest_seam_top(const pattern::Piece& piece, Region region,
                                              const LayoutHeights& heights, double y,
                                              const std::vector<pattern::EdgeRange>& ranges) {
    const bool down = is_sleeve(region);
    std::optional<double> nearest;
    for (const Crossing& x : outline_crossings(piece, region, heights, y)) {
        const std::optional<pattern::Point2> top = seam_top(piece, region, heights, x.edge, ranges);
        if (!top) {
            continue;
        }
        const double h = layout_height(piece, region, heights, *top);
        if ((down ? h < y : h > y) && (!nearest || (down ? h > *nearest : h < *nearest))) {
            nearest = h;
        }
    }
    return nearest;
}

/// How often a piece goes round the body (a trunk piece) or the arm (a sleeve).
inline double girth_count(const pattern::Piece& piece, bool sleeve) {
    return (sleeve ? 1.0 : double(std::max(piece.cut_count, 1))) * (piece.fold ? 2.0 : 1.0);
}

inline bool trunk_region(Region r) {
    return r == Region::torso_front || r == Region::torso_back || r == Region::skirt_front ||
           r == Region::skirt_back;
}

/// The bindings of trouser legs (garment/README.md, "Bindings found on the body"): the waist on
/// the edges labelled as the waist, the high hip and hip across every leg piece above its crotch,
/// the thigh and knee round one leg below it, the waist to the knee (and, for a draft that
/// declares it, to the floor) down each leg piece of that leg, the cross seam along the centre
/// seams. Girths and lengths already bound (on a bodice or skirt) are left alone.
inline void bind_trouser_legs(pattern::Pattern& base,
                              const std::vector<std::optional<Region>>& placed,
                              const std::vector<Region>& regions, const LayoutHeights& heights,
                              const std::vector<PieceLayout>& outline_layout,
                              const measurement::MeasurementSet& measurements,
                              const measurement::LandmarkSet& landmarks,
                              std::vector<pattern::MeasurementBinding>& bindings,
                              std::vector<std::string>& notes) {
    std::vector<std::size_t> legs;
    for (std::size_t i = 0; i < base.pieces.size(); ++i) {
        if (placed[i] && is_leg(*placed[i])) {
            legs.push_back(i);
        }
    }
    if (legs.empty()) {
        return;
    }
    const auto mm = [](double v) { return std::to_string(int(std::lround(v))); };
    // Legs drafted once and sewn to their mirror image at the crotch (pattern::
    // freesewing_mirror_seam_rules): those centre edges are sewn, and the piece goes round the
    // body twice above the crotch (once on each leg).
    std::set<std::string> paired;
    std::set<std::pair<std::string, std::size_t>> closed, centre;
    for (const pattern::NamedSeamRule& rule : pattern::freesewing_mirror_seam_rules()) {
        if (base.name.rfind(rule.design, 0) != 0) {
            continue;
        }
        for (const pattern::NamedChain& c : rule.a) {
            const pattern::Piece* piece = pattern::find_design_piece(base, c.piece);
            for (const std::size_t e : pattern::named_chain_edges(piece, c)) {
                closed.insert({piece->name, e});
                centre.insert({piece->name, e});
                paired.insert(piece->name);
            }
        }
    }
    const auto leg_of = [&](const std::string& name) -> std::optional<Region> {
        for (const std::size_t i : legs) {
            if (base.pieces[i].name == name) {
                return placed[i];
            }
        }
        return std::nullopt;
    };
    for (const std::size_t i : legs) {
        const pattern::Piece& piece = base.pieces[i];
        if (piece.fold && piece.fold->edge) {
            closed.insert({piece.name, *piece.fold->edge});
        }
    }
    for (const pattern::Seam& seam : base.seams) {
        const auto ra = leg_of(seam.a.piece), rb = leg_of(seam.b.piece);
        if (!ra || !rb) {
            continue;
        }
        // A seam joining the two legs (left to right) is a centre seam.
        const bool left_a = *ra == Region::leg_left_front || *ra == Region::leg_left_back;
        const bool left_b = *rb == Region::leg_left_front || *rb == Region::leg_left_back;
        for (const pattern::EdgeRange* r : {&seam.a, &seam.b}) {
            const std::size_t n = pattern::find_piece(base, r->piece)->outline.edges.size();
            for (std::size_t k = 0; k < r->count && n > 0; ++k) {
                closed.insert({r->piece, (r->first_edge + k) % n});
                if (left_a != left_b) {
                    centre.insert({r->piece, (r->first_edge + k) % n});
                }
            }
        }
    }
    // The top of the legs (where the waist is placed) and each leg's crotch: its fork point's
    // height, else the lowest point of its centre seam (sewn to the other leg), else the body's
    // crotch.
    double top = -1e300;
    for (const std::size_t i : legs) {
        for (const double h : outline_layout[i].h) {
            top = std::max(top, h);
        }
    }
    const std::optional<Vec3> body_crotch = landmarks.point("crotch");
    std::vector<std::optional<double>> crotch(base.pieces.size());
    for (const std::size_t i : legs) {
        const pattern::Piece& piece = base.pieces[i];
        const auto fork = piece.points.find("fork");
        if (fork != piece.points.end()) {
            crotch[i] = layout_height(piece, regions[i], heights, fork->second);
            continue;
        }
        for (std::size_t e = 0; e < piece.outline.edges.size(); ++e) {
            if (centre.count({piece.name, e})) {
                for (const pattern::Point2& q :
                     {pattern::start_point(piece.outline.edges[e].curve),
                      pattern::end_point(piece.outline.edges[e].curve)}) {
                    const double h = layout_height(piece, regions[i], heights, q);
                    crotch[i] = crotch[i] ? std::min(*crotch[i], h) : h;
                }
            }
        }
        if (!crotch[i] && body_crotch) {
            crotch[i] = (*body_crotch)[1];
        }
    }
    // One leg for the leg's girths and lengths: the body's left when the pattern has it.
    bool has_left = false;
    for (const std::size_t i : legs) {
        has_left =
            has_left || *placed[i] == Region::leg_left_front || *placed[i] == Region::leg_left_back;
    }
    const auto on_leg = [&](std::size_t i) {
        const bool left =
            *placed[i] == Region::leg_left_front || *placed[i] == Region::leg_left_back;
        return left == has_left;
    };
    const auto bound = [&](const std::string& name) {
        for (const pattern::MeasurementBinding& b : bindings) {
            if (b.measurement == name) {
                return true;
            }
        }
        return false;
    };
    const auto pattern_name = [&base](const std::string& ours) {
        const std::string fs = sizes::freesewing_name(ours);
        return !fs.empty() && base.measurements_used.count(fs) > 0 ? fs : ours;
    };
    // The value a binding's ease is taken against: the draft's declared one, else the body's;
    // nullopt (with a note) when the draft declares others only or the body has none.
    const auto base_value = [&](const std::string& ours,
                                const std::string& named) -> std::optional<double> {
        if (!base.measurements_used.empty() && !base.measurements_used.count(named)) {
            notes.push_back(ours + " (trouser legs): not bound (pattern '" + base.name +
                            "' declares the measurements it was drafted for, not this one)");
            return std::nullopt;
        }
        const auto declared = base.measurements_used.find(named);
        if (declared != base.measurements_used.end()) {
            return declared->second;
        }
        const measurement::Measurement* m = measurements.find(ours);
        if (!m || m->value <= 0) {
            notes.push_back(ours + " (trouser legs): not bound (the body has no " + ours + ")");
            return std::nullopt;
        }
        return m->value;
    };
    // A declared length from the waist (the legs' top), else the body's distance from its waist.
    const auto level = [&](const std::string& girth,
                           const std::string& length) -> std::optional<double> {
        const std::string named = sizes::freesewing_name(length);
        for (const std::string& k : {length, named}) {
            const auto it = base.measurements_used.find(k);
            if (!k.empty() && it != base.measurements_used.end() && it->second > 0) {
                return top - it->second;
            }
        }
        const measurement::Measurement* g = measurements.find(girth);
        if (!g || !g->closed || std::abs(g->plane_normal[1]) < 0.9) {
            return std::nullopt;
        }
        return g->plane_point[1];
    };
    // Removes the named points a binding left out added to its pieces.
    const auto drop_points = [&base](const pattern::MeasurementBinding& b) {
        for (const pattern::BoundFeature& f : b.features) {
            pattern::Piece* piece = pattern::find_piece(base, f.piece);
            piece->points.erase(f.from_point);
            piece->points.erase(f.to_point);
        }
    };
    const auto finish = [&](pattern::MeasurementBinding& b, const std::string& ours, double value,
                            double garment, const std::string& pieces, const std::string& at) {
        const measurement::Measurement* body = measurements.find(ours);
        if (body && body->value > 0 && garment < kLeastGirthRatio * body->value) {
            notes.push_back(ours + " (trouser legs): not bound (" + pieces + " come to " +
                            mm(garment) + " mm round a body of " + mm(body->value) + " mm" + at +
                            ")");
            drop_points(b);
            return;
        }
        b.ease_mm = garment - value;
        notes.push_back(b.measurement + ": " + pieces + "; garment " + mm(garment) + " mm, " +
                        "base " + mm(value) + " mm, ease " + mm(b.ease_mm) + " mm" + at);
        bindings.push_back(std::move(b));
    };
    const auto times = [](double c) { return c != 1 ? " ×" + std::to_string(int(c)) : ""; };
    // Legs sewn below a bodice that holds the waist (a jumpsuit) do not start at the waist: no
    // length is measured from their top.
    const bool legs_at_waist = !bound(pattern_name("waist_girth"));
    // The waist: the edges labelled as the waist (FreeSewing's trousers on import, GarmentCode's
    // lower_interface), as a tape round the top of the trousers.
    if (!bound(pattern_name("waist_girth"))) {
        const std::string ours = "waist_girth", named = pattern_name(ours);
        pattern::MeasurementBinding b{named, {}, 0};
        double garment = 0;
        std::string pieces;
        for (const std::size_t i : legs) {
            const pattern::Piece& piece = base.pieces[i];
            std::vector<std::size_t> edges;
            double len = 0;
            for (std::size_t e = 0; e < piece.outline.edges.size(); ++e) {
                if (is_waistband_label(piece.outline.edges[e].label)) {
                    edges.push_back(e);
                    len += pattern::length(piece.outline.edges[e]);
                }
            }
            if (edges.empty()) {
                continue;
            }
            const double count = girth_count(piece, false) * (paired.count(piece.name) ? 2 : 1);
            garment += count * len;
            pieces += (pieces.empty() ? "" : ", ") + piece.name + times(count);
            b.features.push_back({piece.name, edges, {}, {}, count});
        }
        if (b.features.empty()) {
            notes.push_back(ours +
                            " (trouser legs): not bound (no leg piece has an edge labelled "
                            "as the waist)");
        } else if (const std::optional<double> value = base_value(ours, named)) {
            finish(b, ours, *value, garment, pieces, ", along the edges labelled as the waist");
        }
    }
    // Girths across the legs: round the body above the crotch (every leg piece), round one leg
    // below it.
    struct LegGirth {
        const char* name;
        const char* length;  ///< the declared length from the waist that gives its level
        bool round_one_leg;
    };
    static const LegGirth leg_girths[] = {{"high_hip_girth", "waist_to_high_hip", false},
                                          {"hip_girth", "waist_to_hips", false},
                                          {"thigh_girth", "", true},
                                          {"knee_girth", "waist_to_knee", true}};
    std::optional<double> knee_level;
    for (const LegGirth& lg : leg_girths) {
        const std::string ours = lg.name, named = pattern_name(ours);
        if (bound(named)) {
            continue;
        }
        const std::optional<double> y = level(ours, lg.length);
        if (!y) {
            notes.push_back(ours + " (trouser legs): not bound (the body has no horizontal " +
                            ours + ")");
            continue;
        }
        const std::string at = ", " + mm(top - *y) + " mm below the top of the legs";
        pattern::MeasurementBinding b{named, {}, 0};
        double garment = 0;
        std::string pieces, open;
        for (const std::size_t i : legs) {
            if (!crotch[i] ||
                (lg.round_one_leg ? *y >= *crotch[i] || !on_leg(i) : *y <= *crotch[i])) {
                continue;
            }
            pattern::Piece& piece = base.pieces[i];
            const auto span = outermost_crossings(piece, regions[i], heights, *y);
            if (!span) {
                continue;
            }
            const auto& [lo, hi] = *span;
            for (const Crossing* x : {&lo, &hi}) {
                if (!closed.count({piece.name, x->edge}) && open.empty()) {
                    open = piece.name + " edge " + std::to_string(x->edge);
                }
            }
            const std::string pa = "girth:" + ours + ":a", pb = "girth:" + ours + ":b";
            piece.points[pa] = lo.p;
            piece.points[pb] = hi.p;
            const double count =
                lg.round_one_leg ? girth_count(piece, true)
                                 : girth_count(piece, false) * (paired.count(piece.name) ? 2 : 1);
            garment += count * std::hypot(hi.p.x - lo.p.x, hi.p.y - lo.p.y);
            pieces += (pieces.empty() ? "" : ", ") + piece.name + times(count);
            b.features.push_back({piece.name, {}, pa, pb, count});
        }
        if (b.features.empty()) {
            notes.push_back(ours + " (trouser legs): not bound (no leg piece reaches it " +
                            (lg.round_one_leg ? "below" : "above") + " the crotch" + at + ")");
            continue;
        }
        if (!open.empty()) {
            notes.push_back(ours + " (trouser legs): not bound (" + at.substr(2) + " it crosses " +
                            open + ", which is sewn to no leg piece)");
            drop_points(b);
            continue;
        }
        const std::optional<double> value = base_value(ours, named);
        if (!value) {
            drop_points(b);
            continue;
        }
        if (ours == "knee_girth") {
            knee_level = y;
        }
        finish(b, ours, *value, garment, pieces, at);
    }
    // Lengths down each piece of one leg, along the vertical line through the middle of the knee
    // span: from the top to the knee's level, and for a draft that declares its waist-to-floor
    // length, to the hem.
    for (const char* length : {"waist_to_knee", "outseam"}) {
        const std::string ours = length, named = pattern_name(ours);
        const bool floor = ours == "outseam";
        if (bound(named) || (floor && !base.measurements_used.count(named))) {
            continue;
        }
        if (!legs_at_waist) {
            notes.push_back(ours +
                            " (trouser legs): not bound (the legs are sewn below a bodice "
                            "that holds the waist: their top is not the waist)");
            continue;
        }
        const std::optional<double> knee =
            knee_level ? knee_level : level("knee_girth", "waist_to_knee");
        if (!knee) {
            notes.push_back(ours + " (trouser legs): not bound (the body has no knee level)");
            continue;
        }
        const std::optional<double> value = base_value(ours, named);
        if (!value) {
            continue;
        }
        pattern::MeasurementBinding b{named, {}, 0};
        std::string pieces;
        for (const std::size_t i : legs) {
            if (!on_leg(i)) {
                continue;
            }
            pattern::Piece& piece = base.pieces[i];
            const auto span = outermost_crossings(piece, regions[i], heights, *knee);
            if (!span) {
                continue;
            }
            const auto& [lo, hi] = *span;
            auto v = outline_crossings(piece, regions[i], heights, 0.5 * (lo.s + hi.s), true);
            if (v.size() < 2) {
                continue;
            }
            std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.h < b.h; });
            const Crossing &bottom = v.front(), &upper = v.back();
            const double t = (*knee - bottom.h) / (upper.h - bottom.h);
            const pattern::Point2 at_knee{bottom.p.x + t * (upper.p.x - bottom.p.x),
                                          bottom.p.y + t * (upper.p.y - bottom.p.y)};
            const pattern::Point2 end = floor ? bottom.p : at_knee;
            const std::string pa = "length:" + ours + ":a", pb = "length:" + ours + ":b";
            piece.points[pa] = upper.p;
            piece.points[pb] = end;
            const double len = std::hypot(end.x - upper.p.x, end.y - upper.p.y);
            pattern::MeasurementBinding one{named, {{piece.name, {}, pa, pb, 1}}, len - *value};
            bindings.push_back(std::move(one));
            pieces += (pieces.empty() ? "" : ", ") + piece.name + " " + mm(len) + " mm";
        }
        notes.push_back(pieces.empty() ? ours +
                                             " (trouser legs): not bound (no leg piece holds "
                                             "the knee's level)"
                                       : named + ": " + pieces + " (base " + mm(*value) +
                                             " mm), one per piece");
    }
    // The cross seam: the centre seams of one leg's front and back, from the front waist
    // through the crotch to the back waist.
    {
        const std::string ours = "cross_seam", named = pattern_name(ours);
        pattern::MeasurementBinding b{named, {}, 0};
        double garment = 0;
        std::string pieces;
        for (const std::size_t i : legs) {
            if (!on_leg(i) || bound(named)) {
                continue;
            }
            const pattern::Piece& piece = base.pieces[i];
            std::vector<std::size_t> edges;
            double len = 0;
            for (std::size_t e = 0; e < piece.outline.edges.size(); ++e) {
                if (centre.count({piece.name, e})) {
                    edges.push_back(e);
                    len += pattern::length(piece.outline.edges[e]);
                }
            }
            if (!edges.empty()) {
                garment += len;
                pieces += (pieces.empty() ? "" : ", ") + piece.name;
                b.features.push_back({piece.name, edges, {}, {}, 1});
            }
        }
        if (!b.features.empty()) {
            if (const std::optional<double> value = base_value(ours, named)) {
                b.ease_mm = garment - *value;
                notes.push_back(named + ": " + pieces + " along the centre seams; garment " +
                                mm(garment) + " mm, base " + mm(*value) + " mm, ease " +
                                mm(b.ease_mm) + " mm");
                bindings.push_back(std::move(b));
            }
        } else if (!bound(named)) {
            notes.push_back(ours + " (trouser legs): not bound (no centre seam joins the legs)");
        }
    }
}

}  // namespace internal

/// Infers the girth and length bindings of `base` laid out on `body` (canonical frame; its
/// landmarks and measurements from measure_body), `gap_mm` from the skin as dressing places it.
/// A binding is named as the pattern's own measurements name it (FreeSewing's "chest" when the
/// pattern uses FreeSewing names), else by our name. Girths and lengths the body lacks, that
/// cut no piece, or that the pattern does not declare, girths whose pieces come to less than
/// kLeastGirthRatio of the body's, and pieces without a body region (bindings, collars, ...) are
/// left out with a note; trouser legs bind as internal::bind_trouser_legs says. Throws
/// InvalidInput when nothing was bound.
inline BindingInference infer_girth_bindings(const measurement::Body& body,
                                             const measurement::LandmarkSet& landmarks,
                                             const measurement::MeasurementSet& measurements,
                                             pattern::Pattern base,
                                             double gap_mm = PlacementOptions{}.gap_mm) {
    BindingInference out;
    std::vector<std::optional<Region>> placed;
    std::string unplaced;         // the pieces without a body region, with the reason
    std::vector<Region> regions;  // of the placed pieces; unplaced ones: torso_front, unused
    std::vector<std::vector<pattern::Point2>> outline_points;
    for (const pattern::Piece& p : base.pieces) {
        std::string why;
        placed.push_back(piece_region(p, why));
        if (!placed.back()) {
            out.notes.push_back("piece " + p.name + ": in no girth (no body region: " + why + ")");
            unplaced += (unplaced.empty() ? "" : ", ") + p.name + " (" + why + ")";
        }
        regions.push_back(placed.back().value_or(Region::torso_front));
        outline_points.push_back(placed.back() ? pattern::sample(p.outline, 0.25).points
                                               : std::vector<pattern::Point2>{});
    }
    // The edges a girth may cross: sewn to a piece of the same kind (trunk to trunk, sleeve to
    // sleeve), or a fold. Crossing any other edge (an armhole, a hem) means the garment is open
    // at that level.
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
            !((trunk_region(*ra) && trunk_region(*rb)) || (is_sleeve(*ra) && is_sleeve(*rb)))) {
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
    std::vector<pattern::EdgeRange> side_seams;    // the sides of seams joining trunk pieces
    std::vector<pattern::EdgeRange> sleeve_seams;  // and of seams joining sleeve pieces
    for (const pattern::Seam& seam : base.seams) {
        const auto ra = region_of(seam.a.piece), rb = region_of(seam.b.piece);
        if (ra && rb && trunk_region(*ra) && trunk_region(*rb)) {
            side_seams.push_back(seam.a);
            side_seams.push_back(seam.b);
        }
        if (ra && rb && is_sleeve(*ra) && is_sleeve(*rb)) {
            sleeve_seams.push_back(seam.a);
            sleeve_seams.push_back(seam.b);
        }
    }
    const BodyShape shape = body_shape(body.points(), body.triangles(), body.height(), landmarks);
    const LayoutHeights heights = layout_heights(base, regions, outline_points, shape, gap_mm);
    // The layout of each placed piece's outline samples.
    std::vector<PieceLayout> outline_layout(base.pieces.size());
    for (std::size_t i = 0; i < base.pieces.size(); ++i) {
        if (placed[i]) {
            pattern::PieceMesh samples;
            samples.uv = outline_points[i];
            outline_layout[i] = piece_layout(base.pieces[i], samples, *placed[i], heights.top_y,
                                             heights.waist_y, heights.gc_shift);
        }
    }
    // The sleeves of each arm: their layout's distance down the arm at the top of the cap.
    std::optional<Region> sleeve_side;  // the arm whose sleeves are cut (the body's left first)
    double cap_top[2] = {1e300, 1e300}, sleeve_end[2] = {-1e300, -1e300};
    for (std::size_t i = 0; i < base.pieces.size(); ++i) {
        if (!placed[i] || !is_sleeve(*placed[i])) {
            continue;
        }
        const PieceLayout& l = outline_layout[i];
        const int k = *placed[i] == Region::sleeve_left ? 0 : 1;
        for (const double h : l.h) {
            cap_top[k] = std::min(cap_top[k], h);
            sleeve_end[k] = std::max(sleeve_end[k], h);
        }
        if (!sleeve_side || (*sleeve_side == Region::sleeve_right && k == 0)) {
            sleeve_side = *placed[i];
        }
    }
    // A draft that declares its lengths has its levels where they put them, not where the body
    // has them (the body may be of another size): below the high point of the shoulder (the
    // layout's top) by the declared back length to the waist, and below the waist by the
    // declared waist-to-hip lengths; other trunk levels scale with the waist's depth, arm levels
    // with the declared arm length.
    const auto declared_length = [&base](const std::string& ours) -> std::optional<double> {
        for (const std::string& k : {ours, sizes::freesewing_name(ours)}) {
            const auto it = base.measurements_used.find(k);
            if (!k.empty() && it != base.measurements_used.end() && it->second > 0) {
                return it->second;
            }
        }
        return std::nullopt;
    };
    const measurement::Measurement* body_waist = measurements.find("waist_girth");
    const std::optional<double> back_length = declared_length("hps_to_waist_back");
    const double waist_depth = body_waist ? shape.neck_y - body_waist->plane_point[1] : 0;
    const bool declared_trunk = back_length && waist_depth > 0;
    // The lowest point of the trunk pieces: a draft whose hem is its hip line (a block drafted
    // to the hips) ends on the level; that level is taken just above the hem.
    double trunk_bottom = 1e300;
    for (std::size_t i = 0; i < base.pieces.size(); ++i) {
        if (placed[i] && trunk_region(*placed[i])) {
            const PieceLayout& l = outline_layout[i];
            trunk_bottom = std::min(trunk_bottom, *std::min_element(l.h.begin(), l.h.end()));
        }
    }
    const auto trunk_level = [&](const std::string& name, double body_y) {
        if (!declared_trunk) {
            return body_y;
        }
        const double waist_y = heights.top_y - *back_length;
        const std::optional<double> below =
            declared_length(name == "high_hip_girth" ? "waist_to_high_hip"
                            : name == "hip_girth"    ? "waist_to_hips"
                                                     : "");
        const double y = name == "waist_girth" ? waist_y
                         : below
                             ? waist_y - *below
                             : heights.top_y - (shape.neck_y - body_y) * *back_length / waist_depth;
        return y <= trunk_bottom && y >= trunk_bottom - kHemReach ? trunk_bottom + 1 : y;
    };
    // The arm: the wrist's level goes to the declared shoulder-to-wrist length below the cap's
    // top, the other levels in proportion (distances from the shoulder point, as below).
    double arm_scale = 1, wrist_depth = 0;
    if (const measurement::Measurement* wrist = measurements.find("wrist_girth");
        wrist && wrist->closed) {
        const std::optional<Vec3> a = landmarks.point(
            std::string("acromion") + (wrist->plane_point[0] > 0 ? "_left" : "_right"));
        wrist_depth =
            a ? std::abs(vec3::dot(vec3::sub(wrist->plane_point, *a), wrist->plane_normal)) : 0;
    }
    if (const auto d = declared_length("shoulder_to_wrist"); d && wrist_depth > 0) {
        arm_scale = *d / wrist_depth;
    }
    if (declared_trunk || arm_scale != 1) {
        out.notes.push_back(std::string("levels: where the draft's declared lengths put them (") +
                            (declared_trunk ? "back length to the waist" : "") +
                            (declared_trunk && arm_scale != 1 ? ", " : "") +
                            (arm_scale != 1 ? "arm length" : "") + "), not the body's");
    }
    const auto level_of = [&](const std::string& girth) -> std::optional<double> {
        const measurement::Measurement* g = measurements.find(girth);
        if (!g || !g->closed || std::abs(g->plane_normal[1]) < 0.9) {
            return std::nullopt;
        }
        return trunk_level(girth, g->plane_point[1]);
    };
    // Where a garment's chest and a sleeve's biceps are taken: at the underarm. Above the waist
    // the side seams end at the bottom of the armhole; a chest level above it, or less than
    // kChestBelowArmhole below it, is taken kChestBelowArmhole below it. A sleeve's width
    // at its underarm points, where the cap begins (the top of its underarm seam), is its biceps
    // width (the biceps line of a sleeve draft), whatever the level of the body's own upper-arm
    // girth.
    std::optional<double> armhole_bottom;
    if (const std::optional<double> waist = level_of("waist_girth")) {
        for (std::size_t i = 0; i < base.pieces.size(); ++i) {
            if (placed[i] &&
                (*placed[i] == Region::torso_front || *placed[i] == Region::torso_back)) {
                const std::optional<double> top = internal::nearest_seam_top(
                    base.pieces[i], regions[i], heights, *waist, side_seams);
                if (top && (!armhole_bottom || *top < *armhole_bottom)) {
                    armhole_bottom = top;
                }
            }
        }
    }
    std::optional<double> underarm[2];
    for (std::size_t i = 0; i < base.pieces.size(); ++i) {
        if (!placed[i] || !is_sleeve(*placed[i])) {
            continue;
        }
        // The underarm seam crossed low on the sleeve (a curved hem may hide it at the end).
        const int k = *placed[i] == Region::sleeve_left ? 0 : 1;
        std::optional<double> top;
        for (const double f : {0.97, 0.9, 0.75}) {
            top = top ? top
                      : internal::nearest_seam_top(base.pieces[i], regions[i], heights,
                                                   cap_top[k] + f * (sleeve_end[k] - cap_top[k]),
                                                   sleeve_seams);
        }
        // An underarm point within a centimetre of the cap's top is no cap (a sleeve cut on
        // with the body, a seam along the top of the arm).
        if (top && *top > cap_top[k] + 10 && (!underarm[k] || *top > *underarm[k])) {
            underarm[k] = top;
        }
    }
    std::vector<pattern::MeasurementBinding> bindings;
    // Binds `bound_name`, eased against `value`, to the span p0–p1 of `piece` counted `count`
    // times, its ends named `length:<name>:a|b`; appends "piece N mm" to `pieces`.
    const auto bind_span = [&bindings](pattern::Piece& piece, const std::string& name,
                                       const std::string& bound_name, double value,
                                       const pattern::Point2& p0, const pattern::Point2& p1,
                                       double count, std::string& pieces) {
        const std::string pa = "length:" + name + ":a", pb = "length:" + name + ":b";
        piece.points[pa] = p0;
        piece.points[pb] = p1;
        const double len = count * std::hypot(p1.x - p0.x, p1.y - p0.y);
        pattern::MeasurementBinding b;
        b.measurement = bound_name;
        b.features.push_back({piece.name, {}, pa, pb, count});
        b.ease_mm = len - value;
        bindings.push_back(std::move(b));
        pieces += (pieces.empty() ? "" : ", ") + piece.name + " " +
                  std::to_string(int(std::lround(len))) + " mm";
    };
    const auto drop_points = [&base](const pattern::MeasurementBinding& b) {
        for (const pattern::BoundFeature& f : b.features) {
            pattern::Piece* piece = pattern::find_piece(base, f.piece);
            piece->points.erase(f.from_point);
            piece->points.erase(f.to_point);
        }
    };
    // The name the pattern gives a measurement (FreeSewing's, when it declares it so). A pattern
    // that declares the measurements it was drafted for (FreeSewing's `measurements`) is graded
    // on those alone, and its declared value is the base of the ease: `undeclared` notes one it
    // leaves out.
    const auto pattern_name = [&base](const std::string& ours) {
        const std::string fs = sizes::freesewing_name(ours);
        return !fs.empty() && base.measurements_used.count(fs) > 0 ? fs : ours;
    };
    const auto undeclared = [&](const std::string& ours, const std::string& named) {
        if (base.measurements_used.empty() || base.measurements_used.count(named) > 0) {
            return false;
        }
        out.notes.push_back(ours + ": not bound (pattern '" + base.name +
                            "' declares the measurements it was drafted for, not this one)");
        return true;
    };
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
        const int arm_k = sleeve_side && *sleeve_side == Region::sleeve_left ? 0 : 1;
        const double top = arm ? cap_top[arm_k] : 0;
        double y = arm ? top + arm_scale * std::abs(vec3::dot(vec3::sub(g->plane_point, *acromion),
                                                              g->plane_normal))
                       : trunk_level(name, g->plane_point[1]);
        if (arm && y >= sleeve_end[arm_k] && y <= sleeve_end[arm_k] + kHemReach) {
            // A sleeve drafted to the wrist ends on its level: the girth is the cuff's, taken
            // just above the hem.
            y = sleeve_end[arm_k] - 1;
        }
        std::string where;  // why the level is not the body's
        if (name == "bust_girth" && armhole_bottom && y > *armhole_bottom - kChestBelowArmhole) {
            where = " (" + std::to_string(int(kChestBelowArmhole)) +
                    " mm below the armhole; the body's level is " +
                    std::to_string(int(std::lround(y - *armhole_bottom + kChestBelowArmhole))) +
                    " mm higher)";
            y = *armhole_bottom - kChestBelowArmhole;
        } else if (name == "upper_arm_girth" && underarm[arm_k]) {
            where = " (the underarm point; the body's level is " +
                    std::to_string(int(std::lround(y - *underarm[arm_k] - 1))) + " mm lower)";
            y = *underarm[arm_k] + 1;
        }
        const std::string at = std::to_string(int(std::lround(y - top))) +
                               (arm ? " mm below the cap's top" : " mm") + where;
        pattern::MeasurementBinding b;
        b.measurement = pattern_name(name);
        if (undeclared(name, b.measurement)) {
            continue;
        }
        const auto declared = base.measurements_used.find(b.measurement);
        double garment = 0;
        std::string pieces, open;
        for (std::size_t i = 0; i < base.pieces.size(); ++i) {
            if (!placed[i] || (arm ? *placed[i] != *sleeve_side : !trunk_region(*placed[i]))) {
                continue;
            }
            pattern::Piece& piece = base.pieces[i];
            const auto span = internal::outermost_crossings(piece, regions[i], heights, y);
            if (!span) {
                continue;
            }
            const auto& [lo, hi] = *span;
            for (const internal::Crossing* x : {&lo, &hi}) {
                if (!closed_edges.count({piece.name, x->edge}) && open.empty()) {
                    open = "piece " + piece.name + " edge " + std::to_string(x->edge);
                }
            }
            const std::string pa = "girth:" + name + ":a", pb = "girth:" + name + ":b";
            piece.points[pa] = lo.p;
            piece.points[pb] = hi.p;
            pattern::BoundFeature f;
            f.piece = piece.name;
            f.from_point = pa;
            f.to_point = pb;
            f.count = internal::girth_count(piece, arm);
            garment += f.count * std::hypot(hi.p.x - lo.p.x, hi.p.y - lo.p.y);
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
            drop_points(b);
            continue;
        }
        if (garment < kLeastGirthRatio * g->value) {
            // Knit garments are cut up to a fifth smaller than the body; pieces that come to
            // less than that do not go round it (a piece missing from the layout or placed
            // where it does not belong).
            out.notes.push_back(name + ": not bound (at " + at + " the pieces it cuts come to " +
                                std::to_string(int(std::lround(garment))) + " mm round a body of " +
                                std::to_string(int(std::lround(g->value))) +
                                " mm: they do not go round the body there)");
            drop_points(b);
            continue;
        }
        const bool own = declared != base.measurements_used.end();
        b.ease_mm = garment - (own ? declared->second : g->value);
        out.notes.push_back(
            b.measurement + ": " + pieces + "; garment " +
            std::to_string(int(std::lround(garment))) + " mm, body " +
            std::to_string(int(std::lround(g->value))) + " mm, " +
            (own ? "drafted for " + std::to_string(int(std::lround(declared->second))) + " mm, "
                 : std::string()) +
            "ease " + std::to_string(int(std::lround(b.ease_mm))) + " mm, at " + at);
        bindings.push_back(std::move(b));
    }
    // The neckline and the shoulders of each torso piece. Its shoulder seam is the trunk seam
    // whose upper end is highest: that end (vertex `upper`) is the high point of the shoulder,
    // the other (`lower`) the shoulder point. The neckline runs over the open edges from `upper`
    // away from the seam to the first fold or trunk seam (the centre line, edge `centre`), all
    // above the armhole.
    struct Neckline {
        std::size_t upper = 0, lower = 0, centre = 0;
        std::size_t centre_top = 0;      ///< the vertex where the neckline meets the centre line
        std::vector<std::size_t> edges;  ///< in outline order
        double length = 0;
    };
    std::vector<std::optional<Neckline>> necklines(base.pieces.size());
    std::string neckline_missing;  // why a torso piece has none
    for (std::size_t i = 0; i < base.pieces.size() && armhole_bottom; ++i) {
        if (!placed[i] || (*placed[i] != Region::torso_front && *placed[i] != Region::torso_back)) {
            continue;
        }
        const pattern::Piece& piece = base.pieces[i];
        const std::size_t n = piece.outline.edges.size();
        const auto vertex_h = [&](std::size_t v) {
            return internal::layout_height(piece, regions[i], heights,
                                           pattern::start_point(piece.outline.edges[v % n]),
                                           &outline_points[i]);
        };
        Neckline nl;
        bool found = false, seam_before = false;  // the seam's range ends at `upper`
        double upper_h = -1e300;
        for (const pattern::EdgeRange& r : side_seams) {
            if (r.piece != piece.name || n == 0) {
                continue;
            }
            const std::size_t v0 = r.first_edge % n, v1 = (r.first_edge + r.count) % n;
            for (const std::size_t v : {v0, v1}) {
                if (const double h = vertex_h(v); h > upper_h) {
                    upper_h = h;
                    nl.upper = v;
                    nl.lower = v == v0 ? v1 : v0;
                    seam_before = v == v1;
                    found = true;
                }
            }
        }
        // A seam that ends below the armhole (a side seam) is no shoulder seam.
        found = found && vertex_h(nl.lower) > *armhole_bottom;
        bool closed = false;
        for (std::size_t k = 0; found && k < n; ++k) {
            const std::size_t e = seam_before ? (nl.upper + k) % n : (nl.upper + n - 1 - k) % n;
            if (closed_edges.count({piece.name, e})) {
                nl.centre = e;
                nl.centre_top = seam_before ? e : (e + 1) % n;
                closed = true;
                break;
            }
            if (vertex_h(seam_before ? e + 1 : e) < *armhole_bottom) {
                break;
            }
            nl.edges.push_back(e);
            nl.length += pattern::length(piece.outline.edges[e]);
        }
        if (!closed || nl.edges.empty()) {
            neckline_missing = "on piece " + piece.name +
                               (found ? " the open edges from the shoulder seam's upper end reach "
                                        "no fold or seam above the armhole"
                                      : " no seam above the armhole joins it to another "
                                        "torso piece");
            continue;
        }
        if (!seam_before) {
            std::reverse(nl.edges.begin(), nl.edges.end());
        }
        necklines[i] = std::move(nl);
    }
    // The neck: the necklines of the front and back pieces, when they sit at the neck. A
    // neckline more than kNecklineAtNeck times the neck is a style line (a scoop, a boat neck)
    // that the neck's girth does not set.
    [&] {
        const std::string name = "neck_girth";
        const std::string bound_name =
            base.measurements_used.count(sizes::freesewing_name(name)) > 0
                ? sizes::freesewing_name(name)
                : std::string("neck_base_girth");
        if (undeclared(name, bound_name)) {
            return;
        }
        const measurement::Measurement* g = measurements.find("neck_base_girth");
        g = g && g->value > 0 ? g : measurements.find(name);
        const auto declared = base.measurements_used.find(bound_name);
        const bool own = declared != base.measurements_used.end();
        const double value = own ? declared->second : g && g->value > 0 ? g->value : 0;
        pattern::MeasurementBinding b;
        b.measurement = bound_name;
        double garment = 0;
        bool front = false, back = false;
        std::string pieces;
        for (std::size_t i = 0; i < base.pieces.size(); ++i) {
            if (!necklines[i]) {
                continue;
            }
            const double c = internal::girth_count(base.pieces[i], false);
            b.features.push_back({base.pieces[i].name, necklines[i]->edges, {}, {}, c});
            garment += c * necklines[i]->length;
            (*placed[i] == Region::torso_front ? front : back) = true;
            pieces += (pieces.empty() ? "" : ", ") + base.pieces[i].name +
                      (c != 1 ? " ×" + std::to_string(int(c)) : "");
        }
        const auto mm = [](double v) { return std::to_string(int(std::lround(v))); };
        const std::string why =
            value <= 0                  ? "the body has no neck girth"
            : !armhole_bottom           ? "no armhole found below a neckline"
            : !neckline_missing.empty() ? neckline_missing
            : !(front && back)
                ? std::string("no ") + (front ? "back" : "front") + " torso piece holds a neckline"
            : garment < kLeastGirthRatio * value ? "the necklines come to " + mm(garment) +
                                                       " mm round a neck of " + mm(value) + " mm"
            : garment > kNecklineAtNeck * value
                ? "the neckline, " + mm(garment) + " mm, is wider than the neck (" + mm(value) +
                      " mm) by more than a quarter: a style line, not set by the neck"
                : "";
        if (!why.empty()) {
            out.notes.push_back(name + ": not bound (" + why + ")");
            return;
        }
        b.ease_mm = garment - value;
        out.notes.push_back(b.measurement + ": the neckline of " + pieces + "; garment " +
                            mm(garment) + " mm, " + (own ? "drafted for " : "body ") + mm(value) +
                            " mm, ease " + mm(b.ease_mm) + " mm");
        bindings.push_back(std::move(b));
    }();
    // The shoulder width across the back: on each back piece from the centre line to the
    // shoulder point, level with it (both sides: count 2); the centre point may lie in the neck
    // by up to kNeckReach.
    [&] {
        const std::string name = "shoulder_width_back";
        const std::string bound_name = pattern_name(name);
        if (undeclared(name, bound_name)) {
            return;
        }
        const measurement::Measurement* m = measurements.find(name);
        const auto declared = base.measurements_used.find(bound_name);
        const bool own = declared != base.measurements_used.end();
        const double value = own ? declared->second : m && m->value > 0 ? m->value : 0;
        if (value <= 0) {
            out.notes.push_back(name + ": not bound (the body has no " + name + ")");
            return;
        }
        std::string pieces;
        for (std::size_t i = 0; i < base.pieces.size(); ++i) {
            if (!necklines[i] || *placed[i] != Region::torso_back) {
                continue;
            }
            pattern::Piece& piece = base.pieces[i];
            const Neckline& nl = *necklines[i];
            const std::size_t n = piece.outline.edges.size();
            const pattern::Point2 p = pattern::start_point(piece.outline.edges[nl.lower % n]);
            // The centre line: the fold's line, else the line of the centre edge; the point on it
            // at the shoulder point's height must lie below the neckline's end on it.
            const bool on_fold = piece.fold && piece.fold->edge == nl.centre;
            const pattern::Point2 c0 =
                on_fold ? piece.fold->line.a : pattern::start_point(piece.outline.edges[nl.centre]);
            const pattern::Point2 c1 =
                on_fold ? piece.fold->line.b : pattern::end_point(piece.outline.edges[nl.centre]);
            if (std::abs(c1.y - c0.y) < 1e-6) {
                continue;
            }
            const double t = (p.y - c0.y) / (c1.y - c0.y);
            const pattern::Point2 c{c0.x + t * (c1.x - c0.x), p.y};
            const pattern::Point2 centre_top =
                pattern::start_point(piece.outline.edges[nl.centre_top]);
            if (internal::layout_height(piece, regions[i], heights, c, &outline_points[i]) >
                    internal::layout_height(piece, regions[i], heights, centre_top,
                                            &outline_points[i]) +
                        kNeckReach ||
                std::hypot(p.x - c.x, p.y - c.y) < 10) {
                continue;  // the centre line at the shoulder's height is deep in the neck
            }
            bind_span(piece, name, bound_name, value, c, p, 2, pieces);
        }
        out.notes.push_back(
            pieces.empty() ? name +
                                 ": not bound (no back piece holds its centre line level with the "
                                 "shoulder point)"
                           : bound_name + ": " + pieces + " (" + (own ? "drafted for " : "body ") +
                                 std::to_string(int(std::lround(value))) + " mm), one per piece");
    }();
    // Vertical lengths, one binding per piece (a length each piece realises on its own), each
    // along the layout's vertical line s = const of the piece: on trunk pieces at their centre
    // line (the back length from the top of a back piece to the waist; the waist to the high hip
    // and to the hip) or at their side (the waist to the bottom of the armhole), and on a sleeve
    // that reaches the wrist from its cap's top to its end (shoulder to wrist).
    struct LengthRule {
        const char* name;
        const char* upper;  ///< the girth whose level ends the span above; "": the outline
        const char* lower;  ///< the girth whose level ends it below; "": a sleeve's end
        bool side;          ///< at the piece's side (else its centre line)
        bool torso_only;    ///< on torso pieces only (else skirts too)
    };
    static const LengthRule length_rules[] = {
        {"hps_to_waist_back", "", "waist_girth", false, true},
        {"waist_to_armpit", "", "waist_girth", true, true},
        {"waist_to_high_hip", "waist_girth", "high_hip_girth", false, false},
        {"waist_to_hips", "waist_girth", "hip_girth", false, false},
        {"shoulder_to_wrist", "", "", false, false},
    };
    for (const LengthRule& rule : length_rules) {
        const std::string name = rule.name;
        const bool arm = name == "shoulder_to_wrist";
        const std::string bound_name = pattern_name(name);
        if (undeclared(name, bound_name)) {
            continue;
        }
        const auto declared = base.measurements_used.find(bound_name);
        const measurement::Measurement* m = measurements.find(name);
        const bool own = declared != base.measurements_used.end();
        if (!own && (!m || m->value <= 0)) {
            out.notes.push_back(name + ": not bound (the body has no " + name + ")");
            continue;
        }
        const double value = own ? declared->second : m->value;
        const std::optional<double> lower = arm ? std::optional<double>(0) : level_of(rule.lower);
        const std::optional<double> upper =
            *rule.upper ? level_of(rule.upper) : std::optional<double>(1e300);
        if (!lower || !upper || (arm && (!sleeve_side || wrist_depth <= 0))) {
            out.notes.push_back(name + ": not bound (the body has no level for it)");
            continue;
        }
        const auto takes = [&](Region r) {
            return arm                           ? r == *sleeve_side
                   : name == "hps_to_waist_back" ? r == Region::torso_back
                   : rule.torso_only ? r == Region::torso_front || r == Region::torso_back
                                     : trunk_region(r);
        };
        std::string pieces, why;
        std::size_t found = 0;
        const auto add_length = [&](pattern::Piece& piece, const pattern::Point2& p0,
                                    const pattern::Point2& p1) {
            if (std::hypot(p1.x - p0.x, p1.y - p0.y) < 10) {
                return;
            }
            bind_span(piece, name, bound_name, value, p0, p1, 1, pieces);
            ++found;
        };
        for (std::size_t i = 0; i < base.pieces.size(); ++i) {
            if (!placed[i] || !takes(*placed[i])) {
                continue;
            }
            pattern::Piece& piece = base.pieces[i];
            double s_c = 0;
            if (arm) {
                // Down the line through the cap's top.
                const PieceLayout& l = outline_layout[i];
                s_c = l.s[std::min_element(l.h.begin(), l.h.end()) - l.h.begin()] + 0.01;
            } else {
                const auto span = internal::outermost_crossings(piece, regions[i], heights, *lower);
                if (!span) {
                    continue;
                }
                const auto& [lo, hi] = *span;
                if (hi.s - lo.s < 4) {
                    continue;
                }
                if (rule.side) {
                    // Up the side seam the level crosses, from the level to the seam's top end
                    // (the bottom of the armhole).
                    const internal::Crossing& x = std::abs(hi.s) >= std::abs(lo.s) ? hi : lo;
                    const std::optional<pattern::Point2> top =
                        internal::seam_top(piece, regions[i], heights, x.edge, side_seams);
                    if (!top) {
                        continue;
                    }
                    if (internal::layout_height(piece, regions[i], heights, *top) <= *lower) {
                        continue;  // the seam ends below the level: no armhole above it
                    }
                    add_length(piece, x.p, *top);
                    continue;
                }
                s_c = std::clamp(0.0, lo.s + 1, hi.s - 1);
            }
            auto v = internal::outline_crossings(piece, regions[i], heights, s_c, true);
            std::sort(v.begin(), v.end(), [](const auto& a, const auto& b) { return a.h < b.h; });
            // The stretch of the line inside the piece that holds the lower end (in h, the
            // layout's height grows upwards; a sleeve's distance down the arm grows downwards).
            const double h_lo = arm ? (v.empty() ? 0 : v.front().h) : *lower;
            std::size_t k = 0;
            while (k + 1 < v.size() && !(v[k].h <= h_lo && h_lo <= v[k + 1].h)) {
                k += 2;
            }
            if (k + 1 >= v.size()) {
                continue;
            }
            const internal::Crossing &a = v[k], &c = v[k + 1];
            const auto at = [&](double h) {
                const double t = (h - a.h) / (c.h - a.h);
                return pattern::Point2{a.p.x + t * (c.p.x - a.p.x), a.p.y + t * (c.p.y - a.p.y)};
            };
            pattern::Point2 p0, p1;
            if (arm) {
                // The sleeve must reach the wrist's level (within kHemReach).
                if (c.h - a.h < arm_scale * wrist_depth - kHemReach) {
                    why = "the sleeve ends " +
                          std::to_string(int(std::lround(arm_scale * wrist_depth - (c.h - a.h)))) +
                          " mm above the wrist";
                    continue;
                }
                p0 = a.p;
                p1 = c.p;
            } else {
                if (*upper < 1e300 && *upper > c.h) {
                    continue;  // the upper level is off the piece along this line
                }
                p0 = at(h_lo);
                p1 = *upper < 1e300 ? at(*upper) : c.p;
            }
            add_length(piece, p0, p1);
        }
        out.notes.push_back(
            found == 0 ? name + ": not bound (" +
                             (why.empty() ? std::string("no piece holds both its ends") : why) + ")"
                       : bound_name + ": " + pieces + " (" + (own ? "drafted for " : "body ") +
                             std::to_string(int(std::lround(value))) + " mm), one per piece");
    }
    internal::bind_trouser_legs(base, placed, regions, heights, outline_layout, measurements,
                                landmarks, bindings, out.notes);
    if (bindings.empty()) {
        throw InvalidInput(
            "pattern '" + base.name +
            "': no girth of the body goes round its torso, skirt, sleeve or "
            "trouser-leg pieces and no length lies on them, so no binding was found" +
            (unplaced.empty() ? std::string() : "; not placed: " + unplaced) +
            ": give the bindings (--bindings)");
    }
    base.bindings = std::move(bindings);
    out.pattern = std::move(base);
    return out;
}

}  // namespace tapeline::garment
