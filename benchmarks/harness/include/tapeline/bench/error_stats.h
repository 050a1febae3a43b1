// Errors of a distance field against a reference field (an exact method's, or analytic truth).
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstddef>
#include <vector>

namespace tapeline::bench {

/// Relative errors over the vertices that count: reachable in the reference, not excluded (the
/// source and its 1-ring, where relative error is dominated by the size of the first triangles
/// and says little about a method). Vertices where exactly one of the two is infinite are counted
/// as mismatches and left out of the statistics. mean and max are NaN when no vertex counts.
struct ErrorStats {
    double mean = NAN;
    double max = NAN;
    std::size_t count = 0;
    std::size_t reachability_mismatches = 0;
};

ErrorStats relative_errors(const std::vector<double>& values, const std::vector<double>& reference,
                           const std::vector<char>& excluded);

/// A number, or null for NaN and infinities (which JSON cannot hold).
inline nlohmann::json number_or_null(double x) {
    return std::isfinite(x) ? nlohmann::json(x) : nlohmann::json(nullptr);
}

}  // namespace tapeline::bench
