// Seams given by named points: each side a list of outline chains between named outline
// vertices. Formats that carry no stitch information (FreeSewing) get their seams this way, from
// the drafting conventions of each design (freesewing_designs.h).
#pragma once

#include <tapeline/pattern/pattern.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::pattern {

/// A seam whose sides may each span several edge ranges (a binding strip sewn to the front and
/// the back armhole). Pattern::seams holds the seams of one range per side (pattern_seams).
struct SeamSpec {
    std::string name;  ///< seam name
    /// The ranges of side A and side B.
    ///@{
    std::vector<EdgeRange> a, b;
    ///@}
    /// For a seam of one range per side: how the ranges meet (a Seam records it).
    SeamDirection direction = SeamDirection::opposite;
};

/// The seams of `seams` that a Pattern can hold (one edge range per side), as Seams.
inline std::vector<Seam> pattern_seams(const std::vector<SeamSpec>& seams) {
    std::vector<Seam> out;
    for (const SeamSpec& s : seams) {
        if (s.a.size() == 1 && s.b.size() == 1) {
            out.push_back({s.name, s.a[0], s.b[0], s.direction});
        }
    }
    return out;
}

/// Edges of `o` from the outline vertex at `a` to the one at `b` (within `tol`): the way round
/// that passes the outline vertex at `via` when given, else the shorter way by length; empty when
/// a point is not an outline vertex.
inline std::vector<std::size_t> outline_chain(const Outline& o, const Point2& a, const Point2& b,
                                              const Point2* via = nullptr, double tol = 0.01) {
    const std::size_t n = o.edges.size();
    std::size_t ia = n, ib = n, iv = n;
    for (std::size_t k = 0; k < n; ++k) {
        const Point2 q = start_point(o.edges[k]);
        if (ia == n && distance(q, a) <= tol) {
            ia = k;
        }
        if (ib == n && distance(q, b) <= tol) {
            ib = k;
        }
        if (via && iv == n && distance(q, *via) <= tol) {
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
        lf += length(o.edges[k]);
    }
    for (std::size_t k = ib; k != ia; k = (k + 1) % n) {
        bwd.push_back(k);
        lb += length(o.edges[k]);
    }
    if (via) {
        return std::find(fwd.begin(), fwd.end(), iv) != fwd.end() ? fwd : bwd;
    }
    return lf <= lb ? fwd : bwd;
}

/// One side of a derived seam: the outline chain of `piece` (its name without the design prefix,
/// e.g. "front" for "teagan.front", or the full name) between two named outline vertices.
struct NamedChain {
    /// Piece, and the named outline vertices the chain runs between.
    ///@{
    std::string piece, from, to;
    ///@}
    std::string via;  ///< an outline vertex the chain passes (empty: the shorter way round)
};

/// A seam of a design given by the named points of its pieces.
struct NamedSeamRule {
    std::string design;  ///< design name (Pattern::name starts with it)
    std::string name;    ///< seam name
    /// The chains of side A and side B.
    ///@{
    std::vector<NamedChain> a, b;
    ///@}
};

/// The piece of `p` a rule's chain names: its full name, or its name without the design prefix
/// ("front" for "teagan.front"); nullptr when there is none.
inline const Piece* find_design_piece(const Pattern& p, const std::string& name) {
    for (const Piece& piece : p.pieces) {
        const auto dot = piece.name.find('.');
        if (piece.name == name ||
            (dot != std::string::npos && piece.name.substr(dot + 1) == name)) {
            return &piece;
        }
    }
    return nullptr;
}

/// The same, for a pattern that may be changed.
inline Piece* find_design_piece(Pattern& p, const std::string& name) {
    return const_cast<Piece*>(find_design_piece(static_cast<const Pattern&>(p), name));
}

/// The outline edges of `piece` that chain `c` names (outline_chain between its named points);
/// empty when the piece is missing, a named point is missing or not an outline vertex.
inline std::vector<std::size_t> named_chain_edges(const Piece* piece, const NamedChain& c) {
    if (!piece || !piece->points.count(c.from) || !piece->points.count(c.to) ||
        (!c.via.empty() && !piece->points.count(c.via))) {
        return {};
    }
    return outline_chain(piece->outline, piece->points.at(c.from), piece->points.at(c.to),
                         c.via.empty() ? nullptr : &piece->points.at(c.via));
}

/// A label a design gives the outline chain `chain` of one of its pieces (FreeSewing drafts carry
/// no edge labels: a trouser's waist is where dressing holds it up, garment/README.md).
struct NamedLabelRule {
    std::string design;  ///< design name (Pattern::name starts with it)
    std::string label;   ///< the label its edges get
    NamedChain chain;    ///< the piece and the named outline vertices the edges run between
};

/// Gives the edges of each rule's chain (rules whose design starts p.name) its label, where an
/// edge has none yet; returns how many edges were labelled. A rule whose chain is not found is
/// named in `skipped` when given.
inline std::size_t apply_label_rules(Pattern& p, const std::vector<NamedLabelRule>& rules,
                                     std::vector<std::string>* skipped = nullptr) {
    std::size_t labelled = 0;
    for (const NamedLabelRule& r : rules) {
        if (p.name.rfind(r.design, 0) != 0) {
            continue;
        }
        const NamedChain& c = r.chain;
        Piece* piece = find_design_piece(p, c.piece);
        const std::vector<std::size_t> edges = named_chain_edges(piece, c);
        if (edges.empty()) {
            if (skipped) {
                skipped->push_back(r.design + " " + c.piece + " " + r.label);
            }
            continue;
        }
        for (std::size_t e : edges) {
            if (piece->outline.edges[e].label.empty()) {
                piece->outline.edges[e].label = r.label;
                ++labelled;
            }
        }
    }
    return labelled;
}

/// The seams of `rules` for pattern `p` (rules whose design starts p.name, every chain found).
/// A rule whose chains are not all found is skipped and named in `skipped` when given.
inline std::vector<SeamSpec> named_seams(const Pattern& p, const std::vector<NamedSeamRule>& rules,
                                         std::vector<std::string>* skipped = nullptr) {
    std::vector<SeamSpec> out;
    const auto find = [&](const std::string& name) { return find_design_piece(p, name); };
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
                const Piece* piece = find(c.piece);
                const std::vector<std::size_t> edges = named_chain_edges(piece, c);
                if (edges.empty()) {
                    ok = false;
                    break;
                }
                // The chain is contiguous: first edge and count (wrapping past the last edge).
                (side == 0 ? s.a : s.b).push_back({piece->name, edges.front(), edges.size()});
                starts_at_from[side] = distance(start_point(piece->outline.edges[edges.front()]),
                                                piece->points.at(c.from)) <= 0.01;
            }
        }
        if (ok) {
            // Rules pair `from` with `from`: the ranges' starts meet when both start there.
            s.direction = starts_at_from[0] == starts_at_from[1] ? SeamDirection::same
                                                                 : SeamDirection::opposite;
            out.push_back(std::move(s));
        } else if (skipped) {
            skipped->push_back(r.design + " " + r.name);
        }
    }
    return out;
}

}  // namespace tapeline::pattern
