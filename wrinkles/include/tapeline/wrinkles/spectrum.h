// Dominant wavelength of a sampled height profile (wrinkles, buckled strips and tubes).
//
// Method. The profile's mean is removed, a Hann window applied (it keeps the leakage of a
// non-integer number of periods away from the peak: side lobes fall as 1/k³), the record is
// zero-padded to at least four times its length (a power of two) and transformed with Eigen's
// FFT (unsupported/Eigen/FFT, KissFFT inside). The largest magnitude among the wavelengths the
// record resolves is refined by a parabola through the logarithms of the magnitudes of its bin
// and its two neighbours ("Gaussian interpolation": the Hann main lobe is close to a Gaussian,
// whose logarithm is a parabola; J. O. Smith, "Spectral Audio Signal Processing", 2011,
// §"Quadratic Interpolation of Spectral Peaks"). With the padding the bias of that estimate is
// far below a per cent of the wavelength.
//
// The peak's share of the spectral energy (|X|² over the main lobe of the peak, ± 2 original bins,
// divided by |X|² over all resolved bins) tells a caller whether there is a dominant wavelength:
// a pure sine gives about 1, white noise a few per cent.
//
// Resolved wavelengths: from two samples (Nyquist) up to half the record (at least two periods:
// longer ones cannot be told from the window's own leakage of a trend).
#pragma once

#include <tapeline/core/errors.h>

#include <Eigen/Dense>
#include <unsupported/Eigen/FFT>

#include <algorithm>
#include <cmath>
#include <complex>
#include <cstddef>
#include <numeric>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::wrinkles {

/// The dominant wavelength of a profile.
struct Spectrum {
    double wavelength = 0;  ///< in the unit of the spacing; 0 when the profile is flat
    /// Energy of the peak's main lobe over the energy of every resolved wavelength, in [0, 1].
    double peak_share = 0;
    double amplitude = 0;  ///< amplitude of a sine with the peak's energy, unit of the heights
    std::size_t samples = 0;
    /// The peak is the longest wavelength the record resolves (half the record): the profile may
    /// hold a single bump and no period at all, and `wavelength` is then the record's limit, not
    /// a wavelength of the profile.
    bool at_record_limit = false;
};

namespace internal {

inline void check_profile(const std::vector<double>& heights, double spacing, const char* who) {
    if (!(std::isfinite(spacing) && spacing > 0)) {
        throw InvalidInput(std::string(who) + ": spacing must be finite and > 0, got " +
                           std::to_string(spacing));
    }
    if (heights.size() < 8) {
        throw InvalidInput(std::string(who) + ": need at least 8 samples, got " +
                           std::to_string(heights.size()));
    }
    for (std::size_t i = 0; i < heights.size(); ++i) {
        if (!std::isfinite(heights[i])) {
            throw InvalidInput(std::string(who) + ": height " + std::to_string(i) +
                               " is not finite");
        }
    }
}

}  // namespace internal

/// Dominant wavelength of the uniformly sampled profile `heights` (sample i at i·spacing), among
/// the wavelengths of at least `min_cycles` periods in the record (2: every resolved wavelength;
/// a caller that must tell waves from smooth trends asks for more, and a peak at its limit is then
/// flagged `at_record_limit`). Throws InvalidInput for fewer than 8 samples, a non-finite height
/// (naming its index), a spacing that is not finite and > 0, or min_cycles below 2.
inline Spectrum dominant_wavelength(const std::vector<double>& heights, double spacing,
                                    double min_cycles = 2) {
    internal::check_profile(heights, spacing, "dominant_wavelength");
    if (!(min_cycles >= 2 && std::isfinite(min_cycles))) {
        throw InvalidInput("dominant_wavelength: min_cycles must be finite and >= 2, got " +
                           std::to_string(min_cycles));
    }
    const std::size_t n = heights.size();
    const double mean = std::accumulate(heights.begin(), heights.end(), 0.0) / double(n);
    std::size_t padded = 1;
    while (padded < 4 * n) {
        padded <<= 1;
    }
    const std::size_t pad = padded / n;  // padded bins per original bin (≥ 4, rounded down)
    std::vector<double> x(padded, 0.0);
    double window_energy = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double w = 0.5 - 0.5 * std::cos(2 * M_PI * (double(i) + 0.5) / double(n));
        x[i] = (heights[i] - mean) * w;
        window_energy += w * w;
    }
    Eigen::FFT<double> fft;
    std::vector<std::complex<double>> spec;
    fft.fwd(spec, x);
    const std::size_t half = padded / 2;
    std::vector<double> mag(half + 1);
    for (std::size_t k = 0; k <= half; ++k) {
        mag[k] = std::abs(spec[k]);
    }
    // Resolved bins: wavelength ≤ the record / min_cycles, i.e. frequency index ≥ min_cycles
    // original bins.
    const double record = double(n);  // in samples
    const auto first = static_cast<std::size_t>(std::ceil(min_cycles * double(padded) / record));
    Spectrum out;
    out.samples = n;
    if (first + 1 >= half) {
        return out;
    }
    std::size_t peak = first;
    double total = 0;
    for (std::size_t k = first; k < half; ++k) {
        total += mag[k] * mag[k];
        if (mag[k] > mag[peak]) {
            peak = k;
        }
    }
    if (!(mag[peak] > 0) || !(total > 0)) {
        return out;  // flat profile: no wavelength
    }
    double delta = 0;
    if (peak > first && peak + 1 < half && mag[peak - 1] > 0 && mag[peak + 1] > 0) {
        const double a = std::log(mag[peak - 1]), b = std::log(mag[peak]),
                     c = std::log(mag[peak + 1]);
        const double denom = a - 2 * b + c;
        if (denom < 0) {
            delta = std::clamp(0.5 * (a - c) / denom, -0.5, 0.5);
        }
    }
    out.at_record_limit = peak == first;
    const double freq = (double(peak) + delta) / (double(padded) * spacing);
    out.wavelength = 1 / freq;
    const std::size_t lobe = 2 * pad;
    double lobe_energy = 0;
    for (std::size_t k = (peak > first + lobe ? peak - lobe : first);
         k <= std::min(half - 1, peak + lobe); ++k) {
        lobe_energy += mag[k] * mag[k];
    }
    out.peak_share = std::clamp(lobe_energy / total, 0.0, 1.0);
    // Parseval over the padded record: Σ|x|² = (2/P)·Σ_{k<P/2}|X_k|² for a real signal; a sine of
    // amplitude a under the window has Σ|x|² = a²/2·Σw².
    const double lobe_power = 2 * lobe_energy / double(padded);
    out.amplitude = std::sqrt(2 * lobe_power / window_energy);
    return out;
}

/// `heights` minus their least-squares polynomial of `degree` (0–5) in the sample index (Eigen's
/// column-pivoting QR on the Legendre-scaled Vandermonde columns): a smooth trend under a wave
/// removed. A polynomial of degree d cannot follow more than (d + 1)/2 periods, so a wave of four
/// and more periods survives a cubic nearly whole.
/// \throws InvalidInput when the degree is outside [0, 5] or there are not more samples than
///         coefficients.
inline std::vector<double> remove_polynomial(const std::vector<double>& heights, int degree) {
    if (degree < 0 || degree > 5) {
        throw InvalidInput("remove_polynomial: degree must be in [0, 5], got " +
                           std::to_string(degree));
    }
    const auto n = Eigen::Index(heights.size());
    if (n <= degree + 1) {
        throw InvalidInput("remove_polynomial: " + std::to_string(n) + " samples for degree " +
                           std::to_string(degree));
    }
    Eigen::MatrixXd a(n, degree + 1);
    Eigen::VectorXd y(n);
    for (Eigen::Index i = 0; i < n; ++i) {
        const double x = 2 * double(i) / double(n - 1) - 1;
        double p = 1;
        for (int d = 0; d <= degree; ++d) {
            a(i, d) = p;
            p *= x;
        }
        y(i) = heights[std::size_t(i)];
    }
    const Eigen::VectorXd r = y - a * a.colPivHouseholderQr().solve(y);
    return std::vector<double>(r.data(), r.data() + n);
}

/// Uniform resampling of scattered samples (s, height) by linear interpolation between the
/// samples sorted by s, on the grid s_min, s_min + spacing, ... ≤ s_max. Throws InvalidInput when
/// the sizes differ, a value is not finite, the spacing is not finite and > 0, or fewer than 8
/// grid points would result.
inline std::vector<double> resample_uniform(const std::vector<double>& s,
                                            const std::vector<double>& heights, double spacing) {
    if (s.size() != heights.size()) {
        throw InvalidInput("resample_uniform: " + std::to_string(s.size()) + " positions but " +
                           std::to_string(heights.size()) + " heights");
    }
    if (!(std::isfinite(spacing) && spacing > 0)) {
        throw InvalidInput("resample_uniform: spacing must be finite and > 0, got " +
                           std::to_string(spacing));
    }
    for (std::size_t i = 0; i < s.size(); ++i) {
        if (!std::isfinite(s[i]) || !std::isfinite(heights[i])) {
            throw InvalidInput("resample_uniform: sample " + std::to_string(i) + " is not finite");
        }
    }
    std::vector<std::size_t> order(s.size());
    std::iota(order.begin(), order.end(), std::size_t(0));
    std::stable_sort(order.begin(), order.end(),
                     [&](std::size_t a, std::size_t b) { return s[a] < s[b]; });
    const double lo = s.empty() ? 0 : s[order.front()], hi = s.empty() ? 0 : s[order.back()];
    const double count = std::floor((hi - lo) / spacing) + 1;
    if (s.size() < 2 || !(count >= 8)) {
        throw InvalidInput("resample_uniform: the samples span fewer than 8 grid points");
    }
    std::vector<double> out(static_cast<std::size_t>(count));
    std::size_t j = 0;
    for (std::size_t i = 0; i < out.size(); ++i) {
        const double t = lo + double(i) * spacing;
        while (j + 2 < order.size() && s[order[j + 1]] < t) {
            ++j;
        }
        const double s0 = s[order[j]], s1 = s[order[j + 1]];
        const double h0 = heights[order[j]], h1 = heights[order[j + 1]];
        const double u = s1 > s0 ? std::clamp((t - s0) / (s1 - s0), 0.0, 1.0) : 0.0;
        out[i] = h0 + u * (h1 - h0);
    }
    return out;
}

}  // namespace tapeline::wrinkles
