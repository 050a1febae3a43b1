// A small 2D plot for pictures a person reads (the grading Pareto front and the like): scatter
// series on linear axes with tick marks, tick labels, axis titles, a title and a legend, drawn on
// a canvas.h canvas at one pixel per unit (so every length here is in pixels) and returned as an
// image for png.h. Plots made from JSON output by scripts use matplotlib instead (benchmarks/).
//
// Axes: each range is the data's, widened to include zero when asked, then rounded outwards to
// "nice" ticks (1, 2 or 5 × 10^k apart, about `ticks` of them). Pixel centres: the value v is drawn
// at x_px(v) = left + (v − lo) / (hi − lo) (right − left), y_px likewise from the bottom up; the
// plot box's edges lie on pixel centres (+0.5) so that axes and ticks are crisp one-pixel lines.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/vec2.h>
#include <tapeline/draw/canvas.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

namespace tapeline::draw {

/// One set of points drawn alike, named in the legend (an empty label stays out of the legend).
struct PlotSeries {
    std::string label;         ///< legend entry; empty: not in the legend
    std::vector<Vec2> points;  ///< data coordinates
    Rgb colour{0, 0, 0};       ///< marker colour
    /// Marker shape: filled disc or ring.
    enum class Marker { disc, ring } marker = Marker::disc;  ///< marker shape
    double radius_px = 3;                                    ///< marker radius
};

/// Size, margins, titles and fonts of a plot.
struct PlotOptions {
    /// Image size.
    ///@{
    std::size_t width_px = 640, height_px = 480;
    ///@}
    /// Margins to the plot box.
    ///@{
    double left_px = 80, right_px = 30, top_px = 50, bottom_px = 60;  ///< margins to the plot box
    ///@}
    /// Plot title and axis titles (empty: none).
    ///@{
    std::string title, x_label, y_label;
    ///@}
    /// Widen the ranges to include 0.
    ///@{
    bool x_from_zero = true, y_from_zero = true;  ///< widen the ranges to include 0
    ///@}
    int ticks = 5;              ///< about this many intervals per axis
    double font_px = 10;        ///< tick labels, axis titles, legend
    double title_font_px = 20;  ///< plot title
};

/// One axis: its range and tick values, both in data units.
struct PlotAxis {
    /// Range of the axis.
    ///@{
    double lo = 0, hi = 1;
    ///@}
    double step = 1;            ///< distance between ticks
    std::vector<double> ticks;  ///< tick values, lo to hi
};

/// Where a plot put things: the axes, the plot box and the legend's box (all zero when no series
/// has a label) in pixels (y down).
struct PlotLayout {
    /// The two axes.
    ///@{
    PlotAxis x, y;
    ///@}
    /// The plot box.
    ///@{
    double box_left = 0, box_right = 0, box_top = 0, box_bottom = 0;
    ///@}
    /// The legend's box.
    ///@{
    double legend_left = 0, legend_top = 0, legend_right = 0, legend_bottom = 0;
    ///@}
    /// Pixel column of data value v.
    double x_px(double v) const {
        return box_left + (v - x.lo) / (x.hi - x.lo) * (box_right - box_left);
    }
    /// Pixel row of data value v.
    double y_px(double v) const {
        return box_bottom - (v - y.lo) / (y.hi - y.lo) * (box_bottom - box_top);
    }
};

/// 1, 2 or 5 × 10^k: the smallest of them not below `raw` (positive and finite).
inline double nice_step(double raw) {
    const double p = std::pow(10.0, std::floor(std::log10(raw)));
    for (const double m : {1.0, 2.0, 5.0, 10.0}) {
        if (m * p >= raw * (1 - 1e-12)) {
            return m * p;
        }
    }
    return 10 * p;
}

/// The axis over [lo, hi] (lo ≤ hi, finite) with about `intervals` nice intervals, the range
/// rounded outwards to whole steps. An empty range becomes the step that starts at its value.
///
/// \throws InvalidInput when lo or hi is not finite or lo > hi.
inline PlotAxis nice_axis(double lo, double hi, int intervals) {
    if (!std::isfinite(lo) || !std::isfinite(hi) || lo > hi) {
        throw InvalidInput("plot axis: range [" + std::to_string(lo) + ", " + std::to_string(hi) +
                           "] is not a finite interval");
    }
    PlotAxis a;
    const double span = hi - lo;
    const double magnitude = std::max(std::abs(lo), std::abs(hi));
    a.step = nice_step(span > 0 ? span / std::max(1, intervals)
                                : (magnitude > 0 ? magnitude / std::max(1, intervals) : 1.0));
    const double k0 = std::floor(lo / a.step + 1e-9), k1 = std::ceil(hi / a.step - 1e-9);
    a.lo = k0 * a.step;
    a.hi = std::max(k1, k0 + 1) * a.step;
    for (double k = k0; k <= std::max(k1, k0 + 1) + 0.5; k += 1) {
        a.ticks.push_back(k * a.step == 0 ? 0.0 : k * a.step);
    }
    return a;
}

/// A tick value with as many decimals as the step needs ("0", "2.5", "0.02", "1e+06").
inline std::string tick_label(double v, double step) {
    char buf[32];
    const double mag = std::max(std::abs(v), step);
    if (mag >= 1e6 || mag < 1e-4) {
        std::snprintf(buf, sizeof buf, "%.3g", v);
    } else {
        const int decimals = std::max(0, int(std::ceil(-std::log10(step) - 1e-9)));
        std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    }
    return std::string(buf) == "-0" ? "0" : buf;
}

/// The layout a scatter plot of `series` takes under `o` (no drawing).
///
/// Non-finite points are left out.
///
/// \throws InvalidInput when the margins leave no room in the image.
inline PlotLayout plot_layout(const std::vector<PlotSeries>& series, const PlotOptions& o) {
    double x0 = std::numeric_limits<double>::infinity(), y0 = x0, x1 = -x0, y1 = -x0;
    for (const PlotSeries& s : series) {
        for (const Vec2& p : s.points) {
            if (is_finite(p)) {
                x0 = std::min(x0, p.x);
                x1 = std::max(x1, p.x);
                y0 = std::min(y0, p.y);
                y1 = std::max(y1, p.y);
            }
        }
    }
    if (!(x0 <= x1)) {
        x0 = y0 = 0;
        x1 = y1 = 1;
    }
    if (o.x_from_zero) {
        x0 = std::min(x0, 0.0);
        x1 = std::max(x1, 0.0);
    }
    if (o.y_from_zero) {
        y0 = std::min(y0, 0.0);
        y1 = std::max(y1, 0.0);
    }
    PlotLayout l;
    l.x = nice_axis(x0, x1, o.ticks);
    l.y = nice_axis(y0, y1, o.ticks);
    l.box_left = std::floor(o.left_px) + 0.5;
    l.box_right = std::floor(double(o.width_px) - o.right_px) + 0.5;
    l.box_top = std::floor(o.top_px) + 0.5;
    l.box_bottom = std::floor(double(o.height_px) - o.bottom_px) + 0.5;
    if (!(l.box_left < l.box_right && l.box_top < l.box_bottom)) {
        throw InvalidInput("plot: margins leave no room in " + std::to_string(o.width_px) + " × " +
                           std::to_string(o.height_px) + " pixels");
    }
    return l;
}

/// The scatter plot as an opaque image on white; `layout` receives where things went.
///
/// \throws InvalidInput as plot_layout.
inline RgbaImage scatter_plot(const std::vector<PlotSeries>& series, const PlotOptions& o = {},
                              PlotLayout* layout = nullptr) {
    PlotLayout l = plot_layout(series, o);
    RgbaImage img = RgbaImage::filled(o.width_px, o.height_px, 255);
    Canvas cv(img, 1.0);
    const Rgb black{0, 0, 0}, grid{0.88, 0.88, 0.88};
    const double fs = o.font_px, tick = 5;
    // Grid first, so that axes and points lie over it.
    for (const double t : l.x.ticks) {
        cv.segment({l.x_px(t), l.box_top}, {l.x_px(t), l.box_bottom}, 1, grid);
    }
    for (const double t : l.y.ticks) {
        cv.segment({l.box_left, l.y_px(t)}, {l.box_right, l.y_px(t)}, 1, grid);
    }
    cv.segment({l.box_left, l.box_bottom}, {l.box_right, l.box_bottom}, 1, black);
    cv.segment({l.box_left, l.box_top}, {l.box_left, l.box_bottom}, 1, black);
    for (const double t : l.x.ticks) {
        const double x = l.x_px(t);
        cv.segment({x, l.box_bottom}, {x, l.box_bottom + tick}, 1, black);
        cv.text(tick_label(t, l.x.step), {x, l.box_bottom + tick + 3 + 0.7 * fs}, fs,
                TextAnchor::middle, black);
    }
    for (const double t : l.y.ticks) {
        const double y = l.y_px(t);
        cv.segment({l.box_left - tick, y}, {l.box_left, y}, 1, black);
        cv.text(tick_label(t, l.y.step), {l.box_left - tick - 4, y + 0.35 * fs}, fs,
                TextAnchor::end, black);
    }
    if (!o.x_label.empty()) {
        cv.text(o.x_label, {0.5 * (l.box_left + l.box_right), l.box_bottom + tick + 3 + 2.3 * fs},
                fs, TextAnchor::middle, black);
    }
    if (!o.y_label.empty()) {  // horizontal, above the y axis: the font has no rotated glyphs
        cv.text(o.y_label, {std::max(2.0, l.box_left - 40), l.box_top - 0.8 * fs}, fs,
                TextAnchor::start, black);
    }
    if (!o.title.empty()) {
        cv.text(o.title, {0.5 * (l.box_left + l.box_right), 4 + 0.7 * o.title_font_px},
                o.title_font_px, TextAnchor::middle, black);
    }
    for (const PlotSeries& s : series) {
        for (const Vec2& p : s.points) {
            if (!is_finite(p)) {
                continue;
            }
            const Vec2 at{l.x_px(p.x), l.y_px(p.y)};
            if (s.marker == PlotSeries::Marker::disc) {
                cv.disc(at, s.radius_px, s.colour);
            } else {
                cv.ring(at, s.radius_px, 2, s.colour);
            }
        }
    }
    // Legend: top right inside the box, on white, one row per labelled series.
    std::vector<const PlotSeries*> named;
    double text_w = 0;
    for (const PlotSeries& s : series) {
        if (!s.label.empty()) {
            named.push_back(&s);
            text_w = std::max(text_w, Canvas::text_width_mm(s.label, fs));
        }
    }
    if (!named.empty()) {
        const double row = 1.6 * fs, pad = 6, marker_w = 16;
        const double w = pad + marker_w + text_w + pad, h = pad + row * double(named.size()) + pad;
        const Vec2 a{l.box_right - 8 - w, l.box_top + 8};
        l.legend_left = a.x;
        l.legend_top = a.y;
        l.legend_right = a.x + w;
        l.legend_bottom = a.y + h;
        cv.fill_rect(a, {a.x + w, a.y + h}, {1, 1, 1});
        cv.polyline({a, {a.x + w, a.y}, {a.x + w, a.y + h}, {a.x, a.y + h}, a}, 1, {0.6, 0.6, 0.6});
        for (std::size_t i = 0; i < named.size(); ++i) {
            const PlotSeries& s = *named[i];
            const double cy = a.y + pad + row * (double(i) + 0.5);
            const Vec2 m{a.x + pad + 0.5 * marker_w, cy};
            if (s.marker == PlotSeries::Marker::disc) {
                cv.disc(m, s.radius_px, s.colour);
            } else {
                cv.ring(m, std::min(s.radius_px, 5.0), 2, s.colour);
            }
            cv.text(s.label, {a.x + pad + marker_w + 2, cy + 0.35 * fs}, fs, TextAnchor::start,
                    black);
        }
    }
    if (layout) {
        *layout = l;
    }
    return img;
}

}  // namespace tapeline::draw
