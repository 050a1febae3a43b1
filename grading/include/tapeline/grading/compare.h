// Outline deviation between two drafts of the same pattern (a graded one against a reference),
// piece by piece: each outline sampled at n points equally spaced in arc length, both centred on
// their sample centroid, the second rotated by the angle that best aligns it (2D Procrustes on
// the arc-length correspondence, refined by a few closest-point iterations), then the symmetric
// nearest-point distance: mean = (mean_a d(a, B) + mean_b d(b, A)) / 2, max over both.
#pragma once

#include <tapeline/pattern/pattern.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

namespace tapeline::grading {

/// How far one piece's outline lies from its reference after alignment.
struct PieceDeviation {
    std::string piece;  ///< piece name
    /// Mean and largest distance of the outline samples to the reference outline.
    ///@{
    double mean_mm = 0, max_mm = 0;
    ///@}
    double rotation_deg = 0;  ///< rotation of the best alignment
};

namespace internal {

inline std::vector<pattern::Point2> sample_equal(const pattern::Outline& o, std::size_t n) {
    const std::vector<pattern::Point2> poly = pattern::sample(o, 0.01).points;
    std::vector<double> cum(poly.size(), 0);
    for (std::size_t i = 1; i < poly.size(); ++i) {
        cum[i] = cum[i - 1] + pattern::distance(poly[i - 1], poly[i]);
    }
    std::vector<pattern::Point2> out;
    std::size_t k = 0;
    for (std::size_t i = 0; i < n; ++i) {
        const double s = cum.back() * double(i) / double(n);
        while (k + 2 < poly.size() && cum[k + 1] < s) {
            ++k;
        }
        const double len = cum[k + 1] - cum[k];
        const double t = len > 0 ? (s - cum[k]) / len : 0;
        out.push_back(poly[k] + t * (poly[k + 1] - poly[k]));
    }
    return out;
}

inline double nearest_on_ring(const pattern::Point2& p, const std::vector<pattern::Point2>& ring,
                              pattern::Point2* q = nullptr) {
    double best = std::numeric_limits<double>::infinity();
    for (std::size_t i = 0; i < ring.size(); ++i) {
        const pattern::Point2 a = ring[i], b = ring[(i + 1) % ring.size()];
        const pattern::Point2 d = b - a;
        const double l2 = pattern::dot(d, d);
        const double t = l2 > 0 ? std::clamp(pattern::dot(p - a, d) / l2, 0.0, 1.0) : 0.0;
        const pattern::Point2 c = a + t * d;
        const double dist = pattern::distance(p, c);
        if (dist < best) {
            best = dist;
            if (q) {
                *q = c;
            }
        }
    }
    return best;
}

inline void centre(std::vector<pattern::Point2>& v) {
    pattern::Point2 c{0, 0};
    for (const auto& p : v) {
        c = c + p;
    }
    c = (1.0 / v.size()) * c;
    for (auto& p : v) {
        p = p - c;
    }
}

inline std::vector<pattern::Point2> rotated(const std::vector<pattern::Point2>& v, double th) {
    const double c = std::cos(th), s = std::sin(th);
    std::vector<pattern::Point2> out;
    for (const auto& p : v) {
        out.push_back({c * p.x - s * p.y, s * p.x + c * p.y});
    }
    return out;
}

}  // namespace internal

/// Deviation of outline `b` from outline `a` after alignment (see the file comment).
inline PieceDeviation outline_deviation(const pattern::Outline& a, const pattern::Outline& b,
                                        std::size_t samples = 400) {
    using namespace internal;
    std::vector<pattern::Point2> A = sample_equal(a, samples), B = sample_equal(b, samples);
    centre(A);
    centre(B);
    // Procrustes on the arc-length correspondence, then closest-point refinement of the angle.
    double num = 0, den = 0;
    for (std::size_t i = 0; i < A.size(); ++i) {
        num += pattern::cross(B[i], A[i]);
        den += pattern::dot(B[i], A[i]);
    }
    double th = std::atan2(num, den);
    for (int it = 0; it < 5; ++it) {
        const std::vector<pattern::Point2> R = rotated(B, th);
        double n2 = 0, d2 = 0;
        for (const auto& p : R) {
            pattern::Point2 q;
            nearest_on_ring(p, A, &q);
            n2 += pattern::cross(p, q);
            d2 += pattern::dot(p, q);
        }
        th += std::atan2(n2, d2);
    }
    const std::vector<pattern::Point2> R = rotated(B, th);
    PieceDeviation d;
    double sa = 0, sb = 0;
    for (const auto& p : A) {
        const double e = nearest_on_ring(p, R);
        sa += e;
        d.max_mm = std::max(d.max_mm, e);
    }
    for (const auto& p : R) {
        const double e = nearest_on_ring(p, A);
        sb += e;
        d.max_mm = std::max(d.max_mm, e);
    }
    d.mean_mm = 0.5 * (sa / A.size() + sb / R.size());
    d.rotation_deg = th * 180 / M_PI;
    return d;
}

/// Per piece (matched by name) deviation of `graded` from `reference`.
inline std::vector<PieceDeviation> pattern_deviation(const pattern::Pattern& reference,
                                                     const pattern::Pattern& graded,
                                                     std::size_t samples = 400) {
    std::vector<PieceDeviation> out;
    for (const pattern::Piece& r : reference.pieces) {
        if (const pattern::Piece* g = pattern::find_piece(graded, r.name)) {
            PieceDeviation d = outline_deviation(r.outline, g->outline, samples);
            d.piece = r.name;
            out.push_back(d);
        }
    }
    return out;
}

/// Every coordinate of a piece scaled by s about the origin (the uniform-scale baseline).
inline pattern::Piece scaled_piece(pattern::Piece p, double s) {
    auto f = [&](pattern::Point2& q) { q = s * q; };
    for (pattern::Edge& e : p.outline.edges) {
        std::visit(
            [&](auto& c) {
                using C = std::decay_t<decltype(c)>;
                if constexpr (std::is_same_v<C, pattern::Line>) {
                    f(c.a);
                    f(c.b);
                } else if constexpr (std::is_same_v<C, pattern::CubicBezier>) {
                    f(c.p0);
                    f(c.p1);
                    f(c.p2);
                    f(c.p3);
                } else {
                    f(c.a);
                    f(c.b);
                    c.radius *= s;
                }
            },
            e.curve);
    }
    return p;
}

}  // namespace tapeline::grading
