// Options and reports of dressing a body (dress.h): placement of the pieces, sewing along geodesic
// strings, the drape and the quality gates. No CGAL or Eigen here (DESIGN.md §3, §5).
//
// Lengths are millimetres in the body's canonical frame (x to the body's left, y up from the
// floor, z to the front); the outputs are converted back to the body's own coordinates and unit.
#pragma once

#include <tapeline/garment/drape_types.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace tapeline::garment {

/// The part of the body a piece is wrapped around before sewing.
enum class Region {
    torso_front,
    torso_back,
    sleeve_left,
    sleeve_right,
    skirt_front,
    skirt_back,
    leg_left_front,   ///< a trouser leg's front on the body's left leg (+x)
    leg_left_back,    ///< its back
    leg_right_front,  ///< a trouser leg's front on the body's right leg (−x)
    leg_right_back    ///< its back
};

inline const char* to_string(Region r) {
    switch (r) {
        case Region::torso_front:
            return "torso_front";
        case Region::torso_back:
            return "torso_back";
        case Region::sleeve_left:
            return "sleeve_left";
        case Region::sleeve_right:
            return "sleeve_right";
        case Region::skirt_front:
            return "skirt_front";
        case Region::skirt_back:
            return "skirt_back";
        case Region::leg_left_front:
            return "leg_left_front";
        case Region::leg_left_back:
            return "leg_left_back";
        case Region::leg_right_front:
            return "leg_right_front";
        case Region::leg_right_back:
            return "leg_right_back";
    }
    return "?";
}

/// A sleeve region.
inline bool is_sleeve(Region r) {
    return r == Region::sleeve_left || r == Region::sleeve_right;
}

/// A trouser-leg region.
inline bool is_leg(Region r) {
    return r == Region::leg_left_front || r == Region::leg_left_back ||
           r == Region::leg_right_front || r == Region::leg_right_back;
}

/// A region on the body's front (torso, skirt or trouser leg).
inline bool is_front(Region r) {
    return r == Region::torso_front || r == Region::skirt_front || r == Region::leg_left_front ||
           r == Region::leg_right_front;
}

/// How pieces are wrapped around the body.
struct PlacementOptions {
    double gap_mm = 15;       ///< clearance between the body and the wrapped pieces
    double slice_mm = 10;     ///< height step of the torso cross-sections
    double layer_gap_mm = 6;  ///< extra radial offset between overlapping pieces
};

/// How seams are sewn: strings along the body, pulled shut over `sew_seconds`.
struct SewingOptions {
    double sew_seconds = 0.6;      ///< the strings shrink to zero over this simulated time
    double settle_seconds = 1.4;   ///< simulated time after the seams are closed
    double max_extra_seconds = 2;  ///< more settling while the cloth still moves
    /// Velocity damping (fraction lost per second) during that extra settling: it changes how
    /// fast the garment comes to rest, not where.
    double settle_damping_per_second = 6;
    double string_offset_mm = 8;  ///< strings run this far outside the skin
    double compliance = 1e-4;     ///< XPBD compliance of the sewing pull, mm/N
    /// Seams whose two sides differ by more than this fraction of the longer are reported as not
    /// closable (they are still sewn; the report names them).
    double length_mismatch = 0.15;
    /// After sewing, pairs closer than this are welded into one vertex for the drape (0: half
    /// the resolution); pairs further apart stay zero-length stitches.
    double weld_within_mm = 0;
};

/// Everything dress() needs besides the body and the pattern.
struct DressOptions {
    double resolution_mm = 10;  ///< target cloth edge length
    /// How the pieces are wrapped around the body.
    PlacementOptions placement;
    /// How the seams are sewn and how long the garment settles.
    SewingOptions sewing;
    /// Solver steps of both phases; a zero body_clearance_mm becomes the larger of the fabric's
    /// thickness and a sixth of resolution_mm. 40 sub-steps per frame by default: with the
    /// solver's own 10, garments at 20 mm and finer are so much softer than their fabric that
    /// they slide off the shoulders (the GarmentCode shirt's top 208 mm below its placement at
    /// 20 mm, 55 mm with 40; at 10 mm it falls off the body).
    DrapeOptions drape = [] {
        DrapeOptions d;
        d.substeps = 40;
        return d;
    }();
    /// The fabric of every piece.
    FabricParams fabric;
    std::vector<std::string> without_pieces;  ///< pieces left out (with their seams), by name
    /// After the drape, solve for the static equilibrium (DrapeSolver::relax): the sub-stepped
    /// solver leaves cloth hanging from the shoulders stretched by its few constraint passes,
    /// the direct solve takes it to the fabric's own stretch.
    bool relax = true;
    /// How; it stops once settled: five accepted steps in a row after the releases that moved
    /// at most 0.1 % of the vertices more than 0.3 mm (a tenth of the report's static gate).
    RelaxOptions relax_options = [] {
        RelaxOptions r;
        r.settle_iterations = 5;
        return r;
    }();
    /// How the solves after a flattening of fold-overs run (see smooth_folds): from a garment
    /// at rest but for the flattened patches, a shorter schedule, friction from the tenth
    /// iteration and releases until the twentieth (the first solve's 30 and 45 made each of
    /// them run 50 iterations or more). Friction from the first iteration held the stretch the
    /// first solve had left: the T-shirt at 20 mm then ended at p95 1.056 (docs/garment.md).
    RelaxOptions relax_again_options = [] {
        RelaxOptions r;
        r.settle_iterations = 5;
        r.friction_from_iteration = 10;
        r.release_until_iteration = 20;
        return r;
    }();
    /// The static solve holds the cloth above every body vertex too
    /// (DrapeSolver::set_body_points, reach: the grid's cell), not only its vertices and edge
    /// midpoints against the grid, which rounds off bumps narrower than a few cells.
    bool body_points = true;
    /// Flatten the cloth's fold-overs (DrapeSolver::smooth_fold_overs) after the drape and,
    /// where the static solve folds cloth over again, after it and solve again: `fold_cycles`
    /// static solves at most (>= 1).
    bool smooth_folds = true;
    FoldOptions fold_options;  ///< how
    /// Static solves at most (>= 1): another runs only where the flattening after a solve found
    /// fold-overs.
    int fold_cycles = 4;
    double sdf_cell_mm = 5;  ///< cell of the body's signed-distance grid
    /// Hold the open waist edges the pattern labels (`waist`, GarmentCode's `lower_interface`) at
    /// their height during the drape and the static solve, as a waistband does (waistband.h).
    bool waistband = true;
    /// How firmly: the band alone would carry the whole garment's weight this far below the
    /// height it holds (mm, finite, > 0); a linear spring along the vertical, shared equally by
    /// the held vertices, so the same at any resolution. The hips carry what they can: a waist
    /// that sits on them is not pulled up, and the crotch of trousers whose rise is a little
    /// short for the body pulls the waist down a little instead of stretching.
    double waistband_sag_mm = 20;
};

/// Sewing quality of one seam at the end of the drape.
struct SeamReport {
    /// The seam's name in the pattern.
    std::string name;
    /// Stitch pairs (a vertex on each side, joined by one string) along the seam.
    std::size_t pairs = 0;
    /// Lengths of the two sides in the pattern, mm.
    ///@{
    double side_a_mm = 0, side_b_mm = 0;
    ///@}
    double string_mm = 0;  ///< mean length of its strings before sewing
    /// Mean and largest distance between the two vertices of its pairs after the drape, mm.
    ///@{
    double gap_mean_mm = 0, gap_max_mm = 0;
    ///@}
    /// False when its sides differ by more than SewingOptions::length_mismatch of the longer
    /// side; the seam is sewn all the same.
    bool closable = true;
    std::string problem;  ///< why it is not closable (empty when it is)
};

/// Where each piece went.
struct PieceReport {
    /// The piece's name in the pattern.
    std::string name;
    /// The body region it was wrapped around, as to_string(Region) spells it.
    std::string region;
    /// Vertices and triangles of its cloth mesh (at DressOptions::resolution_mm).
    ///@{
    std::size_t vertices = 0, triangles = 0;
    ///@}
    std::size_t placed_inside = 0;  ///< its vertices inside the body after placement
};

/// One quality gate: a measured value against its limit.
struct Gate {
    /// The QualityFigures member it checks ("stretch_p95", "max_depth_mm", ...).
    std::string name;
    /// The measured value and the largest value that passes.
    ///@{
    double value = 0, limit = 0;
    ///@}
    /// value <= limit.
    bool passed = false;
};

/// Quality figures of a draped garment (quality.h).
struct QualityFigures {
    /// Garment vertices inside the closed body (exact inside test).
    std::size_t vertices_inside_body = 0;
    double max_depth_mm = 0;              ///< deepest cloth vertex inside the body
    std::size_t edges_crossing_body = 0;  ///< cloth edges crossing body triangles
    /// Midpoints of the first (up to 100) crossing edges, mm: where to look.
    std::vector<Vec3> body_crossing_points;
    std::size_t self_intersections = 0;  ///< cloth edges crossing cloth triangles
    /// Midpoints of the first (up to 100) cloth edges crossing cloth triangles, mm.
    std::vector<Vec3> self_crossing_points;
    /// The self-intersections by the pair of pieces they join, "edge's piece / triangle's piece"
    /// with the names in order (one name when both are of the same piece), most first.
    std::vector<std::pair<std::string, std::size_t>> self_crossings_by_pieces;
    /// Median, 95th percentile and maximum over the triangles of the largest principal stretch
    /// (triangle_stretch(); 1: unstretched).
    ///@{
    double stretch_median = 1, stretch_p95 = 1, stretch_max = 1;
    ///@}
    double stretch_above_105_percent = 0;  ///< % of triangles with a stretch above 1.05
    /// The 95th-percentile stretch of the triangles lying on the body (centroid within the
    /// contact band of the skin, garment_quality()) and of the others: stretch on the body is
    /// the garment's fit, stretch off it is the cloth's own sag under gravity and the solver's
    /// softness. 1 when there is no such triangle (or no band was given).
    ///@{
    double stretch_p95_on_body = 1, stretch_p95_off_body = 1;
    ///@}
    double triangles_on_body_percent = 0;  ///< % of triangles lying on the body
    double moving_fraction = 0;            ///< vertices that moved > 0.3 mm in the last frame
    /// Largest distance between the two vertices of a stitch pair at the end of the drape, mm.
    double stitch_gap_max_mm = 0;
    /// How far the garment's highest point came down from where the placement put it, mm (up
    /// the body's axis): a garment hangs from the body a few millimetres below its placement;
    /// one that slid down or fell off the body shows here whatever the other figures say.
    double top_drop_mm = 0;
};

/// One opening of a garment (a boundary loop of the welded mesh; openings.h). Canonical frame,
/// mm.
struct Opening {
    std::vector<std::uint32_t> loop;  ///< its vertices in order around it
    std::vector<Vec3> points;         ///< their positions
    double height_mm = 0;             ///< mean height (y) of its vertices
    double length_mm = 0;             ///< length of the closed 3D polyline
    /// Extents along the canonical x (left) and z (front) axes: a hem's width and depth.
    ///@{
    double width_mm = 0, depth_mm = 0;
    ///@}
    Vec3 normal{0, 1, 0};          ///< unit normal of its plane (Newell), pointing up (y ≥ 0)
    double hull_perimeter_mm = 0;  ///< perimeter of the convex hull of its plane projection
    int folds = 0;                 ///< peaks of the depth inside that hull (file comment)
    double deepest_fold_mm = 0;    ///< largest depth inside the hull
    /// Signed distance of its vertices from the body (filled by the caller; 0 when not).
    ///@{
    double clearance_mean_mm = 0, clearance_max_mm = 0;
    ///@}
};

/// What dress() did and how good the garment is.
struct DressReport {
    /// One per piece dressed, in the pattern's order (pieces left out have none).
    std::vector<PieceReport> pieces;
    /// One per seam sewn, in the pattern's order (seams of pieces left out have none).
    std::vector<SeamReport> seams;
    /// Vertices and triangles of the cloth of all pieces, before welding.
    ///@{
    std::size_t cloth_vertices = 0, cloth_triangles = 0;
    ///@}
    std::size_t garment_vertices = 0;           ///< after welding
    std::size_t boundary_loops = 0;             ///< openings of the welded garment
    std::size_t pairs_welded_before_drape = 0;  ///< stitch pairs closed by the sewing phase
    /// Vertices of the welded cloth the waistband holds at their height (0: none; waistband.h).
    std::size_t waistband_vertices = 0;
    double body_clearance_mm = 0;                   ///< distance the cloth kept from the body, mm
    std::size_t placement_vertices_inside = 0;      ///< after placement (must be 0)
    std::size_t placement_piece_intersections = 0;  ///< after placement (must be 0)
    /// Quality figures of the welded garment.
    QualityFigures quality;
    /// quality_gates() of `quality`.
    std::vector<Gate> gates;
    /// Every gate passed.
    bool passed = false;
    /// Solver frames run, sewing and drape together.
    std::size_t frames = 0;
    /// Simulated time of sewing and drape together, s.
    double simulated_seconds = 0;
    /// Wall ms per solver frame per 10 000 cloth vertices (the static solve left out).
    double ms_per_step_per_10k = 0;
    /// Wall times, seconds.
    ///@{
    double measure_seconds = 0, sdf_seconds = 0, placement_seconds = 0, strings_seconds = 0,
           drape_seconds = 0, quality_seconds = 0, total_seconds = 0;
    ///@}
    /// DrapeOptions::threads as given (0: all cores).
    int threads = 0;
    /// The last static solve (DressOptions::relax; iterations 0 when it did not run).
    RelaxReport relax;
    /// Every static solve, in order (the first with DressOptions::relax_options, the others
    /// with relax_again_options; empty when none ran).
    std::vector<RelaxReport> relax_solves;
    /// Static solves run (1 + the flattenings that found fold-overs after one, at most
    /// DressOptions::fold_cycles; 0 without the static solve).
    int relax_runs = 0;
    /// Each flattening of fold-overs, in order: after the drape, then after each static solve
    /// (DressOptions::smooth_folds; empty when it did not run).
    std::vector<FoldReport> folds;
    /// The garment's openings (garment_openings()), lowest first, with their clearance from the
    /// body.
    std::vector<Opening> openings;
};

/// A triangle mesh with per-corner pattern coordinates (the welded garment).
struct GarmentMesh {
    std::vector<Vec3> positions;                ///< mm
    std::vector<Tri> triangles;                 ///< vertex indices
    std::vector<std::array<UV, 3>> uv;          ///< per corner, pattern mm
    std::vector<std::uint32_t> triangle_piece;  ///< piece index of each triangle
    std::vector<std::string> piece_names;       ///< per piece
    /// Per triangle: unit warp direction in its pattern coordinates (the piece's grainline;
    /// empty: the pattern's +y axis everywhere).
    std::vector<UV> grain;
};

}  // namespace tapeline::garment
