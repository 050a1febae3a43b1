// Wrinkle class of every triangle of a draped garment, and the wavelength and amplitude of the
// wrinkles the fabric should show there.
//
// Class (from the strain against the pattern, strain.h, in the grain frame):
//  - none: no direction of the triangle is shorter than in the pattern by more than
//    `compression_threshold` (s_min ≥ 1 − threshold): there is no excess length to fold;
//  - shear: compressed, the yarns sheared by more than `shear_threshold_deg`, and the compression
//    axis within `bias_window_deg` of a bias direction (45° to the grain): the diagonal folds of
//    sheared cloth;
//  - tension: compressed across while stretched along (s_max > 1 + `tension_threshold`): the
//    folds that run along a pull (a sheet pulled between two points, cloth hanging from a
//    shoulder);
//  - compression: compressed with no pull along the crests (a sleeve pushed up the arm).
// The first that applies of shear, tension, compression wins. The crests run along dir_max, the
// waves along dir_min.
//
// Wavelength: the buckling law of a sheet on an elastic foundation (E. Cerda, L. Mahadevan,
// "Geometry and Physics of Wrinkling", PRL 90, 074302, 2003): B·w'''' + N·w'' + K·w = 0 has its
// first unstable mode at λ = 2π·(B/K)^{1/4}, N_c = 2·√(B·K). B is the fabric's bending rigidity for
// curvature along the waves (garment/bending.h, B(ψ) at the compression axis). K is the stiffness
// with which the cloth resists leaving its draped shape, from the tension T along the crests
// (the normal stress of the fabric's linear membrane law, warp and weft stiffness and shear, at
// the triangle's strains; 0 when that stress is compressive):
//  - curvature-induced stiffness K = T·κ², κ the draped surface's normal curvature along the
//    crests (a crest that rises by w on a surface curved by κ along a tension T is pulled back by
//    T·κ²·w; D. Paulsen et al., "Curvature-induced stiffness and the spatial variation of
//    wavelength in wrinkled sheets", PNAS 113, 1144, 2016);
//  - with `tension_length_mm` = L > 0, also T·(π/L)²: the restoring force of a tension acting
//    over a length L on a crest that rises as a half sine along it (Cerda & Mahadevan's stretched
//    sheet, K ~ T/L²).
// Where K is 0 (no tension along the crests, or neither curvature nor L) the law sets no
// wavelength and none is predicted (`wavelength_mm` NaN; counted in `no_foundation`).
// Amplitude: the excess length Δ = 1 − s_min taken up by a sine of wavelength λ, whose arc length
// exceeds its span by (π·A/λ)² for small slopes: A = (λ/π)·√Δ.
//
// Units: positions and pattern coordinates in mm; fabric as garment::FabricParams (N/m, µN·m).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/draw/mesh_render.h>
#include <tapeline/garment/bending.h>
#include <tapeline/garment/drape_types.h>
#include <tapeline/garment/garment_types.h>
#include <tapeline/wrinkles/strain.h>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace tapeline::wrinkles {

/// The wrinkle class of a triangle (see the file comment).
enum class WrinkleClass : std::uint8_t { none = 0, tension = 1, shear = 2, compression = 3 };

inline constexpr std::size_t kWrinkleClasses = 4;

/// "none", "tension", "shear" or "compression".
inline const char* to_string(WrinkleClass c) {
    switch (c) {
        case WrinkleClass::tension:
            return "tension";
        case WrinkleClass::shear:
            return "shear";
        case WrinkleClass::compression:
            return "compression";
        case WrinkleClass::none:
            break;
    }
    return "none";
}

/// Thresholds of the classes and the length of the tension term (see the file comment).
struct ClassifyOptions {
    double compression_threshold = 0.01;  ///< compressed when s_min < 1 − this (> 0, < 1)
    double tension_threshold = 0.01;      ///< tension wrinkles when s_max > 1 + this (>= 0)
    double shear_threshold_deg = 3;       ///< shear wrinkles above this shear angle (>= 0)
    double bias_window_deg = 22.5;        ///< compression axis this close to a bias (0–45)
    /// L of the tension term T·(π/L)² of the foundation, mm (0: off; otherwise > 0).
    double tension_length_mm = 0;
};

/// What the classification says of one triangle.
struct TriangleWrinkles {
    WrinkleClass cls = WrinkleClass::none;
    TriangleStrain strain;
    double tension_n_m = 0;      ///< T: normal stress along the crests (dir_max), N/m, >= 0
    double curvature_1_mm = 0;   ///< κ: normal curvature along the crests, 1/mm
    double bending_un_m = 0;     ///< B: bending rigidity for curvature along the waves, µN·m
    double foundation_n_m3 = 0;  ///< K, N/m³
    /// λ, mm (NaN: not compressed, or no foundation).
    double wavelength_mm = std::numeric_limits<double>::quiet_NaN();
    /// A, mm (NaN where λ is).
    double amplitude_mm = std::numeric_limits<double>::quiet_NaN();
};

/// Totals of a classification.
struct WrinkleReport {
    std::size_t triangles = 0;
    std::size_t degenerate = 0;  ///< pattern triangles of zero area (class none)
    std::array<std::size_t, kWrinkleClasses> count{};  ///< triangles per class
    /// Share of the pattern area per class, %.
    std::array<double, kWrinkleClasses> area_percent{};
    /// Median predicted wavelength and amplitude per class over its predicted triangles, mm
    /// (NaN: none predicted).
    ///@{
    std::array<double, kWrinkleClasses> median_wavelength_mm{}, median_amplitude_mm{};
    ///@}
    std::size_t predicted = 0;      ///< compressed triangles with a wavelength
    std::size_t no_foundation = 0;  ///< compressed triangles where K is 0 (no wavelength)
    double seconds = 0;
};

/// Per-triangle results and their totals.
struct WrinkleField {
    std::vector<TriangleWrinkles> triangles;
    WrinkleReport report;
};

namespace internal {

inline void check_options(const ClassifyOptions& o) {
    auto bad = [](const std::string& what, double v) {
        throw InvalidInput("wrinkle classification: " + what + " (got " + std::to_string(v) + ")");
    };
    if (!(o.compression_threshold > 0 && o.compression_threshold < 1)) {
        bad("compression_threshold must lie in (0, 1)", o.compression_threshold);
    }
    if (!(o.tension_threshold >= 0 && std::isfinite(o.tension_threshold))) {
        bad("tension_threshold must be finite and >= 0", o.tension_threshold);
    }
    if (!(o.shear_threshold_deg >= 0 && o.shear_threshold_deg < 90)) {
        bad("shear_threshold_deg must lie in [0, 90)", o.shear_threshold_deg);
    }
    if (!(o.bias_window_deg >= 0 && o.bias_window_deg <= 45)) {
        bad("bias_window_deg must lie in [0, 45]", o.bias_window_deg);
    }
    if (!(o.tension_length_mm >= 0 && std::isfinite(o.tension_length_mm))) {
        bad("tension_length_mm must be finite and >= 0", o.tension_length_mm);
    }
}

inline void check_fabric(const garment::FabricParams& f) {
    auto positive = [&](const char* what, double v) {
        if (!(v > 0 && std::isfinite(v))) {
            throw InvalidInput("wrinkle classification: fabric '" + f.name + "': " + what +
                               " must be a positive finite number (got " + std::to_string(v) + ")");
        }
    };
    positive("stretch_warp_n_m", f.stretch_warp_n_m);
    positive("stretch_weft_n_m", f.stretch_weft_n_m);
    positive("shear_n_m", f.shear_n_m);
    positive("bending_un_m", f.bending_un_m);
}

inline double median(std::vector<double> v) {
    if (v.empty()) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    const std::size_t k = v.size() / 2;
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
}

}  // namespace internal

/// The normal stress (N/m) along the pattern direction `d` (unit, pattern coordinates) of the
/// fabric's linear membrane law at the strains of `s` (`grain`: unit warp direction): warp and
/// weft stress k·ε, shear stress G·γ, projected on d. Negative: compression.
inline double membrane_stress_along(const garment::FabricParams& f, const TriangleStrain& s,
                                    const UV& grain, const UV& d) {
    const UV weft{-grain[1], grain[0]};
    const double c = d[0] * grain[0] + d[1] * grain[1];
    const double sn = d[0] * weft[0] + d[1] * weft[1];
    const double sw = f.stretch_warp_n_m * s.warp_strain;
    const double sf = f.stretch_weft_n_m * s.weft_strain;
    const double tau = f.shear_n_m * s.shear_rad;
    return sw * c * c + sf * sn * sn + 2 * tau * c * sn;
}

/// λ = 2π·(B/K)^{1/4} in mm for B in µN·m and K in N/m³ (NaN unless both are positive).
inline double buckling_wavelength_mm(double bending_un_m, double foundation_n_m3) {
    if (!(bending_un_m > 0 && foundation_n_m3 > 0)) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return 2 * M_PI * std::pow(bending_un_m * 1e-6 / foundation_n_m3, 0.25) * 1e3;
}

/// A = (λ/π)·√Δ: the amplitude of a sine of wavelength λ whose arc length exceeds its span by
/// the fraction Δ (small slopes). NaN when λ is not finite or Δ < 0.
inline double wrinkle_amplitude_mm(double wavelength_mm, double excess) {
    if (!(std::isfinite(wavelength_mm) && excess >= 0)) {
        return std::numeric_limits<double>::quiet_NaN();
    }
    return wavelength_mm / M_PI * std::sqrt(excess);
}

/// Classifies every triangle of `g` (positions in mm, pattern coordinates in mm, g.grain per
/// triangle or +y when empty) for `fabric` (see the file comment).
///
/// \throws InvalidInput naming the triangle, vertex or option: a vertex index out of range, a
///         position or pattern coordinate that is not finite, array sizes that do not match, a
///         grain of zero length, options out of range, a fabric stiffness that is not positive.
inline WrinkleField classify_wrinkles(const garment::GarmentMesh& g,
                                      const garment::FabricParams& fabric,
                                      const ClassifyOptions& o = {}) {
    const auto t0 = std::chrono::steady_clock::now();
    internal::check_options(o);
    internal::check_fabric(fabric);
    const std::size_t nt = g.triangles.size();
    if (g.uv.size() != nt) {
        throw InvalidInput("wrinkle classification: " + std::to_string(nt) + " triangles but " +
                           std::to_string(g.uv.size()) + " pattern triangles");
    }
    if (!g.grain.empty() && g.grain.size() != nt) {
        throw InvalidInput("wrinkle classification: " + std::to_string(nt) + " triangles but " +
                           std::to_string(g.grain.size()) + " grain directions");
    }
    for (std::size_t v = 0; v < g.positions.size(); ++v) {
        for (double c : g.positions[v]) {
            if (!std::isfinite(c)) {
                throw InvalidInput("wrinkle classification: vertex " + std::to_string(v) +
                                   " has a coordinate that is not finite");
            }
        }
    }
    for (std::size_t f = 0; f < nt; ++f) {
        for (std::uint32_t v : g.triangles[f]) {
            if (v >= g.positions.size()) {
                throw InvalidInput("wrinkle classification: triangle " + std::to_string(f) +
                                   " names vertex " + std::to_string(v) + " of " +
                                   std::to_string(g.positions.size()));
            }
        }
        for (const UV& t : g.uv[f]) {
            if (!(std::isfinite(t[0]) && std::isfinite(t[1]))) {
                throw InvalidInput("wrinkle classification: triangle " + std::to_string(f) +
                                   " has a pattern coordinate that is not finite");
            }
        }
        if (!g.grain.empty() && !(std::hypot(g.grain[f][0], g.grain[f][1]) > 1e-12)) {
            throw InvalidInput("wrinkle classification: triangle " + std::to_string(f) +
                               " has a grain direction of zero length");
        }
    }
    const std::vector<Vec3> normals = draw::vertex_normals(g.positions, g.triangles);
    WrinkleField out;
    out.triangles.resize(nt);
    WrinkleReport& r = out.report;
    r.triangles = nt;
    std::array<double, kWrinkleClasses> area{};
    double total_area = 0;
    std::array<std::vector<double>, kWrinkleClasses> lambdas, amplitudes;
    // The compression axis at ψ from the warp lies within w of a bias (45° or 135°) exactly when
    // |cos 2ψ| <= sin 2w.
    const double bias_limit = std::sin(2 * o.bias_window_deg * M_PI / 180) + 1e-12;
    for (std::size_t f = 0; f < nt; ++f) {
        TriangleWrinkles& w = out.triangles[f];
        const Tri& t = g.triangles[f];
        UV grain{0, 1};
        if (!g.grain.empty()) {
            const double l = std::hypot(g.grain[f][0], g.grain[f][1]);
            grain = {g.grain[f][0] / l, g.grain[f][1] / l};
        }
        w.strain = triangle_strain(g.positions[t[0]], g.positions[t[1]], g.positions[t[2]], g.uv[f],
                                   grain);
        const double a = pattern_area(g.uv[f]);
        total_area += a;
        if (!w.strain.valid) {
            ++r.degenerate;
            ++r.count[0];
            area[0] += a;
            continue;
        }
        const TriangleStrain& s = w.strain;
        if (s.s_min < 1 - o.compression_threshold) {
            const double psi = s.min_angle_from_warp_deg * M_PI / 180;
            const bool near_bias = std::abs(std::cos(2 * psi)) <= bias_limit;
            if (std::abs(s.shear_rad) * 180 / M_PI > o.shear_threshold_deg && near_bias) {
                w.cls = WrinkleClass::shear;
            } else if (s.s_max > 1 + o.tension_threshold) {
                w.cls = WrinkleClass::tension;
            } else {
                w.cls = WrinkleClass::compression;
            }
            w.tension_n_m = std::max(0.0, membrane_stress_along(fabric, s, grain, s.rest_max));
            w.curvature_1_mm = triangle_curvature(g.positions, t, normals).along(s.dir_max);
            const UV weft{-grain[1], grain[0]};
            const double c = s.rest_min[0] * grain[0] + s.rest_min[1] * grain[1];
            const double sn = s.rest_min[0] * weft[0] + s.rest_min[1] * weft[1];
            w.bending_un_m = garment::bending_rigidity_un_m(fabric, c, sn);
            const double kappa_m = w.curvature_1_mm * 1e3;
            double k = w.tension_n_m * kappa_m * kappa_m;
            if (o.tension_length_mm > 0) {
                const double q = M_PI / (o.tension_length_mm * 1e-3);
                k += w.tension_n_m * q * q;
            }
            w.foundation_n_m3 = k;
            w.wavelength_mm = buckling_wavelength_mm(w.bending_un_m, k);
            w.amplitude_mm = wrinkle_amplitude_mm(w.wavelength_mm, 1 - s.s_min);
            const std::size_t c0 = std::size_t(w.cls);
            if (std::isfinite(w.wavelength_mm)) {
                ++r.predicted;
                lambdas[c0].push_back(w.wavelength_mm);
                amplitudes[c0].push_back(w.amplitude_mm);
            } else {
                ++r.no_foundation;
            }
        }
        ++r.count[std::size_t(w.cls)];
        area[std::size_t(w.cls)] += a;
    }
    for (std::size_t c = 0; c < kWrinkleClasses; ++c) {
        r.area_percent[c] = total_area > 0 ? 100 * area[c] / total_area : 0;
        r.median_wavelength_mm[c] = internal::median(lambdas[c]);
        r.median_amplitude_mm[c] = internal::median(amplitudes[c]);
    }
    r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    return out;
}

/// The report as JSON (mm, %, seconds; a NaN median is null).
inline nlohmann::ordered_json wrinkle_report_json(const WrinkleReport& r) {
    nlohmann::ordered_json j;
    j["triangles"] = r.triangles;
    j["degenerate"] = r.degenerate;
    nlohmann::ordered_json classes = nlohmann::ordered_json::object();
    for (std::size_t c = 0; c < kWrinkleClasses; ++c) {
        nlohmann::ordered_json k;
        k["triangles"] = r.count[c];
        k["area_percent"] = r.area_percent[c];
        k["median_wavelength_mm"] = std::isfinite(r.median_wavelength_mm[c])
                                        ? nlohmann::ordered_json(r.median_wavelength_mm[c])
                                        : nlohmann::ordered_json(nullptr);
        k["median_amplitude_mm"] = std::isfinite(r.median_amplitude_mm[c])
                                       ? nlohmann::ordered_json(r.median_amplitude_mm[c])
                                       : nlohmann::ordered_json(nullptr);
        classes[to_string(WrinkleClass(c))] = k;
    }
    j["classes"] = classes;
    j["predicted"] = r.predicted;
    j["no_foundation"] = r.no_foundation;
    j["seconds"] = r.seconds;
    return j;
}

/// Per-triangle arrays as JSON: class name, λ and A (mm; null where not predicted), the principal
/// stretches, the shear angle (degrees), T (N/m), κ (1/mm) and K (N/m³).
inline nlohmann::ordered_json wrinkle_triangles_json(const WrinkleField& w) {
    nlohmann::ordered_json cls = nlohmann::ordered_json::array(),
                           lam = nlohmann::ordered_json::array(),
                           amp = nlohmann::ordered_json::array(),
                           smax = nlohmann::ordered_json::array(),
                           smin = nlohmann::ordered_json::array(),
                           shear = nlohmann::ordered_json::array(),
                           ten = nlohmann::ordered_json::array(),
                           kap = nlohmann::ordered_json::array(),
                           fk = nlohmann::ordered_json::array();
    auto num = [](double v) {
        return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
    };
    for (const TriangleWrinkles& t : w.triangles) {
        cls.push_back(to_string(t.cls));
        lam.push_back(num(t.wavelength_mm));
        amp.push_back(num(t.amplitude_mm));
        smax.push_back(t.strain.s_max);
        smin.push_back(t.strain.s_min);
        shear.push_back(t.strain.shear_rad * 180 / M_PI);
        ten.push_back(t.tension_n_m);
        kap.push_back(t.curvature_1_mm);
        fk.push_back(t.foundation_n_m3);
    }
    nlohmann::ordered_json j;
    j["class"] = cls;
    j["wavelength_mm"] = lam;
    j["amplitude_mm"] = amp;
    j["stretch_max"] = smax;
    j["stretch_min"] = smin;
    j["shear_deg"] = shear;
    j["tension_n_m"] = ten;
    j["curvature_1_mm"] = kap;
    j["foundation_n_m3"] = fk;
    return j;
}

/// Colours of the classes in pictures: none grey-blue, tension orange, shear violet,
/// compression red.
inline std::vector<draw::Rgb> wrinkle_class_colours() {
    return {{0.62, 0.68, 0.78}, {0.95, 0.6, 0.15}, {0.6, 0.35, 0.8}, {0.85, 0.15, 0.15}};
}

}  // namespace tapeline::wrinkles
