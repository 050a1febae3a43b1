// Seamly2D / Valentina measurement files: the individual file (.vit; root <vit> or <smis>),
// written and read, and the multisize table (.vst; root <vst> or <smms>), read. XML through
// tapeline/core/xml.h.
//
// Written: format 0.3.3 of the individual file, the version Seamly2D and Valentina share (their
// schema fixes the order of <personal>: family-name, given-name, birth-date, gender, email; the
// birth date is Valentina's own placeholder for "unknown", 1800-01-01). Unit mm; one <m> per
// measurement: under its Seamly2D/Valentina known name (catalogue.h) when it has one, else as a
// custom measurement, "@" + our name (their rule for user-defined names); every one with a full
// name (its ISO 8559-1 title, else our name in words, with the side) and a description (what the
// tape does, the unit, the ISO 8559-1 clause when the catalogue has one). Format 0.3.3 has no
// per-measurement unit: angles are written in degrees and say so in their description.
//
// Read: names as the file spells them, values in mm (angles — see is_angle_measurement — and
// values marked specialUnits stay as written). Values are numbers or formulas over the file's
// other measurements (internal/seamly_formula.h says which). A multisize table without
// <size step=…>/<height step=…> uses Seamly2D's fixed grid (size step 2 cm, height step 6 cm, in
// the file's unit); tables with <dimensions> (Valentina 0.5 and later) are refused.
#pragma once

#include <tapeline/core/errors.h>
#include <tapeline/core/json_read.h>
#include <tapeline/core/units.h>
#include <tapeline/core/xml.h>
#include <tapeline/core/xml_escape.h>
#include <tapeline/sizes/catalogue.h>
#include <tapeline/sizes/internal/seamly_formula.h>
#include <tapeline/sizes/measurement_set.h>

#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <map>
#include <ostream>
#include <set>
#include <string>
#include <vector>

namespace tapeline::sizes {

namespace internal {

/// The full name written for a measurement: its ISO 8559-1 title, else its name in words; the
/// side of a per-side variant in brackets.
inline std::string seamly_full_name(const std::string& ours) {
    const CatalogueMatch m = find_measurement(ours);
    std::string title = m && *m.entry->iso_title ? m.entry->iso_title : (m ? m.entry->name : ours);
    for (char& c : title) {
        c = c == '_' ? ' ' : c;
    }
    if (title.compare(0, 4, "hps ") == 0) {
        title = "HPS " + title.substr(4);  // the high point of the shoulder
    }
    return m.side.empty() ? title : title + " (" + m.side + ")";
}

/// The description written for a measurement: how the tape runs, the unit, the side, and the
/// ISO 8559-1 clause when the catalogue has one.
inline std::string seamly_description(const std::string& ours) {
    const CatalogueMatch m = find_measurement(ours);
    // Indexed by MeasurementKind: girth, length, width, height, angle.
    static const char* const how[] = {"Girth: a closed tape around the body",
                                      "Length: a tape along the skin",
                                      "Width: a tape across the body, along the skin",
                                      "Height: vertical distance from the floor", "Angle"};
    std::string d =
        m ? how[static_cast<int>(m.entry->kind)] : "Measured on the body by tapeline measure";
    d += is_angle_measurement(ours) ? ", in degrees" : ", in mm";
    if (!m.side.empty()) {
        d += ", on the " + m.side + " side";
    }
    d += ".";
    if (m && *m.entry->iso_number) {
        d +=
            std::string(" ISO 8559-1:2017 ") + m.entry->iso_number + " " + m.entry->iso_title + ".";
    }
    return d;
}

/// A measurement value from a Seamly2D attribute: a plain number.
inline double seamly_number(const std::string& text, const std::string& where) {
    const char* b = text.c_str();
    char* e = nullptr;
    const double v = std::strtod(b, &e);
    while (e && *e && std::isspace(static_cast<unsigned char>(*e))) {
        ++e;
    }
    if (text.empty() || e == b || *e != '\0') {
        throw InvalidInput(where + ": value '" + text + "' is not a number");
    }
    if (!std::isfinite(v)) {
        throw InvalidInput(where + ": value '" + text + "' is not finite");
    }
    return v;
}

/// Whether `text` is a plain number (what seamly_number accepts), not a formula.
inline bool seamly_is_number(const std::string& text) {
    const char* b = text.c_str();
    char* e = nullptr;
    std::strtod(b, &e);
    while (e && *e && std::isspace(static_cast<unsigned char>(*e))) {
        ++e;
    }
    return !text.empty() && e != b && *e == '\0';
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

/// Writes measurements as a Seamly2D/Valentina individual measurement file (see the file comment);
/// non-finite values are left out. `notes` goes into `<notes>` (the body file, say).
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
        << "        <birth-date>1800-01-01</birth-date>\n"
        << "        <gender>unknown</gender>\n"
        << "        <email/>\n"
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
        out << "        <m name=\"" << xml_escape(name) << "\" value=\"" << value
            << "\" full_name=\"" << xml_escape(internal::seamly_full_name(ours))
            << "\" description=\"" << xml_escape(internal::seamly_description(ours)) << "\"/>\n";
    }
    out << "    </body-measurements>\n"
        << "</vit>\n";
}

inline void write_seamly_individual(std::ostream& out, const MeasurementSet& set,
                                    const std::string& notes = "") {
    write_seamly_individual(out, named_values(set), notes);
}

/// A Seamly2D/Valentina individual measurement file (.vit; root `<vit>` or `<smis>`). Values may be
/// formulas over the file's other measurements (internal/seamly_formula.h); separators (Valentina
/// 0.5's `<m type="separator">`) are skipped; a value with specialUnits="true" is not scaled. A
/// formula that refers to a name the file does not define (directly or through another formula)
/// leaves its measurement out, listed in `left_out` with the reason; any other formula the
/// reader cannot evaluate refuses the file.
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
    struct Raw {
        std::string value, where;
        bool special_units;
    };
    std::map<std::string, Raw> raw;
    std::vector<std::string> order;
    for (const xml::Element& e : body->children) {
        if (e.name != "m") {
            continue;
        }
        const std::string where = source + ":" + std::to_string(e.line);
        const std::string* type = e.attribute("type");
        if (type && *type == "separator") {
            continue;
        }
        const std::string* name = e.attribute("name");
        const std::string* value = e.attribute("value");
        if (!name || name->empty()) {
            throw InvalidInput(where + ": <m> without a name");
        }
        if (!value) {
            throw InvalidInput(where + ": measurement '" + *name + "' has no value");
        }
        const std::string* special = e.attribute("specialUnits");
        if (!raw.emplace(*name, Raw{*value, where, special && *special == "true"}).second) {
            throw InvalidInput(where + ": measurement '" + *name + "' is defined twice");
        }
        order.push_back(*name);
    }
    // Values in the file's unit, each formula evaluated once, references followed depth-first.
    std::map<std::string, double> done;
    std::set<std::string> visiting;
    std::function<double(const std::string&, const std::string&)> value_of =
        [&](const std::string& name, const std::string& from) -> double {
        if (const auto d = done.find(name); d != done.end()) {
            return d->second;
        }
        const auto r = raw.find(name);
        if (r == raw.end()) {
            throw internal::SeamlyUndefinedName(from + ": refers to '" + name +
                                                "', which the file does not define");
        }
        const std::string mw = r->second.where + ": measurement '" + name + "'";
        // Bounded so that a hostile chain of references cannot exhaust the stack.
        if (visiting.size() >= 1000) {
            throw InvalidInput(mw + ": formulas refer to each other more than 1000 deep");
        }
        if (!visiting.insert(name).second) {
            throw InvalidInput(mw + ": its formula refers back to itself (a cycle)");
        }
        const std::string& text = r->second.value;
        const double v = seamly_is_number(text)
                             ? seamly_number(text, mw)
                             : SeamlyFormula(
                                   text,
                                   [&](const std::string& n) {
                                       return value_of(n, mw + ": formula '" + text + "'");
                                   },
                                   mw)
                                   .evaluate();
        visiting.erase(name);
        return done[name] = v;
    };
    MeasurementSet m;
    m.name = file_stem(source);
    m.source = source;
    for (const std::string& name : order) {
        try {
            const double v = value_of(name, source);
            const bool unscaled = raw.at(name).special_units || is_angle_measurement(name);
            m.values[name] = unscaled ? v : scale * v;
        } catch (const internal::SeamlyUndefinedName& e) {
            // Seamly2D cannot evaluate this one either: it opens the file and marks the value as
            // an error, so the other measurements stay usable.
            m.left_out[name] = e.what();
            visiting.clear();
        }
    }
    return m;
}

/// A Seamly2D/Valentina multisize measurement table (.vst; root `<vst>` or `<smms>`).
inline MultisizeTable parse_seamly_multisize(const std::string& text, const std::string& source) {
    using namespace internal;
    const xml::Element root = xml::parse(text, source);
    if (root.name != "vst" && root.name != "smms") {
        throw InvalidInput(source + ": root element <" + root.name +
                           "> is not a multisize measurement file (<vst> or <smms>)");
    }
    if (const xml::Element* d = root.child("dimensions")) {
        throw InvalidInput(source + ":" + std::to_string(d->line) +
                           ": multisize tables with <dimensions> (Valentina 0.5 and later) are not "
                           "supported; tables with <size> and <height> are");
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
