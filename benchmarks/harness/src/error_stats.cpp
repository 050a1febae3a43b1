#include <tapeline/bench/error_stats.h>

#include <algorithm>

namespace tapeline::bench {

ErrorStats relative_errors(const std::vector<double>& values, const std::vector<double>& reference,
                           const std::vector<char>& excluded) {
    ErrorStats s;
    double sum = 0, mx = 0;
    for (std::size_t i = 0; i < values.size(); ++i) {
        if (excluded[i]) {
            continue;
        }
        const bool fin_v = std::isfinite(values[i]);
        const bool fin_r = std::isfinite(reference[i]);
        if (fin_v != fin_r) {
            ++s.reachability_mismatches;
            continue;
        }
        if (!fin_r || reference[i] <= 0) {
            continue;
        }
        const double e = std::abs(values[i] - reference[i]) / reference[i];
        sum += e;
        mx = std::max(mx, e);
        ++s.count;
    }
    if (s.count > 0) {
        s.mean = sum / static_cast<double>(s.count);
        s.max = mx;
    }
    return s;
}

}  // namespace tapeline::bench
