// The raster canvas of every Tapeline picture (pattern PNGs, body measurement pictures, plots):
// anti-aliased strokes, dashed polylines, filled polygons, rectangles, discs and rings, and text
// in the built-in 5 × 8 bitmap font (internal/bitmap_font.h; no font library), on an 8-bit RGBA
// image. No dependency beyond the standard library and core/vec2.h; PNG encoding is png.h.
//
// Coordinates are page millimetres, y down, as in SVG; a canvas of r pixels per mm draws the page
// point (x, y) at pixel position (r x, r y), so pixel (i, j) covers [i, i+1)/r × [j, j+1)/r mm.
// A canvas of 1 pixel per mm draws in pixels.
//
// Anti-aliasing: each stroke segment covers a pixel by clamp(w/2 + 1/2 − d, 0, 1), d the distance
// from the pixel centre to the segment (a box filter of one pixel across the edge), blended "over"
// the page. Strokes are at least one pixel wide so that low resolutions still show every line.
// Filled polygons (non-zero winding) take the fraction of a 4 × 4 grid of sample points per pixel
// that lies inside. Text glyphs are scaled to the font-size (one font pixel = a tenth of the em,
// capitals 0.7 em) and box-filtered: a pixel's coverage is the area of it that font pixels cover.
// Characters outside printable ASCII are drawn as a hollow box, one per code point. Shaded meshes
// are z-buffered by mesh_render.h into an image of their own and pasted onto the canvas.
#pragma once

#include <tapeline/core/vec2.h>
#include <tapeline/draw/internal/bitmap_font.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace tapeline::draw {

/// A colour, each channel in [0, 1].
struct Rgb {
    /// Red, green, blue.
    ///@{
    double r, g, b;
    ///@}
};

/// Linear interpolation from a (t = 0) to b (t = 1), per channel.
inline Rgb mix(Rgb a, Rgb b, double t) {
    return {a.r + (b.r - a.r) * t, a.g + (b.g - a.g) * t, a.b + (b.b - a.b) * t};
}

/// SVG's text-anchor: x is the left end of the text, its middle, or its right end.
enum class TextAnchor { start, middle, end };

/// An 8-bit RGBA raster.
struct RgbaImage {
    /// Size in pixels.
    ///@{
    std::size_t width = 0, height = 0;
    ///@}
    std::vector<std::uint8_t> rgba;  ///< row-major, top row first, 8 bits per channel

    /// A width × height image whose every byte (all four channels) is `value`: 255 opaque white,
    /// 0 transparent.
    static RgbaImage filled(std::size_t width, std::size_t height, std::uint8_t value) {
        RgbaImage img;
        img.width = width;
        img.height = height;
        img.rgba.assign(4 * width * height, value);
        return img;
    }
    /// The four channels of pixel (x, y); not bounds-checked.
    const std::uint8_t* pixel(std::size_t x, std::size_t y) const {
        return &rgba[4 * (y * width + x)];
    }
};

/// Drawing on an RgbaImage in page millimetres (y down): anti-aliased strokes, fills, markers
/// and bitmap-font text. Every picture of the project is drawn through it.
class Canvas {
public:
    /// Draws on `img` (which must outlive the canvas) at `ppmm` pixels per millimetre.
    Canvas(RgbaImage& img, double ppmm) : img_(img), s_(ppmm) {}

    /// Resolution of the canvas.
    double pixels_per_mm() const { return s_; }
    /// The image drawn on.
    RgbaImage& image() { return img_; }

    /// A stroke from a to b in page millimetres (y down), width in mm.
    void segment(Vec2 a, Vec2 b, double width_mm, Rgb c) {
        a = s_ * a;
        b = s_ * b;
        const double hw = 0.5 * std::max(width_mm * s_, 1.0);
        const long x0 = std::max(0L, long(std::floor(std::min(a.x, b.x) - hw - 1)));
        const long x1 =
            std::min(long(img_.width) - 1, long(std::ceil(std::max(a.x, b.x) + hw + 1)));
        const long y0 = std::max(0L, long(std::floor(std::min(a.y, b.y) - hw - 1)));
        const long y1 =
            std::min(long(img_.height) - 1, long(std::ceil(std::max(a.y, b.y) + hw + 1)));
        for (long y = y0; y <= y1; ++y) {
            for (long x = x0; x <= x1; ++x) {
                const double d = distance_to_segment({x + 0.5, y + 0.5}, a, b);
                const double cov = std::clamp(hw + 0.5 - d, 0.0, 1.0);
                if (cov > 0) {
                    blend(std::size_t(x), std::size_t(y), c, cov);
                }
            }
        }
    }

    /// An open polyline; dashes (dash_mm > 0) continue across vertices.
    void polyline(const std::vector<Vec2>& pts, double width_mm, Rgb c, double dash_mm = 0,
                  double gap_mm = 0) {
        if (dash_mm <= 0) {
            for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
                segment(pts[i], pts[i + 1], width_mm, c);
            }
            return;
        }
        bool on = true;
        double left = dash_mm;
        for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
            Vec2 a = pts[i];
            const Vec2 b = pts[i + 1];
            double len = distance(a, b);
            while (len > 0) {
                const double step = std::min(left, len);
                const Vec2 e = a + (step / len) * (b - a);
                if (on) {
                    segment(a, e, width_mm, c);
                }
                a = e;
                len -= step;
                left -= step;
                if (left <= 1e-12) {
                    on = !on;
                    left = on ? dash_mm : gap_mm;
                }
            }
        }
    }

    /// A filled polygon (closed implicitly; non-zero winding, so self-overlaps fill once).
    void fill_polygon(const std::vector<Vec2>& pts, Rgb c) {
        if (pts.size() < 3) {
            return;
        }
        std::vector<Vec2> q;
        q.reserve(pts.size());
        double xmin = HUGE_VAL, ymin = HUGE_VAL, xmax = -HUGE_VAL, ymax = -HUGE_VAL;
        for (const Vec2& p : pts) {
            q.push_back(s_ * p);
            xmin = std::min(xmin, q.back().x);
            xmax = std::max(xmax, q.back().x);
            ymin = std::min(ymin, q.back().y);
            ymax = std::max(ymax, q.back().y);
        }
        if (!(xmin <= xmax && ymin <= ymax)) {
            return;
        }
        const long x0 = std::max(0L, long(std::floor(xmin)));
        const long x1 = std::min(long(img_.width), long(std::ceil(xmax)));
        const long y0 = std::max(0L, long(std::floor(ymin)));
        const long y1 = std::min(long(img_.height), long(std::ceil(ymax)));
        const auto winding = [&q](Vec2 p) {
            int w = 0;
            for (std::size_t i = 0; i < q.size(); ++i) {
                const Vec2 a = q[i], b = q[(i + 1) % q.size()];
                const double side = cross(b - a, p - a);
                if (a.y <= p.y) {
                    w += b.y > p.y && side > 0;
                } else {
                    w -= b.y <= p.y && side < 0;
                }
            }
            return w;
        };
        constexpr int n = 4;  // samples per pixel and axis
        for (long y = y0; y < y1; ++y) {
            for (long x = x0; x < x1; ++x) {
                int inside = 0;
                for (int sy = 0; sy < n; ++sy) {
                    for (int sx = 0; sx < n; ++sx) {
                        inside += winding({x + (sx + 0.5) / n, y + (sy + 0.5) / n}) != 0;
                    }
                }
                if (inside > 0) {
                    blend(std::size_t(x), std::size_t(y), c, double(inside) / (n * n));
                }
            }
        }
    }

    /// Fills the axis-aligned rectangle with corners a and b (page mm), opaque.
    void fill_rect(Vec2 a, Vec2 b, Rgb c) {
        a = s_ * a;
        b = s_ * b;
        for (long y = std::max(0L, long(a.y));
             y < std::min(long(img_.height), long(std::ceil(b.y))); ++y) {
            for (long x = std::max(0L, long(a.x));
                 x < std::min(long(img_.width), long(std::ceil(b.x))); ++x) {
                // Coverage of the pixel by the rectangle, per axis.
                const double cx =
                    std::clamp(std::min(b.x, x + 1.0) - std::max(a.x, double(x)), 0.0, 1.0);
                const double cy =
                    std::clamp(std::min(b.y, y + 1.0) - std::max(a.y, double(y)), 0.0, 1.0);
                blend(std::size_t(x), std::size_t(y), c, cx * cy);
            }
        }
    }

    /// A filled, anti-aliased disc; radius in mm (at least half a pixel).
    void disc(Vec2 centre, double radius_mm, Rgb c) {
        round_shape(
            centre, radius_mm, [](double r, double d) { return r + 0.5 - d; }, c);
    }

    /// An anti-aliased circle of stroke width `width_mm` centred on radius `radius_mm`.
    void ring(Vec2 centre, double radius_mm, double width_mm, Rgb c) {
        const double hw = 0.5 * std::max(width_mm * s_, 1.0);
        round_shape(
            centre, radius_mm + hw / s_,
            [r = radius_mm * s_, hw](double, double d) { return hw + 0.5 - std::abs(d - r); }, c);
    }

    /// Copies every pixel of `src` whose alpha is not zero onto the image, `src`'s top left
    /// corner at pixel (x_px, y_px); what falls outside is dropped.
    void paste(const RgbaImage& src, long x_px, long y_px) {
        for (std::size_t y = 0; y < src.height; ++y) {
            for (std::size_t x = 0; x < src.width; ++x) {
                const std::uint8_t* p = src.pixel(x, y);
                const long X = x_px + long(x), Y = y_px + long(y);
                if (p[3] == 0 || X < 0 || Y < 0 || X >= long(img_.width) ||
                    Y >= long(img_.height)) {
                    continue;
                }
                std::copy(p, p + 4, &img_.rgba[4 * (std::size_t(Y) * img_.width + std::size_t(X))]);
            }
        }
    }

    /// Width of a text's ink in mm at a font-size, as text() draws it.
    static double text_width_mm(const std::string& s, double font_size_mm) {
        const std::size_t n = internal::text_glyphs(s).size();
        return n == 0 ? 0.0
                      : double(n * internal::kGlyphAdvance - 1) * font_size_mm /
                            internal::kFontPixelsPerEm;
    }

    /// Text with its baseline at `at` (page mm), as an SVG `<text>` of that font-size and anchor.
    void text(const std::string& s, Vec2 at, double font_size_mm, TextAnchor anchor, Rgb c) {
        using namespace internal;
        const std::vector<const Glyph*> glyphs = text_glyphs(s);
        if (glyphs.empty() || !(font_size_mm > 0)) {
            return;
        }
        const double u = font_size_mm / kFontPixelsPerEm * s_;  // one font pixel, in pixels
        const double ink_w = double(glyphs.size() * kGlyphAdvance - 1) * u;
        const double shift = anchor == TextAnchor::middle ? 0.5 * ink_w
                             : anchor == TextAnchor::end  ? ink_w
                                                          : 0.0;
        const double left = at.x * s_ - shift;
        const double top = at.y * s_ - kGlyphRowsAboveBaseline * u;
        const long x0 = std::max(0L, long(std::floor(left)));
        const long x1 = std::min(long(img_.width), long(std::ceil(left + ink_w)));
        const long y0 = std::max(0L, long(std::floor(top)));
        const long y1 = std::min(long(img_.height), long(std::ceil(top + kGlyphRows * u)));
        if (x0 >= x1 || y0 >= y1) {
            return;
        }
        // Coverage summed over the string before blending once, so that adjacent font pixels
        // sharing an image pixel add up instead of compositing over each other (no seams).
        const std::size_t w = std::size_t(x1 - x0);
        std::vector<double> cov(w * std::size_t(y1 - y0), 0.0);
        for (std::size_t g = 0; g < glyphs.size(); ++g) {
            for (int row = 0; row < kGlyphRows; ++row) {
                const std::uint8_t bits = (*glyphs[g])[std::size_t(row)];
                for (int col = 0; col < kGlyphColumns; ++col) {
                    if (!(bits & (0x10 >> col))) {
                        continue;
                    }
                    const double ax = left + double(g * kGlyphAdvance + std::size_t(col)) * u;
                    const double ay = top + row * u;
                    const double bx = ax + u, by = ay + u;
                    for (long y = std::max(y0, long(std::floor(ay)));
                         y < std::min(y1, long(std::ceil(by))); ++y) {
                        const double cy = std::min(by, y + 1.0) - std::max(ay, double(y));
                        for (long x = std::max(x0, long(std::floor(ax)));
                             x < std::min(x1, long(std::ceil(bx))); ++x) {
                            const double cx = std::min(bx, x + 1.0) - std::max(ax, double(x));
                            if (cx > 0 && cy > 0) {
                                cov[std::size_t(y - y0) * w + std::size_t(x - x0)] += cx * cy;
                            }
                        }
                    }
                }
            }
        }
        for (long y = y0; y < y1; ++y) {
            for (long x = x0; x < x1; ++x) {
                const double a = std::min(1.0, cov[std::size_t(y - y0) * w + std::size_t(x - x0)]);
                if (a > 0) {
                    blend(std::size_t(x), std::size_t(y), c, a);
                }
            }
        }
    }

    /// Composites colour c at opacity a over pixel (x, y).
    void blend(std::size_t x, std::size_t y, Rgb c, double a) {
        std::uint8_t* p = &img_.rgba[4 * (y * img_.width + x)];
        const double dst_a = p[3] / 255.0;
        const double out_a = a + dst_a * (1 - a);
        const double src[3] = {c.r, c.g, c.b};
        for (int k = 0; k < 3; ++k) {
            const double v = out_a > 0 ? (src[k] * a + p[k] / 255.0 * dst_a * (1 - a)) / out_a : 0;
            p[k] = std::uint8_t(std::lround(255 * std::clamp(v, 0.0, 1.0)));
        }
        p[3] = std::uint8_t(std::lround(255 * std::clamp(out_a, 0.0, 1.0)));
    }

private:
    /// Blends c over the pixels around `centre` by coverage(r_px, d): r_px the radius in pixels
    /// (at least half a pixel), d the pixel centre's distance from the centre in pixels.
    template <typename Coverage>
    void round_shape(Vec2 centre, double radius_mm, Coverage coverage, Rgb c) {
        const Vec2 p = s_ * centre;
        const double r = std::max(radius_mm * s_, 0.5);
        const long x0 = std::max(0L, long(std::floor(p.x - r - 1)));
        const long x1 = std::min(long(img_.width) - 1, long(std::ceil(p.x + r + 1)));
        const long y0 = std::max(0L, long(std::floor(p.y - r - 1)));
        const long y1 = std::min(long(img_.height) - 1, long(std::ceil(p.y + r + 1)));
        for (long y = y0; y <= y1; ++y) {
            for (long x = x0; x <= x1; ++x) {
                const double cov =
                    std::clamp(coverage(r, distance({x + 0.5, y + 0.5}, p)), 0.0, 1.0);
                if (cov > 0) {
                    blend(std::size_t(x), std::size_t(y), c, cov);
                }
            }
        }
    }

    RgbaImage& img_;
    double s_;
};

}  // namespace tapeline::draw
