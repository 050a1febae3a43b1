// Height profiles of a fine drape in windows of its pattern: the measurement that the comparison
// with a prediction (compare.h), the training of the synthesis and its check against a fine
// simulation (synthesis.h) share.
//
// A window lies in the pattern plane of one piece: centred on a point, `half_length` mm either
// side along an axis (the waves' direction) and `half_width` mm either side across it. The fine
// vertices inside it (a CGAL kd-tree range query over the vertices' pattern points, pieces lifted
// apart as in embedding.h) are binned along the axis at a quarter of the fine mesh's mean pattern
// edge; the mean height of each bin is taken, empty bins are filled by linear interpolation
// between their filled neighbours, the ends are cut to the first and last filled bin, and the
// profile's least-squares polynomial of a chosen degree is removed (a line by default: a window
// on a slope is not a wave; a cubic where whole garment-scale bulges must go too). The profile goes
// to dominant_wavelength() (spectrum.h). A window is resolved when it holds at least 16 fine
// vertices and its profile spans at least eight bins.
#pragma once

#include <tapeline/garment/garment_types.h>
#include <tapeline/wrinkles/embedding.h>
#include <tapeline/wrinkles/spectrum.h>

#include <CGAL/Exact_predicates_inexact_constructions_kernel.h>
#include <CGAL/Fuzzy_iso_box.h>
#include <CGAL/Kd_tree.h>
#include <CGAL/Search_traits_3.h>
#include <CGAL/Search_traits_adapter.h>
#include <CGAL/property_map.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <tuple>
#include <vector>

namespace tapeline::wrinkles {

/// What one window shows.
struct WindowProfile {
    std::size_t vertices = 0;  ///< fine vertices inside the window
    bool resolved = false;     ///< enough vertices and bins for a spectrum (see the file comment)
    Spectrum spectrum;         ///< of the detrended profile (wavelength in pattern mm)
    double rms_mm = 0;         ///< root mean square of the detrended profile
    /// Length of the window the profile covers along the axis (first to last filled bin), mm:
    /// less than the window's length where the window reaches past the piece's outline.
    double span_mm = 0;
};

/// A fine drape's heights over its pattern, ready for window queries (see the file comment).
class PatternWindows {
public:
    /// `heights`: one per vertex of `fine` (mm), e.g. the Embedding's height_mm.
    /// \throws InvalidInput when the sizes differ or a used height is not finite.
    PatternWindows(const garment::GarmentMesh& fine, std::vector<double> heights)
        : heights_(std::move(heights)) {
        if (heights_.size() != fine.positions.size()) {
            throw InvalidInput("pattern windows: " + std::to_string(heights_.size()) +
                               " heights for " + std::to_string(fine.positions.size()) +
                               " vertices");
        }
        where_.assign(fine.positions.size(), {0, 0});
        std::vector<std::uint8_t> seen(fine.positions.size(), 0);
        double edge_sum = 0;
        std::size_t edges = 0;
        for (std::size_t f = 0; f < fine.triangles.size(); ++f) {
            for (int k = 0; k < 3; ++k) {
                const garment::UV& a = fine.uv[f][std::size_t(k)];
                const garment::UV& b = fine.uv[f][std::size_t((k + 1) % 3)];
                edge_sum += std::hypot(a[0] - b[0], a[1] - b[1]);
                ++edges;
                const std::uint32_t v = fine.triangles[f][std::size_t(k)];
                if (!seen[v]) {
                    seen[v] = 1;
                    if (!std::isfinite(heights_[v])) {
                        throw InvalidInput("pattern windows: the height of vertex " +
                                           std::to_string(v) + " is not finite");
                    }
                    where_[v] = a;
                    entries_.emplace_back(
                        Point(a[0], a[1], internal::kPieceGap * double(fine.triangle_piece[f])), v);
                }
            }
        }
        bin_ = edges > 0 ? 0.25 * edge_sum / double(edges) : 1;
        tree_.insert(entries_.begin(), entries_.end());
        tree_.build();
    }

    /// Bin width of the profiles, pattern mm.
    double bin_mm() const { return bin_; }

    /// The window on `piece` centred at `centre`, `axis` a unit pattern direction; the profile's
    /// least-squares polynomial of `detrend_degree` is removed and the spectrum looks at
    /// wavelengths of at least `min_cycles` periods in it (remove_polynomial(),
    /// dominant_wavelength()).
    WindowProfile profile(std::uint32_t piece, const garment::UV& centre, const garment::UV& axis,
                          double half_length, double half_width, double min_cycles = 2,
                          int detrend_degree = 1) const {
        WindowProfile out;
        const garment::UV crest{-axis[1], axis[0]};
        const double reach = std::hypot(half_length, half_width);
        const double z = internal::kPieceGap * double(piece);
        std::vector<Entry> found;
        tree_.search(std::back_inserter(found),
                     Box(Point(centre[0] - reach, centre[1] - reach, z - 1),
                         Point(centre[0] + reach, centre[1] + reach, z + 1)));
        const auto nbins = static_cast<std::size_t>(std::ceil(2 * half_length / bin_));
        std::vector<double> sum(nbins, 0.0);
        std::vector<std::size_t> count(nbins, 0);
        for (const Entry& en : found) {
            const std::uint32_t v = std::get<1>(en);
            const double du = where_[v][0] - centre[0], dv = where_[v][1] - centre[1];
            const double s = du * axis[0] + dv * axis[1];
            const double q = du * crest[0] + dv * crest[1];
            if (std::abs(s) > half_length || std::abs(q) > half_width) {
                continue;
            }
            const auto b = std::min(nbins - 1, static_cast<std::size_t>((s + half_length) / bin_));
            sum[b] += heights_[v];
            ++count[b];
            ++out.vertices;
        }
        std::vector<double> s_of, h_of;
        for (std::size_t b = 0; b < nbins; ++b) {
            if (count[b] > 0) {
                s_of.push_back((double(b) + 0.5) * bin_);
                h_of.push_back(sum[b] / double(count[b]));
            }
        }
        out.span_mm = s_of.empty() ? 0 : s_of.back() - s_of.front() + bin_;
        if (out.vertices < 16 || s_of.size() < 8 || s_of.back() - s_of.front() < 8 * bin_) {
            return out;
        }
        std::vector<double> h = resample_uniform(s_of, h_of, bin_);
        h = remove_polynomial(h, detrend_degree);
        const double n = double(h.size());
        double ss = 0;
        for (double x : h) {
            ss += x * x;
        }
        out.rms_mm = std::sqrt(ss / n);
        out.spectrum = dominant_wavelength(h, bin_, min_cycles);
        out.resolved = true;
        return out;
    }

private:
    using K = CGAL::Exact_predicates_inexact_constructions_kernel;
    using Point = K::Point_3;
    using Entry = std::tuple<Point, std::uint32_t>;
    using Traits = CGAL::Search_traits_adapter<Entry, CGAL::Nth_of_tuple_property_map<0, Entry>,
                                               CGAL::Search_traits_3<K>>;
    using Tree = CGAL::Kd_tree<Traits>;
    using Box = CGAL::Fuzzy_iso_box<Traits>;

    std::vector<double> heights_;
    std::vector<garment::UV> where_;
    std::vector<Entry> entries_;
    Tree tree_;
    double bin_ = 1;
};

}  // namespace tapeline::wrinkles
