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
    std::vector<Edge> edges;  ///< the loop, in order
};

/// The grain line: fabric warp direction, drawn from `from` to `to`.
struct GrainLine {
    /// Ends of the line.
    ///@{
    Point2 from, to;
    ///@}
};

/// A notch on the outline, `offset` mm along edge `edge` from its start.
struct Notch {
    std::size_t edge = 0;       ///< outline edge the notch is on
    double offset = 0;          ///< mm along the edge from its start
    std::string name;           ///< notch name, may be empty
    std::string kind = "slit";  ///< slit, v, t, castle, u, check (ASTM D6673 layers 4, 80–83)
};

/// A line drawn on the piece but not cut: fold, placement, button line, help line.
struct InternalLine {
    std::string name;         ///< line name
    std::string kind;         ///< source class: "fold", "help", "dotted", ...
    std::vector<Edge> edges;  ///< the drawn line
};

/// A dart: its stitching lines (legs to the tip), drawn on the piece.
struct Dart {
    std::string name;         ///< dart name
    std::vector<Edge> edges;  ///< its stitching lines
};

/// The piece is half of a symmetric piece cut on the fold along `line`; `edge` is the outline
/// edge lying on the fold when there is one.
struct Fold {
    Line line;                        ///< the fold line
    std::optional<std::size_t> edge;  ///< outline edge on the fold, if any
};

/// Where a piece sits in 3D before stitching (GarmentCode): translation in mm and Euler angles in
/// degrees, applied to (x, y, 0) as R·p + t with R = Rx·Ry·Rz for order "XYZ" (intrinsic).
struct Placement3D {
    std::array<double, 3> translation{0, 0, 0};   ///< mm
    std::array<double, 3> rotation_deg{0, 0, 0};  ///< Euler angles, degrees
    std::string rotation_order = "XYZ";           ///< axis order of the rotation
};

/// One pattern piece: its cut outline and what is drawn or marked on it.
struct Piece {
    std::string name;                          ///< piece name, unique in the pattern
    Outline outline;                           ///< the cut outline
    std::map<std::string, Point2> points;      ///< named points (FreeSewing points, landmarks)
    std::optional<GrainLine> grain;            ///< fabric grain, if given
    std::vector<Notch> notches;                ///< notches on the outline
    std::vector<InternalLine> internal_lines;  ///< lines drawn, not cut
    std::vector<Dart> darts;                   ///< darts drawn on the piece
    std::optional<Fold> fold;                  ///< set when the piece is cut on the fold
    int cut_count = 1;                         ///< how many times the piece is cut
    bool mirrored = false;                 ///< half of those cuts are mirrored (a left/right pair)
    std::optional<Placement3D> placement;  ///< 3D placement (GarmentCode), if given
    std::string label;                     ///< free text from the source (GarmentCode panel label)
};

/// `count` consecutive outline edges of `piece` starting at `first_edge`, in outline order,
/// wrapping past the last edge.
struct EdgeRange {
    std::string piece;           ///< piece name
    std::size_t first_edge = 0;  ///< first outline edge of the range
    std::size_t count = 1;       ///< number of edges
};

/// How the two sides of a seam meet: `same` joins the start of side A to the start of side B,
/// `opposite` joins the start of A to the end of B.
enum class SeamDirection { same, opposite };

/// Two outline edge ranges sewn together.
struct Seam {
    std::string name;  ///< seam name, unique in the pattern
    /// The two sides.
    ///@{
    EdgeRange a, b;
    ///@}
    SeamDirection direction = SeamDirection::opposite;  ///< how the sides meet
};

/// One outline feature a measurement governs: either the total length of outline edges
/// (`edges` non-empty) or the straight distance between two named points of `piece`. `count`
/// says how often the feature occurs on the body (2 for a half piece cut on the fold, ...).
struct BoundFeature {
    std::string piece;               ///< piece name
    std::vector<std::size_t> edges;  ///< outline edges (length form)
    /// Named points of the straight-distance form (empty with `edges`).
    ///@{
    std::string from_point, to_point;
    ///@}
    double count = 1;  ///< occurrences on the body
};

/// A body measurement and the features that realise it: Σ count·length(feature) = value + ease.
struct MeasurementBinding {
    std::string measurement;             ///< measurement name, as in the measurement set
    std::vector<BoundFeature> features;  ///< features whose lengths add up to it
    double ease_mm = 0;                  ///< the ease: Σ count·length(feature) − value
};

/// A sewing pattern: pieces, seams and the measurements it was drafted for, in mm.
struct Pattern {
    std::string name;               ///< pattern name (database key)
    std::string designer;           ///< designer or source project
    std::string garment_type;       ///< garment type ("shirt", "trousers", ...)
    std::string size;               ///< size label of the draft
    std::vector<std::string> tags;  ///< free search tags
    std::string units = "mm";   ///< always "mm" inside the model; validation rejects anything else
    std::string source;         ///< file or generator it came from
    std::vector<Piece> pieces;  ///< pieces in source order
    std::vector<Seam> seams;    ///< seams between piece edges
    std::map<std::string, double> measurements_used;  ///< name → mm (degrees for angles)
    std::vector<MeasurementBinding> bindings;         ///< what grading fits
};

/// What an importer did besides building the pattern: pieces it skipped, gaps it closed, ...
struct ImportReport {
    std::size_t pieces = 0;          ///< pieces imported
    std::size_t skipped_pieces = 0;  ///< pieces left out (see notes)
    std::size_t seams = 0;           ///< seams imported or derived
    std::vector<std::string> notes;  ///< one line each, naming the piece
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
    std::vector<Point2> points;              ///< polyline points, mm
    std::vector<std::size_t> edge_of_point;  ///< per point: the edge it ends
};

/// The outline as a polyline within `tolerance` mm (see OutlinePolyline).
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
    std::size_t edge = 0;  ///< outline edge index
    double offset = 0;     ///< mm along the edge from its start
    double distance = 0;   ///< distance from the point to the outline
    Point2 point;          ///< the nearest outline point
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
