// Virtual fabric tests: the laboratory tests a fabric is measured with, simulated by the cloth
// solver (drape_solver.h) on the fabric's own parameters, so that a fabric's numbers can be seen
// to come back out of the simulation.
//
//  - Peirce cantilever (F. T. Peirce, J. Text. Inst. 21, 1930; ASTM D1388; SiroFAST-2): a strip
//    25 mm wide, held flat on a table by its template, is pushed over the edge until its tip
//    touches the plane through the edge inclined 41.5° below the horizontal; the overhang is then
//    twice the bending length C, and B = W·g·C³. The heavy elastica gives exactly this: solving
//    B·θ'' = −w·(l − s)·cos θ with θ(0) = 0, θ'(l) = 0 puts the tip chord at 41.49° for
//    w·l³/B = 8, i.e. l = 2C. Quasi-static: for each overhang the strip is let down from flat,
//    clamped at the edge, and run to rest; the overhang whose rest shape has its tip on the 41.5°
//    line is found by a log-log secant on the tip chord angle (|angle − 41.5°| < 0.02°).
//  - Tensile strip (KES-F, SiroFAST-3): a strip 50 mm wide and 100 mm long between clamps, one
//    end held, the other pulled with 5, 20 and 100 gf/cm spread over its width; strain from the
//    pulled end's displacement at rest.
//  - Bias extension (SiroFAST-3 EB5): a strip cut at 45° to the warp, 50 × 200 mm, pulled at both
//    ends with 5 gf/cm; in its middle third the stress is a uniaxial T along the bias, i.e.
//    T/2 on warp, weft and shear in the grain frame, so the shear angle γ (warp–weft angle minus
//    90°) gives G = (T/2)/γ.
//  - Cusick drape test (BS 5058, ISO 9073-9): a disc 300 mm across clamped on a support disc
//    180 mm across, let fall, run to rest and brought to its static equilibrium; the shadow
//    (projection from above, rasterised at 0.5 mm) gives the drape coefficient DC = (S −
//    A_pedestal)/(A_disc − A_pedestal) and the outline's number of nodes (folds).
//
// Loads are applied through attachments to targets 10 km away whose compliance makes their pull
// the wanted force (the pull changes by the displacement over 10 km, below 1e-5). All tests run
// without gravity except the cantilever and Cusick tests. Pictures go through the drawing module.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/vec2.h>
#include <tapeline/draw/canvas.h>
#include <tapeline/garment/bending.h>
#include <tapeline/garment/collider.h>
#include <tapeline/garment/drape_solver.h>
#include <tapeline/garment/fabric_lab.h>
#include <tapeline/garment/openings.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <random>
#include <string>
#include <vector>

namespace tapeline::garment {

/// How a virtual fabric test runs.
struct FabricTestOptions {
    double resolution_mm = 10;   ///< target cloth edge length, mm
    int threads = 1;             ///< solver threads (0: all cores)
    double perturbation_mm = 0;  ///< Cusick: random vertical offsets of the flat start, mm
    std::uint32_t seed = 1;      ///< of the perturbation
    double max_seconds = 30;     ///< simulated-time limit of one run to rest
    int iterations = 1;          ///< constraint passes per sub-step (cantilever)
    bool static_solve = true;    ///< Cusick: bring the rest to its static equilibrium
};

/// A pedestal: the vertical cylinder of `radius` around the y axis with its flat top at y = top,
/// `depth` deep (infinitely deep by default; 0: a flat disc): signed distance and gradient in
/// closed form.
class PedestalCollider : public Collider {
public:
    /// A pedestal of `radius` whose top is at height `top` and whose bottom is `depth` below it,
    /// all mm.
    PedestalCollider(double radius, double top,
                     double depth = std::numeric_limits<double>::infinity())
        : radius_(radius), top_(top), depth_(depth) {}
    double signed_distance(const Vec3& p, Vec3* gradient) const override {
        const double r = std::hypot(p[0], p[2]);
        const double dr = r - radius_;
        // Distance outside the slab between the bottom and the top, and which face is nearer.
        const double above = p[1] - top_, below = top_ - depth_ - p[1];
        const double dy = std::max(above, below);
        const double sy = above >= below ? 1.0 : -1.0;
        const Vec3 radial = r > 1e-12 ? Vec3{p[0] / r, 0, p[2] / r} : Vec3{1, 0, 0};
        double d;
        Vec3 g;
        if (dr > 0 && dy > 0) {
            d = std::hypot(dr, dy);
            g = {radial[0] * dr / d, sy * dy / d, radial[2] * dr / d};
        } else if (dr > dy) {
            d = dr;
            g = radial;
        } else {
            d = dy;
            g = {0, sy, 0};
        }
        if (gradient) {
            *gradient = g;
        }
        return std::isfinite(d) ? d : std::numeric_limits<double>::quiet_NaN();
    }

private:
    double radius_, top_, depth_;
};

namespace internal {

// A rectangular strip in the x–z plane at height y: nx × ny cells of cell_x × cell_z starting at
// (x0, y, z0) (the first column first_cell_x wide when given), rest coordinates (x, z), right
// triangles with alternating diagonals, grain `grain` in those rest coordinates.
inline ClothModel strip_model(int nx, int ny, double cell_x, double cell_z, double x0, double y,
                              double z0, UV grain, double first_cell_x = 0) {
    ClothModel c;
    const double first = first_cell_x > 0 ? first_cell_x : cell_x;
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            c.positions.push_back(
                {x0 + (i == 0 ? 0.0 : first + (i - 1) * cell_x), y, z0 + j * cell_z});
        }
    }
    auto at = [&](int i, int j) { return static_cast<std::uint32_t>(j * (nx + 1) + i); };
    auto uv = [&](std::uint32_t v) { return UV{c.positions[v][0], c.positions[v][2]}; };
    auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t d) {
        c.triangles.push_back({a, b, d});
        c.rest_uv.push_back({uv(a), uv(b), uv(d)});
        c.grain.push_back(grain);
    };
    for (int j = 0; j < ny; ++j) {
        for (int i = 0; i < nx; ++i) {
            if ((i + j) % 2 == 0) {
                add(at(i, j), at(i + 1, j + 1), at(i + 1, j));
                add(at(i, j), at(i, j + 1), at(i + 1, j + 1));
            } else {
                add(at(i, j), at(i, j + 1), at(i + 1, j));
                add(at(i + 1, j), at(i, j + 1), at(i + 1, j + 1));
            }
        }
    }
    return c;
}

// A rectangular strip `width` wide across z, in the x–z plane at y = 0, meshed near-equilateral as
// the drapes' pieces (Delaunay refinement) and the Cusick disc are: columns of vertices across the
// strip at x = k·cell_x, k = 0 … nx, with one more at x = −first_cell_x when first_cell_x > 0;
// rows cell_x·2/√3 apart (equilateral triangles when that divides the width), every odd column
// offset by half a row with the strip's two edges added; consecutive columns zipped in z. Every
// vertex of a column is then the wing of the one edge of the next column it faces, so a bend
// across the strip loads the whole width. On right triangles with alternating diagonals only
// every other vertex of a column is a wing of the next column's edges, and the strip sags
// through the zigzag that leaves: a short strip 17 % beyond the beam of its segments (this mesh:
// 2.4 %), and over twice its bending length a tip 6.5 % lower with a shear rigidity of 26.5 N/m
// than with 3000 (this mesh: 0.7 %; tests/garment/test_fabric_tests.cpp). `columns` receives each
// column's vertices in z order.
inline ClothModel lattice_strip_model(int nx, double cell_x, double width, double first_cell_x,
                                      UV grain, std::vector<std::vector<std::uint32_t>>& columns) {
    ClothModel c;
    const int rows =
        std::max(1, static_cast<int>(std::lround(width / (cell_x * 2 / std::sqrt(3.0)))));
    const double dz = width / rows;
    columns.clear();
    auto add_column = [&](double x, bool offset) {
        std::vector<double> zs;
        if (offset) {
            zs.push_back(-width / 2);
            for (int j = 0; j < rows; ++j) {
                zs.push_back(-width / 2 + (j + 0.5) * dz);
            }
            zs.push_back(width / 2);
        } else {
            for (int j = 0; j <= rows; ++j) {
                zs.push_back(-width / 2 + j * dz);
            }
        }
        columns.emplace_back();
        for (double z : zs) {
            columns.back().push_back(static_cast<std::uint32_t>(c.positions.size()));
            c.positions.push_back({x, 0, z});
        }
    };
    if (first_cell_x > 0) {
        add_column(-first_cell_x, false);
    }
    for (int k = 0; k <= nx; ++k) {
        add_column(k * cell_x, k % 2 == 1);
    }
    auto uv = [&](std::uint32_t v) { return UV{c.positions[v][0], c.positions[v][2]}; };
    auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t d) {
        c.triangles.push_back({a, b, d});
        c.rest_uv.push_back({uv(a), uv(b), uv(d)});
        c.grain.push_back(grain);
    };
    for (std::size_t k = 0; k + 1 < columns.size(); ++k) {
        const auto& a = columns[k];
        const auto& b = columns[k + 1];
        std::size_t i = 0, j = 0;
        while (i + 1 < a.size() || j + 1 < b.size()) {
            const bool advance_a =
                j + 1 >= b.size() ||
                (i + 1 < a.size() && c.positions[a[i + 1]][2] <= c.positions[b[j + 1]][2] + 1e-9);
            if (advance_a) {
                add(a[i], a[i + 1], b[j]);
                ++i;
            } else {
                add(a[i], b[j + 1], b[j]);
                ++j;
            }
        }
    }
    return c;
}

// Runs the solver until a frame moves no vertex more than `still_mm` three frames in a row, or
// `max_seconds` of simulated time; returns whether it came to rest.
inline bool run_to_rest(DrapeSolver& solver, double still_mm, double max_seconds,
                        std::size_t* frames = nullptr) {
    int quiet = 0;
    std::size_t f = 0;
    const auto limit = static_cast<std::size_t>(max_seconds / solver.options().frame_seconds);
    for (; f < limit && quiet < 3; ++f) {
        const StepReport r = solver.step();
        quiet = r.max_move_mm < still_mm ? quiet + 1 : 0;
    }
    if (frames) {
        *frames = f;
    }
    return quiet >= 3;
}

// Attachments that pull vertices `ids` (with weights summing to 1) with `force_n` in total along
// `direction` (unit): each is tied to a target 1e7 mm away with compliance distance/force.
inline std::vector<Attachment> pulls(const DrapeSolver& s, const std::vector<std::uint32_t>& ids,
                                     const std::vector<double>& weights, double force_n,
                                     const Vec3& direction) {
    constexpr double far = 1e7;
    std::vector<Attachment> out;
    for (std::size_t k = 0; k < ids.size(); ++k) {
        const Vec3& p = s.positions()[ids[k]];
        Attachment a;
        a.vertex = ids[k];
        a.target = {p[0] + far * direction[0], p[1] + far * direction[1],
                    p[2] + far * direction[2]};
        a.compliance = far / (force_n * weights[k]);
        out.push_back(a);
    }
    return out;
}

inline void check_options(const FabricTestOptions& o, const FabricParams& f) {
    if (!(std::isfinite(o.resolution_mm) && o.resolution_mm >= 1 && o.resolution_mm <= 50)) {
        throw InvalidInput("fabric test: resolution must be within 1 and 50 mm, got " +
                           std::to_string(o.resolution_mm));
    }
    if (!(o.perturbation_mm >= 0 && o.perturbation_mm <= 10)) {
        throw InvalidInput("fabric test: perturbation must be within 0 and 10 mm");
    }
    if (!(o.max_seconds > 0) || o.threads < 0) {
        throw InvalidInput("fabric test: max_seconds must be > 0 and threads >= 0");
    }
    if (!(f.density_g_m2 > 0) || !(f.bending_un_m >= 0) || !(f.stretch_warp_n_m > 0) ||
        !(f.stretch_weft_n_m > 0) || !(f.shear_n_m > 0)) {
        throw InvalidInput("fabric test: fabric '" + f.name +
                           "' needs positive density, stretch and shear and non-negative bending");
    }
}

/// Solver options of a strip pulled without gravity (tensile and bias tests): the blow-up check
/// off (the pull does work it does not count; it knows gravity's only), and sub-steps in the
/// explicit-like regime of the stretch constraints (α/h² ≫ Σw|∇C|²) so that the rest strain is
/// the fabric's and not the step's: h = 0.1/ω, ω² = k·A·Σw|∇C|², Σw|∇C|² ≈ 2·(3/m)/dx². The
/// caller sets the damping.
inline DrapeOptions pulled_strip_options(const FabricParams& f, double dx, double dz, int threads) {
    DrapeOptions opt;
    opt.gravity = {0, 0, 0};
    opt.self_collision = false;
    opt.max_energy_growth = 1e12;
    opt.threads = threads;
    const double kmax = std::max({f.stretch_warp_n_m, f.stretch_weft_n_m, f.shear_n_m});
    const double area = dx * dz / 2, m = f.density_g_m2 * 1e-9 * dx * dz / 3;
    const double omega =
        std::sqrt(kmax * area * 2 * (3 / m) / (std::min(dx, dz) * std::min(dx, dz)));
    opt.frame_seconds = 1.0 / 300;
    opt.substeps =
        std::clamp(static_cast<int>(std::ceil(opt.frame_seconds * omega / 0.1)), 10, 20000);
    return opt;
}

}  // namespace internal

// ---------------------------------------------------------------------------------------------
// Peirce cantilever

/// Result of the cantilever test in one direction.
struct CantileverResult {
    std::string direction;                          ///< "warp" or "weft"
    double target_mm = 0;                           ///< the fabric's bending length (B/(W·g))^⅓
    double overhang_mm = 0;                         ///< overhang whose tip lies on the 41.5° line
    double bending_length_mm = 0;                   ///< overhang / 2
    double error_pct = 0;                           ///< (simulated − target)/target·100
    double tip_angle_deg = 0;                       ///< tip chord angle of the last run
    int runs = 0;                                   ///< simulations run (one per overhang tried)
    std::size_t vertices = 0;                       ///< of the last strip
    int substeps = 0;                               ///< per 1/30 s frame
    bool settled = true;                            ///< every run came to rest
    double seconds = 0;                             ///< wall time
    std::vector<std::array<double, 2>> centreline;  ///< (x, y) of the last rest shape, mm
};

/// Tip chord angle (degrees below the horizontal) of a strip of `overhang` mm clamped at the
/// table edge, at rest; `line` receives the centre line.
inline double cantilever_tip_angle(const FabricParams& fabric, bool weft, double overhang,
                                   const FabricTestOptions& o, bool* settled, std::size_t* verts,
                                   int* substeps, std::vector<std::array<double, 2>>* line) {
    const double width = 25, res = o.resolution_mm;
    const int nx = std::max(2, static_cast<int>(std::ceil(overhang / res - 1e-9)));
    const double dx = overhang / nx;
    // A narrow row of cells on the table (held by the template: pinned), nx beyond the edge at
    // x = 0. The hinge on the edge line then bends over half its dual length (b/2 beyond the
    // edge, a/2 → 0 on the table): k = 2·B·|e|/(a + b) → 2·B·|e|/b, which is the clamp's
    // boundary condition; a full cell on the table would let the edge hinge turn as if the strip
    // were free over a/2 behind the edge, an error of order one cell in the overhang.
    const double table_cell = 1e-3 * dx;
    std::vector<std::vector<std::uint32_t>> columns;
    ClothModel strip = internal::lattice_strip_model(nx, dx, width, table_cell,
                                                     weft ? UV{0, 1} : UV{1, 0}, columns);
    const double dz = width / static_cast<double>(columns.front().size() - 1);  // row spacing
    strip.pinned.assign(strip.positions.size(), 0);
    for (std::size_t v = 0; v < strip.positions.size(); ++v) {
        strip.pinned[v] = strip.positions[v][0] <= 1e-9 ? 1 : 0;
    }
    // No collider: the strip on the table is pinned, and beyond the edge it never comes back
    // over the table on its way to 41.5°. A table under the strip's mid-surface keeps the cloth
    // a clearance (the fabric's thickness) from its edge, and bending down at the clamp brings
    // the strip's first edge within that of the corner at once: the edge contact then pushes it
    // up, a rounded edge instead of Peirce's clamp (cotton jersey over 2C at 5 mm: tip 40.8°
    // with a table, 42.9° without, 42.8° from the static solve of the strip's own energies;
    // tests/garment/test_fabric_tests.cpp).
    FabricParams f = fabric;
    f.friction = 0;
    DrapeOptions opt;
    opt.self_collision = false;
    opt.threads = o.threads;
    // Sub-steps: the bending hinges must stay compliant (α/h² well above the inverse mass term)
    // for the rest shape to be the fabric's, not the step's: h ≤ 0.1/ω with ω² ≈ k·Σw|∇θ|² of
    // the stiffest hinge, k = B·|e|²/A_e ≈ B·dz/dx, Σw|∇θ|² ≈ 4·(3/m)/dx², m = W·dx·dz/3.
    const double b = bending_rigidity_un_m(f, weft ? 0 : 1, weft ? 1 : 0);
    const double m = f.density_g_m2 * 1e-9 * dx * dz / 3;
    const double omega = std::sqrt(std::max(b, 1e-9) * (dz / dx) * 4 * (3 / m) / (dx * dx));
    opt.substeps =
        std::clamp(static_cast<int>(std::ceil(opt.frame_seconds * omega / 0.1)), 20, 4000);
    // About half the critical damping of the first mode (ω₁ = 3.516·√(B/(ρ·l⁴))): the rest
    // shape does not depend on damping, only the time to reach it.
    const double l_m = overhang * 1e-3;
    const double omega1 =
        3.516 * std::sqrt(b * 1e-6 / (f.density_g_m2 * 1e-3 * l_m * l_m * l_m * l_m));
    opt.damping_per_second = std::max(omega1, 1.0) + f.damping_per_second;
    opt.iterations = std::max(1, o.iterations);
    DrapeSolver solver(strip, f, opt);
    std::size_t frames = 0;
    const bool rest = internal::run_to_rest(solver, 1e-4, o.max_seconds, &frames);
    if (settled) {
        *settled = *settled && rest;
    }
    if (verts) {
        *verts = strip.positions.size();
    }
    if (substeps) {
        *substeps = opt.substeps;
    }
    // Tip: mean of the free end's vertices; the chord from the clamp line (x = 0, y = 0).
    auto column_mean = [&](const std::vector<std::uint32_t>& column) {
        double x = 0, y = 0;
        for (std::uint32_t v : column) {
            x += solver.positions()[v][0];
            y += solver.positions()[v][1];
        }
        return std::array<double, 2>{x / column.size(), y / column.size()};
    };
    const auto [tx, ty] = column_mean(columns.back());
    if (line) {
        line->clear();
        for (const auto& column : columns) {
            line->push_back(column_mean(column));
        }
    }
    return std::atan2(-ty, tx) * 180 / 3.14159265358979323846;
}

/// The cantilever test along the warp (weft = false) or the weft.
inline CantileverResult cantilever_test(const FabricParams& fabric, bool weft,
                                        const FabricTestOptions& o = {}) {
    internal::check_options(o, fabric);
    const auto start = std::chrono::steady_clock::now();
    CantileverResult r;
    r.direction = weft ? "weft" : "warp";
    const double b = weft ? bending_weft_of(fabric) : fabric.bending_un_m;
    if (!(b > 0)) {
        throw InvalidInput("fabric test: fabric '" + fabric.name + "' has no " + r.direction +
                           " bending rigidity");
    }
    r.target_mm = bending_length_mm(b, fabric.density_g_m2);
    constexpr double target_deg = 41.5;
    // Start from the small-deflection estimate for a strip of 20 mm (chord angle ∝ l³) so the
    // search does not start at the answer; then a log-log secant on angle(l).
    double l0 = 40, a0 = cantilever_tip_angle(fabric, weft, l0, o, &r.settled, &r.vertices,
                                              &r.substeps, &r.centreline);
    r.runs = 1;
    double l1 = l0 * std::cbrt(target_deg / std::max(a0, 0.01));
    l1 = std::clamp(l1, 0.25 * l0, 4 * l0);
    double a1 = 0;
    for (int it = 0; it < 14; ++it) {
        a1 = cantilever_tip_angle(fabric, weft, l1, o, &r.settled, &r.vertices, &r.substeps,
                                  &r.centreline);
        ++r.runs;
        if (std::abs(a1 - target_deg) < 0.02) {
            break;
        }
        const double slope = std::log(a1 / a0) / std::log(l1 / l0);
        const double p = std::isfinite(slope) && slope > 0.2 ? slope : 3.0;
        double l2 = l1 * std::pow(target_deg / a1, 1 / p);
        l2 = std::clamp(l2, 0.5 * l1, 2 * l1);
        l0 = l1;
        a0 = a1;
        l1 = l2;
    }
    r.overhang_mm = l1;
    r.tip_angle_deg = a1;
    r.bending_length_mm = l1 / 2;
    r.error_pct = (r.bending_length_mm - r.target_mm) / r.target_mm * 100;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

// ---------------------------------------------------------------------------------------------
// Tensile strip and bias extension

/// One load of the tensile test.
struct TensilePoint {
    /// The pull, gf per cm of strip width (5, 20 or 100).
    double load_gf_cm = 0;
    double target_pct = 0;     ///< the fabric's strain there (FAST E5/E20/E100, or load/k)
    double simulated_pct = 0;  ///< with the fabric's secant stiffness at this load
    double error_pct = 0;      ///< relative error of simulated_pct, %
    double linear_pct = 0;     ///< with the fabric's single solver stiffness (what drapes use)
    /// Relative error of linear_pct, %.
    double linear_error_pct = 0;
};

/// Result of the tensile test in one direction.
struct TensileResult {
    /// "warp" or "weft".
    std::string direction;
    bool measured_curve = false;  ///< targets from the fabric's lab curve (else load/stiffness)
    /// One per load, in the order 5, 20, 100 gf/cm.
    std::vector<TensilePoint> points;
    /// Vertices of the strip.
    std::size_t vertices = 0;
    /// Solver sub-steps per 1/300 s frame.
    int substeps = 0;
    /// Every run came to rest within its time limit.
    bool settled = true;
    /// Wall time of the whole test, s.
    double seconds = 0;
};

/// Strain (%) of a strip pulled with `load_gf_cm` along the warp (weft = false) or the weft with
/// tensile stiffness `k` (N/m) in that direction: 50 × 100 mm, one end pinned.
inline double tensile_strain_pct(const FabricParams& fabric, bool weft, double k, double load_gf_cm,
                                 const FabricTestOptions& o, bool* settled, std::size_t* verts,
                                 int* substeps) {
    const double length = 100, width = 50, res = o.resolution_mm;
    const int nx = std::max(2, static_cast<int>(std::ceil(length / res - 1e-9)));
    const int ny = std::max(1, static_cast<int>(std::ceil(width / res - 1e-9)));
    const double dx = length / nx, dz = width / ny;
    ClothModel strip = internal::strip_model(nx, ny, dx, dz, 0, 0, 0, weft ? UV{0, 1} : UV{1, 0});
    strip.pinned.assign(strip.positions.size(), 0);
    std::vector<std::uint32_t> end;
    std::vector<double> weights;
    for (int j = 0; j <= ny; ++j) {
        strip.pinned[static_cast<std::size_t>(j) * (nx + 1)] = 1;
        end.push_back(static_cast<std::uint32_t>(j * (nx + 1) + nx));
        weights.push_back((j == 0 || j == ny ? 0.5 : 1.0) / ny);
    }
    FabricParams f = fabric;
    (weft ? f.stretch_weft_n_m : f.stretch_warp_n_m) = k;
    DrapeOptions opt = internal::pulled_strip_options(f, dx, dz, o.threads);
    // Damping near the first axial mode: ω₁ = (π/2)·√(k/ρ)/L.
    const double omega1 = 1.5708 * std::sqrt(k / (f.density_g_m2 * 1e-3)) / (length * 1e-3);
    opt.damping_per_second = omega1;
    DrapeSolver solver(strip, f, opt);
    const double force = load_gf_cm * kGfPerCmToNPerM * width * 1e-3;  // N
    solver.set_attachments(internal::pulls(solver, end, weights, force, {1, 0, 0}));
    std::size_t frames = 0;
    const bool rest = internal::run_to_rest(solver, 1e-5, o.max_seconds / 10, &frames);
    if (settled) {
        *settled = *settled && rest;
    }
    if (verts) {
        *verts = strip.positions.size();
    }
    if (substeps) {
        *substeps = opt.substeps;
    }
    double x = 0;
    for (std::uint32_t v : end) {
        x += solver.positions()[v][0];
    }
    x /= end.size();
    return (x - length) / length * 100;
}

/// The tensile test at 5, 20 and 100 gf/cm along the warp or the weft. With a measured curve
/// (Fabric::extension_*_pct) each load runs with the secant stiffness load/E of that load (the
/// solver is linear: a strain-dependent stiffness would have to be set this way) and, separately,
/// with the fabric's single solver stiffness; without one the target is load/stiffness.
inline TensileResult tensile_test(const Fabric& fabric, bool weft,
                                  const FabricTestOptions& o = {}) {
    internal::check_options(o, fabric.params);
    const auto start = std::chrono::steady_clock::now();
    TensileResult r;
    r.direction = weft ? "weft" : "warp";
    const auto& curve = weft ? fabric.extension_weft_pct : fabric.extension_warp_pct;
    r.measured_curve = std::isfinite(curve[0]);
    const double k = weft ? fabric.params.stretch_weft_n_m : fabric.params.stretch_warp_n_m;
    for (int i = 0; i < 3; ++i) {
        TensilePoint p;
        p.load_gf_cm = kFastLoadsGfCm[i];
        p.target_pct = r.measured_curve ? curve[i] : p.load_gf_cm * kGfPerCmToNPerM / k * 100;
        const double k_secant = secant_stiffness_n_m(p.load_gf_cm, p.target_pct);
        p.simulated_pct = tensile_strain_pct(fabric.params, weft, k_secant, p.load_gf_cm, o,
                                             &r.settled, &r.vertices, &r.substeps);
        p.error_pct = (p.simulated_pct - p.target_pct) / p.target_pct * 100;
        p.linear_pct = r.measured_curve ? tensile_strain_pct(fabric.params, weft, k, p.load_gf_cm,
                                                             o, &r.settled, nullptr, nullptr)
                                        : p.simulated_pct;
        p.linear_error_pct = (p.linear_pct - p.target_pct) / p.target_pct * 100;
        r.points.push_back(p);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

/// Result of the bias-extension test.
struct BiasResult {
    /// The pull at each end, gf per cm of strip width.
    double load_gf_cm = 5;
    double target_shear_n_m = 0;           ///< the fabric's G
    double shear_angle_deg = 0;            ///< mean warp–weft angle change in the middle third
    double simulated_shear_n_m = 0;        ///< (T/2)/γ
    double error_pct = 0;                  ///< of simulated_shear_n_m
    double bias_extension_pct = 0;         ///< strip strain in the middle third (EB5)
    double target_bias_extension_pct = 0;  ///< FAST EB5 = 123/G (yarn stretch neglected)
    /// Vertices of the strip.
    std::size_t vertices = 0;
    /// Solver sub-steps per 1/300 s frame.
    int substeps = 0;
    /// The strip came to rest within its time limit.
    bool settled = true;
    /// Wall time, s.
    double seconds = 0;
};

/// The bias-extension test at 5 gf/cm (see the file comment).
inline BiasResult bias_test(const Fabric& fabric, const FabricTestOptions& o = {}) {
    internal::check_options(o, fabric.params);
    const auto start = std::chrono::steady_clock::now();
    BiasResult r;
    const FabricParams& f = fabric.params;
    r.target_shear_n_m = f.shear_n_m;
    r.target_bias_extension_pct = bias_extension_pct_of(f.shear_n_m);
    const double length = 200, width = 50, res = o.resolution_mm;
    const int nx = std::max(6, static_cast<int>(std::ceil(length / res - 1e-9)));
    const int ny = std::max(1, static_cast<int>(std::ceil(width / res - 1e-9)));
    const double dx = length / nx, dz = width / ny;
    const double s = std::sqrt(0.5);
    ClothModel strip = internal::strip_model(nx, ny, dx, dz, 0, 0, 0, UV{s, s});
    std::vector<std::uint32_t> left, right;
    std::vector<double> weights;
    for (int j = 0; j <= ny; ++j) {
        left.push_back(static_cast<std::uint32_t>(j * (nx + 1)));
        right.push_back(static_cast<std::uint32_t>(j * (nx + 1) + nx));
        weights.push_back((j == 0 || j == ny ? 0.5 : 1.0) / ny);
    }
    DrapeOptions opt = internal::pulled_strip_options(f, dx, dz, o.threads);
    const double omega1 =
        3.1416 * std::sqrt(4 * f.shear_n_m / (f.density_g_m2 * 1e-3)) / (length * 1e-3);
    opt.damping_per_second = omega1;
    DrapeSolver solver(strip, f, opt);
    const double force = r.load_gf_cm * kGfPerCmToNPerM * width * 1e-3;
    std::vector<Attachment> a = internal::pulls(solver, right, weights, force, {1, 0, 0});
    const std::vector<Attachment> b = internal::pulls(solver, left, weights, force, {-1, 0, 0});
    a.insert(a.end(), b.begin(), b.end());
    solver.set_attachments(a);
    r.settled = internal::run_to_rest(solver, 1e-5, o.max_seconds / 5);
    r.vertices = strip.positions.size();
    r.substeps = opt.substeps;
    // Middle third: shear angle per triangle from its deformation gradient's warp and weft
    // columns, and the strip's strain between the third lines.
    using namespace tapeline::vec3;
    const auto& x = solver.positions();
    double gamma = 0;
    int count = 0;
    for (std::size_t t = 0; t < strip.triangles.size(); ++t) {
        const auto& tri = strip.triangles[t];
        const auto& u = strip.rest_uv[t];
        const double cx = (u[0][0] + u[1][0] + u[2][0]) / 3;
        if (cx < length / 3 || cx > 2 * length / 3) {
            continue;
        }
        // F = [x1 − x0, x2 − x0]·Dm⁻¹ with Dm in the grain frame (warp, weft).
        auto to_grain = [&](const UV& p) { return UV{s * p[0] + s * p[1], -s * p[0] + s * p[1]}; };
        const UV a0 = to_grain(u[0]), a1 = to_grain(u[1]), a2 = to_grain(u[2]);
        const double m00 = a1[0] - a0[0], m10 = a1[1] - a0[1], m01 = a2[0] - a0[0],
                     m11 = a2[1] - a0[1];
        const double det = m00 * m11 - m01 * m10;
        const double i00 = m11 / det, i01 = -m01 / det, i10 = -m10 / det, i11 = m00 / det;
        const Vec3 e1 = sub(x[tri[1]], x[tri[0]]), e2 = sub(x[tri[2]], x[tri[0]]);
        const Vec3 fw = add(scale(e1, i00), scale(e2, i10));  // F·warp
        const Vec3 ff = add(scale(e1, i01), scale(e2, i11));  // F·weft
        const double cosang = dot(fw, ff) / (norm(fw) * norm(ff));
        gamma += std::abs(std::asin(std::clamp(cosang, -1.0, 1.0)));
        ++count;
    }
    gamma /= count;
    r.shear_angle_deg = gamma * 180 / 3.14159265358979323846;
    const double tension = r.load_gf_cm * kGfPerCmToNPerM;
    r.simulated_shear_n_m = tension / 2 / gamma;
    r.error_pct = (r.simulated_shear_n_m - r.target_shear_n_m) / r.target_shear_n_m * 100;
    auto mean_x_at = [&](int i) {
        double sx = 0;
        for (int j = 0; j <= ny; ++j) {
            sx += x[static_cast<std::size_t>(j) * (nx + 1) + i][0];
        }
        return sx / (ny + 1);
    };
    const int i1 = nx / 3, i2 = nx - nx / 3;
    const double rest = (i2 - i1) * dx;
    r.bias_extension_pct = (mean_x_at(i2) - mean_x_at(i1) - rest) / rest * 100;
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

// ---------------------------------------------------------------------------------------------
// Cusick drape test

/// Result of one Cusick run.
struct CusickResult {
    /// Radii of the disc (300 mm across) and the pedestal (180 mm across), mm.
    ///@{
    double disc_radius_mm = 150, pedestal_radius_mm = 90;
    ///@}
    /// Area S of the shadow, the pedestal's top included, mm².
    double shadow_area_mm2 = 0;
    double drape_coefficient = 0;           ///< (S − A_pedestal)/(A_disc − A_pedestal), 0..1
    int nodes = 0;                          ///< folds of the shadow's outline
    std::vector<double> outline_radius_mm;  ///< shadow radius every degree (from +x towards +z)
    /// Vertices of the cloth.
    std::size_t vertices = 0;
    /// Solver sub-steps per 1/30 s frame.
    int substeps = 0;
    /// Frames run until the cloth came to rest (or the time limit).
    std::size_t frames = 0;
    /// The cloth came to rest within FabricTestOptions::max_seconds.
    bool settled = true;
    /// The Newton static solve that follows the rest (DrapeSolver::relax, tolerance 0.001 mm;
    /// unless FabricTestOptions::static_solve is off): DC, nodes and the shadow are of its
    /// equilibrium; `relax.converged` says it got there, `relax.max_residual_of_weight` how
    /// well each vertex is balanced.
    RelaxReport relax;
    /// Wall time, s.
    double seconds = 0;
    /// Shadow raster (1: covered), shadow_pixels × shadow_pixels over ±shadow_half_mm.
    std::vector<std::uint8_t> shadow;
    /// Pixels along each side of the shadow raster (0.5 mm pixels; row j, column i at
    /// shadow[j·shadow_pixels + i], i along x and j along z).
    int shadow_pixels = 0;
    /// Half the side of the square the raster covers, centred on the pedestal's axis, mm.
    double shadow_half_mm = 0;
    std::vector<Vec3> positions;  ///< rest shape of the cloth
    /// Triangles of the cloth (indices into `positions`).
    std::vector<Tri> triangles;
};

namespace internal {

// An annulus (ring mesh) from r0 to r1 in the x–z plane at height y, `rings` + 1 rings evenly
// spaced, each with about 2πr/res vertices, alternate rings staggered by half a vertex,
// consecutive rings zipped by angle: near-equilateral. With `first_ring_width` > 0 the first ring
// is that far inside the second, its vertices the second's scaled towards the centre (same
// count, same angles: thin quads, each cut in two; a staggered ring that close would sit outside
// the second ring's chords and fold its triangles over), and the other rings are evenly spaced
// from the second ring's radius to r1.
inline ClothModel annulus_model(double r0, double r1, int rings, double y, double res,
                                double first_ring_width = 0) {
    ClothModel c;
    const double pi = 3.14159265358979323846;
    const bool thin_first = first_ring_width > 0;
    std::vector<double> radius, offset;
    std::vector<int> count;
    for (int k = 0; k <= rings; ++k) {
        radius.push_back(thin_first
                             ? (k == 0 ? r0
                                       : r0 + first_ring_width +
                                             (r1 - r0 - first_ring_width) * (k - 1) / (rings - 1))
                             : r0 + (r1 - r0) * k / rings);
        count.push_back(std::max(12, static_cast<int>(std::round(2 * pi * radius[k] / res))));
        offset.push_back((k % 2) * 0.5);  // stagger alternate rings
    }
    if (thin_first) {
        count[0] = count[1];
        offset[0] = offset[1];
    }
    std::vector<std::uint32_t> start;
    for (int k = 0; k <= rings; ++k) {
        start.push_back(static_cast<std::uint32_t>(c.positions.size()));
        for (int i = 0; i < count[k]; ++i) {
            const double a = 2 * pi * (i + offset[k]) / count[k];
            c.positions.push_back({radius[k] * std::cos(a), y, radius[k] * std::sin(a)});
        }
    }
    auto angle = [&](int k, int i) { return ((i % count[k]) + offset[k]) / count[k]; };
    auto uv = [&](std::uint32_t v) { return UV{c.positions[v][0], c.positions[v][2]}; };
    auto add = [&](std::uint32_t a, std::uint32_t b, std::uint32_t d) {
        c.triangles.push_back({a, b, d});
        c.rest_uv.push_back({uv(a), uv(b), uv(d)});
        c.grain.push_back({1, 0});
    };
    for (int k = 0; k < rings; ++k) {
        int i = 0, j = 0;
        const int n0 = count[k], n1 = count[k + 1];
        while (i < n0 || j < n1) {
            const double ai = angle(k, i + 1), aj = angle(k + 1, j + 1);
            const std::uint32_t p = start[k] + i % n0, q = start[k + 1] + j % n1;
            const bool advance_inner = j >= n1 || (i < n0 && ai <= aj);
            if (advance_inner) {
                add(p, start[k] + (i + 1) % n0, q);
                ++i;
            } else {
                add(p, start[k + 1] + (j + 1) % n1, q);
                ++j;
            }
        }
    }
    return c;
}

}  // namespace internal

/// The Cusick test (see the file comment): returns DC, nodes, the shadow and the rest shape.
inline CusickResult cusick_test(const FabricParams& fabric, const FabricTestOptions& o = {}) {
    internal::check_options(o, fabric);
    const auto start = std::chrono::steady_clock::now();
    CusickResult r;
    const double pi = 3.14159265358979323846;
    const double res = o.resolution_mm, rp = r.pedestal_radius_mm, rd = r.disc_radius_mm;
    const FabricParams& f = fabric;
    // The cloth from a ring 1/1000 of the ring spacing inside the pedestal's rim (clamped
    // between the two discs of the tester: pinned, with the rim's ring) out to the disc's edge.
    // The hinges along the rim then bend over half their dual length, as at a clamp (the
    // cantilever's clamp row likewise); a whole ring of cells inside gives them half the
    // stiffness.
    const int rings = std::max(2, static_cast<int>(std::ceil((rd - rp) / (res * 0.866) - 1e-9)));
    const double spacing = (rd - rp) / rings;
    const double clamp_ring = 0.001 * spacing;
    ClothModel cloth =
        internal::annulus_model(rp - clamp_ring, rd, rings + 1, f.thickness_mm, res, clamp_ring);
    cloth.pinned.assign(cloth.positions.size(), 0);
    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<double> jitter(-1, 1);
    for (std::size_t v = 0; v < cloth.positions.size(); ++v) {
        Vec3& p = cloth.positions[v];
        const double r0 = std::hypot(p[0], p[2]);
        if (r0 <= rp + 1e-6) {
            cloth.pinned[v] = 1;
        } else if (o.perturbation_mm > 0) {
            p[1] += o.perturbation_mm * jitter(rng);
        }
    }
    // The pedestal set back from the clamp's edge by the clearance the solver keeps (the fabric's
    // thickness): the edge contact keeps every edge that clearance from the pedestal's rim, so a
    // rim under the last pinned ring would hold the first edge leaving the clamp near horizontal,
    // the more so the thicker the fabric (at 20 mm, 3 mm thick, the edge's sine of descent 0.21
    // against 0.76 at 0.3 mm), as if the clamp reached a ring further out. Set back, the rim never
    // touches cloth hanging outward from the clamp, and the clamp's edge is where the cloth is
    // free to turn down, as between the tester's two discs. The support is a flat disc, as the
    // tester's is, not a column: cloth hanging straight down from the clamp's edge would lean on
    // a column's wall (the static solve then ends with the limp fabrics held against it by
    // contact forces that do not balance, silk's 1,400 times a vertex's weight).
    const PedestalCollider pedestal(rp - f.thickness_mm, 0, 0);
    DrapeOptions opt;
    opt.threads = o.threads;
    opt.self_collision = true;
    // Sub-steps as in the cantilever (compliant hinges), at least 20 per frame.
    const double edge = res, m = f.density_g_m2 * 1e-9 * edge * edge * 0.433;
    double bmax = 0;
    for (double a = 0; a < 3.2; a += 0.2) {
        bmax = std::max(bmax, bending_rigidity_un_m(f, std::cos(a), std::sin(a)));
    }
    const double omega = std::sqrt(std::max(bmax, 1e-9) * 1.2 * 4 * (3 / m) / (edge * edge));
    opt.substeps =
        std::clamp(static_cast<int>(std::ceil(opt.frame_seconds * omega / 0.2)), 20, 400);
    opt.damping_per_second = 2 + f.damping_per_second;
    DrapeSolver solver(cloth, f, opt, &pedestal);
    r.settled = internal::run_to_rest(solver, 0.02, o.max_seconds, &r.frames);
    // The sub-stepped drape's rest is not the disc's static equilibrium: the hanging cloth comes
    // to rest with its folds short of where its bending and stretch balance its weight (denim at
    // 20 mm: DC 56 % at rest, 71 % after the static solve), the more so the coarser the mesh.
    // The Newton static solve (DrapeSolver::relax, as a drape ends) brings it there.
    if (o.static_solve) {
        RelaxOptions relax;
        relax.tolerance_mm = 0.001;
        relax.max_iterations = 200;
        r.relax = solver.relax(relax);
    }
    r.vertices = cloth.positions.size();
    r.substeps = opt.substeps;
    r.positions = solver.positions();
    r.triangles = cloth.triangles;
    // Shadow: rasterise every triangle projected on the floor (x, z), and the pedestal's top.
    const double half = rd + 10, px = 0.5;
    const int n = static_cast<int>(std::ceil(2 * half / px));
    r.shadow.assign(static_cast<std::size_t>(n) * n, 0);
    r.shadow_pixels = n;
    r.shadow_half_mm = half;
    auto cover = [&](int i, int j) { r.shadow[static_cast<std::size_t>(j) * n + i] = 1; };
    for (int j = 0; j < n; ++j) {
        for (int i = 0; i < n; ++i) {
            const double x = -half + (i + 0.5) * px, z = -half + (j + 0.5) * px;
            if (x * x + z * z <= rp * rp) {
                cover(i, j);
            }
        }
    }
    for (const Tri& t : cloth.triangles) {
        const Vec3& a = r.positions[t[0]];
        const Vec3& b = r.positions[t[1]];
        const Vec3& c = r.positions[t[2]];
        const double x0 = std::min({a[0], b[0], c[0]}), x1 = std::max({a[0], b[0], c[0]});
        const double z0 = std::min({a[2], b[2], c[2]}), z1 = std::max({a[2], b[2], c[2]});
        const double det = (b[0] - a[0]) * (c[2] - a[2]) - (c[0] - a[0]) * (b[2] - a[2]);
        if (std::abs(det) < 1e-12) {
            continue;
        }
        const int i0 = std::max(0, static_cast<int>(std::floor((x0 + half) / px)));
        const int i1 = std::min(n - 1, static_cast<int>(std::floor((x1 + half) / px)));
        const int j0 = std::max(0, static_cast<int>(std::floor((z0 + half) / px)));
        const int j1 = std::min(n - 1, static_cast<int>(std::floor((z1 + half) / px)));
        for (int j = j0; j <= j1; ++j) {
            for (int i = i0; i <= i1; ++i) {
                const double x = -half + (i + 0.5) * px, z = -half + (j + 0.5) * px;
                const double l1 = ((b[0] - x) * (c[2] - z) - (c[0] - x) * (b[2] - z)) / det;
                const double l2 = ((c[0] - x) * (a[2] - z) - (a[0] - x) * (c[2] - z)) / det;
                const double l3 = 1 - l1 - l2;
                if (l1 >= 0 && l2 >= 0 && l3 >= 0) {
                    cover(i, j);
                }
            }
        }
    }
    std::size_t covered = 0;
    for (std::uint8_t v : r.shadow) {
        covered += v;
    }
    r.shadow_area_mm2 = covered * px * px;
    const double a_ped = pi * rp * rp, a_disc = pi * rd * rd;
    r.drape_coefficient = (r.shadow_area_mm2 - a_ped) / (a_disc - a_ped);
    // Outline: the farthest covered pixel along each degree; nodes are the outline's maxima
    // that stand at least 2 mm above the minima on both sides (a fold, not pixel noise).
    r.outline_radius_mm.assign(360, rp);
    for (int d = 0; d < 360; ++d) {
        const double a = d * pi / 180;
        for (double rr = rp; rr <= half; rr += px / 2) {
            const int i = static_cast<int>(std::floor((rr * std::cos(a) + half) / px));
            const int j = static_cast<int>(std::floor((rr * std::sin(a) + half) / px));
            if (i >= 0 && j >= 0 && i < n && j < n &&
                r.shadow[static_cast<std::size_t>(j) * n + i]) {
                r.outline_radius_mm[d] = rr;
            }
        }
    }
    std::vector<double> smooth(360);
    for (int d = 0; d < 360; ++d) {
        double sum = 0;
        for (int k = -2; k <= 2; ++k) {
            sum += r.outline_radius_mm[(d + k + 360) % 360];
        }
        smooth[d] = sum / 5;
    }
    r.nodes = internal::closed_peaks(smooth, 2);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    return r;
}

// ---------------------------------------------------------------------------------------------
// Pictures

/// The cantilever's rest shape seen from the side: the table, the 41.5° line through its edge,
/// the strip's centre line (warp blue, weft orange dashed), the bending lengths in the caption.
inline draw::RgbaImage cantilever_picture(const std::vector<CantileverResult>& results,
                                          const std::string& title, double ppmm = 6) {
    double reach = 40;
    for (const auto& r : results) {
        reach = std::max(reach, r.overhang_mm);
    }
    const double margin = 6, line_h = 5, caption_h = line_h * (1 + results.size()) + 4;
    const double w = std::max(reach * 1.4 + 2 * margin, 110.0);
    const double h = reach * 0.95 + 2 * margin + caption_h;
    draw::RgbaImage img = draw::RgbaImage::filled(static_cast<std::size_t>(w * ppmm),
                                                  static_cast<std::size_t>(h * ppmm), 255);
    draw::Canvas cv(img, ppmm);
    const Vec2 edge{margin + reach * 0.25, margin + caption_h};
    auto page = [&](double x, double y) { return Vec2{edge.x + x, edge.y - y}; };
    cv.fill_rect(page(-reach * 0.25, 0), page(0, -reach * 0.9), {0.8, 0.78, 0.72});
    const double pi = 3.14159265358979323846;
    const double c = std::cos(41.5 * pi / 180), s = std::sin(41.5 * pi / 180);
    cv.polyline({page(0, 0), page(reach * 1.1 * c, -reach * 1.1 * s)}, 0.3, {0.3, 0.3, 0.3}, 2,
                1.5);
    cv.text("41.5 deg", page(reach * 0.9 * c + 3, -reach * 0.9 * s), 3, draw::TextAnchor::start,
            {0.3, 0.3, 0.3});
    const draw::Rgb colours[2] = {{0.2, 0.4, 0.85}, {0.9, 0.5, 0.15}};
    cv.text(title, {margin, margin + line_h}, 4, draw::TextAnchor::start, {0, 0, 0});
    for (std::size_t k = 0; k < results.size(); ++k) {
        std::vector<Vec2> line;
        for (const auto& p : results[k].centreline) {
            line.push_back(page(p[0], p[1]));
        }
        // The weft line dashed, so that it shows where it lies on the warp line.
        cv.polyline(line, 0.8, colours[k % 2], k % 2 ? 2.0 : 0.0, k % 2 ? 1.5 : 0.0);
        char buf[160];
        std::snprintf(buf, sizeof buf, "%s: C %.2f mm, target %.2f mm (%+.1f %%)",
                      results[k].direction.c_str(), results[k].bending_length_mm,
                      results[k].target_mm, results[k].error_pct);
        cv.text(buf, {margin, margin + line_h * (k + 2)}, 3.5, draw::TextAnchor::start,
                colours[k % 2]);
    }
    return img;
}

/// The Cusick shadow from above: the shadow in grey, the pedestal and the disc as circles, the
/// drape coefficient and the nodes in the caption.
inline draw::RgbaImage cusick_picture(const CusickResult& r, const std::string& title,
                                      double ppmm = 2) {
    const double margin = 6, half = r.shadow_half_mm, title_h = 10;
    const double w = 2 * half + 2 * margin, h = 2 * half + 2 * margin + title_h;
    draw::RgbaImage img = draw::RgbaImage::filled(static_cast<std::size_t>(w * ppmm),
                                                  static_cast<std::size_t>(h * ppmm), 255);
    draw::Canvas cv(img, ppmm);
    const Vec2 centre{margin + half, margin + title_h + half};
    const double px = 2 * half / r.shadow_pixels;
    for (int j = 0; j < r.shadow_pixels; ++j) {
        for (int i = 0; i < r.shadow_pixels; ++i) {
            if (r.shadow[static_cast<std::size_t>(j) * r.shadow_pixels + i]) {
                const double x = centre.x - half + i * px, y = centre.y - half + j * px;
                cv.fill_rect({x, y}, {x + px, y + px}, {0.45, 0.47, 0.55});
            }
        }
    }
    cv.ring(centre, r.pedestal_radius_mm, 0.6, {0.9, 0.3, 0.2});
    cv.ring(centre, r.disc_radius_mm, 0.4, {0.2, 0.2, 0.2});
    char buf[200];
    std::snprintf(buf, sizeof buf, "%s  DC %.1f %%  nodes %d", title.c_str(),
                  100 * r.drape_coefficient, r.nodes);
    cv.text(buf, {margin, margin + 5}, 5, draw::TextAnchor::start, {0, 0, 0});
    return img;
}

}  // namespace tapeline::garment
