// What every SVG writer of Tapeline shares: the document's opening, numbers for attributes,
// colours, point lists, text escaping (core's xml_escape) and raster images embedded as PNG data
// URIs. The writers themselves (pattern/svg.h, measurement/picture.h, geodesic/unfold_svg.h) keep
// their own elements; these helpers only keep the bytes they share in one place.
#pragma once

#include <tapeline/core/vec2.h>
#include <tapeline/core/xml_escape.h>
#include <tapeline/draw/canvas.h>
#include <tapeline/draw/png.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <ostream>
#include <string>
#include <vector>

namespace tapeline::draw {

using tapeline::xml_escape;

/// `v` with exactly `decimals` decimals (printf's %.Nf), as an attribute value.
inline std::string svg_fixed(double v, int decimals = 3) {
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.*f", decimals, v);
    return buf;
}

/// `v` rounded to `decimals` decimals with trailing zeros and a trailing point dropped, and "-0"
/// written "0": smaller files, the same values to the last decimal kept.
inline std::string svg_number(double v, int decimals = 3) {
    std::string s = svg_fixed(v, decimals);
    if (s.find('.') != std::string::npos) {
        s.erase(s.find_last_not_of('0') + 1);
        if (!s.empty() && s.back() == '.') {
            s.pop_back();
        }
    }
    return s == "-0" ? "0" : s;
}

/// "x,y x,y ..." for the points attribute of `<polyline>` and `<polygon>`; with `trim`, numbers as
/// svg_number, else as svg_fixed.
inline std::string svg_points(const std::vector<Vec2>& pts, int decimals = 3, bool trim = true) {
    std::string out;
    for (const Vec2& p : pts) {
        if (!out.empty()) {
            out += ' ';
        }
        out += trim ? svg_number(p.x, decimals) + "," + svg_number(p.y, decimals)
                    : svg_fixed(p.x, decimals) + "," + svg_fixed(p.y, decimals);
    }
    return out;
}

/// "#rrggbb", each channel clamped to [0, 1] and rounded to 8 bits.
inline std::string svg_colour(Rgb c) {
    char s[8];
    const auto ch = [](double v) { return int(std::lround(255 * std::clamp(v, 0.0, 1.0))); };
    std::snprintf(s, sizeof s, "#%02x%02x%02x", ch(c.r), ch(c.g), ch(c.b));
    return s;
}

/// RFC 4648 base64 with padding.
inline std::string base64(const std::vector<std::uint8_t>& bytes) {
    static const char* k = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
    std::string out;
    out.reserve((bytes.size() + 2) / 3 * 4);
    for (std::size_t i = 0; i < bytes.size(); i += 3) {
        const std::uint32_t n = (std::uint32_t(bytes[i]) << 16) |
                                (i + 1 < bytes.size() ? std::uint32_t(bytes[i + 1]) << 8 : 0) |
                                (i + 2 < bytes.size() ? std::uint32_t(bytes[i + 2]) : 0);
        out += k[(n >> 18) & 63];
        out += k[(n >> 12) & 63];
        out += i + 1 < bytes.size() ? k[(n >> 6) & 63] : '=';
        out += i + 2 < bytes.size() ? k[n & 63] : '=';
    }
    return out;
}

/// The image as a "data:image/png;base64,..." URI for an `<image>`'s href.
///
/// \throws InvalidInput as encode_png.
/// \throws std::runtime_error as encode_png.
inline std::string png_data_uri(const RgbaImage& img, double pixels_per_mm) {
    return "data:image/png;base64," + base64(encode_png(img, pixels_per_mm));
}

/// The XML declaration and the opening `<svg>` tag: the SVG namespace, then `before`, then width
/// and height (each followed by `unit`, e.g. "mm" or "" for user units) and a viewBox from the
/// origin over the same numbers, then `after`. `before` and `after` are extra attributes, each
/// starting with a space.
inline void svg_open(std::ostream& out, const std::string& width, const std::string& height,
                     const std::string& unit, const std::string& before = "",
                     const std::string& after = "") {
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<svg xmlns=\"http://www.w3.org/2000/svg\"" << before << " width=\"" << width << unit
        << "\" height=\"" << height << unit << "\" viewBox=\"0 0 " << width << ' ' << height << '"'
        << after << ">\n";
}

}  // namespace tapeline::draw
