// PNG drawing, decoded with libpng's simplified reader (a different code path from the writer):
// image size = SVG page × resolution, dark pixels where the outlines pass, background where
// nothing is drawn, and a clear error for absurd resolutions.
#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/pattern/io_garmentcode.h>
#include <tapeline/pattern/png.h>

#include <tapeline_test/pattern.h>

#include <gtest/gtest.h>

#include <cmath>
#include <sstream>

using namespace tapeline::pattern;

namespace {

struct Decoded {
    std::size_t width = 0, height = 0;
    std::vector<std::uint8_t> rgba;
    const std::uint8_t* at(long x, long y) const { return &rgba[4 * (std::size_t(y) * width + x)]; }
    /// Darkest grey level (mean of RGB, alpha-composited on white) in the 3 × 3 block around.
    double darkest(long x, long y) const {
        double best = 255;
        for (long dy = -1; dy <= 1; ++dy) {
            for (long dx = -1; dx <= 1; ++dx) {
                const long xx = std::clamp(x + dx, 0L, long(width) - 1);
                const long yy = std::clamp(y + dy, 0L, long(height) - 1);
                best = std::min(best, grey(xx, yy));
            }
        }
        return best;
    }
    double grey(long x, long y) const {
        const std::uint8_t* p = at(x, y);
        const double a = p[3] / 255.0;
        return (p[0] + p[1] + p[2]) / 3.0 * a + 255 * (1 - a);
    }
};

Decoded decode(const std::string& bytes) {
    png_image image{};
    image.version = PNG_IMAGE_VERSION;
    Decoded d;
    if (!png_image_begin_read_from_memory(&image, bytes.data(), bytes.size())) {
        ADD_FAILURE() << "libpng cannot read the PNG: " << image.message;
        return d;
    }
    image.format = PNG_FORMAT_RGBA;
    d.width = image.width;
    d.height = image.height;
    d.rgba.resize(PNG_IMAGE_SIZE(image));
    if (!png_image_finish_read(&image, nullptr, d.rgba.data(), 0, nullptr)) {
        ADD_FAILURE() << "libpng decode failed: " << image.message;
    }
    return d;
}

struct PixelStats {
    std::size_t outline_samples = 0, dark = 0, outside_samples = 0, white = 0;
};

/// Samples the outlines (every 2 mm) and points 6 mm outside them (beyond the 3 mm seam-mark
/// ticks plus a pixel of anti-aliasing at 1 px/mm). "Dark": a stroke one pixel wide (0.5 mm at
/// 2 px/mm) that runs between pixel centres is drawn as two pixels of 50 % coverage, so the
/// darkest pixel near it is at most mid-grey (≤ 128); strokes two pixels or more wide have a
/// pixel centre within half a pixel of the centre line, covered ≥ 75 %.
PixelStats check_drawing(const Pattern& pat, double ppmm, const Decoded& img,
                         const PngReport& rep) {
    PixelStats st;
    const auto px = [&](const Point2& p, std::size_t i) {
        const Point2 off = rep.layout.piece_offsets[i];
        return std::pair<long, long>{long(std::floor((p.x + off.x) * ppmm)),
                                     long(std::floor((off.y - p.y) * ppmm))};
    };
    // All outlines in page coordinates, to skip outside samples near another line.
    std::vector<std::vector<Point2>> rings;
    for (std::size_t i = 0; i < pat.pieces.size(); ++i) {
        std::vector<Point2> ring = sample(pat.pieces[i].outline, 0.05).points;
        for (Point2& p : ring) {
            p = p + Point2{rep.layout.piece_offsets[i].x, 0};
            p.y = rep.layout.piece_offsets[i].y - p.y;
        }
        rings.push_back(std::move(ring));
    }
    for (std::size_t i = 0; i < pat.pieces.size(); ++i) {
        const Piece& piece = pat.pieces[i];
        const double inward = signed_area(piece.outline) >= 0 ? 1.0 : -1.0;
        for (const Edge& e : piece.outline.edges) {
            const double len = length(e);
            const int n = std::max(1, int(len / 2));
            for (int k = 0; k < n; ++k) {
                const double t = parameter_at_length(e.curve, len * (k + 0.5) / n);
                const Point2 p = point_at(e.curve, t);
                const auto [x, y] = px(p, i);
                ++st.outline_samples;
                if (img.darkest(x, y) < (0.5 * ppmm >= 2 ? 64 : 135)) {
                    ++st.dark;
                }
                const Point2 q = p + (-6.0 * inward) * left_normal(tangent_at(e.curve, t));
                Point2 qp{q.x + rep.layout.piece_offsets[i].x, rep.layout.piece_offsets[i].y - q.y};
                bool near = false;
                for (const auto& ring : rings) {
                    for (std::size_t k2 = 0; k2 + 1 < ring.size() && !near; ++k2) {
                        near = internal::distance_to_segment(qp, ring[k2], ring[k2 + 1]) < 5.5;
                    }
                }
                if (!near) {
                    ++st.outside_samples;
                    const auto [qx, qy] = px(q, i);
                    if (img.grey(qx, qy) == 255) {
                        ++st.white;
                    }
                }
            }
        }
    }
    return st;
}

}  // namespace

TEST(PatternPng, TwoPiecePatternPixels) {
    const Pattern pat = tapeline_test::two_piece_pattern();
    for (const double ppmm : {1.0, 4.0}) {
        SCOPED_TRACE(ppmm);
        PngOptions o;
        o.pixels_per_mm = ppmm;
        std::ostringstream out;
        const PngReport rep = write_png(pat, out, o);
        const Decoded img = decode(out.str());
        ASSERT_EQ(img.width, std::size_t(std::ceil(rep.layout.width_mm * ppmm)));
        ASSERT_EQ(img.height, std::size_t(std::ceil(rep.layout.height_mm * ppmm)));
        EXPECT_EQ(rep.png_bytes, out.str().size());
        const PixelStats st = check_drawing(pat, ppmm, img, rep);
        EXPECT_EQ(st.dark, st.outline_samples);
        EXPECT_EQ(st.white, st.outside_samples);
        EXPECT_GT(st.outside_samples, 100u);
        // The back piece's centre holds only (undrawn) text: background.
        const Point2 off = rep.layout.piece_offsets[1];
        EXPECT_EQ(img.grey(long((100 + off.x) * ppmm), long((off.y - 100) * ppmm)), 255);
        // Page corner: background, opaque white.
        EXPECT_EQ(img.at(0, 0)[3], 255);
        EXPECT_EQ(img.grey(0, 0), 255);
        // The scale bar is solid black in its middle.
        const double bar_y = rep.layout.height_mm - o.layout.margin_mm - 12 + 2;
        EXPECT_EQ(img.grey(long((o.layout.margin_mm + 50) * ppmm), long(bar_y * ppmm)), 0);
        // The grain line (100, 50)–(100, 250) on the front at 4 px/mm is dark in its middle.
        const Point2 f = rep.layout.piece_offsets[0];
        if (ppmm == 4.0) {
            EXPECT_LT(img.darkest(long((100 + f.x) * ppmm), long((f.y - 150) * ppmm)), 100);
        }
    }
}

TEST(PatternPng, AntiAliasedEdges) {
    // A slanted outline at 4 px/mm leaves intermediate grey levels beside it.
    Pattern pat;
    pat.name = "slant";
    Piece p;
    p.name = "tri";
    p.outline = tapeline_test::polygon({{0, 0}, {100, 37}, {0, 100}});
    pat.pieces.push_back(p);
    PngOptions o;
    o.pixels_per_mm = 4;
    const RgbaImage img = rasterise_pattern(pat, o);
    std::size_t partial = 0;
    for (std::size_t k = 0; k < img.rgba.size(); k += 4) {
        partial += img.rgba[k] > 10 && img.rgba[k] < 245;
    }
    EXPECT_GT(partial, 200u);
}

TEST(PatternPng, EverySharedPattern) {
    std::vector<std::string> files;
    for (const char* kind : {"freesewing", "garmentcode"}) {
        for (const auto& f : tapeline_test::files_ending(
                 tapeline_test::shared_patterns_dir() + "/" + kind, ".json")) {
            if (f.find("measurement_sets") == std::string::npos) {
                files.push_back(f);
            }
        }
    }
    if (files.empty()) {
        GTEST_SKIP() << "shared pattern data absent";
    }
    tapeline_test::TempDir dir;
    for (const std::string& f : files) {
        const Pattern pat =
            f.find("/garmentcode/") != std::string::npos ? read_garmentcode(f) : read_freesewing(f);
        PngOptions o;
        o.pixels_per_mm = 2;
        const std::string path = dir.file(pat.name + ".png");
        const PngReport rep = write_png(pat, path, o);
        const Decoded img = decode(tapeline_test::slurp(path));
        ASSERT_EQ(img.width, std::size_t(std::ceil(rep.layout.width_mm * 2)));
        ASSERT_EQ(img.height, std::size_t(std::ceil(rep.layout.height_mm * 2)));
        const PixelStats st = check_drawing(pat, 2, img, rep);
        std::printf(
            "  %-26s %5zu × %5zu px, %7zu B; outline samples dark %zu/%zu, outside "
            "white %zu/%zu\n",
            pat.name.c_str(), img.width, img.height, rep.png_bytes, st.dark, st.outline_samples,
            st.white, st.outside_samples);
        EXPECT_EQ(st.dark, st.outline_samples) << f;
        // Outside points 6 mm away from their outline and 5.5 mm from every other: background unless another drawing
        // (a fold line, an internal line running out of the piece) passes there.
        EXPECT_GE(double(st.white), 0.98 * double(st.outside_samples)) << f;
    }
}

TEST(PatternPng, AbsurdResolutionIsRefused) {
    const Pattern pat = tapeline_test::two_piece_pattern();
    PngOptions o;
    o.pixels_per_mm = 1000;
    try {
        rasterise_pattern(pat, o);
        ADD_FAILURE();
    } catch (const tapeline::InvalidInput& e) {
        const std::string m = e.what();
        EXPECT_NE(m.find("'test pattern'"), std::string::npos) << m;
        EXPECT_NE(m.find("over the limit of 100"), std::string::npos) << m;
        EXPECT_NE(m.find("lower the resolution"), std::string::npos) << m;
    }
    for (const double bad : {0.0, -2.0, std::nan("")}) {
        o.pixels_per_mm = bad;
        try {
            rasterise_pattern(pat, o);
            ADD_FAILURE() << bad;
        } catch (const tapeline::InvalidInput& e) {
            EXPECT_NE(std::string(e.what()).find("must be positive"), std::string::npos);
        }
    }
}
