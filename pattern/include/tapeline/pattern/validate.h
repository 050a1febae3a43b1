// Validation of a sewing pattern: is every outline a closed simple loop of finite curves, does
// every seam name existing edges, and do the two sides of each seam have the same length?
//
// Errors make the pattern unusable (open or self-intersecting outline, NaN, a seam naming a
// missing piece or edge, units other than mm); warnings flag what a pattern maker may intend
// (seam sides of different lengths — sleeve-cap ease — and degenerate edges). Self-intersection
// is tested on polylines within `sample_tolerance_mm` of the curves with an O(n²) segment test
// culled by bounding boxes (a few hundred segments per piece).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/pattern/pattern.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace tapeline::pattern {

/// Tolerances and limits of validate().
struct ValidationOptions {
    double closure_tolerance_mm = 1e-3;   ///< largest gap between consecutive edges
    double sample_tolerance_mm = 0.01;    ///< polyline tolerance of the self-intersection test
    bool check_self_intersection = true;  ///< test outlines for self-intersection
    /// Seam sides differing by more than max(absolute, relative · longer side) are reported.
    double seam_length_tolerance_mm = 0.5;
    double seam_length_relative_tolerance = 0.0;  ///< relative part of the seam tolerance
    double min_edge_length_mm = 1e-6;  ///< shorter edges are reported as degenerate (warning)
    /// Largest |coordinate| of an edge end: 10 km. Beyond it a pattern is a unit error, and
    /// sampling its curves at sample_tolerance_mm would not end.
    double max_coordinate_mm = 1e7;
    double min_piece_area_mm2 = 1.0;  ///< outlines enclosing less are reported (error)
};

/// One problem found by validate().
struct ValidationIssue {
    std::string code;   ///< open_outline, self_intersection, non_finite, missing_edge, ...
    std::string piece;  ///< empty when the issue is not about one piece
    std::optional<std::size_t> edge;  ///< the outline edge concerned, if one
    std::string message;              ///< one line naming the piece and edge
};

/// What validate() found: errors make a pattern unusable, warnings do not.
struct ValidationReport {
    std::vector<ValidationIssue> errors;        ///< problems that make the pattern unusable
    std::vector<ValidationIssue> warnings;      ///< problems worth a look
    std::size_t pieces_checked = 0;             ///< pieces validated
    std::size_t seams_checked = 0;              ///< seams validated
    double largest_seam_mismatch_mm = 0;        ///< over all seams, |length A − length B|
    bool ok() const { return errors.empty(); }  ///< no errors
};

namespace internal {

inline std::string fmt_mm(double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, std::abs(v) < 1e9 ? "%.3f" : "%.3g", v);
    return buf;
}

inline std::string fmt_point(const Point2& p) {
    return "(" + fmt_mm(p.x) + ", " + fmt_mm(p.y) + ")";
}

inline std::string piece_ref(const std::string& name) {
    return "piece '" + name + "'";
}

inline bool finite_edges(const std::vector<Edge>& edges) {
    for (const Edge& e : edges) {
        if (!is_finite(e.curve)) {
            return false;
        }
    }
    return true;
}

/// First crossing of the closed polyline with itself: the two edges and a point near it.
struct Crossing {
    std::size_t edge_a, edge_b;
    Point2 where;
};

inline std::optional<Crossing> first_crossing(const OutlinePolyline& poly) {
    // Drop repeated points so that every segment has a direction.
    if (poly.points.empty()) {
        return std::nullopt;
    }
    const std::size_t last_edge = poly.edge_of_point.back();
    std::vector<Point2> pts;
    std::vector<std::size_t> edge;
    for (std::size_t i = 0; i < poly.points.size(); ++i) {
        if (pts.empty() || distance(pts.back(), poly.points[i]) > 0) {
            pts.push_back(poly.points[i]);
            edge.push_back(poly.edge_of_point[i]);
        }
    }
    while (pts.size() > 1 && distance(pts.front(), pts.back()) == 0) {
        pts.pop_back();
        edge.pop_back();
    }
    const std::size_t n = pts.size();
    if (n < 3) {
        return std::nullopt;
    }
    // Segment k runs from pts[k] to pts[k+1]; it belongs to the edge its end point was sampled
    // from (the start point of an edge's first segment belongs to the previous edge).
    auto seg_edge = [&](std::size_t k) { return k + 1 < n ? edge[k + 1] : last_edge; };
    struct Box {
        double x0, y0, x1, y1;
    };
    std::vector<Box> box(n);
    for (std::size_t k = 0; k < n; ++k) {
        const Point2 a = pts[k], b = pts[(k + 1) % n];
        box[k] = {std::min(a.x, b.x), std::min(a.y, b.y), std::max(a.x, b.x), std::max(a.y, b.y)};
    }
    for (std::size_t i = 0; i < n; ++i) {
        const Point2 a = pts[i], b = pts[(i + 1) % n];
        // Adjacent segments share a point; they overlap only when the second turns straight back.
        {
            const Point2 c = pts[(i + 2) % n];
            const Point2 u = b - a, v = c - b;
            if (std::abs(cross(u, v)) <= 1e-12 * norm(u) * norm(v) && dot(u, v) < 0) {
                return Crossing{seg_edge(i), seg_edge((i + 1) % n), b};
            }
        }
        for (std::size_t j = i + 2; j < n; ++j) {
            if (i == 0 && j == n - 1) {
                continue;  // adjacent through the closing point
            }
            if (box[j].x0 > box[i].x1 || box[j].x1 < box[i].x0 || box[j].y0 > box[i].y1 ||
                box[j].y1 < box[i].y0) {
                continue;
            }
            const Point2 c = pts[j], d = pts[(j + 1) % n];
            if (segments_intersect(a, b, c, d)) {
                const auto x = segment_intersection(a, b, c, d);
                return Crossing{seg_edge(i), seg_edge(j), x ? *x : a};
            }
        }
    }
    return std::nullopt;
}

}  // namespace internal

/// Checks `pattern`; never throws for a bad pattern (the report says what is wrong).
inline ValidationReport validate(const Pattern& pattern, const ValidationOptions& options = {}) {
    using internal::fmt_mm;
    using internal::fmt_point;
    using internal::piece_ref;
    ValidationReport rep;
    auto error = [&](std::string code, std::string piece, std::optional<std::size_t> edge,
                     std::string msg) {
        rep.errors.push_back({std::move(code), std::move(piece), edge, std::move(msg)});
    };
    auto warning = [&](std::string code, std::string piece, std::optional<std::size_t> edge,
                       std::string msg) {
        rep.warnings.push_back({std::move(code), std::move(piece), edge, std::move(msg)});
    };

    if (pattern.units != "mm") {
        error("unknown_units", "", std::nullopt,
              "pattern '" + pattern.name + "': units '" + pattern.units +
                  "' (the model holds millimetres; convert on import)");
    }
    for (const auto& [name, value] : pattern.measurements_used) {
        if (!std::isfinite(value)) {
            error("non_finite", "", std::nullopt,
                  "pattern '" + pattern.name + "': measurement '" + name + "' is not finite");
        }
    }

    if (pattern.pieces.empty()) {
        error("no_pieces", "", std::nullopt, "pattern '" + pattern.name + "' has no pieces");
    }
    std::set<std::string> names;
    for (const Piece& piece : pattern.pieces) {
        ++rep.pieces_checked;
        const std::string where = piece_ref(piece.name);
        if (piece.name.empty()) {
            error("unnamed_piece", "", std::nullopt, "a piece has an empty name");
        } else if (!names.insert(piece.name).second) {
            error("duplicate_piece", piece.name, std::nullopt,
                  where + ": two pieces have this name");
        }
        const auto& edges = piece.outline.edges;
        if (edges.empty()) {
            error("empty_outline", piece.name, std::nullopt, where + ": outline has no edges");
            continue;
        }
        bool finite = true;
        for (std::size_t i = 0; i < edges.size(); ++i) {
            if (!is_finite(edges[i].curve)) {
                error("non_finite", piece.name, i,
                      where + ": edge " + std::to_string(i) + " has a NaN or infinite coordinate");
                finite = false;
            } else {
                for (const Point2& p : {start_point(edges[i]), end_point(edges[i])}) {
                    const double m = std::max(std::abs(p.x), std::abs(p.y));
                    if (finite && m > options.max_coordinate_mm) {
                        error("out_of_range", piece.name, i,
                              where + ": edge " + std::to_string(i) + " reaches " + fmt_mm(m) +
                                  " mm from the origin, beyond the " +
                                  fmt_mm(options.max_coordinate_mm) +
                                  " mm a pattern may span (wrong units?)");
                        finite = false;
                    }
                }
            }
        }
        for (const auto& [pname, p] : piece.points) {
            if (!is_finite(p)) {
                error("non_finite", piece.name, std::nullopt,
                      where + ": point '" + pname + "' is not finite");
            }
        }
        if (piece.grain && !(is_finite(piece.grain->from) && is_finite(piece.grain->to))) {
            error("non_finite", piece.name, std::nullopt, where + ": grain line is not finite");
        }
        for (const InternalLine& l : piece.internal_lines) {
            if (!internal::finite_edges(l.edges)) {
                error("non_finite", piece.name, std::nullopt,
                      where + ": internal line '" + l.name + "' is not finite");
            }
        }
        for (const Dart& d : piece.darts) {
            if (!internal::finite_edges(d.edges)) {
                error("non_finite", piece.name, std::nullopt,
                      where + ": dart '" + d.name + "' is not finite");
            }
        }
        if (piece.cut_count < 1) {
            error("bad_cut_count", piece.name, std::nullopt,
                  where + ": cut count " + std::to_string(piece.cut_count) + " (must be >= 1)");
        }
        for (const Notch& n : piece.notches) {
            if (n.edge >= edges.size() || !std::isfinite(n.offset)) {
                error("missing_edge", piece.name, n.edge,
                      where + ": notch '" + n.name + "' is on edge " + std::to_string(n.edge) +
                          ", which the outline (" + std::to_string(edges.size()) +
                          " edges) does not have");
            }
        }
        if (piece.fold && piece.fold->edge && *piece.fold->edge >= edges.size()) {
            error("missing_edge", piece.name, piece.fold->edge,
                  where + ": fold is on edge " + std::to_string(*piece.fold->edge) +
                      ", which the outline does not have");
        }
        if (!finite) {
            continue;
        }
        bool closed = true;
        for (std::size_t i = 0; i < edges.size(); ++i) {
            const std::size_t j = (i + 1) % edges.size();
            const double gap = distance(end_point(edges[i]), start_point(edges[j]));
            if (gap > options.closure_tolerance_mm) {
                closed = false;
                error("open_outline", piece.name, i,
                      where + ": outline is open between edge " + std::to_string(i) + " (ends at " +
                          fmt_point(end_point(edges[i])) + ") and edge " + std::to_string(j) +
                          " (starts at " + fmt_point(start_point(edges[j])) + "), gap " +
                          fmt_mm(gap) + " mm");
            }
            if (const auto* arc = std::get_if<Arc>(&edges[i].curve)) {
                if (arc_frame(*arc).radius_too_small) {
                    error("arc_radius", piece.name, i,
                          where + ": edge " + std::to_string(i) + " is an arc of radius " +
                              fmt_mm(arc->radius) + " mm, less than half its chord " +
                              fmt_mm(0.5 * distance(arc->a, arc->b)) + " mm");
                }
            }
            if (length(edges[i]) < options.min_edge_length_mm) {
                warning("degenerate_edge", piece.name, i,
                        where + ": edge " + std::to_string(i) + " has length " +
                            fmt_mm(length(edges[i])) + " mm");
            }
        }
        if (!closed) {
            continue;
        }
        const OutlinePolyline poly = sample(piece.outline, options.sample_tolerance_mm);
        if (options.check_self_intersection) {
            if (const auto x = internal::first_crossing(poly)) {
                error("self_intersection", piece.name, x->edge_a,
                      where + ": outline crosses itself: edge " + std::to_string(x->edge_a) +
                          " meets edge " + std::to_string(x->edge_b) + " near " +
                          fmt_point(x->where) + " mm");
                continue;  // the lobes' signed areas cancel: the area says nothing more
            }
        }
        const double area = std::abs(signed_area(poly.points));
        if (area < options.min_piece_area_mm2) {
            error("zero_area", piece.name, std::nullopt,
                  where + ": outline encloses " + fmt_mm(area) + " mm2, less than " +
                      fmt_mm(options.min_piece_area_mm2) + " mm2");
        }
    }

    auto check_range = [&](const EdgeRange& r, const std::string& what) -> const Piece* {
        const Piece* piece = find_piece(pattern, r.piece);
        if (!piece) {
            error("missing_piece", r.piece, std::nullopt,
                  what + " names piece '" + r.piece + "', which the pattern does not have");
            return nullptr;
        }
        const std::size_t n = piece->outline.edges.size();
        if (r.count == 0 || r.first_edge >= n || r.count > n) {
            error("missing_edge", r.piece, r.first_edge,
                  what + " names edges " + std::to_string(r.first_edge) + ".." +
                      std::to_string(r.first_edge + r.count) + " (exclusive) of " +
                      piece_ref(r.piece) + ", which has " + std::to_string(n) + " edges");
            return nullptr;
        }
        return piece;
    };
    for (std::size_t s = 0; s < pattern.seams.size(); ++s) {
        const Seam& seam = pattern.seams[s];
        ++rep.seams_checked;
        const std::string what =
            "seam " + std::to_string(s) + (seam.name.empty() ? "" : " '" + seam.name + "'");
        const Piece* pa = check_range(seam.a, what + " side A");
        const Piece* pb = check_range(seam.b, what + " side B");
        if (!pa || !pb || !internal::finite_edges(pa->outline.edges) ||
            !internal::finite_edges(pb->outline.edges)) {
            continue;
        }
        const double la = length(*pa, seam.a), lb = length(*pb, seam.b);
        const double diff = std::abs(la - lb);
        rep.largest_seam_mismatch_mm = std::max(rep.largest_seam_mismatch_mm, diff);
        const double tol = std::max(options.seam_length_tolerance_mm,
                                    options.seam_length_relative_tolerance * std::max(la, lb));
        if (diff > tol) {
            warning("seam_length_mismatch", seam.a.piece, seam.a.first_edge,
                    what + ": side A (" + piece_ref(seam.a.piece) + " edge " +
                        std::to_string(seam.a.first_edge) + ", " + std::to_string(seam.a.count) +
                        " edges) is " + fmt_mm(la) + " mm, side B (" + piece_ref(seam.b.piece) +
                        " edge " + std::to_string(seam.b.first_edge) + ", " +
                        std::to_string(seam.b.count) + " edges) is " + fmt_mm(lb) +
                        " mm: differ by " + fmt_mm(diff) + " mm > " + fmt_mm(tol) + " mm");
        }
    }

    for (const MeasurementBinding& b : pattern.bindings) {
        const std::string what = "binding of measurement '" + b.measurement + "'";
        if (!std::isfinite(b.ease_mm)) {
            error("non_finite", "", std::nullopt, what + ": ease is not finite");
        }
        for (const BoundFeature& f : b.features) {
            const Piece* piece = find_piece(pattern, f.piece);
            if (!piece) {
                error("missing_piece", f.piece, std::nullopt,
                      what + " names piece '" + f.piece + "', which the pattern does not have");
                continue;
            }
            for (std::size_t e : f.edges) {
                if (e >= piece->outline.edges.size()) {
                    error("missing_edge", f.piece, e,
                          what + " names edge " + std::to_string(e) + " of " + piece_ref(f.piece) +
                              ", which has " + std::to_string(piece->outline.edges.size()) +
                              " edges");
                }
            }
            if (f.edges.empty()) {
                for (const std::string& pt : {f.from_point, f.to_point}) {
                    if (!piece->points.count(pt)) {
                        error("missing_point", f.piece, std::nullopt,
                              what + " names point '" + pt + "' of " + piece_ref(f.piece) +
                                  ", which the piece does not have");
                    }
                }
            }
        }
    }
    return rep;
}

/// Length of a bound feature (the features must exist: see validate()); 0 for a missing piece.
///
/// \throws std::out_of_range when an edge or point index of `f` is out of range.
inline double feature_length(const Pattern& pattern, const BoundFeature& f) {
    const Piece* piece = find_piece(pattern, f.piece);
    if (!piece) {
        return 0;
    }
    if (!f.edges.empty()) {
        double total = 0;
        for (std::size_t e : f.edges) {
            total += length(piece->outline.edges.at(e));
        }
        return total;
    }
    return distance(piece->points.at(f.from_point), piece->points.at(f.to_point));
}

/// validate(), then throws InvalidInput with the first error, prefixed by `context` (a file name,
/// or the pattern's source when empty). Returns the report (warnings) otherwise.
///
/// \throws InvalidInput with the first error and the count of the others.
inline ValidationReport require_valid(const Pattern& pattern, const ValidationOptions& options = {},
                                      const std::string& context = {}) {
    ValidationReport rep = validate(pattern, options);
    if (!rep.errors.empty()) {
        const std::string where = !context.empty() ? context : pattern.source;
        std::string msg = (where.empty() ? "" : where + ": ") + rep.errors.front().message;
        if (rep.errors.size() > 1) {
            msg += " (and " + std::to_string(rep.errors.size() - 1) + " more errors)";
        }
        throw InvalidInput(msg);
    }
    return rep;
}

}  // namespace tapeline::pattern
