// What the `tapeline wrinkles` commands share: a garment OBJ read in mm (its unit found from its
// pattern coordinates or given), the body it was draped on in the same frame and unit, and the
// table cell format.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/units.h>
#include <tapeline/core/vec3.h>
#include <tapeline/garment/garment_io.h>
#include <tapeline/garment/garment_types.h>
#include <tapeline/wrinkles/strain.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::app::wrinkles_io {

namespace tg = tapeline::garment;

/// A figure right-aligned in 12 (or `width`) columns with one decimal, "-" when not finite.
inline std::string cell(double v, int width = 12) {
    char buf[48];
    if (std::isfinite(v)) {
        std::snprintf(buf, sizeof buf, "%*.1f", width, v);
    } else {
        std::snprintf(buf, sizeof buf, "%*s", width, "-");
    }
    return buf;
}

/// The file's unit from the median size ratio of its triangles to their pattern triangles (mm):
/// a draped cloth is within a few percent of its pattern, so the ratio sits near 1 (mm), 0.1
/// (cm), 0.01 (dm) or 0.001 (m). Refuses a ratio that is not within a factor 1.5 of one of them.
inline LengthUnit garment_unit(const tg::GarmentMesh& g, const std::string& path) {
    std::vector<double> r;
    for (std::size_t f = 0; f < g.triangles.size(); ++f) {
        const auto& t = g.triangles[f];
        const double a3 =
            0.5 * vec3::norm(vec3::cross(vec3::sub(g.positions[t[1]], g.positions[t[0]]),
                                         vec3::sub(g.positions[t[2]], g.positions[t[0]])));
        const double a2 = tapeline::wrinkles::pattern_area(g.uv[f]);
        if (a2 > 0 && a3 > 0) {
            r.push_back(std::sqrt(a3 / a2));
        }
    }
    if (r.empty()) {
        throw InvalidInput(path + ": every triangle or its pattern triangle has zero area");
    }
    std::nth_element(r.begin(), r.begin() + std::ptrdiff_t(r.size() / 2), r.end());
    const double ratio = r[r.size() / 2];
    for (LengthUnit u : {LengthUnit::mm, LengthUnit::cm, LengthUnit::dm, LengthUnit::m}) {
        if (std::abs(std::log(ratio * millimetres_per(u))) < std::log(1.5)) {
            return u;
        }
    }
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4g", ratio);
    throw InvalidInput(path +
                       ": cannot tell the unit of the positions (median size against the "
                       "pattern, in mm, is " +
                       std::string(buf) + "); give --units");
}

/// --units: nullopt for auto, else the unit (InvalidInput for anything but mm, cm, dm, m).
inline std::optional<LengthUnit> units_option(const std::string& units) {
    if (units == "auto") {
        return std::nullopt;
    }
    const auto u = length_unit(units);
    if (!u || *u == LengthUnit::inch) {
        throw InvalidInput("--units " + units + ": expected auto, mm, cm, dm or m");
    }
    return u;
}

/// Reads a garment OBJ and scales it to mm; `found` is the unit given or found.
inline tg::GarmentMesh garment_in_mm(const std::string& path, std::optional<LengthUnit> given,
                                     LengthUnit& found) {
    tg::GarmentMesh g = tg::read_garment_obj(path);
    found = given ? *given : garment_unit(g, path);
    for (tg::Vec3& p : g.positions) {
        p = vec3::scale(p, millimetres_per(found));
    }
    return g;
}

}  // namespace tapeline::app::wrinkles_io
