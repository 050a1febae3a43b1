// One-dimensional searches used to place levels: golden-section minimisation on a bracket and
// bisection of a predicate's switch point.
#pragma once

#include <cmath>
#include <functional>
#include <limits>
#include <utility>

namespace tapeline::measurement::internal {

/// Minimum of f on [a, b] by golden-section search, to within `tolerance`; f may return +inf for
/// levels where the quantity does not exist. Returns (argmin, min). Assumes f unimodal on the
/// bracket; callers bracket around the best sample of a dense scan first.
inline std::pair<double, double> golden_minimum(const std::function<double(double)>& f, double a,
                                                double b, double tolerance) {
    const double g = (std::sqrt(5.0) - 1) / 2;
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = f(c), fd = f(d);
    while (b - a > tolerance) {
        if (fc <= fd) {
            b = d;
            d = c;
            fd = fc;
            c = b - g * (b - a);
            fc = f(c);
        } else {
            a = c;
            c = d;
            fc = fd;
            d = a + g * (b - a);
            fd = f(d);
        }
    }
    return fc <= fd ? std::make_pair(c, fc) : std::make_pair(d, fd);
}

/// Dense scan of f on [a, b] with `samples` points, then golden-section refinement around the
/// best sample. Returns (argmin, min); min is +inf when f is +inf everywhere.
inline std::pair<double, double> scan_minimum(const std::function<double(double)>& f, double a,
                                              double b, int samples, double tolerance) {
    double best_t = a, best = std::numeric_limits<double>::infinity();
    const double h = samples > 1 ? (b - a) / (samples - 1) : 0;
    for (int i = 0; i < samples; ++i) {
        const double t = a + i * h;
        const double v = f(t);
        if (v < best) {
            best = v;
            best_t = t;
        }
    }
    if (!std::isfinite(best) || h <= tolerance) {
        return {best_t, best};
    }
    const auto refined =
        golden_minimum(f, std::max(a, best_t - h), std::min(b, best_t + h), tolerance);
    return refined.second <= best ? refined : std::make_pair(best_t, best);
}

/// The switch point of a predicate that is false at `lo` and true at `hi` (either order of
/// lo < hi or lo > hi), to within `tolerance`; returns (last false, first true).
inline std::pair<double, double> bisect(const std::function<bool(double)>& p, double lo, double hi,
                                        double tolerance) {
    while (std::abs(hi - lo) > tolerance) {
        const double mid = 0.5 * (lo + hi);
        if (p(mid)) {
            hi = mid;
        } else {
            lo = mid;
        }
    }
    return {lo, hi};
}

}  // namespace tapeline::measurement::internal
