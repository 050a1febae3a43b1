// PNG drawing of a pattern: the SVG drawing (svg.h) rasterised at a chosen resolution.
//
// Same layout, same strokes: write_svg's piece placement and page size are reused, so a pixel
// (i, j) covers SVG user units [i, i+1)/r × [j, j+1)/r mm at r pixels per mm. Drawn: outlines,
// internal lines (grey, dashed), darts, fold lines (blue, dashed), grain lines with arrowheads,
// notches, seam-mark ticks (red), the scale bar, and the SVG's text — piece names, cut counts,
// seam names (red, as the seam-mark ticks), the scale bar's label — at the SVG's positions,
// anchors and font sizes, in the built-in 5 × 8 bitmap font (the canvas, font and encoder are the
// drawing module's: draw/canvas.h, draw/png.h). Glyphs are scaled to the
// font-size (one font pixel = a tenth of the em, capitals 0.7 em) and box-filtered: a pixel's
// coverage is the area of it that font pixels cover. At 2 px/mm all text is legible; at 1 px/mm the
// 10 mm names are, the 5–6 mm labels blur. Characters outside printable ASCII are drawn as a hollow
// box, one per code point.
//
// Anti-aliasing: each stroke segment covers a pixel by clamp(w/2 + 1/2 − d, 0, 1), d the distance
// from the pixel centre to the segment (a box filter of one pixel across the edge), blended
// "over" the page. Curves are flattened within a quarter pixel. Strokes are at least one pixel
// wide so that low resolutions still show every line. The PNG is 8-bit RGBA with a pHYs chunk
// giving the resolution, so viewers and printers can reproduce the 1:1 scale.
#pragma once

#include <tapeline/core/atomic_write.h>
#include <tapeline/core/errors.h>
#include <tapeline/draw/canvas.h>
#include <tapeline/draw/png.h>
#include <tapeline/pattern/pattern.h>
#include <tapeline/pattern/svg.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace tapeline::pattern {

/// Resolution, layout and limits of the PNG drawing.
struct PngOptions {
    double pixels_per_mm = 2;             ///< resolution (> 0)
    SvgOptions layout;                    ///< page layout and notch length, as for the SVG
    double max_megapixels = 100;          ///< refuse larger images (400 MB of RGBA)
    bool transparent_background = false;  ///< else white
    bool draw_text = true;                ///< names, cut counts, seam names, scale-bar label
};

/// An 8-bit RGBA raster (draw/canvas.h).
using RgbaImage = draw::RgbaImage;

/// What the PNG export produced.
struct PngReport {
    /// Image size.
    ///@{
    std::size_t width_px = 0, height_px = 0;
    ///@}
    double pixels_per_mm = 0;   ///< resolution used
    SvgReport layout;           ///< page size in mm and piece offsets, as in the SVG
    std::size_t png_bytes = 0;  ///< size of the encoded file
};

/// PNG bytes of an RGBA image; `pixels_per_mm` goes into the pHYs chunk.
using draw::encode_png;

/// The drawing as an RGBA image (see the file comment). Throws InvalidInput for a resolution that
/// is not positive or would exceed `max_megapixels`.
///
/// \throws InvalidInput for a resolution that is not positive or an image beyond
///         `max_megapixels`.
inline RgbaImage rasterise_pattern(const Pattern& pattern, const PngOptions& o = {},
                                   PngReport* report = nullptr) {
    using namespace internal;
    using draw::Rgb;
    using draw::TextAnchor;
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
    RgbaImage img =
        RgbaImage::filled(std::size_t(w), std::size_t(h), o.transparent_background ? 0 : 255);
    draw::Canvas cv(img, r);
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
            cv.text(piece.name, centre, 10, TextAnchor::middle, black);
            cv.text(cut_text(piece), {centre.x, centre.y + 8}, 6, TextAnchor::middle, black);
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
///
/// \throws InvalidInput as rasterise_pattern.
inline PngReport write_png(const Pattern& pattern, std::ostream& out, const PngOptions& o = {}) {
    PngReport rep;
    rep.png_bytes = draw::write_png(out, rasterise_pattern(pattern, o, &rep), o.pixels_per_mm);
    return rep;
}

/// Writes the PNG to `path` atomically.
///
/// \throws InvalidInput as rasterise_pattern, or naming `path` when it cannot be written;
///         `path` is left untouched then.
inline PngReport write_png(const Pattern& pattern, const std::string& path,
                           const PngOptions& o = {}) {
    PngReport rep;
    write_file_atomically(
        path, [&](std::ostream& out) { rep = write_png(pattern, out, o); }, true);
    return rep;
}

}  // namespace tapeline::pattern
