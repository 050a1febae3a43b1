// The wrinkles of a fine drape against the prediction on a coarse drape of the same garment:
// for every compressed coarse triangle with a predicted wavelength, the dominant wavelength and
// amplitude of the fine drape's height field (embedding.h) over a window around it.
//
// Window. In the pattern plane of the triangle's piece: centred on its centroid, `periods`
// predicted wavelengths long along its compression axis (the waves' direction, TriangleStrain::
// rest_min) and `width_fraction` of a predicted wavelength wide along the crests; its detrended
// height profile and spectrum come from PatternWindows (window.h); the dominant
// wavelength, a length of pattern, times the triangle's s_min is the draped wavelength. A window
// counts as measured when its profile has a dominant wavelength (peak share at least
// `min_peak_share`) that is not the longest the window resolves (Spectrum::at_record_limit), an
// amplitude of at least `min_amplitude_mm`, and at least 16 fine vertices.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/garment/garment_types.h>
#include <tapeline/wrinkles/classify.h>
#include <tapeline/wrinkles/embedding.h>
#include <tapeline/wrinkles/spectrum.h>
#include <tapeline/wrinkles/window.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <tuple>
#include <vector>

namespace tapeline::wrinkles {

/// How the windows are cut (see the file comment).
struct CompareOptions {
    double periods = 4;             ///< window length in predicted wavelengths (>= 2)
    double width_fraction = 0.5;    ///< window width in predicted wavelengths (> 0)
    double min_peak_share = 0.3;    ///< a dominant wavelength needs this share (0–1)
    double min_amplitude_mm = 0.1;  ///< and this amplitude (>= 0): smaller is no visible wave
};

/// One compressed coarse triangle: what was predicted and what the fine drape shows there.
struct WindowComparison {
    std::uint32_t triangle = 0;
    WrinkleClass cls = WrinkleClass::none;
    double predicted_wavelength_mm = 0, predicted_amplitude_mm = 0;
    double measured_wavelength_mm = 0, measured_amplitude_mm = 0;
    double peak_share = 0;
    std::size_t fine_vertices = 0;  ///< in the window
    bool measured = false;          ///< see the file comment
};

/// Totals over the windows.
struct ComparisonReport {
    std::size_t windows = 0;   ///< compressed coarse triangles with a predicted wavelength
    std::size_t measured = 0;  ///< of them, windows with a dominant wavelength in the fine drape
    /// Per class: measured windows and the median of |measured / predicted − 1| of wavelength and
    /// amplitude, % (NaN: none measured).
    ///@{
    std::array<std::size_t, kWrinkleClasses> measured_per_class{};
    std::array<double, kWrinkleClasses> median_wavelength_error_percent{},
        median_amplitude_error_percent{};
    ///@}
    /// The same over every measured window.
    ///@{
    double median_wavelength_error_percent_all = std::numeric_limits<double>::quiet_NaN();
    double median_amplitude_error_percent_all = std::numeric_limits<double>::quiet_NaN();
    ///@}
    /// Median of measured / predicted wavelength over the measured windows (1: unbiased).
    double median_wavelength_ratio = std::numeric_limits<double>::quiet_NaN();
    double rms_height_mm = 0;   ///< of the whole fine drape over the coarse one (embedding)
    double max_outside_mm = 0;  ///< embedding: fine outline beyond the coarse one, pattern mm
};

struct Comparison {
    std::vector<WindowComparison> windows;
    ComparisonReport report;
    Embedding embedding;
};

/// Compares the fine drape `fine` with the classification `field` of the coarse drape `coarse`
/// (both GarmentMesh of one pattern, mm).
///
/// \throws InvalidInput as embed_fine_in_coarse(), for a `field` of another size than `coarse`'s
///         triangles, or options out of range.
inline Comparison compare_wrinkles(const garment::GarmentMesh& coarse, const WrinkleField& field,
                                   const garment::GarmentMesh& fine, const CompareOptions& o = {}) {
    if (!(o.periods >= 2 && std::isfinite(o.periods))) {
        throw InvalidInput("wrinkle comparison: periods must be >= 2 (got " +
                           std::to_string(o.periods) + ")");
    }
    if (!(o.width_fraction > 0 && std::isfinite(o.width_fraction))) {
        throw InvalidInput("wrinkle comparison: width_fraction must be > 0 (got " +
                           std::to_string(o.width_fraction) + ")");
    }
    if (!(o.min_amplitude_mm >= 0 && std::isfinite(o.min_amplitude_mm))) {
        throw InvalidInput("wrinkle comparison: min_amplitude_mm must be finite and >= 0 (got " +
                           std::to_string(o.min_amplitude_mm) + ")");
    }
    if (!(o.min_peak_share >= 0 && o.min_peak_share <= 1)) {
        throw InvalidInput("wrinkle comparison: min_peak_share must lie in [0, 1] (got " +
                           std::to_string(o.min_peak_share) + ")");
    }
    if (field.triangles.size() != coarse.triangles.size()) {
        throw InvalidInput("wrinkle comparison: " + std::to_string(field.triangles.size()) +
                           " classified triangles for a coarse mesh of " +
                           std::to_string(coarse.triangles.size()));
    }
    Comparison out;
    out.embedding = embed_fine_in_coarse(coarse, fine);
    const Embedding& e = out.embedding;

    std::vector<double> heights(fine.positions.size(), 0.0);
    for (std::size_t v = 0; v < heights.size(); ++v) {
        heights[v] = e.vertices[v].height_mm;
    }
    const PatternWindows windows(fine, std::move(heights));

    std::array<std::vector<double>, kWrinkleClasses> lam_err, amp_err;
    std::vector<double> all_lam, all_amp, ratios;
    ComparisonReport& r = out.report;
    for (std::size_t t = 0; t < coarse.triangles.size(); ++t) {
        const TriangleWrinkles& w = field.triangles[t];
        if (w.cls == WrinkleClass::none || !std::isfinite(w.wavelength_mm)) {
            continue;
        }
        ++r.windows;
        WindowComparison c;
        c.triangle = std::uint32_t(t);
        c.cls = w.cls;
        c.predicted_wavelength_mm = w.wavelength_mm;
        c.predicted_amplitude_mm = w.amplitude_mm;
        const auto& u = coarse.uv[t];
        const garment::UV centre = pattern_centroid(u);
        const WindowProfile p = windows.profile(coarse.triangle_piece[t], centre, w.strain.rest_min,
                                                0.5 * o.periods * w.wavelength_mm,
                                                0.5 * o.width_fraction * w.wavelength_mm);
        c.fine_vertices = p.vertices;
        if (p.resolved) {
            const Spectrum& sp = p.spectrum;
            // Pattern length to draped length: the waves' direction is shortened by s_min.
            c.measured_wavelength_mm = sp.wavelength * w.strain.s_min;
            c.measured_amplitude_mm = sp.amplitude;
            c.peak_share = sp.peak_share;
            c.measured = sp.wavelength > 0 && !sp.at_record_limit &&
                         sp.peak_share >= o.min_peak_share && sp.amplitude >= o.min_amplitude_mm;
        }
        if (c.measured) {
            ++r.measured;
            ++r.measured_per_class[std::size_t(c.cls)];
            const double le =
                100 * std::abs(c.measured_wavelength_mm / c.predicted_wavelength_mm - 1);
            const double ae =
                100 * std::abs(c.measured_amplitude_mm / c.predicted_amplitude_mm - 1);
            lam_err[std::size_t(c.cls)].push_back(le);
            amp_err[std::size_t(c.cls)].push_back(ae);
            all_lam.push_back(le);
            all_amp.push_back(ae);
            ratios.push_back(c.measured_wavelength_mm / c.predicted_wavelength_mm);
        }
        out.windows.push_back(c);
    }
    for (std::size_t k = 0; k < kWrinkleClasses; ++k) {
        r.median_wavelength_error_percent[k] = internal::median(lam_err[k]);
        r.median_amplitude_error_percent[k] = internal::median(amp_err[k]);
    }
    r.median_wavelength_error_percent_all = internal::median(all_lam);
    r.median_amplitude_error_percent_all = internal::median(all_amp);
    r.median_wavelength_ratio = internal::median(ratios);
    r.rms_height_mm = e.rms_height_mm;
    r.max_outside_mm = e.max_outside_mm;
    return out;
}

/// The report as JSON (%, mm; a NaN median is null).
inline nlohmann::ordered_json comparison_report_json(const ComparisonReport& r) {
    auto num = [](double v) {
        return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
    };
    nlohmann::ordered_json j;
    j["windows"] = r.windows;
    j["measured"] = r.measured;
    nlohmann::ordered_json classes = nlohmann::ordered_json::object();
    for (std::size_t k = 1; k < kWrinkleClasses; ++k) {
        classes[to_string(WrinkleClass(k))] = {
            {"measured", r.measured_per_class[k]},
            {"median_wavelength_error_percent", num(r.median_wavelength_error_percent[k])},
            {"median_amplitude_error_percent", num(r.median_amplitude_error_percent[k])}};
    }
    j["classes"] = classes;
    j["median_wavelength_error_percent"] = num(r.median_wavelength_error_percent_all);
    j["median_amplitude_error_percent"] = num(r.median_amplitude_error_percent_all);
    j["median_wavelength_ratio"] = num(r.median_wavelength_ratio);
    j["rms_height_mm"] = r.rms_height_mm;
    j["max_outside_mm"] = r.max_outside_mm;
    return j;
}

}  // namespace tapeline::wrinkles
