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
// FreeSewing exports no seams (no stitch information in its JSON: only outline paths and named
// points). `freesewing_seams` derives them from the same design knowledge, per design: each side
// is a list of outline chains between named outline vertices (the shorter way round), e.g. the
// side seam (front hem → armhole against back hem → armhole) or the sleeve cap against the front
// and back armholes. Only the base draft is read.
#pragma once

#include <tapeline/grading/internal/model.h>
#include <tapeline/pattern/pattern.h>

#include <algorithm>
#include <string>
#include <vector>

namespace tapeline::grading {

struct NamedSpan {
    std::string from, to;
    double count = 0;  // 0: the rule's count
};

struct NamedSpanRule {
    std::string measurement;
    std::vector<NamedSpan> spans;  // alternatives, first found on a piece wins
    bool girth = false;
    double count = 0;    // 0: 2 on a fold, else 1 (girth); 1 (per piece)
    bool chain = false;  // bind the outline edges between the points, not the straight span
};

/// Edges of `o` from the outline vertex at `a` to the one at `b` (within `tol`): the way round
/// that passes the outline vertex at `via` when given, else the shorter way by length; empty when
/// a point is not an outline vertex.
inline std::vector<std::size_t> outline_chain(const pattern::Outline& o, const pattern::Point2& a,
                                              const pattern::Point2& b,
                                              const pattern::Point2* via = nullptr,
                                              double tol = 0.01) {
    namespace tp = tapeline::pattern;
    const std::size_t n = o.edges.size();
    std::size_t ia = n, ib = n, iv = n;
    for (std::size_t k = 0; k < n; ++k) {
        const tp::Point2 q = tp::start_point(o.edges[k]);
        if (ia == n && tp::distance(q, a) <= tol) {
            ia = k;
        }
        if (ib == n && tp::distance(q, b) <= tol) {
            ib = k;
        }
        if (via && iv == n && tp::distance(q, *via) <= tol) {
            iv = k;
        }
    }
    if (ia == n || ib == n || ia == ib || (via && (iv == n || iv == ia || iv == ib))) {
        return {};
    }
    std::vector<std::size_t> fwd, bwd;
    double lf = 0, lb = 0;
    for (std::size_t k = ia; k != ib; k = (k + 1) % n) {
        fwd.push_back(k);
        lf += tp::length(o.edges[k]);
    }
    for (std::size_t k = ib; k != ia; k = (k + 1) % n) {
        bwd.push_back(k);
        lb += tp::length(o.edges[k]);
    }
    if (via) {
        return std::find(fwd.begin(), fwd.end(), iv) != fwd.end() ? fwd : bwd;
    }
    return lf <= lb ? fwd : bwd;
}

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
                    f.edges = outline_chain(piece.outline, ia->second, ib->second);
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

/// One side of a derived seam: the outline chain of `piece` (its name without the design prefix,
/// e.g. "front" for "teagan.front", or the full name) between two named outline vertices.
struct NamedChain {
    std::string piece, from, to;
    std::string via;  // an outline vertex the chain passes (empty: the shorter way round)
};

struct NamedSeamRule {
    std::string design;  // FreeSewing design name (Pattern::name starts with it)
    std::string name;
    std::vector<NamedChain> a, b;
};

/// Seams of the FreeSewing designs, from their drafting conventions (FreeSewing's JSON carries no
/// stitch information). A seam whose sides are equal in the base draft is held equal; a deliberate
/// difference (sleeve-cap ease, a binding strip shorter than its edge) keeps its base ratio
/// (grading/README.md).
inline const std::vector<NamedSeamRule>& freesewing_seam_rules() {
    static const std::vector<NamedSeamRule> rules = {
        {"aaron", "side", {{"front", "hem", "armhole"}}, {{"back", "hem", "armhole"}}},
        {"aaron",
         "shoulder",
         {{"front", "strapRight", "strapLeft"}},
         {{"back", "strapRight", "strapLeft"}}},
        {"aaron",
         "armhole binding",
         {{"armBinding", "topLeft", "bottomLeft"}},
         {{"front", "armhole", "strapRight"}, {"back", "armhole", "strapRight"}}},
        {"aaron",
         "neck binding",
         {{"neckBinding", "topLeft", "bottomLeft"}},
         {{"front", "strapLeft", "cfNeck"}, {"back", "strapLeft", "cbNeck"}}},
        {"brian", "side", {{"front", "hips", "armhole"}}, {{"back", "hips", "armhole"}}},
        {"brian", "shoulder", {{"front", "shoulder", "neck"}}, {{"back", "shoulder", "neck"}}},
        {"brian",
         "armhole",
         {{"sleeve", "bicepsRight", "bicepsLeft", "capQ2"}},
         {{"front", "armhole", "shoulder"}, {"back", "armhole", "shoulder"}}},
        {"brian",
         "sleeve",
         {{"sleeve", "bicepsLeft", "wristLeft"}},
         {{"sleeve", "bicepsRight", "wristRight"}}},
        {"teagan", "side", {{"front", "hem", "armhole"}}, {{"back", "hem", "armhole"}}},
        {"teagan", "shoulder", {{"front", "shoulder", "neck"}}, {{"back", "shoulder", "neck"}}},
        {"teagan",
         "armhole",
         {{"sleeve", "bicepsRight", "bicepsLeft", "capQ2"}},
         {{"front", "armhole", "shoulder"}, {"back", "armhole", "shoulder"}}},
        {"teagan",
         "sleeve",
         {{"sleeve", "bicepsLeft", "hemLeft"}},
         {{"sleeve", "bicepsRight", "hemRight"}}},
        {"titan",
         "outseam",
         {{"front", "styleWaistOut", "floorOut"}},
         {{"back", "styleWaistOut", "floorOut"}}},
        {"titan", "inseam", {{"front", "fork", "floorIn"}}, {{"back", "fork", "floorIn"}}},
        {"simon", "side", {{"frontRight", "hem", "armhole"}}, {{"back", "hem", "armhole"}}},
        {"simon", "shoulder", {{"frontRight", "shoulder", "neck"}}, {{"yoke", "shoulder", "neck"}}},
        {"simon",
         "armhole",
         {{"sleeve", "bicepsRight", "bicepsLeft", "capQ2"}},
         {{"frontRight", "armhole", "shoulder"},
          {"back", "armhole", "armholeYokeSplit"},
          {"yoke", "armholeYokeSplit", "shoulder"}}},
        {"simon",
         "sleeve",
         {{"sleeve", "bicepsLeft", "wristLeft"}},
         {{"sleeve", "bicepsRight", "wristRight"}}},
        {"simon",
         "cuff",
         {{"cuff", "bottomLeft", "bottomRight"}},
         {{"sleeve", "wristLeft", "wristRight", "cuffMid"}}},
    };
    return rules;
}

/// The seams of `rules` for pattern `p` (rules whose design starts p.name, every chain found).
/// A rule whose chains are not all found is skipped and named in `skipped` when given.
inline std::vector<SeamSpec> named_seams(const pattern::Pattern& p,
                                         const std::vector<NamedSeamRule>& rules,
                                         std::vector<std::string>* skipped = nullptr) {
    namespace tp = tapeline::pattern;
    std::vector<SeamSpec> out;
    auto find = [&](const std::string& name) -> const tp::Piece* {
        for (const tp::Piece& piece : p.pieces) {
            const auto dot = piece.name.find('.');
            if (piece.name == name ||
                (dot != std::string::npos && piece.name.substr(dot + 1) == name)) {
                return &piece;
            }
        }
        return nullptr;
    };
    for (const NamedSeamRule& r : rules) {
        if (p.name.rfind(r.design, 0) != 0) {
            continue;
        }
        SeamSpec s;
        s.name = r.name;
        bool ok = true;
        bool starts_at_from[2] = {true, true};
        for (int side = 0; side < 2 && ok; ++side) {
            for (const NamedChain& c : side == 0 ? r.a : r.b) {
                const tp::Piece* piece = find(c.piece);
                if (!piece || !piece->points.count(c.from) || !piece->points.count(c.to) ||
                    (!c.via.empty() && !piece->points.count(c.via))) {
                    ok = false;
                    break;
                }
                const std::vector<std::size_t> edges =
                    outline_chain(piece->outline, piece->points.at(c.from), piece->points.at(c.to),
                                  c.via.empty() ? nullptr : &piece->points.at(c.via));
                if (edges.empty()) {
                    ok = false;
                    break;
                }
                // The chain is contiguous: first edge and count (wrapping past the last edge).
                (side == 0 ? s.a : s.b).push_back({piece->name, edges.front(), edges.size()});
                starts_at_from[side] =
                    tp::distance(tp::start_point(piece->outline.edges[edges.front()]),
                                 piece->points.at(c.from)) <= 0.01;
            }
        }
        if (ok) {
            // Rules pair `from` with `from`: the ranges' starts meet when both start there.
            s.direction = starts_at_from[0] == starts_at_from[1] ? tp::SeamDirection::same
                                                                 : tp::SeamDirection::opposite;
            out.push_back(std::move(s));
        } else if (skipped) {
            skipped->push_back(r.design + " " + r.name);
        }
    }
    return out;
}

/// The seams FreeSewing's designs imply (freesewing_seam_rules).
inline std::vector<SeamSpec> freesewing_seams(const pattern::Pattern& p,
                                              std::vector<std::string>* skipped = nullptr) {
    return named_seams(p, freesewing_seam_rules(), skipped);
}

/// FreeSewing's conventions (freesewing_span_rules) on a pattern imported from FreeSewing.
inline std::size_t add_freesewing_bindings(pattern::Pattern& p) {
    return add_named_span_bindings(p, freesewing_span_rules());
}

}  // namespace tapeline::grading
