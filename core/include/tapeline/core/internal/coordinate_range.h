// The coordinate range the numerics are built for, checked once when a mesh or point set is read.
//
// Lengths are formed as differences of coordinates, squared (edge lengths, cotangent weights,
// areas) and sometimes squared again (triangle areas squared in the heat method and the window
// propagation). With |x| <= 1e15 the fourth powers stay far below DBL_MAX; with a bounding-box
// diagonal of at least 1e-12 and at least 1e-9 of the largest |x|, the squares stay far above
// DBL_MIN and positions keep 7 significant digits relative to the extent of the shape.
#pragma once

#include <tapeline/core/errors.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>
#include <string>
#include <vector>

namespace tapeline {

inline constexpr double max_abs_coordinate = 1e15;
inline constexpr double min_coordinate_spread = 1e-12;
inline constexpr double min_relative_coordinate_spread = 1e-9;

namespace internal {

inline std::string short_number(double x) {
    std::ostringstream s;
    s.precision(3);
    s << x;
    return s.str();
}

/// `n` points (called `item` in messages) of `dim` coordinates each at `xyz[dim * i + k]`;
/// InvalidInput naming `file` and the first point outside the range, or the spread when the points
/// nearly coincide.
inline void check_coordinate_range(const std::string& file, const double* xyz, std::size_t n,
                                   std::size_t dim, const char* item = "point") {
    if (n == 0 || dim == 0) {
        return;
    }
    double largest = 0;
    std::vector<double> extent(dim);
    for (std::size_t k = 0; k < dim; ++k) {
        double lo = xyz[k], hi = xyz[k];
        for (std::size_t i = 0; i < n; ++i) {
            const double x = xyz[dim * i + k];
            if (!(std::abs(x) <= max_abs_coordinate)) {
                throw InvalidInput(
                    file + ": " + item + " " + std::to_string(i) + " has coordinate " +
                    short_number(x) + ", outside the supported range |x| <= " +
                    short_number(max_abs_coordinate) + " (rescale or re-centre the input)");
            }
            lo = std::min(lo, x);
            hi = std::max(hi, x);
            largest = std::max(largest, std::abs(x));
        }
        extent[k] = hi - lo;
    }
    // Scaled so that extents near 1e-300 do not underflow when squared.
    const double widest = *std::max_element(extent.begin(), extent.end());
    double sum = 0;
    for (double e : extent) {
        sum += widest > 0 ? (e / widest) * (e / widest) : 0;
    }
    const double spread = widest * std::sqrt(sum);
    if (n > 1 &&
        (spread < min_coordinate_spread || spread < min_relative_coordinate_spread * largest)) {
        throw InvalidInput(
            file + ": the " + std::to_string(n) + " points span only " + short_number(spread) +
            " (bounding-box diagonal) at coordinates up to " + short_number(largest) +
            "; at least " + short_number(min_coordinate_spread) + " and " +
            short_number(min_relative_coordinate_spread) +
            " of the largest coordinate are needed (rescale or re-centre the input)");
    }
}

}  // namespace internal
}  // namespace tapeline
