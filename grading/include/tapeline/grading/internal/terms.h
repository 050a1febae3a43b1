// Residual terms of the grading problem, templated on the scalar so that the same code serves
// Ceres's automatic differentiation and plain double evaluation (NSGA-II fitness, reports).
//
// Every term reads node positions through `pos(k)`, k = 0..idx.size()−1 a slot of the term;
// the caller maps slots to nodes (all nodes for double evaluation, the term's parameter blocks
// for Ceres). Formulas: grading/README.md.
#pragma once

#include <array>
#include <cmath>
#include <cstddef>
#include <vector>

namespace tapeline::grading::internal {

template <typename T>
struct V2 {
    T x, y;
};
template <typename T>
V2<T> operator-(const V2<T>& a, const V2<T>& b) {
    return {a.x - b.x, a.y - b.y};
}
template <typename T>
V2<T> operator+(const V2<T>& a, const V2<T>& b) {
    return {a.x + b.x, a.y + b.y};
}
template <typename T>
T dot2(const V2<T>& a, const V2<T>& b) {
    return a.x * b.x + a.y * b.y;
}
template <typename T>
T cross2(const V2<T>& a, const V2<T>& b) {
    return a.x * b.y - a.y * b.x;
}
template <typename T>
T norm2(const V2<T>& a) {
    using std::sqrt;
    // sqrt'(0) is infinite: a vanishing vector keeps a finite derivative.
    const T s = a.x * a.x + a.y * a.y;
    return s > T(1e-24) ? sqrt(s) : T(0);
}

/// Signed change of the angle from (c0, d0) = (sin, cos) of a base angle to the angle of (c, d),
/// in (−π, π]: the current angle rotated back by the base angle.
template <typename T>
T angle_change(const T& c, const T& d, double sin0, double cos0) {
    using std::atan2;
    return atan2(c * cos0 - d * sin0, d * cos0 + c * sin0);
}

/// One length contribution: a straight span between two nodes (a named-point feature or a line
/// edge), a cubic Bézier edge, or an arc edge whose length follows its chord (the arc keeps its
/// shape: radius scales with the chord).
struct LengthItem {
    enum Kind { span, cubic, arc } kind = span;
    std::array<std::size_t, 4> slot{0, 0, 0, 0};
    double coef = 1;
    double arc_ratio = 1;  // arc length / chord at the base
};

/// w · (Σ coef·length(item) − constant): a binding (constant = target + ease) or a seam (items of
/// side B with coef −1, constant 0).
struct LengthTerm {
    std::vector<std::size_t> idx;
    std::vector<LengthItem> items;
    double constant = 0;
    double weight = 1;
    static constexpr int residuals = 1;

    template <typename T, typename Pos>
    T length(const Pos& pos) const {
        // 8-point Gauss–Legendre on two halves: exact to < 1e-6 mm for pattern curves.
        static const double gx[4] = {0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
                                     0.9602898564975363};
        static const double gw[4] = {0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
                                     0.1012285362903763};
        T total(0);
        for (const LengthItem& it : items) {
            if (it.kind == LengthItem::span) {
                total += T(it.coef) * norm2(pos(it.slot[1]) - pos(it.slot[0]));
            } else if (it.kind == LengthItem::arc) {
                total += T(it.coef * it.arc_ratio) * norm2(pos(it.slot[1]) - pos(it.slot[0]));
            } else {
                const V2<T> p0 = pos(it.slot[0]), p1 = pos(it.slot[1]), p2 = pos(it.slot[2]),
                            p3 = pos(it.slot[3]);
                T len(0);
                for (int half = 0; half < 2; ++half) {
                    for (int k = 0; k < 8; ++k) {
                        const double xk = k < 4 ? -gx[3 - k] : gx[k - 4];
                        const double wk = k < 4 ? gw[3 - k] : gw[k - 4];
                        const double t = 0.25 * (xk + 1) + 0.5 * half;
                        const double u = 1 - t;
                        // B'(t) = 3[(1−t)²(p1−p0) + 2t(1−t)(p2−p1) + t²(p3−p2)]
                        const double a = 3 * u * u, b = 6 * t * u, c = 3 * t * t;
                        const V2<T> d{
                            T(a) * (p1.x - p0.x) + T(b) * (p2.x - p1.x) + T(c) * (p3.x - p2.x),
                            T(a) * (p1.y - p0.y) + T(b) * (p2.y - p1.y) + T(c) * (p3.y - p2.y)};
                        len += T(0.25 * wk) * norm2(d);
                    }
                }
                total += T(it.coef) * len;
            }
        }
        return total;
    }

    template <typename T, typename Pos>
    void operator()(const Pos& pos, T* r) const {
        r[0] = T(weight) * (length<T>(pos) - T(constant));
    }
};

/// w·L_ref·(θ − θ0): θ the turn from the incoming tangent (slot 1 − slot 0) to the outgoing one
/// (slot 2 − slot 1) at an outline vertex; used also for the grain direction (slots 0 → 1 against
/// a fixed base direction, two slots).
struct TurnTerm {
    std::vector<std::size_t> idx;  // 3 slots: a, vertex, b
    double sin0 = 0, cos0 = 1;
    double weight = 1;
    static constexpr int residuals = 1;

    template <typename T, typename Pos>
    void operator()(const Pos& pos, T* r) const {
        const V2<T> t1 = pos(1) - pos(0), t2 = pos(2) - pos(1);
        r[0] = T(weight) * angle_change(cross2(t1, t2), dot2(t1, t2), sin0, cos0);
    }
};

struct GrainTerm {
    std::vector<std::size_t> idx;  // 2 slots: from, to
    double sin0 = 0, cos0 = 1;
    double weight = 1;
    static constexpr int residuals = 1;

    template <typename T, typename Pos>
    void operator()(const Pos& pos, T* r) const {
        const V2<T> g = pos(1) - pos(0);
        r[0] = T(weight) * angle_change(g.y, g.x, sin0, cos0);
    }
};

/// A cubic's inner control points in the frame of its chord, divided by the chord length
/// (u along, v across): four numbers that fix the curve up to a similarity. Residual
/// w·chord0·(shape − shape0).
struct CurveTerm {
    std::vector<std::size_t> idx;  // 4 slots: p0..p3
    std::array<double, 4> shape0{0, 0, 0, 0};
    double weight = 1;  // includes chord0
    static constexpr int residuals = 4;

    template <typename T, typename Pos>
    void operator()(const Pos& pos, T* r) const {
        const V2<T> p0 = pos(0), c = pos(3) - p0;
        const T l2 = dot2(c, c) + T(1e-12);
        const V2<T> a = pos(1) - p0, b = pos(2) - p0;
        r[0] = T(weight) * (dot2(a, c) / l2 - T(shape0[0]));
        r[1] = T(weight) * (cross2(c, a) / l2 - T(shape0[1]));
        r[2] = T(weight) * (dot2(b, c) / l2 - T(shape0[2]));
        r[3] = T(weight) * (cross2(c, b) / l2 - T(shape0[3]));
    }
};

/// Shape of a cubic (see CurveTerm) at the base.
inline std::array<double, 4> curve_shape(double x0, double y0, double x1, double y1, double x2,
                                         double y2, double x3, double y3) {
    const double cx = x3 - x0, cy = y3 - y0, l2 = cx * cx + cy * cy + 1e-12;
    const double ax = x1 - x0, ay = y1 - y0, bx = x2 - x0, by = y2 - y0;
    return {(ax * cx + ay * cy) / l2, (cx * ay - cy * ax) / l2, (bx * cx + by * cy) / l2,
            (cx * by - cy * bx) / l2};
}

/// w·(|p_j − p_i| − s·l0): the distance between two nodes of a piece against one uniform scale s
/// of the piece (a separate variable in Ceres, its least-squares value in double evaluation).
struct ProportionTerm {
    std::size_t i = 0, j = 0, piece = 0;
    double l0 = 1;
    double weight = 1;
};

}  // namespace tapeline::grading::internal
