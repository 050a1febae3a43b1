// PNG drawing, decoded with libpng's simplified reader (a different code path from the writer):
// image size = SVG page × resolution, dark pixels where the outlines pass, background where
// nothing is drawn, and a clear error for absurd resolutions. Text: every <text> the SVG writes
// (parsed from the SVG itself) has ink at its place in the PNG that is not on any line (lines
// found by rendering again with draw_text = false), and no ink outside those places. The canvas,
// font and encoder themselves are tested in tests/draw.
#include <tapeline/pattern/io_freesewing.h>
#include <tapeline/pattern/io_garmentcode.h>
#include <tapeline/pattern/png.h>

#include <tapeline_test/image.h>
#include <tapeline_test/pattern.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <regex>
#include <set>
#include <sstream>

using namespace tapeline::pattern;

namespace {

using tapeline_test::decode;
using tapeline_test::Decoded;
using tapeline_test::from_image;
using tapeline_test::PixelBox;
using tapeline_test::text_box;

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
        // (100, 100) on the back, 34 mm below its cut count: background.
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
        GTEST_SKIP() << tapeline_test::shared_patterns_dir() << " absent";
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
        // Outside points 6 mm away from their outline and 5.5 mm from every other: background
        // unless another drawing (a fold line, an internal line running out of the piece) passes
        // there.
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

namespace {

/// One <text> of the SVG: baseline position, font-size, anchor, code points.
struct SvgText {
    double x = 0, y = 0, size = 0;
    bool middle = false;
    std::size_t code_points = 0;
    std::string content;
};

std::vector<SvgText> svg_texts(const std::string& svg) {
    std::vector<SvgText> out;
    const std::regex re("<text([^>]*)>([^<]*)</text>");
    const auto attr = [](const std::string& a, const std::string& name) {
        std::smatch m;
        return std::regex_search(a, m, std::regex(" " + name + "=\"([^\"]*)\"")) ? m[1].str()
                                                                                 : std::string();
    };
    for (auto it = std::sregex_iterator(svg.begin(), svg.end(), re); it != std::sregex_iterator();
         ++it) {
        const std::string a = (*it)[1].str();
        SvgText t;
        t.x = std::stod(attr(a, "x"));
        t.y = std::stod(attr(a, "y"));
        t.size = std::stod(attr(a, "font-size"));
        t.middle = attr(a, "text-anchor") == "middle";
        // Unescape the five XML entities write_svg produces.
        std::string c = (*it)[2].str();
        for (const auto& [ent, ch] : {std::pair<std::string, std::string>{"&lt;", "<"},
                                      {"&gt;", ">"},
                                      {"&quot;", "\""},
                                      {"&apos;", "'"},
                                      {"&amp;", "&"}}) {
            for (std::size_t k = c.find(ent); k != std::string::npos; k = c.find(ent, k + 1)) {
                c.replace(k, ent.size(), ch);
            }
        }
        t.content = c;
        for (unsigned char b : c) {
            t.code_points += (b & 0xC0) != 0x80;
        }
        out.push_back(t);
    }
    return out;
}

PixelBox text_box(const SvgText& t, double ppmm, double grow_cells = 1) {
    return text_box(t.x, t.y, t.size, t.middle, t.code_points, ppmm, grow_cells);
}

}  // namespace

TEST(PatternPng, SvgTextAppearsInPng) {
    std::vector<Pattern> patterns = {tapeline_test::two_piece_pattern()};
    for (const char* kind : {"freesewing", "garmentcode"}) {
        for (const auto& f : tapeline_test::files_ending(
                 tapeline_test::shared_patterns_dir() + "/" + kind, ".json")) {
            if (f.find("measurement_sets") == std::string::npos) {
                patterns.push_back(f.find("/garmentcode/") != std::string::npos
                                       ? read_garmentcode(f)
                                       : read_freesewing(f));
            }
        }
    }
    const double ppmm = 2;
    for (const Pattern& pat : patterns) {
        SCOPED_TRACE(pat.name);
        PngOptions o;
        o.pixels_per_mm = ppmm;
        const Decoded with = from_image(rasterise_pattern(pat, o));
        o.draw_text = false;
        const Decoded without = from_image(rasterise_pattern(pat, o));
        ASSERT_EQ(with.width, without.width);
        const std::vector<SvgText> texts = svg_texts(to_svg(pat, o.layout));
        // Two per piece, one per seam side, the scale bar's label.
        ASSERT_GE(texts.size(), 2 * pat.pieces.size() + 1);
        std::vector<PixelBox> boxes;
        for (const SvgText& t : texts) {
            boxes.push_back(text_box(t, ppmm));
        }
        // Ink not on any line: dark with text, background in the 3 × 3 block without.
        const auto text_ink = [&](long x, long y) {
            return with.grey(x, y) < 160 && without.darkest(x, y) == 255;
        };
        std::size_t names = 0;
        for (std::size_t k = 0; k < texts.size(); ++k) {
            const SvgText& t = texts[k];
            std::size_t ink = 0;
            const PixelBox b = text_box(t, ppmm, 0);
            for (long y = std::max(0L, b.y0); y < std::min(long(with.height), b.y1); ++y) {
                for (long x = std::max(0L, b.x0); x < std::min(long(with.width), b.x1); ++x) {
                    ink += text_ink(x, y);
                }
            }
            const std::size_t visible =
                t.code_points - std::size_t(std::count(t.content.begin(), t.content.end(), ' '));
            if (t.size == 10) {
                // A piece name: ≥ 4 font pixels (2 × 2 px each at 10 mm, 2 px/mm) per character
                // off the lines; a '.' has 4, most glyphs 10–17, and lines may cross a few.
                ++names;
                EXPECT_GE(ink, 16 * visible) << "piece name '" << t.content << "'";
            } else {
                EXPECT_GT(ink, 0u) << "'" << t.content << "' at " << t.x << ", " << t.y;
            }
        }
        EXPECT_EQ(names, pat.pieces.size());
        // Every pixel the text changed lies in some text's box.
        std::size_t stray = 0;
        for (long y = 0; y < long(with.height); ++y) {
            for (long x = 0; x < long(with.width); ++x) {
                if (std::memcmp(with.at(x, y), without.at(x, y), 4) != 0) {
                    bool in = false;
                    for (const PixelBox& b : boxes) {
                        in = in || b.contains(x, y);
                    }
                    stray += !in;
                }
            }
        }
        EXPECT_EQ(stray, 0u);
    }
}

TEST(PatternPng, ScaleBarLabel) {
    const Pattern pat = tapeline_test::two_piece_pattern();
    for (const double ppmm : {1.0, 2.0, 5.0}) {
        SCOPED_TRACE(ppmm);
        PngOptions o;
        o.pixels_per_mm = ppmm;
        PngReport rep;
        const Decoded with = from_image(rasterise_pattern(pat, o, &rep));
        o.draw_text = false;
        const Decoded without = from_image(rasterise_pattern(pat, o));
        // "100 mm" with its baseline at the bar's bottom, 4 mm right of the bar (svg.h).
        const double bar_y = rep.layout.height_mm - o.layout.margin_mm - 12;
        const PixelBox b = text_box(o.layout.margin_mm + o.layout.scale_bar_mm + 4, bar_y + 4, 6,
                                    false, 6, ppmm, 0);
        std::size_t ink_with = 0, ink_without = 0;
        for (long y = b.y0; y < b.y1; ++y) {
            for (long x = b.x0; x < b.x1; ++x) {
                ink_with += with.grey(x, y) < 192;
                ink_without += without.grey(x, y) < 255;
            }
        }
        // Each glyph inks 10–14 font pixels of 0.6 mm: ≥ 3.6 mm²; ask for 1.5 mm² per glyph.
        EXPECT_GT(ink_with, std::size_t(1.5 * 5 * ppmm * ppmm));
        EXPECT_EQ(ink_without, 0u);
    }
}
