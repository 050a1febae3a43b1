// Seamly2D / Valentina measurement files: the individual file (.vit; root <vit> or <smis>),
// written and read, and the multisize table (.vst; root <vst> or <smms>), read. XML through
// tapeline/core/xml.h.
//
// Written: unit mm, one <m name=... value=.../> per measurement; a measurement with a Seamly2D
// known name (catalogue.h) under that name, the others as custom measurements, "@" + our name
// (Seamly2D's rule for user-defined names); its ISO 8559-1 title as full name and, when the
// catalogue has a clause number, in the description. Read: names as the file spells them, values
// in mm (angles — see is_angle_measurement — stay in degrees). Values must be plain numbers:
// Seamly2D formulas are not evaluated. A multisize table without <size step=…>/<height step=…>
// uses Seamly2D's fixed grid (size step 2 cm, height step 6 cm, in the file's unit).
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/json_read.h>
#include <tapeline/core/units.h>
#include <tapeline/core/xml.h>
#include <tapeline/core/xml_escape.h>
#include <tapeline/sizes/catalogue.h>
#include <tapeline/sizes/measurement_set.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ostream>
#include <string>

namespace tapeline::sizes {

/// Writes measurements as a Seamly2D individual measurement file (unit mm; angles in degrees,
/// which Seamly2D keeps unscaled); non-finite values are left out. `notes` goes into <notes>
/// (the body file, say).
inline void write_seamly_individual(std::ostream& out, const NamedValues& values,
                                    const std::string& notes = "") {
    out << "<?xml version=\"1.0\" encoding=\"UTF-8\"?>\n"
        << "<vit>\n"
        << "    <!--Measured by tapeline measure (tape girths and skin lengths).-->\n"
        << "    <version>0.3.3</version>\n"
        << "    <read-only>false</read-only>\n";
    if (notes.empty()) {
        out << "    <notes/>\n";
    } else {
        out << "    <notes>" << xml_escape(notes) << "</notes>\n";
    }
    out << "    <unit>mm</unit>\n"
        << "    <pm_system>998</pm_system>\n"
        << "    <personal>\n"
        << "        <family-name/>\n"
        << "        <given-name/>\n"
        << "        <gender>unknown</gender>\n"
        << "    </personal>\n"
        << "    <body-measurements>\n";
    for (const auto& [ours, v] : values) {
        if (!std::isfinite(v)) {
            continue;
        }
        const std::string known = seamly_name(ours);
        const std::string name = known.empty() ? "@" + ours : known;
        char value[64];
        std::snprintf(value, sizeof value, "%.3f", v);
        const std::string title = iso_title(ours), number = iso_number(ours);
        const std::string full = title.empty() ? ours : title;
        out << "        <m name=\"" << xml_escape(name) << "\" value=\"" << value
            << "\" full_name=\"" << xml_escape(full) << "\"";
        if (!number.empty()) {
            out << " description=\"" << xml_escape("ISO 8559-1:2017 " + number + " " + full)
                << "\"";
        }
        out << "/>\n";
    }
    out << "    </body-measurements>\n"
        << "</vit>\n";
}

inline void write_seamly_individual(std::ostream& out, const MeasurementSet& set,
                                    const std::string& notes = "") {
    write_seamly_individual(out, named_values(set), notes);
}

namespace internal {

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

}  // namespace internal

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
    return parse_seamly_individual(json::read_text_file(path), path);
}

inline MultisizeTable read_seamly_multisize(const std::string& path) {
    return parse_seamly_multisize(json::read_text_file(path), path);
}

}  // namespace tapeline::sizes
