// What grading writes besides the graded pattern: the fit table (text), the report and the grade
// rules (JSON), a DXF-.RUL-like rule table (text), and the Pareto front as a PNG scatter plot
// drawn with pattern/png.h's encoder and bitmap font (no plotting library).
#pragma once

#include <tapeline/core/atomic_write.h>
#include <tapeline/grading/grade.h>
#include <tapeline/grading/grading_json.h>
#include <tapeline/pattern/internal/bitmap_font.h>
#include <tapeline/pattern/png.h>

#include <nlohmann/json.hpp>

#include <cstdio>
#include <sstream>
#include <string>

namespace tapeline::grading {

inline std::string fit_table(const GradingReport& r) {
    std::ostringstream o;
    char line[256];
    std::snprintf(line, sizeof line, "%-20s %-34s %9s %8s %9s %8s\n", "measurement", "pieces",
                  "target", "ease", "achieved", "error");
    o << line;
    for (const FitRow& f : r.fit) {
        std::snprintf(line, sizeof line, "%-20s %-34s %9.1f %8.1f %9.2f %8.2f\n",
                      f.measurement.c_str(), f.where.substr(0, 34).c_str(), f.target_mm, f.ease_mm,
                      f.achieved_mm, f.error_mm);
        o << line;
    }
    for (const SeamRow& s : r.seams) {
        std::snprintf(line, sizeof line, "seam %-26s %9.2f %9.2f  ratio %.3f  mismatch %6.2f mm\n",
                      s.name.c_str(), s.length_a_mm, s.length_b_mm, s.ratio, s.mismatch_mm);
        o << line;
    }
    return o.str();
}

inline nlohmann::json report_json(const GradingReport& r) { return r; }

/// Grade rules as JSON: per piece, per named point or outline vertex, base → graded and the
/// offset (mm, y up).
inline nlohmann::json rules_json(const GradeResult& g, const std::string& from,
                                 const std::string& to) {
    nlohmann::json j;
    j["format"] = "tapeline-grade-rules";
    j["format_version"] = 1;
    j["units"] = "mm";
    j["from"] = from;
    j["to"] = to;
    j["rules"] = nlohmann::json::array();
    for (const GradeRule& r : g.rules) {
        j["rules"].push_back({{"piece", r.piece},
                              {"point", r.point},
                              {"base", {r.base.x, r.base.y}},
                              {"graded", {r.graded.x, r.graded.y}},
                              {"offset", {r.graded.x - r.base.x, r.graded.y - r.base.y}}});
    }
    return j;
}

/// A rule table in the spirit of an AAMA/ASTM .RUL file: one rule per outline vertex, the x and y
/// offsets from the base size to the graded size (two sizes only), in mm.
inline std::string rul_table(const GradeResult& g, const std::string& from, const std::string& to) {
    std::ostringstream o;
    o << "RULE: DELTA\nUNITS: METRIC\nNUMBER OF SIZES: 2\nSIZE LIST: " << from << " " << to
      << "\nSAMPLE SIZE: " << from << "\n";
    std::size_t k = 0;
    for (const GradeRule& r : g.rules) {
        if (r.point.rfind("edge ", 0) != 0) {
            continue;
        }
        char line[160];
        std::snprintf(line, sizeof line, "RULE: %zu  ; %s %s\n0.000,0.000 %.3f,%.3f\n", ++k,
                      r.piece.c_str(), r.point.c_str(), r.graded.x - r.base.x,
                      r.graded.y - r.base.y);
        o << line;
    }
    o << "END\n";
    return o.str();
}

namespace internal {

struct Canvas {
    pattern::RgbaImage img;
    void set(long x, long y, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
        if (x < 0 || y < 0 || x >= long(img.width) || y >= long(img.height)) {
            return;
        }
        std::uint8_t* p = &img.rgba[4 * (std::size_t(y) * img.width + std::size_t(x))];
        p[0] = r;
        p[1] = g;
        p[2] = b;
        p[3] = 255;
    }
    void text(long x, long y, const std::string& s, int scale = 2) {
        for (char ch : s) {
            const int c = (ch < 32 || ch > 126) ? '?' : ch;
            const auto& glyph = pattern::internal::kBitmapFont[c - 32];
            for (int row = 0; row < pattern::internal::kGlyphRows; ++row) {
                for (int col = 0; col < pattern::internal::kGlyphColumns; ++col) {
                    if (glyph[row] & (1 << (pattern::internal::kGlyphColumns - 1 - col))) {
                        for (int a = 0; a < scale; ++a) {
                            for (int b = 0; b < scale; ++b) {
                                set(x + col * scale + a, y + row * scale + b, 0, 0, 0);
                            }
                        }
                    }
                }
            }
            x += pattern::internal::kGlyphAdvance * scale;
        }
    }
};

}  // namespace internal

/// The candidates in the (fit, style) plane: NSGA-II members grey, polished members blue, the
/// Ceres fast path green, the chosen one a red ring; axes labelled. PNG bytes.
inline std::vector<std::uint8_t> pareto_png(const GradingReport& r) {
    internal::Canvas c;
    c.img.width = 640;
    c.img.height = 480;
    c.img.rgba.assign(4 * c.img.width * c.img.height, 255);
    const long x0 = 80, x1 = 610, y0 = 420, y1 = 40;
    double fmax = 1e-9, smax = 1e-9;
    for (const ParetoPoint& p : r.front) {
        fmax = std::max(fmax, p.fit);
        smax = std::max(smax, p.style);
    }
    fmax *= 1.05;
    smax *= 1.05;
    for (long x = x0; x <= x1; ++x) {
        c.set(x, y0, 0, 0, 0);
    }
    for (long y = y1; y <= y0; ++y) {
        c.set(x0, y, 0, 0, 0);
    }
    auto px = [&](double f) { return x0 + long((x1 - x0) * f / fmax); };
    auto py = [&](double s) { return y0 - long((y0 - y1) * s / smax); };
    for (std::size_t i = 0; i < r.front.size(); ++i) {
        const ParetoPoint& p = r.front[i];
        std::uint8_t cr = 150, cg = 150, cb = 150;
        if (p.origin == "ceres") {
            cr = 0, cg = 160, cb = 0;
        } else if (p.polished) {
            cr = 30, cg = 80, cb = 220;
        }
        const long X = px(p.fit), Y = py(p.style);
        for (long a = -3; a <= 3; ++a) {
            for (long b = -3; b <= 3; ++b) {
                if (a * a + b * b <= 9) {
                    c.set(X + a, Y + b, cr, cg, cb);
                }
                if (i == r.chosen && a * a + b * b >= 25 - 8) {
                    c.set(X + a * 2, Y + b * 2, 220, 0, 0);
                }
            }
        }
    }
    char buf[64];
    c.text(x0, y0 + 20, "fit: RMS binding+seam error (mm), 0 to");
    std::snprintf(buf, sizeof buf, "%.3g", fmax);
    c.text(x1 - 60, y0 + 20, buf);
    c.text(10, 10, "style (RMS, mm-equiv.), 0 to");
    std::snprintf(buf, sizeof buf, "%.3g", smax);
    c.text(360, 10, buf);
    c.text(x0 + 20, y1 + 10, "grey NSGA-II  blue +Ceres  green Ceres  red chosen", 1);
    return pattern::encode_png(c.img, 1.0);
}

}  // namespace tapeline::grading
