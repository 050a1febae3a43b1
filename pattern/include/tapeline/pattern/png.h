// PNG drawing of a pattern: the SVG drawing (svg.h) rasterised at a chosen resolution.
//
// Same layout, same strokes: write_svg's piece placement and page size are reused, so a pixel
// (i, j) covers SVG user units [i, i+1)/r × [j, j+1)/r mm at r pixels per mm. Drawn: outlines,
// internal lines (grey, dashed), darts, fold lines (blue, dashed), grain lines with arrowheads,
// notches, seam-mark ticks (red), the scale bar, and the SVG's text — piece names, cut counts,
// seam names (red, as the seam-mark ticks), the scale bar's label — at the SVG's positions,
// anchors and font sizes, in the built-in 5 × 8 bitmap font (internal/bitmap_font.h; no font
// library). Glyphs are scaled to the font-size (one font pixel = a tenth of the em, capitals
// 0.7 em) and box-filtered: a pixel's coverage is the area of it that font pixels cover. At
// 2 px/mm all text is legible; at 1 px/mm the 10 mm names are, the 5–6 mm labels blur.
// Characters outside printable ASCII are drawn as a hollow box, one per code point.
//
// Anti-aliasing: each stroke segment covers a pixel by clamp(w/2 + 1/2 − d, 0, 1), d the distance
// from the pixel centre to the segment (a box filter of one pixel across the edge), blended
// "over" the page. Curves are flattened within a quarter pixel. Strokes are at least one pixel
// wide so that low resolutions still show every line. The PNG is 8-bit RGBA with a pHYs chunk
// giving the resolution, so viewers and printers can reproduce the 1:1 scale.
#pragma once

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/pattern/internal/bitmap_font.h>
#include <tapeline/pattern/pattern.h>
#include <tapeline/pattern/svg.h>

#include <png.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace tapeline::pattern {

struct PngOptions {
    double pixels_per_mm = 2;
    SvgOptions layout;                    // page layout and notch length, as for the SVG
    double max_megapixels = 100;          // refuse larger images (400 MB of RGBA)
    bool transparent_background = false;  // else white
    bool draw_text = true;                // names, cut counts, seam names, scale-bar label
};

struct RgbaImage {
    std::size_t width = 0, height = 0;
    std::vector<std::uint8_t> rgba;  // row-major, top row first
};

struct PngReport {
    std::size_t width_px = 0, height_px = 0;
    double pixels_per_mm = 0;
    SvgReport layout;  // page size in mm and piece offsets, as in the SVG
    std::size_t png_bytes = 0;
};

namespace internal {

struct Rgb {
    double r, g, b;
};

/// SVG's text-anchor: x is the left end of the text, or its middle.
enum class TextAnchor { start, middle };

class Canvas {
public:
    Canvas(RgbaImage& img, double ppmm) : img_(img), s_(ppmm) {}

    /// A stroke from a to b in page millimetres (y down), width in mm.
    void segment(Point2 a, Point2 b, double width_mm, Rgb c) {
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

    void polyline(const std::vector<Point2>& pts, double width_mm, Rgb c, double dash_mm = 0,
                  double gap_mm = 0) {
        if (dash_mm <= 0) {
            for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
                segment(pts[i], pts[i + 1], width_mm, c);
            }
            return;
        }
        // Dashes continue across vertices.
        bool on = true;
        double left = dash_mm;
        for (std::size_t i = 0; i + 1 < pts.size(); ++i) {
            Point2 a = pts[i];
            const Point2 b = pts[i + 1];
            double len = distance(a, b);
            while (len > 0) {
                const double step = std::min(left, len);
                const Point2 e = a + (step / len) * (b - a);
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

    void fill_rect(Point2 a, Point2 b, Rgb c) {
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

    /// Text with its baseline at `at` (page mm), as an SVG <text> of that font-size and anchor.
    void text(const std::string& s, Point2 at, double font_size_mm, TextAnchor anchor, Rgb c) {
        const std::vector<const Glyph*> glyphs = text_glyphs(s);
        if (glyphs.empty() || !(font_size_mm > 0)) {
            return;
        }
        const double u = font_size_mm / kFontPixelsPerEm * s_;  // one font pixel, in pixels
        const double ink_w = double(glyphs.size() * kGlyphAdvance - 1) * u;
        const double left = at.x * s_ - (anchor == TextAnchor::middle ? 0.5 * ink_w : 0.0);
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

private:
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

    RgbaImage& img_;
    double s_;
};

inline void png_write_to_vector(png_structp png, png_bytep data, png_size_t n) {
    auto* out = static_cast<std::vector<std::uint8_t>*>(png_get_io_ptr(png));
    out->insert(out->end(), data, data + n);
}

inline void png_flush_nothing(png_structp) {}

inline void png_error_throw(png_structp png, png_const_charp msg) {
    *static_cast<std::string*>(png_get_error_ptr(png)) = msg;
    png_longjmp(png, 1);
}

inline void png_warning_ignore(png_structp, png_const_charp) {}

/// libpng reports errors by longjmp; this frame holds no C++ objects with destructors.
inline bool png_encode_raw(const RgbaImage& img, double ppmm, std::vector<std::uint8_t>* out,
                           std::string* error, png_bytep* rows) {
    png_structp png =
        png_create_write_struct(PNG_LIBPNG_VER_STRING, error, png_error_throw, png_warning_ignore);
    if (!png) {
        return false;
    }
    png_infop info = png_create_info_struct(png);
    if (!info || setjmp(png_jmpbuf(png))) {
        png_destroy_write_struct(&png, &info);
        return false;
    }
    png_set_write_fn(png, out, png_write_to_vector, png_flush_nothing);
    png_set_IHDR(png, info, png_uint_32(img.width), png_uint_32(img.height), 8,
                 PNG_COLOR_TYPE_RGB_ALPHA, PNG_INTERLACE_NONE, PNG_COMPRESSION_TYPE_DEFAULT,
                 PNG_FILTER_TYPE_DEFAULT);
    const auto ppm = png_uint_32(std::lround(ppmm * 1000.0));
    png_set_pHYs(png, info, ppm, ppm, PNG_RESOLUTION_METER);
    png_set_rows(png, info, rows);
    png_write_png(png, info, PNG_TRANSFORM_IDENTITY, nullptr);
    png_destroy_write_struct(&png, &info);
    return true;
}

}  // namespace internal

/// PNG bytes of an RGBA image; `pixels_per_mm` goes into the pHYs chunk.
inline std::vector<std::uint8_t> encode_png(const RgbaImage& img, double pixels_per_mm) {
    if (img.width == 0 || img.height == 0 || img.rgba.size() != 4 * img.width * img.height) {
        throw InvalidInput("PNG encoding: image of " + std::to_string(img.width) + " × " +
                           std::to_string(img.height) + " pixels with " +
                           std::to_string(img.rgba.size()) + " bytes is malformed");
    }
    std::vector<png_bytep> rows(img.height);
    for (std::size_t y = 0; y < img.height; ++y) {
        rows[y] = const_cast<png_bytep>(&img.rgba[4 * y * img.width]);
    }
    std::vector<std::uint8_t> out;
    std::string error = "out of memory";
    if (!internal::png_encode_raw(img, pixels_per_mm, &out, &error, rows.data())) {
        throw std::runtime_error("PNG encoding failed: " + error);
    }
    return out;
}

/// The drawing as an RGBA image (see the file comment). Throws InvalidInput for a resolution that
/// is not positive or would exceed `max_megapixels`.
inline RgbaImage rasterise_pattern(const Pattern& pattern, const PngOptions& o = {},
                                   PngReport* report = nullptr) {
    using namespace internal;
    const double r = o.pixels_per_mm;
    if (!(r > 0) || !std::isfinite(r)) {
        throw InvalidInput("PNG export of '" + pattern.name + "': resolution " + std::to_string(r) +
                           " pixels per mm must be positive");
    }
    std::ostream sink(nullptr);  // only the layout is wanted
    const SvgReport lay = write_svg(pattern, sink, o.layout);
    const double w = std::ceil(lay.width_mm * r), h = std::ceil(lay.height_mm * r);
    if (w * h > o.max_megapixels * 1e6 || w > 1e9 || h > 1e9) {
        throw InvalidInput("PNG export of '" + pattern.name + "': " + std::to_string(lay.width_mm) +
                           " × " + std::to_string(lay.height_mm) + " mm at " + std::to_string(r) +
                           " pixels per mm is " + std::to_string(w) + " × " + std::to_string(h) +
                           " pixels (" + std::to_string(w * h / 1e6) + " Mpx), over the limit of " +
                           std::to_string(o.max_megapixels) + " Mpx; lower the resolution");
    }
    RgbaImage img;
    img.width = std::size_t(w);
    img.height = std::size_t(h);
    img.rgba.assign(4 * img.width * img.height, o.transparent_background ? 0 : 255);
    Canvas cv(img, r);
    const double tol = 0.25 / r;  // quarter of a pixel, in mm
    const Rgb black{0, 0, 0}, grey{0.4, 0.4, 0.4}, blue{0, 0.4, 0.8}, red{0.8, 0, 0};

    for (std::size_t i = 0; i < pattern.pieces.size(); ++i) {
        const Piece& piece = pattern.pieces[i];
        const Point2 off = lay.piece_offsets[i];
        const auto map = [&](const Point2& p) { return Point2{p.x + off.x, off.y - p.y}; };
        const auto mapped = [&](const std::vector<Edge>& edges) {
            std::vector<Point2> pts;
            for (std::size_t k = 0; k < edges.size(); ++k) {
                sample(edges[k].curve, tol, pts, k > 0);
            }
            for (Point2& p : pts) {
                p = map(p);
            }
            return pts;
        };
        for (const InternalLine& l : piece.internal_lines) {
            cv.polyline(mapped(l.edges), 0.3, grey, 2, 2);
        }
        for (const Dart& d : piece.darts) {
            cv.polyline(mapped(d.edges), 0.4, black);
        }
        if (piece.fold) {
            cv.polyline({map(piece.fold->line.a), map(piece.fold->line.b)}, 0.5, blue, 6, 3);
        }
        if (piece.grain) {
            const Point2 a = map(piece.grain->from), b = map(piece.grain->to);
            cv.segment(a, b, 0.4, black);
            const double len = distance(a, b);
            if (len > 0) {
                const Point2 u = (1.0 / len) * (b - a), n = left_normal(u);
                for (const auto& [tip, dir] : {std::pair{b, u}, std::pair{a, -1.0 * u}}) {
                    cv.segment(tip, tip - 3.6 * dir + 1.8 * n, 0.4, black);
                    cv.segment(tip, tip - 3.6 * dir - 1.8 * n, 0.4, black);
                }
            }
        }
        cv.polyline(mapped(piece.outline.edges), 0.5, black);
        const double inward = signed_area(piece.outline, 0.1) >= 0 ? 1.0 : -1.0;
        for (const Notch& n : piece.notches) {
            if (n.edge >= piece.outline.edges.size()) {
                continue;
            }
            const auto [p, q] = notch_mark(piece.outline.edges[n.edge].curve, n.offset, inward,
                                           o.layout.notch_length_mm);
            cv.segment(map(p), map(q), 0.5, black);
        }
        if (o.layout.seam_marks) {
            for (std::size_t s = 0; s < pattern.seams.size(); ++s) {
                const Seam& seam = pattern.seams[s];
                for (const EdgeRange* rg : {&seam.a, &seam.b}) {
                    const auto mark = internal::seam_mark(piece, *rg);
                    if (!mark) {
                        continue;
                    }
                    const auto [p, nrm] = *mark;
                    cv.segment(map(p + (-3.0) * nrm), map(p + 3.0 * nrm), 0.5, red);
                    if (o.draw_text) {
                        cv.text(seam.name.empty() ? "seam " + std::to_string(s) : seam.name,
                                map(p + (inward * 8.0) * nrm), 5, TextAnchor::middle, red);
                    }
                }
            }
        }
        if (o.draw_text) {
            // Name and cut count at the middle of the bounding box, as write_svg places them.
            Box b;
            for (const Point2& p : sample(piece.outline, o.layout.sample_tolerance_mm).points) {
                b.add(p);
            }
            if (b.empty()) {
                b.add({0, 0});
            }
            const Point2 centre = map({0.5 * (b.x0 + b.x1), 0.5 * (b.y0 + b.y1)});
            std::string cut = "cut " + std::to_string(piece.cut_count);
            if (piece.fold) {
                cut += " on fold";
            }
            if (piece.mirrored) {
                cut += " (mirrored pair)";
            }
            cv.text(piece.name, centre, 10, TextAnchor::middle, black);
            cv.text(cut, {centre.x, centre.y + 8}, 6, TextAnchor::middle, black);
        }
    }
    const double bar_y = lay.height_mm - o.layout.margin_mm - 12;
    cv.fill_rect({o.layout.margin_mm, bar_y},
                 {o.layout.margin_mm + o.layout.scale_bar_mm, bar_y + 4}, black);
    if (o.draw_text) {
        cv.text(num(o.layout.scale_bar_mm) + " mm",
                {o.layout.margin_mm + o.layout.scale_bar_mm + 4, bar_y + 4}, 6, TextAnchor::start,
                black);
    }
    if (report) {
        report->width_px = img.width;
        report->height_px = img.height;
        report->pixels_per_mm = r;
        report->layout = lay;
    }
    return img;
}

/// Writes the PNG to `out`.
inline PngReport write_png(const Pattern& pattern, std::ostream& out, const PngOptions& o = {}) {
    PngReport rep;
    const RgbaImage img = rasterise_pattern(pattern, o, &rep);
    const std::vector<std::uint8_t> bytes = encode_png(img, o.pixels_per_mm);
    out.write(reinterpret_cast<const char*>(bytes.data()), std::streamsize(bytes.size()));
    rep.png_bytes = bytes.size();
    return rep;
}

/// Writes the PNG to `path` atomically.
inline PngReport write_png(const Pattern& pattern, const std::string& path,
                           const PngOptions& o = {}) {
    PngReport rep;
    write_file_atomically(
        path, [&](std::ostream& out) { rep = write_png(pattern, out, o); }, true);
    return rep;
}

}  // namespace tapeline::pattern
