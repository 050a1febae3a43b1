// The sewing-pattern model: named pieces with closed outlines, seams between edge ranges, and the
// body measurements the pattern was drafted from.
//
// Units are millimetres and y points up inside the model (importers convert FreeSewing's y-down
// SVG coordinates and GarmentCode's centimetres). The model is plain data: every field is public,
// validation (validate.h) says whether a Pattern is usable, and the formats (io_*.h, svg.h) read
// and write it. No CGAL here (DESIGN.md §1).
#pragma once

#include <tapeline/pattern/geometry.h>

#include <array>
#include <cstddef>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::pattern {

/// A closed loop of edges; edge i ends where edge i+1 starts and the last ends at the first's
/// start. Orientation is the source's (GarmentCode loops run either way; edge indices are kept so
/// that seams can name them).
struct Outline {
    std::vector<Edge> edges;
};

/// The grain line: fabric warp direction, drawn from `from` to `to`.
struct GrainLine {
    Point2 from, to;
};

/// A notch on the outline, `offset` mm along edge `edge` from its start.
struct Notch {
    std::size_t edge = 0;
    double offset = 0;
    std::string name;
    std::string kind = "slit";  // slit, v, t, castle, u, check (ASTM D6673 layers 4, 80–83)
};

/// A line drawn on the piece but not cut: fold, placement, button line, help line.
struct InternalLine {
    std::string name;
    std::string kind;  // source class: "fold", "help", "dotted", ...
    std::vector<Edge> edges;
};

/// A dart: its stitching lines (legs to the tip), drawn on the piece.
struct Dart {
    std::string name;
    std::vector<Edge> edges;
};

/// The piece is half of a symmetric piece cut on the fold along `line`; `edge` is the outline
/// edge lying on the fold when there is one.
struct Fold {
    Line line;
    std::optional<std::size_t> edge;
};

/// Where a piece sits in 3D before stitching (GarmentCode): translation in mm and Euler angles in
/// degrees, applied to (x, y, 0) as R·p + t with R = Rx·Ry·Rz for order "XYZ" (intrinsic).
struct Placement3D {
    std::array<double, 3> translation{0, 0, 0};
    std::array<double, 3> rotation_deg{0, 0, 0};
    std::string rotation_order = "XYZ";
};

struct Piece {
    std::string name;
    Outline outline;
    std::map<std::string, Point2> points;  // named points (FreeSewing points, landmarks)
    std::optional<GrainLine> grain;
    std::vector<Notch> notches;
    std::vector<InternalLine> internal_lines;
    std::vector<Dart> darts;
    std::optional<Fold> fold;
    int cut_count = 1;      // how many times the piece is cut
    bool mirrored = false;  // half of those cuts are mirrored (a left/right pair)
    std::optional<Placement3D> placement;
    std::string label;  // free text from the source (GarmentCode panel label)
};

/// `count` consecutive outline edges of `piece` starting at `first_edge`, in outline order,
/// wrapping past the last edge.
struct EdgeRange {
    std::string piece;
    std::size_t first_edge = 0;
    std::size_t count = 1;
};

/// How the two sides of a seam meet: `same` joins the start of side A to the start of side B,
/// `opposite` joins the start of A to the end of B.
enum class SeamDirection { same, opposite };

struct Seam {
    std::string name;
    EdgeRange a, b;
    SeamDirection direction = SeamDirection::opposite;
};

/// One outline feature a measurement governs: either the total length of outline edges
/// (`edges` non-empty) or the straight distance between two named points of `piece`. `count`
/// says how often the feature occurs on the body (2 for a half piece cut on the fold, ...).
struct BoundFeature {
    std::string piece;
    std::vector<std::size_t> edges;
    std::string from_point, to_point;
    double count = 1;
};

/// A body measurement and the features that realise it: Σ count·length(feature) = value + ease.
struct MeasurementBinding {
    std::string measurement;
    std::vector<BoundFeature> features;
    double ease_mm = 0;
};

struct Pattern {
    std::string name;
    std::string designer;
    std::string garment_type;
    std::string size;
    std::vector<std::string> tags;
    std::string units = "mm";  // always "mm" inside the model; validation rejects anything else
    std::string source;        // file or generator it came from
    std::vector<Piece> pieces;
    std::vector<Seam> seams;
    std::map<std::string, double> measurements_used;  // name → mm (degrees for angles)
    std::vector<MeasurementBinding> bindings;
};

/// What an importer did besides building the pattern: pieces it skipped, gaps it closed, ...
struct ImportReport {
    std::size_t pieces = 0;
    std::size_t skipped_pieces = 0;
    std::size_t seams = 0;
    std::vector<std::string> notes;  // one line each, naming the piece
};

// --- queries
// --------------------------------------------------------------------------------------

/// The piece named `name`, or nullptr.
inline const Piece* find_piece(const Pattern& p, const std::string& name) {
    for (const Piece& piece : p.pieces) {
        if (piece.name == name) {
            return &piece;
        }
    }
    return nullptr;
}

inline Piece* find_piece(Pattern& p, const std::string& name) {
    return const_cast<Piece*>(find_piece(static_cast<const Pattern&>(p), name));
}

/// Perimeter of the outline.
inline double length(const Outline& o) {
    double total = 0;
    for (const Edge& e : o.edges) {
        total += length(e);
    }
    return total;
}

/// Total length of the edges of `range` on `piece` (which must hold them: see validate()).
inline double length(const Piece& piece, const EdgeRange& range) {
    const std::size_t n = piece.outline.edges.size();
    double total = 0;
    for (std::size_t i = 0; i < range.count && n > 0; ++i) {
        total += length(piece.outline.edges[(range.first_edge + i) % n]);
    }
    return total;
}

/// A polyline within `tolerance` of the outline, from the start of edge 0 round to the end of the
/// last edge (so the first point is repeated at the end of a closed outline), and for each point
/// the edge it ends (the first point: edge 0).
struct OutlinePolyline {
    std::vector<Point2> points;
    std::vector<std::size_t> edge_of_point;
};

inline OutlinePolyline sample(const Outline& o, double tolerance) {
    OutlinePolyline out;
    for (std::size_t i = 0; i < o.edges.size(); ++i) {
        sample(o.edges[i].curve, tolerance, out.points, /*skip_start=*/i > 0);
        out.edge_of_point.resize(out.points.size(), i);
    }
    return out;
}

/// Signed area enclosed by the outline (positive when counter-clockwise), from a polyline within
/// `tolerance` mm.
inline double signed_area(const Outline& o, double tolerance = 0.01) {
    return signed_area(sample(o, tolerance).points);
}

/// Nearest outline position to a point: edge index, distance along that edge, distance away.
struct OutlinePosition {
    std::size_t edge = 0;
    double offset = 0;
    double distance = 0;
    Point2 point;
};

/// Projects `p` on the outline (on a polyline within `tolerance` of it).
inline std::optional<OutlinePosition> project(const Outline& o, const Point2& p,
                                              double tolerance = 0.001) {
    std::optional<OutlinePosition> best;
    for (std::size_t i = 0; i < o.edges.size(); ++i) {
        const std::vector<Point2> pts = sample(o.edges[i].curve, tolerance);
        double along = 0;
        for (std::size_t k = 0; k + 1 < pts.size(); ++k) {
            const Point2 a = pts[k], d = pts[k + 1] - pts[k];
            const double len = norm(d);
            const double t = len > 0 ? std::clamp(dot(p - a, d) / (len * len), 0.0, 1.0) : 0.0;
            const Point2 q = a + t * d;
            const double dist = distance(p, q);
            if (!best || dist < best->distance) {
                best = OutlinePosition{i, along + t * len, dist, q};
            }
            along += len;
        }
    }
    return best;
}

/// Position of a notch on its piece's outline (the edge must exist).
inline Point2 notch_position(const Piece& piece, const Notch& n) {
    const Curve& c = piece.outline.edges.at(n.edge).curve;
    return point_at(c, parameter_at_length(c, n.offset));
}

}  // namespace tapeline::pattern
