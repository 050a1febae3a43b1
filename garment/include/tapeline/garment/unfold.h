// Half pieces cut on the fold, unfolded into whole pieces before they are placed on a body.
//
// A piece cut on the fold (FreeSewing's cut-on-fold bracket: Piece::fold with the outline edge
// lying on the fold line) is half of a symmetric piece. Its whole piece is the outline without
// the fold edge, followed by its mirror image about the fold line traversed backwards, so that the
// loop closes at the fold's two ends and keeps its orientation. Every seam side on the half piece
// then exists twice: on the original edges and on their mirror images. A seam between two folded
// pieces (a side seam between front and back) becomes two seams, "NAME" and "NAME (mirror)",
// with both sides mirrored, which keeps their direction.
//
// A piece that is not folded but is sewn to a folded one (a sleeve sewn to the armholes of a
// front and a back cut on the fold) is one of a left/right pair: it gets a mirrored copy,
// "NAME (mirror)", and every seam it takes part in exists twice, once between the original
// pieces (the original halves of the folded ones) and once between the mirror images — and so on
// for pieces sewn to those. FreeSewing drafts each such piece once (a sleeve, cut twice).
// Trousers are drafted as one leg: a front and a back that the crotch seam joins to their own
// mirror images (pattern::freesewing_mirror_seam_rules). They get their mirrored copies the same
// way, and the crotch seams between each piece and its copy are added from the rules.
//
// A seam of a FreeSewing design whose one side is one outline chain and whose other side is two
// (a sleeve cap sewn to the front and the back armhole) cannot be held by a Pattern (one edge
// range per side). split_chain_seams() splits the one chain at the length ratio of the two — the
// sleeve cap's ease shared in proportion — adding an outline vertex there, into two seams of one
// range per side, "NAME (PIECE)" for each piece of the other side.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/pattern/freesewing_designs.h>
#include <tapeline/pattern/pattern.h>

#include <cmath>
#include <map>
#include <set>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::garment {

namespace internal {

inline pattern::Point2 mirror_point(const pattern::Point2& p, const pattern::Line& l) {
    const pattern::Point2 d = l.b - l.a;
    const double len2 = pattern::dot(d, d);
    const double t = pattern::dot(p - l.a, d) / len2;
    const pattern::Point2 foot = l.a + t * d;
    return foot + (foot - p);
}

inline pattern::Curve mirror_curve(const pattern::Curve& c, const pattern::Line& l) {
    if (const auto* s = std::get_if<pattern::Line>(&c)) {
        return pattern::Line{mirror_point(s->a, l), mirror_point(s->b, l)};
    }
    if (const auto* b = std::get_if<pattern::CubicBezier>(&c)) {
        return pattern::CubicBezier{mirror_point(b->p0, l), mirror_point(b->p1, l),
                                    mirror_point(b->p2, l), mirror_point(b->p3, l)};
    }
    pattern::Arc a = std::get<pattern::Arc>(c);
    a.a = mirror_point(a.a, l);
    a.b = mirror_point(a.b, l);
    a.ccw = !a.ccw;  // a reflection turns the sense of rotation
    return a;
}

/// The two parts of `c` before and after parameter t ∈ (0, 1) (de Casteljau for Béziers; arcs
/// keep their circle).
inline std::pair<pattern::Curve, pattern::Curve> split_curve(const pattern::Curve& c, double t) {
    const pattern::Point2 m = pattern::point_at(c, t);
    if (std::get_if<pattern::Line>(&c)) {
        return {pattern::Line{pattern::start_point(c), m}, pattern::Line{m, pattern::end_point(c)}};
    }
    if (const auto* b = std::get_if<pattern::CubicBezier>(&c)) {
        const auto lerp = [t](const pattern::Point2& p, const pattern::Point2& q) {
            return p + t * (q - p);
        };
        const pattern::Point2 a1 = lerp(b->p0, b->p1), a2 = lerp(b->p1, b->p2),
                              a3 = lerp(b->p2, b->p3);
        const pattern::Point2 b1 = lerp(a1, a2), b2 = lerp(a2, a3);
        return {pattern::CubicBezier{b->p0, a1, b1, m}, pattern::CubicBezier{m, b2, a3, b->p3}};
    }
    const pattern::Arc& a = std::get<pattern::Arc>(c);
    const pattern::ArcFrame f = pattern::arc_frame(a);
    pattern::Arc first = a, second = a;
    first.b = m;
    second.a = m;
    first.radius = second.radius = f.radius;
    first.large_arc = std::abs(t * f.sweep) > M_PI;
    second.large_arc = std::abs((1 - t) * f.sweep) > M_PI;
    return {first, second};
}

/// Splits outline edge `e` of piece `pi` at parameter t ∈ (0, 1) into two edges (e and e + 1);
/// every edge index of the pattern on that piece (seams, notches, fold) follows. InvalidInput
/// when `e` is the piece's fold edge.
inline void split_outline_edge(pattern::Pattern& p, std::size_t pi, std::size_t e, double t) {
    pattern::Piece& piece = p.pieces[pi];
    auto& edges = piece.outline.edges;
    if (piece.fold && piece.fold->edge && *piece.fold->edge == e) {
        throw InvalidInput("dress: pattern '" + p.name + "': edge " + std::to_string(e) +
                           " of piece '" + piece.name + "' is its fold edge and cannot be split");
    }
    const std::size_t n = edges.size();
    const auto parts = split_curve(edges[e].curve, t);
    const double first_length = pattern::length(parts.first);
    edges[e].curve = parts.first;
    edges.insert(edges.begin() + std::ptrdiff_t(e) + 1,
                 pattern::Edge{parts.second, edges[e].label});
    const auto moved = [e](std::size_t i) { return i > e ? i + 1 : i; };
    for (pattern::Notch& notch : piece.notches) {
        if (notch.edge == e && notch.offset > first_length) {
            notch.edge = e + 1;
            notch.offset -= first_length;
        } else {
            notch.edge = moved(notch.edge);
        }
    }
    if (piece.fold && piece.fold->edge) {
        piece.fold->edge = moved(*piece.fold->edge);
    }
    const auto fix = [&](pattern::EdgeRange& r) {
        if (r.piece != piece.name) {
            return;
        }
        const bool covers = (e + n - r.first_edge) % n < r.count;
        r.first_edge = moved(r.first_edge);
        r.count += covers ? 1 : 0;
    };
    for (pattern::Seam& seam : p.seams) {
        fix(seam.a);
        fix(seam.b);
    }
    p.bindings.clear();  // their edge lists refer to the outline before the split
}

/// The mirror image of `piece` about the line x = 0, named "NAME (mirror)": outline edge i becomes
/// edge n − 1 − i, traversed the other way, so that the outline keeps its orientation.
inline pattern::Piece mirrored_copy(const pattern::Piece& piece) {
    const pattern::Line axis{{0, 0}, {0, 1}};
    const auto mirror_edges = [&](const std::vector<pattern::Edge>& in, bool reverse_order) {
        std::vector<pattern::Edge> out;
        for (std::size_t k = 0; k < in.size(); ++k) {
            const pattern::Edge& e = in[reverse_order ? in.size() - 1 - k : k];
            const pattern::Curve c = mirror_curve(e.curve, axis);
            out.push_back({reverse_order ? pattern::reversed(c) : c, e.label});
        }
        return out;
    };
    pattern::Piece m = piece;
    m.name = piece.name + " (mirror)";
    m.outline.edges = mirror_edges(piece.outline.edges, true);
    const std::size_t n = piece.outline.edges.size();
    for (auto& entry : m.points) {
        entry.second = mirror_point(entry.second, axis);
    }
    if (m.grain) {
        m.grain->from = mirror_point(m.grain->from, axis);
        m.grain->to = mirror_point(m.grain->to, axis);
    }
    for (pattern::Notch& notch : m.notches) {
        const double len = pattern::length(piece.outline.edges[notch.edge]);
        notch.edge = n - 1 - notch.edge;
        notch.offset = len - notch.offset;
    }
    for (pattern::InternalLine& line : m.internal_lines) {
        line.edges = mirror_edges(line.edges, false);
    }
    for (pattern::Dart& dart : m.darts) {
        dart.edges = mirror_edges(dart.edges, false);
    }
    return m;
}

inline double range_length(const pattern::Pattern& p, const pattern::EdgeRange& r) {
    return pattern::length(*pattern::find_piece(p, r.piece), r);
}

inline std::size_t piece_index(const pattern::Pattern& p, const std::string& name) {
    for (std::size_t i = 0; i < p.pieces.size(); ++i) {
        if (p.pieces[i].name == name) {
            return i;
        }
    }
    return p.pieces.size();
}

}  // namespace internal

/// Adds to `p` the seams of FreeSewing's design rules (pattern::freesewing_seam_rules) whose one
/// side is one chain and whose other side is two chains meeting at a named point (the sleeve cap
/// against the front and back armholes, meeting at the shoulder: the first chain's `to` is an end
/// of the second): the one chain is split at the
/// ratio of the two chains' lengths (see the file comment) into "NAME (PIECE)" seams. A rule is
/// left out, and named in `skipped` when given, when its chains are not all on the pattern, when a
/// seam of that name is already there, or when its two chains do not meet at a named point.
/// Returns the number of seams added.
inline std::size_t split_chain_seams(pattern::Pattern& p,
                                     std::vector<std::string>* skipped = nullptr) {
    std::size_t added = 0;
    for (const pattern::NamedSeamRule& rule0 : pattern::freesewing_seam_rules()) {
        if (p.name.rfind(rule0.design, 0) != 0) {
            continue;
        }
        const bool a_one = rule0.a.size() == 1 && rule0.b.size() == 2;
        const bool b_one = rule0.b.size() == 1 && rule0.a.size() == 2;
        if (!a_one && !b_one) {
            continue;
        }
        // The rule with its one chain on side A.
        pattern::NamedSeamRule rule = rule0;
        if (b_one) {
            std::swap(rule.a, rule.b);
        }
        const auto skip = [&](const std::string& why) {
            if (skipped) {
                skipped->push_back(rule.design + " " + rule.name + ": " + why);
            }
        };
        bool present = false;
        for (const pattern::Seam& s : p.seams) {
            present = present || s.name == rule.name || s.name.rfind(rule.name + " (", 0) == 0;
        }
        const std::vector<pattern::SeamSpec> spec = pattern::named_seams(p, {rule});
        if (spec.empty() || present) {
            if (!present) {
                skip("its chains are not all on the pattern");
            }
            continue;
        }
        const pattern::NamedChain &c1 = rule.b[0], &c2 = rule.b[1];
        // Rules pair `from` with `from`: chain 1 runs from its `from` (sewn to A's `from`) to its
        // `to`, where chain 2 takes over from its end of that name.
        const bool meet_at_to = c1.to == c2.to;
        const pattern::EdgeRange ra = spec[0].a[0], r1 = spec[0].b[0], r2 = spec[0].b[1];
        if ((!meet_at_to && c1.to != c2.from) || r1.piece == ra.piece || r2.piece == ra.piece) {
            skip("its two chains do not meet at a named point of two other pieces");
            continue;
        }
        const std::size_t pa = internal::piece_index(p, ra.piece);
        const pattern::Piece& piece_a = p.pieces[pa];
        const auto starts_at = [&](const pattern::EdgeRange& r, const std::string& point) {
            const pattern::Piece& pc = *pattern::find_piece(p, r.piece);
            const auto it = pc.points.find(point);
            return it != pc.points.end() &&
                   tapeline::distance(pattern::start_point(pc.outline.edges[r.first_edge]),
                                      it->second) <= 0.01;
        };
        // In outline order: does A run from its `from`; does chain 1 run from its free end
        // towards the meeting point; does chain 2 run from the meeting point.
        const bool a_fwd = starts_at(ra, rule.a[0].from);
        const bool b1_fwd = starts_at(r1, c1.from);
        const bool b2_fwd = starts_at(r2, meet_at_to ? c2.to : c2.from);
        const double l1 = internal::range_length(p, r1), l2 = internal::range_length(p, r2);
        const double la = internal::range_length(p, ra);
        const double from_start = a_fwd ? la * l1 / (l1 + l2) : la * l2 / (l1 + l2);
        // The split: an existing outline vertex within 0.01 mm, or a new one.
        const std::size_t n = piece_a.outline.edges.size();
        double walked = 0;
        bool found = false, inserted = false;
        std::size_t k = ra.first_edge, split_vertex = 0;
        for (std::size_t j = 0; j < ra.count && !found; ++j, k = (k + 1) % n) {
            const double le = pattern::length(piece_a.outline.edges[k]);
            if (j > 0 && std::abs(walked - from_start) <= 0.01) {
                split_vertex = k;
                found = true;
            } else if (walked + le > from_start + 0.01) {
                const double t = pattern::parameter_at_length(piece_a.outline.edges[k].curve,
                                                              from_start - walked);
                internal::split_outline_edge(p, pa, k, t);
                split_vertex = k + 1;
                found = inserted = true;
            }
            walked += le;
        }
        if (!found) {
            skip("its one chain is too short to split");
            continue;
        }
        // A's range after the split, in two parts at the split vertex.
        const std::size_t m = p.pieces[pa].outline.edges.size();
        const std::size_t first =
            inserted && ra.first_edge >= split_vertex ? ra.first_edge + 1 : ra.first_edge;
        const std::size_t count = ra.count + (inserted ? 1 : 0);
        const std::size_t part1 = (split_vertex + m - first) % m;  // edges before the split
        const pattern::EdgeRange before{ra.piece, first, part1};
        const pattern::EdgeRange after{ra.piece, split_vertex % m, count - part1};
        const pattern::EdgeRange a1 = a_fwd ? before : after, a2 = a_fwd ? after : before;
        const auto base = [](const std::string& name) {
            const auto dot = name.rfind('.');
            return dot == std::string::npos ? name : name.substr(dot + 1);
        };
        pattern::Seam s1{
            rule.name + " (" + base(r1.piece) + ")", a1, r1,
            a_fwd == b1_fwd ? pattern::SeamDirection::same : pattern::SeamDirection::opposite};
        pattern::Seam s2{
            rule.name + " (" + base(r2.piece) + ")", a2, r2,
            a_fwd == b2_fwd ? pattern::SeamDirection::same : pattern::SeamDirection::opposite};
        if (b_one) {
            std::swap(s1.a, s1.b);
            std::swap(s2.a, s2.b);
        }
        p.seams.push_back(s1);
        p.seams.push_back(s2);
        added += 2;
    }
    return added;
}

/// The pattern with every piece cut on the fold replaced by its whole piece (see the file
/// comment). InvalidInput naming the piece or seam when a folded piece has no outline edge on its
/// fold line or when a seam side runs across the fold edge. Pieces sewn to folded ones get their
/// mirrored copies (see the file comment).
inline pattern::Pattern unfold_pieces(pattern::Pattern p) {
    const std::string where = "dress: pattern '" + p.name + "'";
    struct Map {
        std::size_t n = 0, fold = 0;
    };
    std::map<std::string, Map> folded;
    for (pattern::Piece& piece : p.pieces) {
        if (!piece.fold) {
            continue;
        }
        if (!piece.fold->edge) {
            throw InvalidInput(where + ": piece '" + piece.name +
                               "' is cut on the fold but no outline edge lies on the fold line");
        }
        const std::size_t n = piece.outline.edges.size(), f = *piece.fold->edge;
        const pattern::Line line{pattern::start_point(piece.outline.edges[f]),
                                 pattern::end_point(piece.outline.edges[f])};
        std::vector<pattern::Edge> out;
        for (std::size_t k = 1; k < n; ++k) {
            out.push_back(piece.outline.edges[(f + k) % n]);
        }
        for (std::size_t k = n - 1; k >= 1; --k) {
            const pattern::Edge& e = piece.outline.edges[(f + k) % n];
            out.push_back({pattern::reversed(internal::mirror_curve(e.curve, line)),
                           e.label.empty() ? e.label : e.label + " (mirror)"});
        }
        piece.outline.edges = std::move(out);
        piece.notches.clear();  // their edge indices refer to the half outline
        piece.fold.reset();
        piece.cut_count = 1;
        folded[piece.name] = {n, f};
    }
    // Pieces sewn to their own mirror image (a trouser leg's front and back, drafted once: the
    // crotch seams) get a mirrored copy too.
    std::vector<const pattern::NamedSeamRule*> mirror_rules;
    std::map<std::string, std::size_t> paired;  // name → edge count
    for (const pattern::NamedSeamRule& rule : pattern::freesewing_mirror_seam_rules()) {
        if (p.name.rfind(rule.design, 0) != 0) {
            continue;
        }
        for (const pattern::NamedChain& c : rule.a) {
            if (const pattern::Piece* piece = pattern::find_design_piece(p, c.piece)) {
                paired[piece->name] = piece->outline.edges.size();
                mirror_rules.push_back(&rule);
            }
        }
    }
    if (folded.empty() && paired.empty()) {
        return p;
    }
    // Original edge i of a folded piece is new edge k = (i − f − 1) mod n; its mirror image is
    // new edge 2n − 3 − k.
    const auto map_range = [&](const pattern::EdgeRange& r, bool mirror,
                               const std::string& seam) -> pattern::EdgeRange {
        const auto it = folded.find(r.piece);
        if (it == folded.end()) {
            return r;
        }
        const auto [n, f] = it->second;
        const std::size_t k0 = (r.first_edge + n - f - 1) % n;
        if (k0 + r.count > n - 1) {
            throw InvalidInput(where + ": seam '" + seam +
                               "' runs across the fold edge of piece '" + r.piece + "'");
        }
        pattern::EdgeRange out = r;
        out.first_edge = mirror ? 2 * n - 3 - (k0 + r.count - 1) : k0;
        return out;
    };
    // Pieces sewn to folded ones, or to those (see the file comment), get a mirrored copy.
    for (bool grew = true; grew;) {
        grew = false;
        for (const pattern::Seam& s : p.seams) {
            const auto joined = [&](const std::string& x) {
                return folded.count(x) > 0 || paired.count(x) > 0;
            };
            for (int side = 0; side < 2; ++side) {
                const std::string& here = side == 0 ? s.a.piece : s.b.piece;
                const std::string& there = side == 0 ? s.b.piece : s.a.piece;
                if (joined(there) && !joined(here)) {
                    paired[here] = pattern::find_piece(p, here)->outline.edges.size();
                    grew = true;
                }
            }
        }
    }
    for (const auto& entry : paired) {
        const std::size_t i = internal::piece_index(p, entry.first);
        p.pieces[i].cut_count = 1;
        p.pieces[i].mirrored = false;
        p.pieces.push_back(internal::mirrored_copy(p.pieces[i]));
    }
    // Range of a paired piece on its mirrored copy: edge i is edge n − 1 − i there, reversed.
    const auto map_paired = [&](const pattern::EdgeRange& r, bool mirror) -> pattern::EdgeRange {
        const auto it = paired.find(r.piece);
        if (it == paired.end() || !mirror) {
            return r;
        }
        const std::size_t n = it->second;
        return {r.piece + " (mirror)", (2 * n - r.first_edge - r.count) % n, r.count};
    };
    const auto map_side = [&](const pattern::EdgeRange& r, bool mirror, const std::string& seam) {
        return paired.count(r.piece) ? map_paired(r, mirror) : map_range(r, mirror, seam);
    };
    std::vector<pattern::Seam> seams;
    for (const pattern::Seam& s : p.seams) {
        const bool twice = folded.count(s.a.piece) > 0 || paired.count(s.a.piece) > 0;
        pattern::Seam a = s;
        a.a = map_side(s.a, false, s.name);
        a.b = map_side(s.b, false, s.name);
        seams.push_back(a);
        if (twice) {
            pattern::Seam m = s;
            m.name = s.name + " (mirror)";
            m.a = map_side(s.a, true, s.name);
            m.b = map_side(s.b, true, s.name);
            seams.push_back(m);
        }
    }
    p.seams = std::move(seams);
    p.bindings.clear();  // their edge indices refer to the half outlines
    if (!mirror_rules.empty()) {
        std::vector<pattern::NamedSeamRule> rules;
        for (const pattern::NamedSeamRule* r : mirror_rules) {
            rules.push_back(*r);
        }
        std::vector<std::string> skipped;
        for (pattern::Seam& s : pattern::pattern_seams(pattern::named_seams(p, rules, &skipped))) {
            p.seams.push_back(std::move(s));
        }
        if (!skipped.empty()) {
            throw InvalidInput(where + ": the seam '" + skipped.front() +
                               "' between a piece and its mirror image was not found on the "
                               "outline (its named points are missing)");
        }
    }
    return p;
}

}  // namespace tapeline::garment
