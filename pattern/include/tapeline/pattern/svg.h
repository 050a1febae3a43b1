// SVG drawing of a pattern at 1:1 scale: one user unit is one millimetre (width/height in mm,
// viewBox in the same numbers), so a printout at 100 % can be checked against the scale bar.
//
// One <g class="piece"> per piece (outline, name and cut count, grain line with arrows, fold
// line, notches as 6 mm ticks into the piece, internal lines, darts, seam marks: a tick and the
// seam's name at the middle of each seam side), pieces laid out left to right in rows, and a
// <g id="scale-bar"> holding a 100 mm bar. The model's y-up coordinates are flipped to SVG's
// y-down.
#pragma once

#include <tapeline/core/atomic_write.h>
#include <tapeline/draw/svg.h>
#include <tapeline/pattern/pattern.h>

#include <algorithm>
#include <cstdio>
#include <limits>
#include <optional>
#include <ostream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::pattern {

/// Page layout and marks of the SVG drawing (the PNG uses the same layout).
struct SvgOptions {
    double margin_mm = 20;           ///< around the page
    double gap_mm = 30;              ///< between pieces
    double max_row_width_mm = 1600;  ///< start a new row beyond this
    double scale_bar_mm = 100;       ///< length of the scale bar
    double notch_length_mm = 6;      ///< length of a notch tick
    /// Chord tolerance of the bounding boxes only; curves are written exactly.
    double sample_tolerance_mm = 0.05;  // for bounding boxes only; curves are written exactly
    bool seam_marks = true;             ///< draw seam names at the middle of their edges
};

/// Where each piece went, for tests and callers that annotate the drawing.
struct SvgReport {
    /// Page size.
    ///@{
    double width_mm = 0, height_mm = 0;
    ///@}
    /// Per piece: model point p is drawn at (p.x + off.x, off.y − p.y).
    std::vector<Point2> piece_offsets;  // model point p is drawn at (p.x + off.x, off.y − p.y)
};

namespace internal {

/// A number for the drawing's attributes: to the micrometre, trailing zeros dropped.
inline std::string num(double v) {
    return draw::svg_number(v, 3);
}

/// "cut 2 on fold (mirrored pair)": how many to cut, written under the piece's name.
inline std::string cut_text(const Piece& piece) {
    std::string cut = "cut " + std::to_string(piece.cut_count);
    if (piece.fold) {
        cut += " on fold";
    }
    if (piece.mirrored) {
        cut += " (mirrored pair)";
    }
    return cut;
}

struct SvgMap {
    Point2 off;
    Point2 operator()(const Point2& p) const { return {p.x + off.x, off.y - p.y}; }
    std::string xy(const Point2& p) const {
        const Point2 q = (*this)(p);
        return num(q.x) + " " + num(q.y);
    }
};

inline void path_data(const std::vector<Edge>& edges, const SvgMap& m, bool close,
                      std::ostream& out) {
    std::optional<Point2> cur;
    for (const Edge& e : edges) {
        const Point2 s = start_point(e);
        if (!cur || distance(*cur, s) > 1e-9) {
            out << (cur ? " " : "") << "M " << m.xy(s);
        }
        if (const auto* l = std::get_if<Line>(&e.curve)) {
            out << " L " << m.xy(l->b);
        } else if (const auto* c = std::get_if<CubicBezier>(&e.curve)) {
            out << " C " << m.xy(c->p1) << " " << m.xy(c->p2) << " " << m.xy(c->p3);
        } else {
            const Arc& a = std::get<Arc>(e.curve);
            // Flipping y turns counter-clockwise into SVG's negative-angle direction: sweep 0.
            out << " A " << num(arc_frame(a).radius) << " " << num(arc_frame(a).radius) << " 0 "
                << (a.large_arc ? 1 : 0) << " " << (a.ccw ? 0 : 1) << " " << m.xy(a.b);
        }
        cur = end_point(e);
    }
    if (close) {
        out << " Z";
    }
}

struct Box {
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0;
    double x1 = -std::numeric_limits<double>::infinity(), y1 = x1;
    void add(const Point2& p) {
        x0 = std::min(x0, p.x);
        y0 = std::min(y0, p.y);
        x1 = std::max(x1, p.x);
        y1 = std::max(y1, p.y);
    }
    bool empty() const { return !(x0 <= x1); }
};

/// Where a seam mark goes on `piece` for one side `r` of a seam: the point halfway along the edge
/// range by length and the left normal there. Empty when `r` is not on `piece` or names no edge.
/// (The SVG and the PNG drawing both use it, so the marks are at the same place.)
inline std::optional<std::pair<Point2, Point2>> seam_mark(const Piece& piece, const EdgeRange& r) {
    const std::size_t ne = piece.outline.edges.size();
    if (r.piece != piece.name || r.first_edge >= ne || r.count == 0) {
        return std::nullopt;
    }
    double half = 0.5 * length(piece, r);
    std::size_t e = r.first_edge;
    for (std::size_t k = 0; k < r.count; ++k) {
        e = (r.first_edge + k) % ne;
        const double l = length(piece.outline.edges[e]);
        if (half <= l || k + 1 == r.count) {
            break;
        }
        half -= l;
    }
    const Curve& c = piece.outline.edges[e].curve;
    const double t = parameter_at_length(c, half);
    return std::make_pair(point_at(c, t), left_normal(tangent_at(c, t)));
}

}  // namespace internal

/// Writes the drawing to `out`. Never throws for a valid pattern; stream errors are the
/// caller's to check.
inline SvgReport write_svg(const Pattern& pattern, std::ostream& out,
                           const SvgOptions& options = {}) {
    using namespace internal;
    SvgReport rep;
    // Layout: rows of pieces, each piece's bounding box placed left to right.
    std::vector<Box> boxes;
    for (const Piece& piece : pattern.pieces) {
        Box b;
        for (const Point2& p : sample(piece.outline, options.sample_tolerance_mm).points) {
            b.add(p);
        }
        if (b.empty()) {
            b.add({0, 0});
        }
        boxes.push_back(b);
    }
    double x = options.margin_mm, y = options.margin_mm, row_h = 0, width = 0;
    for (std::size_t i = 0; i < boxes.size(); ++i) {
        const double w = boxes[i].x1 - boxes[i].x0, h = boxes[i].y1 - boxes[i].y0;
        if (x > options.margin_mm && x + w > options.max_row_width_mm) {
            x = options.margin_mm;
            y += row_h + options.gap_mm;
            row_h = 0;
        }
        rep.piece_offsets.push_back({x - boxes[i].x0, y + boxes[i].y1});
        x += w + options.gap_mm;
        width = std::max(width, x - options.gap_mm);
        row_h = std::max(row_h, h);
    }
    const double bar_y = y + row_h + options.gap_mm;
    rep.width_mm =
        std::max(width, options.margin_mm + options.scale_bar_mm + 40) + options.margin_mm;
    rep.height_mm = bar_y + 12 + options.margin_mm;

    draw::svg_open(out, num(rep.width_mm), num(rep.height_mm), "mm", " version=\"1.1\"");
    out << "<title>" << xml_escape(pattern.name) << "</title>\n"
        << "<defs><marker id=\"arrow\" viewBox=\"0 0 10 10\" refX=\"10\" refY=\"5\" "
           "markerWidth=\"6\" markerHeight=\"6\" orient=\"auto-start-reverse\">"
           "<path d=\"M 0 0 L 10 5 L 0 10 z\"/></marker></defs>\n"
        << "<style>.outline{fill:none;stroke:#000;stroke-width:0.5}"
           ".grain{stroke:#000;stroke-width:0.4}.fold{stroke:#06c;stroke-width:0.5;"
           "stroke-dasharray:6 3}.notch{stroke:#000;stroke-width:0.5}"
           ".internal{fill:none;stroke:#666;stroke-width:0.3;stroke-dasharray:2 2}"
           ".dart{fill:none;stroke:#000;stroke-width:0.4}.seam-mark{stroke:#c00;stroke-width:0.5}"
           "text{font-family:sans-serif}</style>\n";

    for (std::size_t i = 0; i < pattern.pieces.size(); ++i) {
        const Piece& piece = pattern.pieces[i];
        const SvgMap m{rep.piece_offsets[i]};
        const Box& b = boxes[i];
        out << "<g class=\"piece\" id=\"piece-" << i << "\" data-name=\"" << xml_escape(piece.name)
            << "\">\n<path class=\"outline\" d=\"";
        path_data(piece.outline.edges, m, true, out);
        out << "\"/>\n";
        for (const InternalLine& l : piece.internal_lines) {
            out << "<path class=\"internal\" data-name=\"" << xml_escape(l.name) << "\" d=\"";
            path_data(l.edges, m, false, out);
            out << "\"/>\n";
        }
        for (const Dart& d : piece.darts) {
            out << "<path class=\"dart\" data-name=\"" << xml_escape(d.name) << "\" d=\"";
            path_data(d.edges, m, false, out);
            out << "\"/>\n";
        }
        if (piece.fold) {
            const Point2 a = m(piece.fold->line.a), c = m(piece.fold->line.b);
            out << "<line class=\"fold\" x1=\"" << num(a.x) << "\" y1=\"" << num(a.y) << "\" x2=\""
                << num(c.x) << "\" y2=\"" << num(c.y) << "\"/>\n";
        }
        if (piece.grain) {
            const Point2 a = m(piece.grain->from), c = m(piece.grain->to);
            out << "<line class=\"grain\" x1=\"" << num(a.x) << "\" y1=\"" << num(a.y) << "\" x2=\""
                << num(c.x) << "\" y2=\"" << num(c.y)
                << "\" marker-start=\"url(#arrow)\" marker-end=\"url(#arrow)\"/>\n";
        }
        // Notches point into the piece: left of the direction of travel on a counter-clockwise
        // outline, right on a clockwise one.
        const double inward = signed_area(piece.outline, 0.1) >= 0 ? 1.0 : -1.0;
        for (const Notch& n : piece.notches) {
            if (n.edge >= piece.outline.edges.size()) {
                continue;
            }
            const auto [p, q] = notch_mark(piece.outline.edges[n.edge].curve, n.offset, inward,
                                           options.notch_length_mm);
            const Point2 a = m(p), e = m(q);
            out << "<line class=\"notch\" data-name=\"" << xml_escape(n.name) << "\" x1=\""
                << num(a.x) << "\" y1=\"" << num(a.y) << "\" x2=\"" << num(e.x) << "\" y2=\""
                << num(e.y) << "\"/>\n";
        }
        if (options.seam_marks) {
            for (std::size_t s = 0; s < pattern.seams.size(); ++s) {
                const Seam& seam = pattern.seams[s];
                for (const EdgeRange* r : {&seam.a, &seam.b}) {
                    const auto mark = internal::seam_mark(piece, *r);
                    if (!mark) {
                        continue;
                    }
                    const auto [p, nrm] = *mark;
                    const Point2 a = m(p + (-3.0) * nrm), d = m(p + 3.0 * nrm);
                    const Point2 lab = m(p + (inward * 8.0) * nrm);
                    const std::string name =
                        seam.name.empty() ? "seam " + std::to_string(s) : seam.name;
                    out << "<g class=\"seam-mark\" data-seam=\"" << s << "\"><line x1=\""
                        << num(a.x) << "\" y1=\"" << num(a.y) << "\" x2=\"" << num(d.x)
                        << "\" y2=\"" << num(d.y) << "\"/><text x=\"" << num(lab.x) << "\" y=\""
                        << num(lab.y) << "\" font-size=\"5\" text-anchor=\"middle\">"
                        << xml_escape(name) << "</text></g>\n";
                }
            }
        }
        const Point2 centre = m({0.5 * (b.x0 + b.x1), 0.5 * (b.y0 + b.y1)});
        out << "<text class=\"piece-name\" x=\"" << num(centre.x) << "\" y=\"" << num(centre.y)
            << "\" font-size=\"10\" text-anchor=\"middle\">" << xml_escape(piece.name)
            << "</text>\n<text class=\"piece-cut\" x=\"" << num(centre.x) << "\" y=\""
            << num(centre.y + 8) << "\" font-size=\"6\" text-anchor=\"middle\">"
            << xml_escape(cut_text(piece)) << "</text>\n</g>\n";
    }
    out << "<g id=\"scale-bar\"><rect class=\"scale-bar\" x=\"" << num(options.margin_mm)
        << "\" y=\"" << num(bar_y) << "\" width=\"" << num(options.scale_bar_mm)
        << "\" height=\"4\" fill=\"#000\"/><text x=\""
        << num(options.margin_mm + options.scale_bar_mm + 4) << "\" y=\"" << num(bar_y + 4)
        << "\" font-size=\"6\">" << num(options.scale_bar_mm) << " mm</text></g>\n</svg>\n";
    return rep;
}

/// The drawing as an SVG string.
inline std::string to_svg(const Pattern& pattern, const SvgOptions& options = {}) {
    std::ostringstream ss;
    write_svg(pattern, ss, options);
    return ss.str();
}

/// Writes the drawing to `path` atomically.
///
/// \throws InvalidInput naming `path` when it cannot be written; `path` is left untouched.
inline SvgReport write_svg(const Pattern& pattern, const std::string& path,
                           const SvgOptions& options = {}) {
    SvgReport rep;
    write_file_atomically(path, [&](std::ostream& out) { rep = write_svg(pattern, out, options); });
    return rep;
}

}  // namespace tapeline::pattern
