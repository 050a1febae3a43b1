// Measurement bindings read from FreeSewing's point-naming conventions.
//
// The FreeSewing importer binds only the measurements a draft draws as help lines (chest, and
// waist on some designs). FreeSewing's blocks name the points where the draft puts the other
// measurements (centre-back high point `cbHps` to centre-back waist `cbWaist` is hpsToWaistBack,
// `bicepsLeft` to `bicepsRight` the sleeve width at the biceps, ...). This table turns those names
// into bindings of the base draft; the ease of each is what the base draft realises, exactly as for
// the importer's bindings. Only the base pattern is read: nothing comes from the target draft.
//
// A rule binds measurement M to the straight span between two named points of a piece (or, for a
// `chain` rule, to the outline edges between two named outline vertices, the shorter way round);
// both points must lie on or inside the piece's outline (FreeSewing carries every point of a draft
// into each part: a yoke knows the waist) and M must be in the pattern's measurements_used.
//   girth:     one binding over every piece that has the span, count 2 on a piece cut on the fold
//              (or `count` when given), because a girth goes round the body;
//   per_piece: one binding per piece (a length each piece realises on its own).
//
// The seams of the FreeSewing designs come with the pattern:
// <tapeline/pattern/freesewing_designs.h>.
#pragma once

#include <tapeline/grading/internal/model.h>
#include <tapeline/pattern/pattern.h>
#include <tapeline/pattern/seam_chains.h>

#include <algorithm>
#include <string>
#include <vector>

namespace tapeline::grading {

/// A span between two named points of a piece.
struct NamedSpan {
    /// Names of the span's end points.
    ///@{
    std::string from, to;
    ///@}
    double count = 0;  ///< 0: the rule's count
};

/// How a measurement binds to the named points of a drafted pattern.
struct NamedSpanRule {
    std::string measurement;       ///< the measurement bound
    std::vector<NamedSpan> spans;  ///< alternatives, first found on a piece wins
    bool girth = false;            ///< one binding over every piece (else one per piece)
    double count = 0;              ///< 0: 2 on a fold, else 1 (girth); 1 (per piece)
    bool chain = false;  ///< bind the outline edges between the points, not the straight span
};

/// The span rules of FreeSewing's named points.
inline const std::vector<NamedSpanRule>& freesewing_span_rules() {
    static const std::vector<NamedSpanRule> rules = {
        {"chest", {{"cbChest", "chest"}}, true, 0},
        // Titan's legs are cut twice (left and right): its half girths count 2.
        {"waist",
         {{"cbWaist", "waist"}, {"cfWaist", "waist"}, {"styleWaistIn", "styleWaistOut", 2}},
         true,
         0},
        {"hips", {{"cbHips", "hips"}, {"cfHips", "hips"}}, true, 0},
        {"seat", {{"cbSeat", "seatOut", 2}, {"cfSeat", "seatOut", 2}}, true, 0},
        {"neck", {{"neck", "cbNeck"}, {"neck", "cfNeck"}}, true, 0, true},
        {"crossSeam", {{"styleWaistIn", "fork"}}, true, 1, true},
        // The back neck point stands for the high point when cbHps lies off the piece (proportional
        // ease absorbs the neck depth).
        {"hpsToWaistBack",
         {{"cbHps", "cbWaist"}, {"cbHps", "cfWaist"}, {"cbNeck", "cbWaist"}},
         false,
         1},
        {"waistToArmpit", {{"armhole", "waist"}}, false, 1},
        {"waistToHips", {{"cbWaist", "cbHips"}, {"cfWaist", "cfHips"}}, false, 1},
        {"shoulderToShoulder", {{"cbShoulder", "shoulder"}, {"cfShoulder", "shoulder"}}, false, 2},
        // Simon's sleeve ends at its cuff line: the middle of the pleated hem.
        {"shoulderToWrist", {{"sleeveTop", "centerWrist"}, {"sleeveTop", "cuffMid"}}, false, 1},
        {"biceps", {{"bicepsLeft", "bicepsRight"}}, false, 1},
        {"wrist", {{"wristLeft", "wristRight"}}, false, 1},
        {"knee", {{"kneeIn", "kneeOut"}}, true, 1},
        {"waistToKnee", {{"waistX", "knee"}}, false, 1},
        {"waistToFloor", {{"waistX", "floor"}}, false, 1},
    };
    return rules;
}

/// Adds the bindings of `rules` that the pattern supports and does not bind yet; returns how many
/// were added.
inline std::size_t add_named_span_bindings(pattern::Pattern& p,
                                           const std::vector<NamedSpanRule>& rules) {
    namespace tp = tapeline::pattern;
    std::size_t added = 0;
    for (const NamedSpanRule& r : rules) {
        if (!p.measurements_used.count(r.measurement)) {
            continue;
        }
        bool bound = false;
        for (const tp::MeasurementBinding& b : p.bindings) {
            bound = bound || b.measurement == r.measurement;
        }
        if (bound) {
            continue;
        }
        tp::MeasurementBinding girth{r.measurement, {}, 0};
        for (const tp::Piece& piece : p.pieces) {
            for (const NamedSpan& span : r.spans) {
                const std::string &a = span.from, &b = span.to;
                const auto ia = piece.points.find(a), ib = piece.points.find(b);
                if (ia == piece.points.end() || ib == piece.points.end() ||
                    tp::distance(ia->second, ib->second) < 1 ||
                    internal::piece_distance_inside(piece.outline, ia->second) >
                        internal::near_piece_mm ||
                    internal::piece_distance_inside(piece.outline, ib->second) >
                        internal::near_piece_mm) {
                    continue;
                }
                const double count = span.count > 0 ? span.count
                                     : r.count > 0  ? r.count
                                                    : (piece.fold ? 2 : 1);
                tp::BoundFeature f{piece.name, {}, a, b, count};
                double len = count * tp::distance(ia->second, ib->second);
                if (r.chain) {
                    f.edges = tp::outline_chain(piece.outline, ia->second, ib->second);
                    if (f.edges.empty()) {
                        continue;
                    }
                    f.from_point.clear();
                    f.to_point.clear();
                    len = 0;
                    for (std::size_t e : f.edges) {
                        len += count * tp::length(piece.outline.edges[e]);
                    }
                }
                if (r.girth) {
                    girth.features.push_back(f);
                    girth.ease_mm += len;
                } else {
                    p.bindings.push_back(
                        {r.measurement, {f}, len - p.measurements_used.at(r.measurement)});
                    ++added;
                }
                break;
            }
        }
        if (r.girth && !girth.features.empty()) {
            girth.ease_mm -= p.measurements_used.at(r.measurement);
            p.bindings.push_back(girth);
            ++added;
        }
    }
    return added;
}

/// FreeSewing's conventions (freesewing_span_rules) on a pattern imported from FreeSewing.
inline std::size_t add_freesewing_bindings(pattern::Pattern& p) {
    return add_named_span_bindings(p, freesewing_span_rules());
}

}  // namespace tapeline::grading
