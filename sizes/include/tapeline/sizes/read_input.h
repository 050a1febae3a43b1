// Reading a measurement set whatever file it comes in (the base and target sets of `tapeline
// grade --from/--to`), and refusing absurd sets before any work is done.
//
// Accepted: a Seamly2D individual file (.vit); a measurement JSON (json_formats.h: an object with
// a "measurements" array; both names of each entry are kept); a FreeSewing measurement_sets.json
// (an object of sets: pick one by name, or the only one); a flat JSON object {"chest": 979, ...}
// in millimetres, or in the unit of its "units" member.
//
// Patterns bind FreeSewing names (chest, hpsToWaistBack, ...). A .vit names its measurements the
// Seamly2D way (bust_circ, neck_side_to_waist_b, ...) or, for custom ones, "@" + a name
// (`tapeline measure --vit` writes "@" + our name when Seamly2D has none): every name of a .vit
// also comes under its FreeSewing name from the catalogue (add_freesewing_aliases).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/json_read.h>
#include <tapeline/core/units.h>
#include <tapeline/sizes/catalogue.h>
#include <tapeline/sizes/json_formats.h>
#include <tapeline/sizes/measurement_set.h>
#include <tapeline/sizes/seamly.h>

#include <cmath>
#include <map>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace tapeline::sizes {

namespace internal {
/// A value in messages: 6 significant digits ("1e+09", "979", "1e-09").
inline std::string set_value_text(double v) {
    std::ostringstream s;
    s << v;
    return s.str();
}
}  // namespace internal

/// The FreeSewing name a measurement set key stands for: the catalogue's FreeSewing name of the
/// row whose Seamly2D name or our name `key` is ("@" stripped); else the key itself, "@"
/// stripped.
inline std::string freesewing_alias(const std::string& key) {
    const std::string k = !key.empty() && key[0] == '@' ? key.substr(1) : key;
    const CatalogueEntry* e = from_seamly_name(k);
    if (!e || !*e->freesewing) {
        const CatalogueMatch m = find_measurement(k);
        e = m.whole() ? m.entry : e;
    }
    return e && *e->freesewing ? e->freesewing : k;
}

/// Adds, for every key of `m`, its freesewing_alias when `m` does not hold it yet.
inline void add_freesewing_aliases(MeasurementSet& m) {
    std::map<std::string, double> add;
    for (const auto& [k, v] : m.values) {
        const std::string fs = freesewing_alias(k);
        if (!m.values.count(fs) && !add.count(fs)) {
            add[fs] = v;
        }
    }
    m.values.insert(add.begin(), add.end());
}

/// Refuses non-finite or non-positive lengths, a measurement of the catalogue (under any of its
/// names) outside its plausible_range, and a waist above the height (when both are given), naming
/// the set.
///
/// \throws InvalidInput on the first such value.
inline void check_measurement_set(const MeasurementSet& m) {
    const std::string where = m.source.empty() ? "set '" + m.name + "'" : m.source;
    for (const auto& [k, v] : m.values) {
        if (!std::isfinite(v)) {
            throw InvalidInput(where + ": measurement '" + k + "' is not a finite number");
        }
        if (!is_angle_measurement(k) && v <= 0) {
            throw InvalidInput(where + ": measurement '" + k + "' is " + std::to_string(v) +
                               " mm; lengths must be positive");
        }
        if (const CatalogueEntry* e = catalogue_row_of_key(k)) {
            const PlausibleRange r = plausible_range(*e);
            if (v < r.low || v > r.high) {
                throw InvalidInput(
                    where + ": measurement '" + k + "' is " + internal::set_value_text(v) + " " +
                    e->unit() + ", outside the range of a human body (" +
                    internal::set_value_text(r.low) + " to " + internal::set_value_text(r.high) +
                    " " + e->unit() + " for " + to_string(e->kind) + "s); check its unit");
            }
        }
    }
    for (const char* h : {"height", "body_height", "heightTotal"}) {
        const auto height = m.get(h);
        const auto waist = m.get("waist");
        if (height && waist && *waist > *height) {
            throw InvalidInput(where + ": waist " + std::to_string(*waist) +
                               " mm is bigger than the height " + std::to_string(*height) + " mm");
        }
    }
}

/// A measurement set from a parsed JSON document: a measurement JSON or a flat object of
/// millimetres (or of the unit of its "units" member); `where` names it in messages and is its
/// name. Not a FreeSewing sets file (read_measurement_input picks a set of those).
///
/// \throws InvalidInput naming `where` when the document is in neither form, a unit is unknown,
///         or check_measurement_set refuses the set.
inline MeasurementSet measurement_set_from_json(const json::Json& doc, const std::string& where) {
    using json::Json;
    const json::Where top{where, ""};
    json::require_object(doc, top);
    MeasurementSet m;
    if (is_measurement_json(doc)) {
        m = parse_measurement_json(doc, where);
    } else {
        std::string unit = "mm";
        Json values = doc;
        if (const Json* u = json::optional_field(doc, "units")) {
            unit = json::string(*u, top.key("units"));
            values.erase("units");
        }
        m = internal::measurement_object(values, top,
                                         millimetres_per_unit(unit, where + ": units"));
        m.name = where;
    }
    m.source = where;
    check_measurement_set(m);
    return m;
}

/// Reads `path` (see the file comment); `set_name` picks a set of a FreeSewing sets file.
///
/// \throws InvalidInput naming the file (and element) when it cannot be read or parsed, is in
///         none of the accepted forms, `set_name` is not in it (or it holds several sets and
///         none is named), a unit is unknown, or check_measurement_set refuses the set.
inline MeasurementSet read_measurement_input(const std::string& path,
                                             const std::string& set_name = "") {
    using json::Json;
    MeasurementSet m;
    const std::string ext = path.size() > 4 ? path.substr(path.size() - 4) : "";
    if (ext == ".vit") {
        m = read_seamly_individual(path);
        add_freesewing_aliases(m);
    } else {
        const Json doc = json::parse_json_file(path);
        const json::Where top{path, ""};
        json::require_object(doc, top);
        if (is_measurement_json(doc)) {
            m = parse_measurement_json(doc, path);
        } else {
            bool all_objects = !doc.empty();
            for (const auto& [k, v] : doc.items()) {
                all_objects = all_objects && v.is_object();
            }
            if (all_objects) {
                std::vector<MeasurementSet> sets = read_freesewing_measurement_sets(path);
                std::string names;
                for (MeasurementSet& s : sets) {
                    names += (names.empty() ? "" : ", ") + s.name;
                    if (s.name == set_name || (set_name.empty() && sets.size() == 1)) {
                        m = std::move(s);
                    }
                }
                if (m.name.empty()) {
                    throw InvalidInput(path + ": " +
                                       (set_name.empty() ? std::string("holds several sets")
                                                         : "has no set '" + set_name + "'") +
                                       " (" + names + "); pick one with --from-set/--to-set");
                }
            } else {
                m = measurement_set_from_json(doc, path);
                m.name = internal::file_stem(path);
            }
        }
    }
    m.source = path;
    check_measurement_set(m);
    return m;
}

}  // namespace tapeline::sizes
