// Options, report and result of pattern grading (grade.h). Light header (the pattern model only):
// no Ceres, no pagmo, no CGAL, so
// that loggers, the command-line tool and test facades can include it cheaply (DESIGN.md §3).
#pragma once

#include <tapeline/pattern/pattern.h>
#include <tapeline/pattern/seam_chains.h>

#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tapeline::grading {

/// How a binding's ease follows the measurement it is bound to.
enum class EaseMode {
    keep_mm,      ///< the ease in mm stays what the base pattern realises
    proportional  ///< ease / measurement stays what the base pattern realises (FreeSewing's eases
                  ///< are fractions of the measurement, e.g. chestEase 0.15)
};

inline const char* to_string(EaseMode m) {
    return m == EaseMode::keep_mm ? "keep_mm" : "proportional";
}

/// Weights of the residual groups (grading/README.md gives each formula). Fit and seam residuals
/// are in mm; style and smoothness residuals are made lengths by the reference length
/// `GradingOptions::reference_length_mm`, so a weight of 1 means "1 unit here costs as much as
/// 1 mm of fit error".
struct GradingWeights {
    double fit = 100;          ///< per mm of binding error
    double seam = 100;         ///< per mm of seam length difference
    double angle = 10;         ///< per radian of turn-angle change at an outline vertex, × L_ref
    double curve = 1;          ///< per unit of Bézier control-polygon shape change, × chord
    double proportion = 0.05;  ///< per mm of deviation from a uniform per-piece scale
    double grain = 1;          ///< per radian of grain-direction change, × L_ref
    double consistency = 5;    ///< per mm of departure from the local affine displacement model
    double bending = 2;        ///< per unit change of the displacement gradient between neighbours
    double global = 0.2;       ///< per unit of a node's gradient away from the garment's mean
    double trim = 1;  ///< per unit of a trim's gradient across it (GradingOptions::trim_aspect)
};

/// When a graded pattern counts as fitting (the default-solution rule).
struct GradingTolerances {
    double fit_mm = 2;   ///< every bound measurement within this (the default-solution rule)
    double seam_mm = 1;  ///< every seam's two sides within this
};

/// A seam to keep while grading: the outline edges of side A are sewn to those of side B. A side
/// may span several pieces (a sleeve cap against the front and the back armhole). The pattern's
/// own seams (`Pattern::seams`) are used as well.
/// Seams beyond the pattern's own that grading holds: sides of several edge ranges allowed.
using pattern::SeamSpec;

/// Everything grade_pattern can be told; the defaults are the command-line tool's.
struct GradingOptions {
    std::uint32_t seed = 42;       ///< seed of the NSGA-II population
    std::size_t population = 32;   ///< NSGA-II population (rounded up to a multiple of 4, ≥ 8)
    std::size_t generations = 60;  ///< NSGA-II generations; 0 skips the evolutionary search
    EaseMode ease = EaseMode::proportional;  ///< how eases follow their measurements
    GradingWeights weights;                  ///< weights of the residual groups
    GradingTolerances tolerances;            ///< when a candidate fits
    std::size_t threads = 0;                 ///< 0: TBB's default
    bool ceres_polish = true;                ///< polish each front member by Ceres least squares
    std::size_t ceres_iterations = 50;       ///< per solve; more changed no table entry (measured)
    double reference_length_mm = 100;        ///< L_ref: turns angles and strains into lengths
    std::size_t neighbours = 8;              ///< k of the per-piece k-nearest-node smoothness graph
    /// Pareto members polished by Ceres get fit weights weights.fit · f, f log-spaced over
    /// [min_fit_factor, max_fit_factor] along the front (low f: style first).
    ///@{
    double min_fit_factor = 0.01, max_fit_factor = 10;
    ///@}
    /// A girth bound over several pieces grows each piece's part in proportion to its base share
    /// (the way commercial grade rules split a girth increment between front and back), instead of
    /// only fixing the sum.
    bool split_girths = true;
    /// A straight strip (at least this many times longer than wide, filling ≥ 80 % of its box: a
    /// binding strip, a placket) is a trim: graded in length only, as commercial grade rules treat
    /// trims (its width is held by the trim prior instead of growing with the garment). 0: off.
    double trim_aspect = 5;
    /// A bound measurement whose target is more than this many times its base value, or less
    /// than its base value divided by this, is refused (InvalidInput) instead of graded: no grade
    /// of one draft spans a factor of 3 (a child's chest is about 0.6 of an adult's), and a
    /// target in another unit or of garbage would draft a pattern kilometres or microns wide.
    /// 0: no limit.
    double max_target_ratio = 3;
};

/// One row of the fit table: the body measurement the pattern now fits (pattern dimension minus
/// ease) against the target.
struct FitRow {
    std::string measurement;  ///< the bound measurement
    std::string where;        ///< pieces of the features
    double target_mm = 0;     ///< value in the target set
    double ease_mm = 0;       ///< ease the graded pattern keeps
    double achieved_mm = 0;   ///< pattern dimension minus ease
    double error_mm = 0;      ///< achieved − target
};

/// One row of the seam table: the two sides' lengths after grading.
struct SeamRow {
    std::string name;  ///< seam name
    /// Lengths of side A and side B.
    ///@{
    double length_a_mm = 0, length_b_mm = 0;
    ///@}
    /// a / b kept from the base draft: 1 for a seam whose sides are equal there (within the seam
    /// tolerance), else the base draft's deliberate ratio (sleeve-cap ease, a stretched binding)
    double ratio = 1;
    double mismatch_mm = 0;  ///< |a − ratio · b|
};

/// Style of the graded pattern against the base (each a change, 0 = unchanged).
struct StyleMetrics {
    double max_angle_change_deg = 0;   ///< turn angles at outline vertices
    double mean_angle_change_deg = 0;  ///< mean over outline vertices
    double max_curve_change = 0;       ///< Bézier control points in their chord frame (fraction)
    double proportion_spread = 0;      ///< (max − min)/mean of per-edge stretch within a piece
    double max_grain_change_deg = 0;   ///< grain lines
    double cost = 0;                   ///< the weighted style objective f2 (mm², see README)
};

/// One candidate of the search: its two objectives and how it was made.
struct ParetoPoint {
    double fit = 0;                   ///< f1: RMS of fit and seam residuals (mm)
    double style = 0;                 ///< f2: RMS of style residuals (mm-equivalent)
    double max_fit_error_mm = 0;      ///< worst binding error
    double max_seam_mismatch_mm = 0;  ///< worst seam mismatch
    bool polished = false;            ///< Ceres polished it
    bool within_tolerance = false;    ///< within GradingOptions::tolerances
    std::string origin;               ///< "nsga2", "nsga2+ceres", "ceres"
};

/// Wall-clock seconds of the grading phases.
struct GradingTimings {
    /// Set-up, Ceres from the base, NSGA-II, polishing, total.
    ///@{
    double setup_s = 0, ceres_fast_path_s = 0, nsga2_s = 0, polish_s = 0, total_s = 0;
    ///@}
};

/// What grading did and how well the chosen pattern fits.
struct GradingReport {
    /// Pieces, outline nodes, and the least-squares problem's variables and residuals.
    ///@{
    std::size_t pieces = 0, nodes = 0, variables = 0, residuals = 0;
    ///@}
    std::vector<FitRow> fit;         ///< fit table
    std::vector<SeamRow> seams;      ///< seam table
    StyleMetrics style;              ///< style change of the chosen pattern
    std::vector<ParetoPoint> front;  ///< every candidate, NSGA-II members and polished ones
    std::size_t chosen = 0;          ///< index into front
    std::string chosen_why;          ///< why `chosen` was picked
    /// Worst fit error and seam mismatch of the chosen pattern.
    ///@{
    double max_fit_error_mm = 0, max_seam_mismatch_mm = 0;
    ///@}
    bool within_tolerance = false;     ///< both within GradingOptions::tolerances
    std::size_t ceres_iterations = 0;  ///< of the fast path
    std::string ceres_status;          ///< Ceres' termination of the fast path
    std::size_t evaluations = 0;       ///< NSGA-II fitness evaluations
    GradingTimings timings;            ///< phase timings
    std::vector<std::string> notes;    ///< remarks for the user
};

/// One grade rule: where a named point or outline vertex of a piece goes.
struct GradeRule {
    /// Piece, and point: a named point, or "edge k" for the start of outline edge k.
    ///@{
    std::string piece, point;  // point: a named point, or "edge k" for the start of outline edge k
    ///@}
    /// Position in the base and in the graded pattern.
    ///@{
    pattern::Point2 base, graded;
    ///@}
};

/// What grade_pattern returns.
struct GradeResult {
    pattern::Pattern pattern;      ///< the graded pattern (the chosen candidate)
    GradingReport report;          ///< fit and seam tables, front, timings
    std::vector<GradeRule> rules;  ///< where every named point and outline vertex went
};

}  // namespace tapeline::grading
