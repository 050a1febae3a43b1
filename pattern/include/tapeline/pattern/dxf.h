// DXF export for cutting-room software: the AAMA layout that ASTM D6673 ("DXF-ASTM", withdrawn
// 2019) grew out of, written as R12 ASCII DXF (AC1009), which AAMA readers accept.
//
//   HEADER   $ACADVER AC1009, $INSUNITS 4 (mm), $MEASUREMENT 1 (metric); $EXTMIN/$EXTMAX and
//            $LIMMIN/$LIMMAX the box of every entity as inserted (texts estimated: one em per
//            character, 0.35 em below the baseline); the sheet for a 1:1 plot, $PLIMMIN/$PLIMMAX
//            (0,0)–(box + 10 mm on each side) with $PINSBASE putting the box 10 mm inside it, which
//            CAD programs that print without a layout (LibreCAD's dxf2pdf) take as their page
//   TABLES   line type CONTINUOUS; layers 1–8, 14, 80–83 (AAMA layers are numbered, not named)
//   BLOCKS   one BLOCK per piece, in model coordinates (mm, y up, base point 0,0):
//              layer 1  boundary as one closed POLYLINE; TEXT "Piece Name: …", "Size: …",
//                       "Quantity: …" (cut count), "Mirror: Yes" for mirrored pairs
//              layer 2  turn points: POINT at each outline corner (tangent turns > 1°)
//              layer 3  curve points: POINT at every other boundary vertex
//              layer 4  notches (slit, V) as a LINE from the outline point into the piece;
//                       80 T-, 81 castle-, 82 check-, 83 U-notches likewise
//              layer 6  mirror (fold) line, LINE
//              layer 7  grain line, LINE
//              layer 8  internal lines and darts, open POLYLINEs
//   ENTITIES one INSERT per block, pieces laid out in rows so that they do not overlap, and a
//            TEXT "Style Name: …" on layer 1.
// Curves are sampled within `tolerance_mm` (0.05 mm): Béziers by subdivision, arcs by the sagitta
// bound (geometry.h), so every polyline vertex lies on the curve and every chord within the
// tolerance of it. Pieces carry no seam allowance in the model, so the boundary is the seam line;
// sew lines (layer 14) are not written.
#pragma once

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/pattern/pattern.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <ostream>
#include <set>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::pattern {

/// How the DXF is written: curve sampling, mark and text sizes, layout of the pieces.
struct DxfOptions {
    double tolerance_mm = 0.05;      ///< chord tolerance of the curve sampling (> 0)
    double notch_length_mm = 6;      ///< length of a notch line into the piece
    double text_height_mm = 8;       ///< height of the texts in the blocks and of the style name
    double gap_mm = 30;              ///< between inserted pieces
    double max_row_width_mm = 1600;  ///< start a new row of inserts beyond this
};

/// What write_dxf() wrote, for tests and callers that check the file.
struct DxfReport {
    /// Entities written: blocks (one per piece), boundary vertices, turn points (layer 2), curve
    /// points (layer 3), notches (layers 4, 80–83), internal lines and darts (layer 8).
    ///@{
    std::size_t blocks = 0, boundary_vertices = 0, turn_points = 0, curve_points = 0, notches = 0,
                internal_lines = 0;
    ///@}
    std::vector<std::string> block_names;  ///< per piece, as written (sanitised, unique)
    std::vector<Point2> insert_points;     ///< per piece: where its block is inserted
    /// $EXTMIN and $EXTMAX: corners of the box of every entity as inserted, mm.
    ///@{
    Point2 extents_min, extents_max;
    ///@}
};

namespace internal {

/// An axis-aligned box; empty until a point is added.
struct DxfBox {
    Point2 lo{std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity()};
    Point2 hi{-std::numeric_limits<double>::infinity(), -std::numeric_limits<double>::infinity()};

    bool empty() const { return lo.x > hi.x; }
    void add(const Point2& p) {
        lo = {std::min(lo.x, p.x), std::min(lo.y, p.y)};
        hi = {std::max(hi.x, p.x), std::max(hi.y, p.y)};
    }
    void add(const DxfBox& b, const Point2& shift = Point2{0, 0}) {
        if (!b.empty()) {
            add(b.lo + shift);
            add(b.hi + shift);
        }
    }
};

/// Writes group codes; `box` grows by every entity drawn (text by its estimated extent).
class DxfWriter {
public:
    explicit DxfWriter(std::ostream& out) : out_(out) {}
    DxfBox box;

    void code(int c, const std::string& v) {
        char buf[8];
        std::snprintf(buf, sizeof buf, "%3d", c);
        out_ << buf << '\n' << v << '\n';
    }
    void code(int c, double v) {
        char buf[40];
        std::snprintf(buf, sizeof buf, "%.6f", v == 0 ? 0.0 : v);  // no "-0.000000"
        code(c, std::string(buf));
    }
    void code(int c, int v) { code(c, std::to_string(v)); }
    void xy(const Point2& p, int base = 10) {
        code(base, p.x);
        code(base + 10, p.y);
        code(base + 20, 0.0);
    }
    void point(const std::string& layer, const Point2& p) {
        box.add(p);
        code(0, "POINT");
        code(8, layer);
        xy(p);
    }
    void line(const std::string& layer, const Point2& a, const Point2& b) {
        box.add(a);
        box.add(b);
        code(0, "LINE");
        code(8, layer);
        xy(a, 10);
        xy(b, 11);
    }
    void polyline(const std::string& layer, const std::vector<Point2>& pts, bool closed) {
        code(0, "POLYLINE");
        code(8, layer);
        code(66, 1);
        xy({0, 0});
        code(70, closed ? 1 : 0);
        for (const Point2& p : pts) {
            box.add(p);
            code(0, "VERTEX");
            code(8, layer);
            xy(p);
        }
        code(0, "SEQEND");
        code(8, layer);
    }
    void text(const std::string& layer, const Point2& p, double height, const std::string& s) {
        // Glyph widths depend on the reader's font; one em per character bounds the usual CAD
        // fonts, 0.35 em covers descenders.
        box.add(Point2{p.x, p.y - 0.35 * height});
        box.add(Point2{p.x + height * static_cast<double>(s.size()), p.y + height});
        code(0, "TEXT");
        code(8, layer);
        xy(p);
        code(40, height);
        code(1, s);
    }

private:
    std::ostream& out_;
};

/// DXF text is one line of printable characters.
inline std::string dxf_text(const std::string& s) {
    std::string out;
    for (char c : s) {
        out += (static_cast<unsigned char>(c) < 32) ? ' ' : c;
    }
    return out;
}

/// Block names: letters, digits, '-' and '_' only (R12 symbol names), at most 31 characters,
/// unique.
inline std::string dxf_block_name(const std::string& piece, std::set<std::string>& used) {
    std::string base;
    for (char c : piece) {
        const bool ok = (c >= 'A' && c <= 'Z') || (c >= 'a' && c <= 'z') ||
                        (c >= '0' && c <= '9') || c == '-' || c == '_';
        base += ok ? c : '_';
    }
    if (base.empty()) {
        base = "PIECE";
    }
    base = base.substr(0, 27);
    std::string name = base;
    for (int k = 2; used.count(name); ++k) {
        name = base + "_" + std::to_string(k);
    }
    used.insert(name);
    return name;
}

inline std::string notch_layer(const std::string& kind) {
    if (kind == "t") {
        return "80";
    }
    if (kind == "castle") {
        return "81";
    }
    if (kind == "check") {
        return "82";
    }
    if (kind == "u") {
        return "83";
    }
    return "4";
}

inline std::vector<Point2> sample_edges(const std::vector<Edge>& edges, double tol) {
    std::vector<Point2> pts;
    for (std::size_t i = 0; i < edges.size(); ++i) {
        sample(edges[i].curve, tol, pts, i > 0);
    }
    return pts;
}

}  // namespace internal

/// Writes the pattern as AAMA-style DXF to `out`. Throws InvalidInput, before anything is
/// written, for a tolerance that is not positive, a piece with no outline or a non-finite
/// coordinate (the file would be unreadable), or a notch on an edge the piece does not have.
inline DxfReport write_dxf(const Pattern& pattern, std::ostream& out, const DxfOptions& o = {}) {
    using namespace internal;
    if (!(o.tolerance_mm > 0)) {
        throw InvalidInput("DXF export: tolerance must be positive (got " +
                           std::to_string(o.tolerance_mm) + " mm)");
    }
    DxfReport rep;
    // Sample every boundary first: the header needs the extents, the layout the boxes.
    struct Sampled {
        std::vector<Point2> pts;
        std::vector<int> kind;  // 2 turn point, 3 curve point
        double x0, y0, x1, y1;
    };
    std::vector<Sampled> pieces;
    for (const Piece& piece : pattern.pieces) {
        if (piece.outline.edges.empty()) {
            throw InvalidInput("DXF export of '" + pattern.name + "': piece '" + piece.name +
                               "' has no outline");
        }
        Sampled s;
        const std::size_t n = piece.outline.edges.size();
        for (std::size_t i = 0; i < n; ++i) {
            const Curve& c = piece.outline.edges[i].curve;
            if (!is_finite(c)) {
                throw InvalidInput("DXF export of '" + pattern.name + "': piece '" + piece.name +
                                   "' edge " + std::to_string(i) + " has a non-finite coordinate");
            }
            const Curve& prev = piece.outline.edges[(i + n - 1) % n].curve;
            const double turn = std::abs(cross(tangent_at(prev, 1), tangent_at(c, 0))) +
                                (dot(tangent_at(prev, 1), tangent_at(c, 0)) < 0 ? 1.0 : 0.0);
            std::vector<Point2> pts = sample(c, o.tolerance_mm);
            pts.pop_back();  // the end is the next edge's start
            for (std::size_t k = 0; k < pts.size(); ++k) {
                s.pts.push_back(pts[k]);
                s.kind.push_back(k == 0 && turn > std::sin(M_PI / 180) ? 2 : 3);
            }
        }
        s.x0 = s.y0 = std::numeric_limits<double>::infinity();
        s.x1 = s.y1 = -s.x0;
        for (const Point2& p : s.pts) {
            s.x0 = std::min(s.x0, p.x);
            s.y0 = std::min(s.y0, p.y);
            s.x1 = std::max(s.x1, p.x);
            s.y1 = std::max(s.y1, p.y);
        }
        pieces.push_back(std::move(s));
    }
    // Rows of pieces, left to right, rows going down (y up, so decreasing y).
    double x = 0, y_top = 0, row_h = 0;
    Point2 lo{0, 0}, hi{0, 0};
    for (const Sampled& s : pieces) {
        const double w = s.x1 - s.x0, h = s.y1 - s.y0;
        if (x > 0 && x + w > o.max_row_width_mm) {
            x = 0;
            y_top -= row_h + o.gap_mm;
            row_h = 0;
        }
        const Point2 at{x - s.x0, y_top - s.y1};
        rep.insert_points.push_back(at);
        lo = {std::min(lo.x, x), std::min(lo.y, y_top - h)};
        hi = {std::max(hi.x, x + w), std::max(hi.y, y_top)};
        x += w + o.gap_mm;
        row_h = std::max(row_h, h);
    }

    // The header needs the extents of everything drawn: tables, blocks and entities go to a
    // buffer first, each block's box shifted to where it is inserted.
    std::ostringstream body;
    DxfWriter w(body);
    DxfBox extents;
    const std::vector<std::string> layers = {"1", "2",  "3",  "4",  "5",  "6", "7",
                                             "8", "14", "80", "81", "82", "83"};
    w.code(0, "SECTION");
    w.code(2, "TABLES");
    w.code(0, "TABLE");
    w.code(2, "LTYPE");
    w.code(70, 1);
    w.code(0, "LTYPE");
    w.code(2, "CONTINUOUS");
    w.code(70, 0);
    w.code(3, "Solid line");
    w.code(72, 65);
    w.code(73, 0);
    w.code(40, 0.0);
    w.code(0, "ENDTAB");
    w.code(0, "TABLE");
    w.code(2, "LAYER");
    w.code(70, int(layers.size()) + 1);
    for (const std::string& l : std::vector<std::string>{"0"}) {
        w.code(0, "LAYER");
        w.code(2, l);
        w.code(70, 0);
        w.code(62, 7);
        w.code(6, "CONTINUOUS");
    }
    for (const std::string& l : layers) {
        w.code(0, "LAYER");
        w.code(2, l);
        w.code(70, 0);
        w.code(62, 7);
        w.code(6, "CONTINUOUS");
    }
    w.code(0, "ENDTAB");
    w.code(0, "ENDSEC");

    w.code(0, "SECTION");
    w.code(2, "BLOCKS");
    std::set<std::string> used;
    for (std::size_t i = 0; i < pattern.pieces.size(); ++i) {
        const Piece& piece = pattern.pieces[i];
        const Sampled& s = pieces[i];
        const std::string name = dxf_block_name(piece.name, used);
        rep.block_names.push_back(name);
        ++rep.blocks;
        w.box = DxfBox{};
        w.code(0, "BLOCK");
        w.code(8, "0");
        w.code(2, name);
        w.code(70, 0);
        w.xy({0, 0});
        w.code(3, name);
        w.code(1, "");

        w.polyline("1", s.pts, true);
        rep.boundary_vertices += s.pts.size();
        for (std::size_t k = 0; k < s.pts.size(); ++k) {
            w.point(s.kind[k] == 2 ? "2" : "3", s.pts[k]);
            ++(s.kind[k] == 2 ? rep.turn_points : rep.curve_points);
        }
        const double inward = signed_area(s.pts) >= 0 ? 1.0 : -1.0;
        for (const Notch& n : piece.notches) {
            if (n.edge >= piece.outline.edges.size()) {
                throw InvalidInput("DXF export of '" + pattern.name + "': piece '" + piece.name +
                                   "' notch '" + n.name + "' names missing edge " +
                                   std::to_string(n.edge));
            }
            const auto [p, q] =
                notch_mark(piece.outline.edges[n.edge].curve, n.offset, inward, o.notch_length_mm);
            w.line(notch_layer(n.kind), p, q);
            ++rep.notches;
        }
        if (piece.fold) {
            w.line("6", piece.fold->line.a, piece.fold->line.b);
        }
        if (piece.grain) {
            w.line("7", piece.grain->from, piece.grain->to);
        }
        for (const InternalLine& l : piece.internal_lines) {
            w.polyline("8", sample_edges(l.edges, o.tolerance_mm), false);
            ++rep.internal_lines;
        }
        for (const Dart& d : piece.darts) {
            w.polyline("8", sample_edges(d.edges, o.tolerance_mm), false);
            ++rep.internal_lines;
        }
        const double th = o.text_height_mm;
        Point2 at{0.5 * (s.x0 + s.x1) - 4 * th, 0.5 * (s.y0 + s.y1) + th};
        std::vector<std::string> lines = {"Piece Name: " + dxf_text(piece.name),
                                          "Size: " + dxf_text(pattern.size),
                                          "Quantity: " + std::to_string(piece.cut_count)};
        if (piece.mirrored) {
            lines.push_back("Mirror: Yes");
        }
        for (const std::string& t : lines) {
            w.text("1", at, th, t);
            at.y -= 1.5 * th;
        }
        w.code(0, "ENDBLK");
        w.code(8, "0");
        extents.add(w.box, rep.insert_points[i]);
    }
    w.code(0, "ENDSEC");

    w.code(0, "SECTION");
    w.code(2, "ENTITIES");
    w.box = DxfBox{};
    w.text("1", {lo.x, hi.y + 2 * o.text_height_mm}, o.text_height_mm,
           "Style Name: " + dxf_text(pattern.name));
    extents.add(w.box);
    for (std::size_t i = 0; i < pattern.pieces.size(); ++i) {
        w.code(0, "INSERT");
        w.code(8, "1");
        w.code(2, rep.block_names[i]);
        w.xy(rep.insert_points[i]);
    }
    w.code(0, "ENDSEC");
    w.code(0, "EOF");

    const double margin = 10;
    const Point2 size = extents.hi - extents.lo;
    DxfWriter h(out);
    h.code(999, "Tapeline DXF-AAMA export: " + dxf_text(pattern.name));
    h.code(0, "SECTION");
    h.code(2, "HEADER");
    h.code(9, "$ACADVER");
    h.code(1, "AC1009");
    const std::pair<const char*, int> flags[] = {{"$INSUNITS", 4}, {"$MEASUREMENT", 1}};
    for (const auto& [name, value] : flags) {
        h.code(9, name);
        h.code(70, value);
    }
    const std::pair<const char*, Point2> points[] = {
        {"$EXTMIN", extents.lo},
        {"$LIMMIN", extents.lo},
        {"$EXTMAX", extents.hi},
        {"$LIMMAX", extents.hi},
        {"$PLIMMIN", Point2{0, 0}},
        {"$PLIMMAX", Point2{size.x + 2 * margin, size.y + 2 * margin}},
        {"$PINSBASE", Point2{margin - extents.lo.x, margin - extents.lo.y}}};
    for (const auto& [name, p] : points) {
        h.code(9, name);
        h.xy(p);
    }
    h.code(0, "ENDSEC");
    out << body.str();
    rep.extents_min = extents.lo;
    rep.extents_max = extents.hi;
    return rep;
}

/// Writes the DXF file atomically.
inline DxfReport write_dxf(const Pattern& pattern, const std::string& path,
                           const DxfOptions& o = {}) {
    DxfReport rep;
    write_file_atomically(path, [&](std::ostream& out) { rep = write_dxf(pattern, out, o); });
    return rep;
}

}  // namespace tapeline::pattern
