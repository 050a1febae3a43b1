// Body-measurement sets (name → millimetres) and their readers: FreeSewing's measurement_sets.json,
// a flat JSON object with a declared unit, and Seamly2D/Valentina individual (.vit) and multisize
// (.vst) measurement files (XML, read with tapeline/pattern/xml.h).
//
// Names are kept as the source spells them (FreeSewing "chest", Seamly2D "bust_arc_f"); mapping
// them to ISO 8559-1 items is the measurement module's job. Angles (names containing "slope",
// "angle" or "incl", e.g. FreeSewing's shoulderSlope) stay in degrees and are not unit-scaled.
//
// Seamly2D multisize tables are linear in size and height: value(size, height) = base
// + (size − base_size)/size_step · size_increase + (height − base_height)/height_step ·
// height_increase, with the steps from the file's <size step=…>/<height step=…> when present and
// Seamly2D's fixed grid otherwise (size step 2 cm, height step 6 cm, in the file's unit).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/pattern/internal/json_read.h>
#include <tapeline/pattern/xml.h>

#include <cctype>
#include <cmath>
#include <cstdlib>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace tapeline::pattern {

struct MeasurementSet {
    std::string name;
    std::string source;                    // file it came from
    std::map<std::string, double> values;  // mm (angles: degrees)

    std::optional<double> get(const std::string& key) const {
        const auto it = values.find(key);
        return it == values.end() ? std::nullopt : std::optional<double>(it->second);
    }
};

/// One row of a multisize table, in mm.
struct MultisizeEntry {
    double base = 0;
    double size_increase = 0;
    double height_increase = 0;
};

/// A Seamly2D multisize table (.vst), in mm; sizes and heights in the file's numbers.
struct MultisizeTable {
    std::string name;
    std::string source;
    double base_size = 0, base_height = 0;
    double size_step = 0, height_step = 0;
    std::map<std::string, MultisizeEntry> entries;

    /// The individual set for one size and height.
    MeasurementSet at(double size, double height) const {
        MeasurementSet m;
        m.source = source;
        m.name = name + " size " + std::to_string(size) + " height " + std::to_string(height);
        for (const auto& [k, e] : entries) {
            m.values[k] = e.base + (size - base_size) / size_step * e.size_increase +
                          (height - base_height) / height_step * e.height_increase;
        }
        return m;
    }
};

/// Whether a measurement name denotes an angle (kept in degrees, never unit-scaled).
inline bool is_angle_measurement(const std::string& name) {
    std::string n;
    for (char c : name) {
        n += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    }
    return n.find("slope") != std::string::npos || n.find("angle") != std::string::npos ||
           n.find("incl") != std::string::npos;
}

/// Millimetres per unit for "mm", "cm", "m", "in"/"inch"; throws InvalidInput naming `where`
/// for anything else.
inline double millimetres_per_unit(const std::string& unit, const std::string& where) {
    if (unit == "mm") {
        return 1;
    }
    if (unit == "cm") {
        return 10;
    }
    if (unit == "m") {
        return 1000;
    }
    if (unit == "in" || unit == "inch") {
        return 25.4;
    }
    throw InvalidInput(where + ": unknown unit '" + unit + "' (expected mm, cm, m or inch)");
}

namespace internal {

inline MeasurementSet measurement_object(const Json& obj, const Where& w, double scale) {
    require_object(obj, w);
    MeasurementSet m;
    for (const auto& [k, v] : obj.items()) {
        const double x = number(v, w.key(k));
        m.values[k] = is_angle_measurement(k) ? x : scale * x;
    }
    return m;
}

/// A measurement value from a Seamly2D attribute: a plain number (formulas are not evaluated).
inline double seamly_number(const std::string& text, const std::string& where) {
    const char* b = text.c_str();
    char* e = nullptr;
    const double v = std::strtod(b, &e);
    while (e && *e && std::isspace(static_cast<unsigned char>(*e))) {
        ++e;
    }
    if (text.empty() || e == b || *e != '\0') {
        throw InvalidInput(where + ": value '" + text +
                           "' is not a number (Seamly2D formulas are not evaluated)");
    }
    if (!std::isfinite(v)) {
        throw InvalidInput(where + ": value '" + text + "' is not finite");
    }
    return v;
}

inline std::string seamly_unit(const xml::Element& root, const std::string& source) {
    const xml::Element* u = root.child("unit");
    if (!u) {
        throw InvalidInput(source + ": <" + root.name + "> has no <unit>");
    }
    std::string t = u->text;
    t.erase(0, t.find_first_not_of(" \t\r\n"));
    t.erase(t.find_last_not_of(" \t\r\n") + 1);
    return t;
}

inline std::string file_stem(const std::string& path) {
    std::string stem = path.substr(path.find_last_of('/') + 1);
    return stem.substr(0, stem.find_last_of('.'));
}

}  // namespace internal

/// FreeSewing's measurement_sets.json: {"set name": {"measurement": mm, ...}, ...}.
inline std::vector<MeasurementSet> read_freesewing_measurement_sets(const std::string& path) {
    using namespace internal;
    const Json doc = parse_json_file(path);
    const Where top{path, ""};
    require_object(doc, top);
    std::vector<MeasurementSet> out;
    for (const auto& [name, obj] : doc.items()) {
        MeasurementSet m = measurement_object(obj, top.key(name), 1.0);
        m.name = name;
        m.source = path;
        out.push_back(std::move(m));
    }
    return out;
}

/// A flat JSON object {"measurement": value, ...} whose values are in `unit` (declared by the
/// caller: the file does not say; DESIGN.md §8).
inline MeasurementSet read_measurement_json(const std::string& path, const std::string& unit) {
    using namespace internal;
    const double scale = millimetres_per_unit(unit, path);
    MeasurementSet m = measurement_object(parse_json_file(path), Where{path, ""}, scale);
    m.name = file_stem(path);
    m.source = path;
    return m;
}

/// A Seamly2D/Valentina individual measurement file (.vit; root <vit> or <smis>).
inline MeasurementSet parse_seamly_individual(const std::string& text, const std::string& source) {
    using namespace internal;
    const xml::Element root = xml::parse(text, source);
    if (root.name != "vit" && root.name != "smis") {
        throw InvalidInput(source + ": root element <" + root.name +
                           "> is not an individual measurement file (<vit> or <smis>)");
    }
    const double scale = millimetres_per_unit(seamly_unit(root, source), source + ": <unit>");
    const xml::Element* body = root.child("body-measurements");
    if (!body) {
        throw InvalidInput(source + ": no <body-measurements>");
    }
    MeasurementSet m;
    m.name = file_stem(source);
    m.source = source;
    for (const xml::Element& e : body->children) {
        if (e.name != "m") {
            continue;
        }
        const std::string where = source + ":" + std::to_string(e.line);
        const std::string* name = e.attribute("name");
        const std::string* value = e.attribute("value");
        if (!name || name->empty()) {
            throw InvalidInput(where + ": <m> without a name");
        }
        if (!value) {
            throw InvalidInput(where + ": measurement '" + *name + "' has no value");
        }
        const double v = seamly_number(*value, where + ": measurement '" + *name + "'");
        m.values[*name] = is_angle_measurement(*name) ? v : scale * v;
    }
    return m;
}

/// A Seamly2D/Valentina multisize measurement table (.vst; root <vst> or <smms>).
inline MultisizeTable parse_seamly_multisize(const std::string& text, const std::string& source) {
    using namespace internal;
    const xml::Element root = xml::parse(text, source);
    if (root.name != "vst" && root.name != "smms") {
        throw InvalidInput(source + ": root element <" + root.name +
                           "> is not a multisize measurement file (<vst> or <smms>)");
    }
    const double scale = millimetres_per_unit(seamly_unit(root, source), source + ": <unit>");
    MultisizeTable t;
    t.name = file_stem(source);
    t.source = source;
    auto base_of = [&](const char* tag, double default_step, double& base, double& step) {
        const xml::Element* e = root.child(tag);
        if (!e || !e->attribute("base")) {
            throw InvalidInput(source + ": no <" + std::string(tag) + " base=...>");
        }
        const std::string where = source + ":" + std::to_string(e->line) + ": <" + tag + ">";
        base = seamly_number(*e->attribute("base"), where);
        step = e->attribute("step") ? seamly_number(*e->attribute("step"), where)
                                    : default_step / scale;  // the fixed grid, in file units
        if (!(step > 0)) {
            throw InvalidInput(where + ": step must be positive");
        }
    };
    base_of("size", 20.0, t.base_size, t.size_step);
    base_of("height", 60.0, t.base_height, t.height_step);
    const xml::Element* body = root.child("body-measurements");
    if (!body) {
        throw InvalidInput(source + ": no <body-measurements>");
    }
    for (const xml::Element& e : body->children) {
        if (e.name != "m") {
            continue;
        }
        const std::string where = source + ":" + std::to_string(e.line);
        const std::string* name = e.attribute("name");
        if (!name || name->empty()) {
            throw InvalidInput(where + ": <m> without a name");
        }
        const std::string mw = where + ": measurement '" + *name + "'";
        const std::string* base = e.attribute("base");
        if (!base) {
            throw InvalidInput(mw + " has no base value");
        }
        const double s = is_angle_measurement(*name) ? 1.0 : scale;
        MultisizeEntry entry;
        entry.base = s * seamly_number(*base, mw);
        if (const std::string* v = e.attribute("size_increase")) {
            entry.size_increase = s * seamly_number(*v, mw + " size_increase");
        }
        if (const std::string* v = e.attribute("height_increase")) {
            entry.height_increase = s * seamly_number(*v, mw + " height_increase");
        }
        t.entries[*name] = entry;
    }
    return t;
}

inline MeasurementSet read_seamly_individual(const std::string& path) {
    return parse_seamly_individual(internal::read_text_file(path), path);
}

inline MultisizeTable read_seamly_multisize(const std::string& path) {
    return parse_seamly_multisize(internal::read_text_file(path), path);
}

}  // namespace tapeline::pattern
