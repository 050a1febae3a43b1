// Half pieces cut on the fold, unfolded into whole pieces before they are placed on a body.
//
// A piece cut on the fold (FreeSewing's cut-on-fold bracket: Piece::fold with the outline edge
// lying on the fold line) is half of a symmetric piece. Its whole piece is the outline without
// the fold edge, followed by its mirror image about the fold line traversed backwards, so that the
// loop closes at the fold's two ends and keeps its orientation. Every seam side on the half piece
// then exists twice: on the original edges and on their mirror images. A seam between two folded
// pieces (a side seam between front and back) becomes two seams, "NAME" and "NAME (mirror)",
// with both sides mirrored, which keeps their direction.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/pattern/pattern.h>

#include <map>
#include <string>
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

}  // namespace internal

/// The pattern with every piece cut on the fold replaced by its whole piece (see the file
/// comment). InvalidInput naming the piece or seam when a folded piece has no outline edge on its
/// fold line, when a seam side runs across the fold edge, or when a seam joins a folded piece to
/// a piece that is not folded (its mirror half would need a second, mirrored piece).
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
    if (folded.empty()) {
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
    std::vector<pattern::Seam> seams;
    for (const pattern::Seam& s : p.seams) {
        const bool fa = folded.count(s.a.piece) > 0, fb = folded.count(s.b.piece) > 0;
        if (fa != fb) {
            throw InvalidInput(where + ": seam '" + s.name + "' joins piece '" +
                               (fa ? s.a.piece : s.b.piece) + "', cut on the fold, to piece '" +
                               (fa ? s.b.piece : s.a.piece) +
                               "', which is not: its mirror half needs a mirrored copy of that "
                               "piece (not supported yet; leave one of them out with --without)");
        }
        pattern::Seam a = s;
        a.a = map_range(s.a, false, s.name);
        a.b = map_range(s.b, false, s.name);
        seams.push_back(a);
        if (fa) {
            pattern::Seam m = s;
            m.name = s.name + " (mirror)";
            m.a = map_range(s.a, true, s.name);
            m.b = map_range(s.b, true, s.name);
            seams.push_back(m);
        }
    }
    p.seams = std::move(seams);
    p.bindings.clear();  // their edge indices refer to the half outlines
    return p;
}

}  // namespace tapeline::garment
