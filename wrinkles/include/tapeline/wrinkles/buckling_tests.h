// Virtual buckling experiments that check the wrinkle wavelength law on the cloth solver
// (garment/drape_solver.h).
//
// Law. A sheet of bending rigidity B (N·m) on an elastic (Winkler) foundation of stiffness K
// (N/m³) under a compressive membrane force N obeys B·w'''' + N·w'' + K·w = 0; a mode
// w = sin(k·x) appears when N = B·k² + K/k², smallest at k⁴ = K/B, so the sheet wrinkles at
//     N_c = 2·√(B·K),   λ = 2π·(B/K)^{1/4}
// (E. Cerda, L. Mahadevan, "Geometry and physics of wrinkling", PRL 90, 074302, 2003). For a thin
// tube of radius R under axial compression the hoop membrane stiffness Y (N/m) acts as the
// foundation of the axisymmetric mode, K = Y/R², so λ = 2π·(B·R²/Y)^{1/4} (the classical
// axisymmetric buckle of a cylindrical shell; S. Timoshenko, J. Gere, "Theory of Elastic
// Stability", 1961, §11.4, with the shell's membrane and bending stiffness per unit width).
//
// Experiments (no gravity, solver units: mm, kg, s; B in µN·m = 1e-6 N·m; attachment compliance
// in mm/N):
//  - foundation_test: a strip (default 600 × 30 mm, right-triangle grid along the warp) whose two
//    end columns of vertices are clamped (pinned) and brought closer by an end shortening ε of
//    its length. The foundation is one attachment per free vertex of stiffness k_v = K·(vertex
//    area) (compliance 1/(k_v·1e-3) mm/N) pulling it to its own in-plane position at height
//    η_v: the targets are set again before every relax() call, so that at equilibrium the
//    foundation acts out of plane only (between two calls its in-plane pull is k_v times a
//    drift of well under a millimetre, four orders of magnitude below the membrane's). η_v is a
//    seeded random imperfection of the foundation (default ±0.01 mm) that breaks the symmetry
//    and stays for the whole loading.
//  - cylinder_test: a tube (default R = 40, H = 80 mm, warp along the axis, so the hoop stiffness
//    is the weft's and axial wrinkles bend along the warp) closed without a stitch (per-triangle
//    rest UVs run past 2πR on the last column), bottom ring pinned, top ring held by hard
//    attachments and moved down; a seeded radial perturbation is added at every load stage.
//
// Loading. Both are loaded quasi-statically: the end shortening starts at `first_strain`
// (default 2.5e-5, below the critical strain of every case in the docs) and doubles stage by
// stage up to `strain`; each stage starts from the previous stage's equilibrium compressed
// affinely along the axis (a new solver on those positions: DrapeSolver has no way to set
// positions) and runs DrapeSolver::relax() (damped Newton on the solver's own energies, so the
// XPBD iteration count does not bias the result) in rounds of `iterations_per_round` Newton
// iterations. Why quasi-static: moving only the clamps to 1 % in one go, their motion is taken up
// by folds next to them while the middle stays flat, and a strip compressed affinely in one go
// settles into whatever wrinkle count its transient picked, drifting from round to round
// (measured: −8 % to +4 %, docs/wrinkles/scaling.md); a post-buckled strip hardly changes its
// number of wrinkles afterwards (the energy is flat in λ near the optimum), so the wavelength is
// the one chosen at onset, as in a physical test that loads slowly. The tube starts from its
// stage's positions with the bump put back (it has no foundation to carry an imperfection).
//
// Measurement. The height (strip: the centre line; tube: r − R along `generators` generators)
// against the current axial coordinate, resampled uniformly and passed to dominant_wavelength()
// (spectrum.h); a few rows next to the clamps are left out. The tube also reports how much of
// the radial displacement is axisymmetric (energy of the ring means over the total) and the
// number of circumferential lobes at the ring that deviates most from a circle.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/vec2.h>
#include <tapeline/draw/canvas.h>
#include <tapeline/draw/plot.h>
#include <tapeline/garment/drape_solver.h>
#include <tapeline/garment/fabric_tests.h>
#include <tapeline/wrinkles/spectrum.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <functional>
#include <limits>
#include <numeric>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::wrinkles {

using garment::FabricParams;

/// How a buckling experiment runs (lengths mm, stiffness SI).
struct BucklingOptions {
    double resolution_mm = 2.5;  ///< cloth edge length, mm
    /// Strip (foundation_test): length along the warp and width, mm.
    ///@{
    double length_mm = 600, width_mm = 30;
    ///@}
    double foundation_n_m3 = 5000;  ///< Winkler stiffness K, N/m³ (foundation_test)
    /// Tube (cylinder_test): radius and length, mm.
    ///@{
    double radius_mm = 40, height_mm = 80;
    ///@}
    double strain = 0.01;           ///< final end shortening over the length (0 < strain ≤ 0.2)
    double first_strain = 2.5e-5;   ///< first load stage; doubles up to `strain`
    int rounds_per_stage = 2;       ///< relax() calls per load stage (at most)
    int iterations_per_round = 30;  ///< Newton iterations per relax() call
    double imperfection_mm = 0.01;  ///< amplitude of the seeded imperfection, mm
    std::uint32_t seed = 1;         ///< of the imperfection
    int generators = 8;             ///< tube: generators measured
    int threads = 1;                ///< solver threads (0: all cores)
    /// Called with one line per load stage (may be empty).
    std::function<void(const std::string&)> progress;
};

/// What one experiment measured.
struct BucklingResult {
    std::string test;                    ///< "foundation" or "cylinder"
    double bending_un_m = 0;             ///< B along the warp, µN·m
    double foundation_n_m3 = 0;          ///< K (tube: Y/R²), N/m³
    double membrane_n_m = 0;             ///< compressed direction's tensile stiffness, N/m
    double hoop_n_m = 0;                 ///< tube: hoop (weft) stiffness Y, N/m
    double radius_mm = 0;                ///< tube radius, mm (0: strip)
    double predicted_wavelength_mm = 0;  ///< 2π(B/K)^{1/4}
    double measured_wavelength_mm = 0;   ///< strip: centre line; tube: median over generators
    double error_percent = 0;            ///< 100·(measured/predicted − 1)
    double peak_share = 0;               ///< spectral energy share of the peak (mean over lines)
    double amplitude_mm = 0;             ///< amplitude of the dominant wave, mm
    double critical_strain = 0;          ///< predicted onset: N_c / membrane stiffness
    double onset_strain =
        0;  ///< first load stage whose peak amplitude exceeded 10× the imperfection
    double onset_wavelength_mm = 0;  ///< dominant wavelength at that stage, mm
    double strain = 0;               ///< final end shortening
    /// Tube: per generator, the dominant axial wavelength, mm.
    std::vector<double> generator_wavelengths_mm;
    double axisymmetric_share = 0;          ///< tube: ring-mean energy over total radial energy
    double axisymmetric_wavelength_mm = 0;  ///< tube: dominant wavelength of the ring means
    double circumferential_lobes = 0;       ///< tube: 2πR / circumferential wavelength
    std::string pattern;  ///< tube: "axisymmetric", "non-axisymmetric"; strip: "wrinkles"/"flat"
    /// Lines measured (strip: 1, tube: its generators) whose spectral peak is the longest
    /// wavelength the record resolves (Spectrum::at_record_limit): a dent, not a wave train. When
    /// most are, measured_wavelength_mm is the record's limit, not a wavelength.
    std::size_t lines_at_record_limit = 0;
    std::size_t lines = 0;  ///< lines measured
    std::size_t vertices = 0, triangles = 0;
    double resolution_mm = 0;
    int relax_iterations = 0;     ///< Newton iterations over all stages
    bool last_converged = false;  ///< the last relax() call met its tolerance
    double seconds = 0;           ///< wall time
    std::vector<Vec2> profile;    ///< strip centre line / first generator: (s, height), mm
};

/// A sweep over bending rigidities and its log–log fit.
struct ScalingSweep {
    std::vector<BucklingResult> points;
    double slope = 0;  ///< least-squares slope of log λ_measured against log B
    double predicted_slope = 0.25;
    double intercept_mm = 0;  ///< fitted λ at B = 1 µN·m, mm
    double max_abs_error_percent = 0;
    double seconds = 0;
};

namespace internal {

inline void check_buckling(const BucklingOptions& o, const FabricParams& f, double bending,
                           const char* who) {
    auto bad = [&](const std::string& what) { throw InvalidInput(std::string(who) + ": " + what); };
    auto in = [](double v, double lo, double hi) { return std::isfinite(v) && v >= lo && v <= hi; };
    if (!(std::isfinite(bending) && bending > 0)) {
        bad("bending rigidity must be finite and > 0 µN·m, got " + std::to_string(bending));
    }
    if (!in(o.resolution_mm, 0.2, 50)) {
        bad("resolution must be within 0.2 and 50 mm, got " + std::to_string(o.resolution_mm));
    }
    if (!(in(o.strain, 1e-6, 0.2) && in(o.first_strain, 1e-7, 0.2))) {
        bad("strain and first strain must be within 1e-6 and 0.2");
    }
    if (!(o.rounds_per_stage >= 1 && o.iterations_per_round >= 1)) {
        bad("rounds per stage and iterations per round must be >= 1");
    }
    if (!in(o.imperfection_mm, 0, 10)) {
        bad("imperfection must be within 0 and 10 mm, got " + std::to_string(o.imperfection_mm));
    }
    if (o.threads < 0) {
        bad("threads must be >= 0");
    }
    if (!(f.stretch_warp_n_m > 0 && f.stretch_weft_n_m > 0 && f.shear_n_m > 0)) {
        bad("fabric " + f.name + ": stretch and shear stiffness must be > 0");
    }
}

// The fabric with warp rigidity B (µN·m); weft and bias values, when given, scale with it so
// that the fabric's anisotropy is kept.
inline FabricParams with_bending(FabricParams f, double bending) {
    const double r = bending / f.bending_un_m;
    if (f.bending_weft_un_m >= 0) {
        f.bending_weft_un_m *= r;
    }
    if (f.bending_bias_un_m >= 0) {
        f.bending_bias_un_m *= r;
    }
    f.bending_un_m = bending;
    return f;
}

inline garment::DrapeOptions static_options(int threads) {
    garment::DrapeOptions o;
    o.gravity = {0, 0, 0};
    o.self_collision = false;
    o.untangle = false;
    o.threads = threads;
    return o;
}

// The load stages: first, 2·first, 4·first, ... below `last`, then `last`.
inline std::vector<double> load_stages(double first, double last) {
    std::vector<double> s;
    for (double e = first; e < last * (1 - 1e-9); e *= 2) {
        s.push_back(e);
    }
    s.push_back(last);
    return s;
}

/// Median (mean of the middle two for an even count; 0 when empty). Its own name: classify.h's
/// internal::median (upper median, NaN when empty) shares this namespace.
inline double median_or_zero(std::vector<double> v) {
    if (v.empty()) {
        return 0;
    }
    std::sort(v.begin(), v.end());
    const std::size_t n = v.size();
    return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

inline std::string fmt(const char* f, double v) {
    char buf[64];
    std::snprintf(buf, sizeof buf, f, v);
    return buf;
}

/// One relax() round of `o.iterations_per_round` Newton iterations to 1e-4 mm, its iterations
/// and convergence written into `r`; true when it converged.
inline bool relax_round(garment::DrapeSolver& solver, const BucklingOptions& o, BucklingResult& r) {
    garment::RelaxOptions ro = garment::RelaxOptions::proportional(o.iterations_per_round);
    ro.tolerance_mm = 1e-4;
    const garment::RelaxReport rr = solver.relax(ro);
    r.relax_iterations += rr.iterations;
    r.last_converged = rr.converged;
    return rr.converged;
}

}  // namespace internal

/// The strip on a Winkler foundation (see the file comment). `fabric` gives the membrane, shear
/// and density; its bending is replaced by `bending_un_m` (µN·m). Throws InvalidInput naming the
/// option that is out of range.
inline BucklingResult foundation_test(const FabricParams& fabric, double bending_un_m,
                                      const BucklingOptions& o = {}) {
    using namespace garment;
    const auto t0 = std::chrono::steady_clock::now();
    internal::check_buckling(o, fabric, bending_un_m, "foundation test");
    if (!(std::isfinite(o.foundation_n_m3) && o.foundation_n_m3 > 0)) {
        throw InvalidInput(
            "foundation test: foundation stiffness must be finite and > 0 N/m³, got " +
            std::to_string(o.foundation_n_m3));
    }
    if (!(std::isfinite(o.length_mm) && std::isfinite(o.width_mm) &&
          o.length_mm >= 16 * o.resolution_mm && o.width_mm >= 2 * o.resolution_mm &&
          o.length_mm <= 1e4 && o.width_mm <= o.length_mm)) {
        throw InvalidInput(
            "foundation test: the strip must be at least 16 edges long and 2 wide, "
            "and no wider than long");
    }
    const FabricParams f = internal::with_bending(fabric, bending_un_m);
    const double L = o.length_mm, K = o.foundation_n_m3;
    const int nx = static_cast<int>(std::lround(L / o.resolution_mm));
    const int ny = std::max(2, static_cast<int>(std::lround(o.width_mm / o.resolution_mm)));
    const double cx = L / nx, cz = o.width_mm / ny;
    ClothModel model = garment::internal::strip_model(nx, ny, cx, cz, 0, 0, 0, UV{1, 0});
    const std::size_t nv = model.positions.size();
    auto vid = [&](int i, int j) { return std::size_t(j) * std::size_t(nx + 1) + std::size_t(i); };
    model.pinned.assign(nv, 0);
    for (int j = 0; j <= ny; ++j) {
        for (int i : {0, 1, nx - 1, nx}) {
            model.pinned[vid(i, j)] = 1;  // two columns: a clamp holds the slope as well
        }
    }
    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::vector<double> eta(nv);
    for (double& e : eta) {
        e = o.imperfection_mm * unit(rng);
    }
    // k_v = K·A_v, A_v the vertex's share of the strip (halves on the long edges), N/m → mm/N.
    std::vector<double> compliance(nv);
    for (int j = 0; j <= ny; ++j) {
        for (int i = 0; i <= nx; ++i) {
            const double area_m2 = cx * cz * (j == 0 || j == ny ? 0.5 : 1) * 1e-6;
            compliance[vid(i, j)] = 1 / (K * area_m2 * 1e-3);
        }
    }

    BucklingResult r;
    r.test = "foundation";
    r.bending_un_m = bending_un_m;
    r.foundation_n_m3 = K;
    r.membrane_n_m = f.stretch_warp_n_m;
    r.predicted_wavelength_mm = 2 * M_PI * std::pow(bending_un_m * 1e-6 / K, 0.25) * 1e3;
    r.critical_strain = 2 * std::sqrt(bending_un_m * 1e-6 * K) / f.stretch_warp_n_m;
    r.strain = o.strain;
    r.vertices = nv;
    r.triangles = model.triangles.size();
    r.resolution_mm = cx;

    const DrapeOptions dopt = internal::static_options(o.threads);
    std::vector<Vec3> pos = model.positions;
    double previous = 0;
    Spectrum last;
    const int j_mid = ny / 2;
    auto measure = [&](const std::vector<Vec3>& x, double e, std::vector<Vec2>* prof) {
        std::vector<double> s, h;
        for (int i = 3; i <= nx - 3; ++i) {
            s.push_back(x[vid(i, j_mid)][0]);
            h.push_back(x[vid(i, j_mid)][1]);
            if (prof) {
                prof->push_back({x[vid(i, j_mid)][0], x[vid(i, j_mid)][1]});
            }
        }
        const double sp = cx * (1 - e);
        return dominant_wavelength(resample_uniform(s, h, sp), sp);
    };
    for (const double e : internal::load_stages(o.first_strain, o.strain)) {
        for (Vec3& p : pos) {
            p[0] = 0.5 * L + (p[0] - 0.5 * L) * (1 - e) / (1 - previous);
        }
        previous = e;
        ClothModel staged = model;
        staged.positions = pos;
        DrapeSolver solver(std::move(staged), f, dopt);
        for (int round = 0; round < o.rounds_per_stage; ++round) {
            std::vector<Attachment> springs;
            springs.reserve(nv);
            for (std::size_t v = 0; v < nv; ++v) {
                if (model.pinned[v]) {
                    continue;
                }
                const Vec3& p = solver.positions()[v];
                springs.push_back(
                    {static_cast<std::uint32_t>(v), {p[0], eta[v], p[2]}, compliance[v]});
            }
            solver.set_attachments(std::move(springs));
            if (internal::relax_round(solver, o, r)) {
                break;
            }
        }
        pos = solver.positions();
        last = measure(pos, e, nullptr);
        if (r.onset_strain == 0 && last.amplitude > 10 * o.imperfection_mm &&
            last.peak_share > 0.3) {
            r.onset_strain = e;
            r.onset_wavelength_mm = last.wavelength;
        }
        if (o.progress) {
            o.progress("foundation B=" + internal::fmt("%g", bending_un_m) + " strain " +
                       internal::fmt("%.2e", e) + ": lambda " +
                       internal::fmt("%.2f", last.wavelength) + " mm, amplitude " +
                       internal::fmt("%.3f", last.amplitude) + " mm, share " +
                       internal::fmt("%.2f", last.peak_share));
        }
    }
    last = measure(pos, o.strain, &r.profile);
    r.lines = 1;
    r.lines_at_record_limit = last.at_record_limit ? 1 : 0;
    r.measured_wavelength_mm = last.wavelength;
    r.peak_share = last.peak_share;
    r.amplitude_mm = last.amplitude;
    r.pattern = last.amplitude > 10 * o.imperfection_mm ? "wrinkles" : "flat";
    r.error_percent = 100 * (r.measured_wavelength_mm / r.predicted_wavelength_mm - 1);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

/// The tube under axial compression (see the file comment); `bending_un_m` as in foundation_test.
inline BucklingResult cylinder_test(const FabricParams& fabric, double bending_un_m,
                                    const BucklingOptions& o = {}) {
    using namespace garment;
    const auto t0 = std::chrono::steady_clock::now();
    internal::check_buckling(o, fabric, bending_un_m, "cylinder test");
    const double R = o.radius_mm, H = o.height_mm;
    if (!(std::isfinite(R) && std::isfinite(H) && 2 * M_PI * R >= 16 * o.resolution_mm &&
          H >= 16 * o.resolution_mm && R <= 1e4 && H <= 1e4)) {
        throw InvalidInput("cylinder test: the tube must be at least 16 edges around and 16 long");
    }
    if (o.generators < 1) {
        throw InvalidInput("cylinder test: generators must be >= 1, got " +
                           std::to_string(o.generators));
    }
    const FabricParams f = internal::with_bending(fabric, bending_un_m);
    const int na = static_cast<int>(std::lround(2 * M_PI * R / o.resolution_mm));
    const int nz = static_cast<int>(std::lround(H / o.resolution_mm));
    const double du = 2 * M_PI * R / na, dz = H / nz;
    ClothModel model;
    auto vid = [&](int i, int j) {
        return static_cast<std::uint32_t>(j * na + ((i % na) + na) % na);
    };
    for (int j = 0; j <= nz; ++j) {
        for (int i = 0; i < na; ++i) {
            const double th = 2 * M_PI * i / na;
            model.positions.push_back({R * std::cos(th), j * dz, R * std::sin(th)});
        }
    }
    // Rest UVs use the unwrapped column index, so the last column's triangles reach u = 2πR and
    // close the tube onto column 0 without a seam.
    auto add = [&](int i0, int j0, int i1, int j1, int i2, int j2) {
        model.triangles.push_back({vid(i0, j0), vid(i1, j1), vid(i2, j2)});
        model.rest_uv.push_back({UV{i0 * du, j0 * dz}, UV{i1 * du, j1 * dz}, UV{i2 * du, j2 * dz}});
        model.grain.push_back(UV{0, 1});  // warp along the axis
    };
    for (int j = 0; j < nz; ++j) {
        for (int i = 0; i < na; ++i) {
            if ((i + j) % 2 == 0) {
                add(i, j, i + 1, j + 1, i + 1, j);
                add(i, j, i, j + 1, i + 1, j + 1);
            } else {
                add(i, j, i, j + 1, i + 1, j);
                add(i + 1, j, i, j + 1, i + 1, j + 1);
            }
        }
    }
    const std::size_t nv = model.positions.size();
    model.pinned.assign(nv, 0);
    for (int i = 0; i < na; ++i) {
        model.pinned[vid(i, 0)] = 1;
    }
    std::mt19937 rng(o.seed);
    std::uniform_real_distribution<double> unit(-1, 1);
    std::vector<double> bump(nv, 0.0);
    for (int j = 1; j < nz; ++j) {
        for (int i = 0; i < na; ++i) {
            bump[vid(i, j)] = o.imperfection_mm * unit(rng);
        }
    }

    BucklingResult r;
    r.test = "cylinder";
    r.bending_un_m = bending_un_m;
    r.hoop_n_m = f.stretch_weft_n_m;
    r.membrane_n_m = f.stretch_warp_n_m;
    r.radius_mm = R;
    r.foundation_n_m3 = f.stretch_weft_n_m / (R * R * 1e-6);
    r.predicted_wavelength_mm =
        2 * M_PI * std::pow(bending_un_m * 1e-6 / r.foundation_n_m3, 0.25) * 1e3;
    r.critical_strain = 2 * std::sqrt(bending_un_m * 1e-6 * r.foundation_n_m3) / f.stretch_warp_n_m;
    r.strain = o.strain;
    r.vertices = nv;
    r.triangles = model.triangles.size();
    r.resolution_mm = std::min(du, dz);

    const DrapeOptions dopt = internal::static_options(o.threads);
    auto radial = [&](const Vec3& p) { return std::hypot(p[0], p[2]) - R; };
    const int row_lo = 2, row_hi = nz - 2;
    // Dominant axial wavelength along generator g, its profile optionally.
    auto generator = [&](const std::vector<Vec3>& x, int g, double e, std::vector<Vec2>* prof) {
        const int i = g * na / o.generators;
        std::vector<double> s, h;
        for (int j = row_lo; j <= row_hi; ++j) {
            s.push_back(x[vid(i, j)][1]);
            h.push_back(radial(x[vid(i, j)]));
            if (prof) {
                prof->push_back({s.back(), h.back()});
            }
        }
        const double sp = dz * (1 - e);
        return dominant_wavelength(resample_uniform(s, h, sp), sp);
    };
    std::vector<Vec3> pos = model.positions;
    double previous = 0;
    for (const double e : internal::load_stages(o.first_strain, o.strain)) {
        for (std::size_t v = 0; v < nv; ++v) {
            Vec3& p = pos[v];
            p[1] *= (1 - e) / (1 - previous);
            // The same seeded bump at every stage: the ramp must not let the symmetry return.
            const double rr = std::hypot(p[0], p[2]);
            if (rr > 0 && bump[v] != 0) {
                const double s = (rr + bump[v]) / rr;
                p[0] *= s;
                p[2] *= s;
            }
        }
        previous = e;
        ClothModel staged = model;
        staged.positions = pos;
        DrapeSolver solver(std::move(staged), f, dopt);
        std::vector<Attachment> top;
        for (int i = 0; i < na; ++i) {
            top.push_back({vid(i, nz), pos[vid(i, nz)], 0.0});
        }
        solver.set_attachments(std::move(top));
        for (int round = 0; round < o.rounds_per_stage; ++round) {
            if (internal::relax_round(solver, o, r)) {
                break;
            }
        }
        pos = solver.positions();
        const Spectrum g0 = generator(pos, 0, e, nullptr);
        if (r.onset_strain == 0 && g0.amplitude > 10 * o.imperfection_mm && g0.peak_share > 0.3) {
            r.onset_strain = e;
            r.onset_wavelength_mm = g0.wavelength;
        }
        if (o.progress) {
            o.progress("cylinder B=" + internal::fmt("%g", bending_un_m) + " strain " +
                       internal::fmt("%.2e", e) + ": lambda " +
                       internal::fmt("%.2f", g0.wavelength) + " mm, amplitude " +
                       internal::fmt("%.3f", g0.amplitude) + " mm, share " +
                       internal::fmt("%.2f", g0.peak_share));
        }
    }
    std::vector<double> shares, amps;
    for (int g = 0; g < o.generators; ++g) {
        const Spectrum s = generator(pos, g, o.strain, g == 0 ? &r.profile : nullptr);
        r.generator_wavelengths_mm.push_back(s.wavelength);
        ++r.lines;
        r.lines_at_record_limit += s.at_record_limit ? 1 : 0;
        shares.push_back(s.peak_share);
        amps.push_back(s.amplitude);
    }
    r.measured_wavelength_mm = internal::median_or_zero(r.generator_wavelengths_mm);
    r.peak_share = std::accumulate(shares.begin(), shares.end(), 0.0) / double(shares.size());
    r.amplitude_mm = internal::median_or_zero(amps);
    // Axisymmetry: energy of the ring means against that of the whole radial displacement.
    double total = 0, axisym = 0, worst = -1;
    int worst_row = row_lo;
    std::vector<double> ring_means, ring_s;
    for (int j = row_lo; j <= row_hi; ++j) {
        double mean = 0;
        for (int i = 0; i < na; ++i) {
            mean += radial(pos[vid(i, j)]);
        }
        mean /= na;
        double var = 0;
        for (int i = 0; i < na; ++i) {
            const double d = radial(pos[vid(i, j)]);
            total += d * d;
            var += (d - mean) * (d - mean);
        }
        axisym += na * mean * mean;
        ring_means.push_back(mean);
        ring_s.push_back(pos[vid(0, j)][1]);
        if (var > worst) {
            worst = var;
            worst_row = j;
        }
    }
    r.axisymmetric_share = total > 0 ? axisym / total : 0;
    r.axisymmetric_wavelength_mm =
        dominant_wavelength(resample_uniform(ring_s, ring_means, dz * (1 - o.strain)),
                            dz * (1 - o.strain))
            .wavelength;
    std::vector<double> ring;
    for (int i = 0; i < na; ++i) {
        ring.push_back(radial(pos[vid(i, worst_row)]));
    }
    const Spectrum around = dominant_wavelength(ring, du);
    r.circumferential_lobes = around.wavelength > 0 ? 2 * M_PI * R / around.wavelength : 0;
    r.pattern = r.amplitude_mm <= 10 * o.imperfection_mm ? "flat"
                : r.axisymmetric_share >= 0.5            ? "axisymmetric"
                                                         : "non-axisymmetric";
    r.error_percent = 100 * (r.measured_wavelength_mm / r.predicted_wavelength_mm - 1);
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return r;
}

/// Least-squares slope and intercept of log y against log x (at least two points, all > 0).
inline std::pair<double, double> loglog_fit(const std::vector<double>& x,
                                            const std::vector<double>& y) {
    if (x.size() != y.size() || x.size() < 2) {
        throw InvalidInput("loglog_fit: need two or more (x, y) pairs");
    }
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double n = double(x.size());
    for (std::size_t i = 0; i < x.size(); ++i) {
        if (!(x[i] > 0 && y[i] > 0 && std::isfinite(x[i]) && std::isfinite(y[i]))) {
            throw InvalidInput("loglog_fit: point " + std::to_string(i) +
                               " is not finite and positive");
        }
        const double lx = std::log(x[i]), ly = std::log(y[i]);
        sx += lx;
        sy += ly;
        sxx += lx * lx;
        sxy += lx * ly;
    }
    const double den = n * sxx - sx * sx;
    if (!(den > 0)) {
        throw InvalidInput("loglog_fit: all x are equal");
    }
    const double slope = (n * sxy - sx * sy) / den;
    return {slope, std::exp((sy - slope * sx) / n)};
}

/// Runs `test` ("foundation" or "cylinder") for every B in `bendings_un_m` (µN·m, two or more
/// distinct values) and fits the log–log slope of the measured wavelength against B.
inline ScalingSweep scaling_sweep(const std::string& test, const FabricParams& fabric,
                                  const std::vector<double>& bendings_un_m,
                                  const BucklingOptions& o = {}) {
    if (test != "foundation" && test != "cylinder") {
        throw InvalidInput("scaling sweep: test must be foundation or cylinder, got '" + test +
                           "'");
    }
    if (bendings_un_m.size() < 2) {
        throw InvalidInput("scaling sweep: need at least two bending rigidities");
    }
    const auto t0 = std::chrono::steady_clock::now();
    ScalingSweep s;
    std::vector<double> b, l;
    for (const double bend : bendings_un_m) {
        s.points.push_back(test == "foundation" ? foundation_test(fabric, bend, o)
                                                : cylinder_test(fabric, bend, o));
        const BucklingResult& p = s.points.back();
        b.push_back(bend);
        l.push_back(p.measured_wavelength_mm);
        s.max_abs_error_percent = std::max(s.max_abs_error_percent, std::abs(p.error_percent));
        if (o.progress) {
            o.progress(test + " B=" + internal::fmt("%g", bend) + ": predicted " +
                       internal::fmt("%.2f", p.predicted_wavelength_mm) + " mm, measured " +
                       internal::fmt("%.2f", p.measured_wavelength_mm) + " mm (" +
                       internal::fmt("%+.1f", p.error_percent) + " %), " +
                       internal::fmt("%.1f", p.seconds) + " s");
        }
    }
    bool measured = std::all_of(l.begin(), l.end(), [](double v) { return v > 0; });
    if (measured) {
        const auto [slope, c] = loglog_fit(b, l);
        s.slope = slope;
        s.intercept_mm = c;
    } else {
        s.slope = std::numeric_limits<double>::quiet_NaN();
    }
    s.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return s;
}

/// Measured (discs) and predicted (rings) wavelength against B, as log10 values on linear axes
/// (the plot has no log axes); the fitted slope in the title. No legend box (it would hide the
/// top right corner, where the stiffest point lies): the axis title names the markers.
inline draw::RgbaImage scaling_picture(const ScalingSweep& s, const std::string& title) {
    draw::PlotSeries measured, predicted;
    measured.colour = {0.12, 0.47, 0.71};
    predicted.colour = {0.85, 0.33, 0.1};
    predicted.marker = draw::PlotSeries::Marker::ring;
    predicted.radius_px = 5;
    for (const BucklingResult& p : s.points) {
        const double lb = std::log10(p.bending_un_m);
        if (p.measured_wavelength_mm > 0) {
            measured.points.push_back({lb, std::log10(p.measured_wavelength_mm)});
        }
        predicted.points.push_back({lb, std::log10(p.predicted_wavelength_mm)});
    }
    draw::PlotOptions po;
    po.title = title + ": slope " + internal::fmt("%.3f", s.slope) + " (law 0.25)";
    po.x_label = "log10 B [uN m]";
    po.y_label = "log10 wavelength [mm]: rings law, discs measured";
    po.x_from_zero = false;
    po.y_from_zero = false;
    po.title_font_px = 13;
    return draw::scatter_plot({predicted, measured}, po);
}

/// The height profile of one result (strip centre line or first generator), heights in mm.
inline draw::RgbaImage profile_picture(const BucklingResult& r, const std::string& title) {
    draw::PlotSeries line;
    line.points = r.profile;
    line.radius_px = 1.5;
    line.colour = {0.12, 0.47, 0.71};
    draw::PlotOptions po;
    po.width_px = 1000;
    po.height_px = 300;
    po.title = title;
    po.title_font_px = 14;
    po.x_label = r.test == "cylinder" ? "axial position [mm]" : "position along the strip [mm]";
    po.y_label = r.test == "cylinder" ? "r - R [mm]" : "height [mm]";
    po.x_from_zero = false;
    po.y_from_zero = false;
    return draw::scatter_plot({line}, po);
}

}  // namespace tapeline::wrinkles
