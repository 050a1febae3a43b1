// The raster canvas (draw/canvas.h) and its bitmap font: the glyphs are all distinct and inked, a
// UTF-8 string makes one glyph per code point, a string's ink stays in the box its font-size and
// anchor give and reaches every side of it; strokes cover the pixels within half their width of
// the centre line; a filled polygon covers its area (analytic area of a triangle, a concave
// polygon's notch stays empty); discs and rings cover the annulus they describe; paste copies
// only opaque pixels.
#include <tapeline/draw/canvas.h>

#include <tapeline_test/image.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <set>
#include <string>
#include <vector>

using namespace tapeline::draw;
using tapeline::Vec2;
using tapeline_test::Decoded;
using tapeline_test::from_image;
using tapeline_test::PixelBox;
using tapeline_test::text_box;

namespace {

/// Sum of (1 − grey/255) over the image: the inked area in pixels, for black on white.
double ink_area(const RgbaImage& img) {
    const Decoded d = from_image(img);
    double sum = 0;
    for (long y = 0; y < long(img.height); ++y) {
        for (long x = 0; x < long(img.width); ++x) {
            sum += 1 - d.grey(x, y) / 255;
        }
    }
    return sum;
}

}  // namespace

TEST(DrawCanvas, BitmapFontGlyphsDistinctAndInked) {
    using namespace tapeline::draw::internal;
    std::set<Glyph> seen;
    for (int c = 32; c <= 126; ++c) {
        SCOPED_TRACE(std::string(1, char(c)));
        const Glyph& g = glyph_for(std::uint32_t(c));
        EXPECT_EQ(&g, &kBitmapFont[c - 32]);
        int ink = 0;
        for (std::uint8_t row : g) {
            EXPECT_EQ(row & ~0x1F, 0) << "bits beyond the 5 columns";
            for (int b = 0; b < 5; ++b) {
                ink += (row >> b) & 1;
            }
        }
        if (c == ' ') {
            EXPECT_EQ(ink, 0);
        } else {
            EXPECT_GT(ink, 0);
        }
        EXPECT_TRUE(seen.insert(g).second) << "same bitmap as an earlier glyph";
    }
    EXPECT_EQ(seen.count(kPlaceholderGlyph), 0u);
    for (const std::uint32_t c : {0u, 31u, 127u, 0xE9u, 0x20ACu}) {
        EXPECT_EQ(&glyph_for(c), &kPlaceholderGlyph) << c;
    }
}

TEST(DrawCanvas, BitmapFontOneGlyphPerCodePoint) {
    using namespace tapeline::draw::internal;
    // a, é (2 bytes), € (3), U+1F600 (4), b, a stray continuation byte, a truncated 3-byte lead.
    const std::string s =
        "a\xC3\xA9\xE2\x82\xAC\xF0\x9F\x98\x80"
        "b\x80\xE2\x82";
    const std::vector<const Glyph*> g = text_glyphs(s);
    ASSERT_EQ(g.size(), 7u);
    EXPECT_EQ(g[0], &kBitmapFont['a' - 32]);
    EXPECT_EQ(g[4], &kBitmapFont['b' - 32]);
    for (const std::size_t k : {1, 2, 3, 5, 6}) {
        EXPECT_EQ(g[k], &kPlaceholderGlyph) << k;
    }
    EXPECT_TRUE(text_glyphs("").empty());
}

TEST(DrawCanvas, TextInkInsideItsBox) {
    using namespace tapeline::draw::internal;
    struct Case {
        std::string text;
        double x, y, size, ppmm;
        bool middle;
    };
    // Strings reaching the full cell (capitals, descenders, the bar) at several scales, both
    // anchors, partly off-pixel positions, and a non-ASCII one drawn as boxes.
    for (const Case& c : {Case{"Hgjy|_ 100 mm", 20, 40, 6, 2, false},
                          Case{"Hgjy|_ 100 mm", 60.3, 40.7, 10, 4, true},
                          Case{"front (mirrored pair)", 60, 30, 5, 1.3, true},
                          Case{"~!@#$%^&*()", 10.25, 20.1, 6, 3, false},
                          Case{"caf\xC3\xA9 \xE2\x82\xAC", 50, 25, 10, 2, true}}) {
        SCOPED_TRACE(c.text + " at " + std::to_string(c.ppmm) + " px/mm");
        RgbaImage img;
        img.width = std::size_t(120 * c.ppmm);
        img.height = std::size_t(60 * c.ppmm);
        img.rgba.assign(4 * img.width * img.height, 255);
        Canvas cv(img, c.ppmm);
        cv.text(c.text, {c.x, c.y}, c.size, c.middle ? TextAnchor::middle : TextAnchor::start,
                {0, 0, 0});
        const Decoded d = from_image(img);
        std::size_t n = 0;
        for (unsigned char b : c.text) {
            n += (b & 0xC0) != 0x80;
        }
        const PixelBox box = text_box(c.x, c.y, c.size, c.middle, n, c.ppmm);
        // The ink's extent must also reach close to every side of the unexpanded box (within a
        // glyph cell), so a glyph drawn at the wrong scale or anchor fails even if it is small.
        long ix0 = long(img.width), iy0 = long(img.height), ix1 = -1, iy1 = -1;
        std::size_t ink = 0, outside = 0;
        for (long y = 0; y < long(img.height); ++y) {
            for (long x = 0; x < long(img.width); ++x) {
                if (d.grey(x, y) < 255) {
                    ++ink;
                    outside += !box.contains(x, y);
                    ix0 = std::min(ix0, x);
                    iy0 = std::min(iy0, y);
                    ix1 = std::max(ix1, x + 1);
                    iy1 = std::max(iy1, y + 1);
                }
            }
        }
        EXPECT_GT(ink, 0u);
        EXPECT_EQ(outside, 0u);
        const PixelBox tight = text_box(c.x, c.y, c.size, c.middle, n, c.ppmm, 0);
        const double cell_w = 0.6 * c.size * c.ppmm, cell_h = 0.8 * c.size * c.ppmm;
        EXPECT_LE(std::abs(ix0 - tight.x0), cell_w);
        EXPECT_LE(std::abs(ix1 - tight.x1), cell_w);
        EXPECT_LE(std::abs(iy0 - tight.y0), cell_h);
        EXPECT_LE(std::abs(iy1 - tight.y1), cell_h);
    }
}

TEST(DrawCanvas, SegmentCoversPixelsWithinHalfItsWidth) {
    // A horizontal 4-pixel-wide stroke on pixel boundaries at 1 px/mm: rows 8..11 fully covered,
    // the rows beside them untouched (coverage clamp(w/2 + 1/2 − d) is 0 from d = 2.5 on).
    RgbaImage img = RgbaImage::filled(40, 20, 255);
    Canvas cv(img, 1);
    cv.segment({5, 10}, {35, 10}, 4, {0, 0, 0});
    const Decoded d = from_image(img);
    for (long y = 0; y < 20; ++y) {
        SCOPED_TRACE(y);
        const double g = d.grey(20, y);
        if (y >= 8 && y <= 11) {
            EXPECT_EQ(g, 0);
        } else {
            EXPECT_EQ(g, 255);
        }
    }
    EXPECT_EQ(d.grey(38, 10), 255);  // beyond the end and its round cap
}

TEST(DrawCanvas, FilledPolygonCoversItsArea) {
    RgbaImage img = RgbaImage::filled(100, 100, 255);
    Canvas cv(img, 2);  // 2 px per mm: the triangle's 800 mm² are 3200 pixels
    cv.fill_polygon({{5, 5}, {45, 5}, {5, 45}}, {0, 0, 0});
    EXPECT_NEAR(ink_area(img), 3200, 3200 * 0.01);
    // A concave "U": its notch stays white, its arms are black.
    RgbaImage u = RgbaImage::filled(60, 60, 255);
    Canvas cu(u, 1);
    cu.fill_polygon(
        {{10, 10}, {20, 10}, {20, 40}, {40, 40}, {40, 10}, {50, 10}, {50, 50}, {10, 50}},
        {0, 0, 0});
    const Decoded d = from_image(u);
    EXPECT_EQ(d.grey(30, 20), 255);
    EXPECT_EQ(d.grey(15, 20), 0);
    EXPECT_EQ(d.grey(45, 45), 0);
    EXPECT_NEAR(ink_area(u), 40 * 40 - 20 * 30, 1e-9);
    // Fewer than three points draw nothing.
    RgbaImage e = RgbaImage::filled(10, 10, 255);
    Canvas ce(e, 1);
    ce.fill_polygon({{1, 1}, {8, 8}}, {0, 0, 0});
    EXPECT_EQ(ink_area(e), 0);
}

TEST(DrawCanvas, DiscAndRingCoverTheirAnnulus) {
    RgbaImage img = RgbaImage::filled(100, 100, 255);
    Canvas cv(img, 1);
    cv.disc({30, 30}, 10, {0, 0, 0});
    EXPECT_NEAR(ink_area(img), M_PI * 100, M_PI * 100 * 0.02);
    RgbaImage ring = RgbaImage::filled(100, 100, 255);
    Canvas cr(ring, 1);
    cr.ring({50, 50}, 20, 2, {0, 0, 0});
    // Area of the annulus 19 ≤ r ≤ 21.
    EXPECT_NEAR(ink_area(ring), M_PI * (21 * 21 - 19 * 19), M_PI * 80 * 0.03);
    const Decoded d = from_image(ring);
    EXPECT_EQ(d.grey(50, 50), 255);  // hollow
    EXPECT_LT(d.grey(70, 50), 64);   // on the circle
}

TEST(DrawCanvas, PasteCopiesOnlyOpaquePixels) {
    RgbaImage src = RgbaImage::filled(3, 1, 0);
    src.rgba[4 * 1 + 0] = 10;
    src.rgba[4 * 1 + 3] = 255;
    RgbaImage dst = RgbaImage::filled(4, 2, 255);
    Canvas cv(dst, 1);
    cv.paste(src, 2, 1);  // the third source pixel falls outside and is dropped
    EXPECT_EQ(dst.pixel(3, 1)[0], 10);
    EXPECT_EQ(dst.pixel(2, 1)[0], 255);  // transparent source pixel: page kept
    EXPECT_EQ(dst.pixel(3, 0)[0], 255);
}
