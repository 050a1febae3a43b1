// What grading writes besides the graded pattern: the fit table (text), the report and the grade
// rules (JSON), a DXF-.RUL-like rule table (text), and the Pareto front as a PNG scatter plot with
// axes, tick labels and a legend (draw/plot.h; no plotting library).
#pragma once

#include <tapeline/core/atomic_write.h>
#include <tapeline/draw/plot.h>
#include <tapeline/draw/png.h>
#include <tapeline/grading/grade.h>
#include <tapeline/grading/grading_json.h>

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

inline nlohmann::json report_json(const GradingReport& r) {
    return r;
}

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

/// The candidates in the (fit, style) plane: NSGA-II members grey, polished members blue, the
/// Ceres fast path green, the chosen one a red ring; axes with tick labels and a legend. PNG bytes.
///
/// \throws std::runtime_error when PNG encoding fails.
inline std::vector<std::uint8_t> pareto_png(const GradingReport& r) {
    using draw::PlotSeries;
    std::vector<PlotSeries> series(4);
    series[0] = {"NSGA-II", {}, {150 / 255.0, 150 / 255.0, 150 / 255.0}};
    series[1] = {"NSGA-II + Ceres polish", {}, {30 / 255.0, 80 / 255.0, 220 / 255.0}};
    series[2] = {"Ceres fast path", {}, {0, 160 / 255.0, 0}};
    series[3] = {"chosen", {}, {220 / 255.0, 0, 0}, PlotSeries::Marker::ring, 6};
    for (std::size_t i = 0; i < r.front.size(); ++i) {
        const ParetoPoint& p = r.front[i];
        const std::size_t k = p.origin == "ceres" ? 2 : p.polished ? 1 : 0;
        series[k].points.push_back({p.fit, p.style});
        if (i == r.chosen) {
            series[3].points.push_back({p.fit, p.style});
        }
    }
    draw::PlotOptions o;
    o.title = "Pareto front of the grading";
    o.x_label = "fit: RMS binding + seam error (mm)";
    o.y_label = "style: RMS change (mm-equivalent)";
    return draw::encode_png(draw::scatter_plot(series, o), 1.0);
}

}  // namespace tapeline::grading
